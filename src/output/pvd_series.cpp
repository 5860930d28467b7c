#include "output/pvd_series.hpp"

#include <bit>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plyimpact::output {
namespace fs = std::filesystem;

namespace {

void append_xml_escaped(std::string& out, std::string_view text) {
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
}

}  // namespace

PvdSeries::PvdSeries(fs::path directory, std::string name)
    : directory_(std::move(directory)), name_(std::move(name)) {
  if (name_.empty() || name_.find('/') != std::string::npos) {
    throw RunError(msg() << "PVD series name '" << name_ << "' must be a non-empty file stem");
  }
}

void PvdSeries::add(double time, const std::string& vtu_file_name) { add(time, vtu_file_name, 0, ""); }

void PvdSeries::add(double time, const std::string& vtu_file_name, int part, const std::string& block_name) {
  if (!std::isfinite(time)) {
    throw RunError(msg() << "PVD series '" << path().string() << "': frame '" << vtu_file_name
                         << "' has non-finite time " << time);
  }
  const fs::path file(vtu_file_name);
  if (vtu_file_name.empty() || file.is_absolute()) {
    throw RunError(msg() << "PVD series '" << path().string() << "': frame file '"
                         << vtu_file_name << "' must be a path relative to '"
                         << directory_.string() << "'");
  }
  if (part < 0) {
    throw RunError(msg() << "PVD series '" << path().string() << "': frame '" << vtu_file_name
                         << "' has negative part " << part);
  }
  frames_.push_back({time, file.generic_string(), part, block_name});
}

void PvdSeries::write() const {
  const char* byte_order =
      std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  std::string xml;
  xml.reserve(160 + 80 * frames_.size());
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"";
  xml += byte_order;
  xml += "\">\n  <Collection>\n";
  char time[32];
  for (const Entry& e : frames_) {
    // 17 significant digits round-trip any double, so ParaView's time matches the solver's.
    std::snprintf(time, sizeof time, "%.17g", e.time);
    xml += "    <DataSet timestep=\"";
    xml += time;
    xml += "\" group=\"\" part=\"";
    xml += std::to_string(e.part);
    if (!e.name.empty()) {
      xml += "\" name=\"";
      append_xml_escaped(xml, e.name);
    }
    xml += "\" file=\"";
    append_xml_escaped(xml, e.file);
    xml += "\"/>\n";
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_text_atomically(path(), xml);
}

fs::path PvdSeries::path() const { return directory_ / (name_ + ".pvd"); }

}  // namespace plyimpact::output
