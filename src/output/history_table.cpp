#include "output/history_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plyimpact::output {

namespace {

// RFC 4180: a name with a comma, quote or line break is quoted, quotes doubled.
void append_csv_field(std::string& out, const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) {
    out += text;
    return;
  }
  out += '"';
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

void append_number(std::string& out, double v) {
  // glibc prints a NaN with the sign bit set as "-nan"; one spelling keeps readers simple.
  if (std::isnan(v)) {
    out += "nan";
  } else if (std::isinf(v)) {
    out += v > 0 ? "inf" : "-inf";
  } else {
    char buf[32];
    const int n = std::snprintf(buf, sizeof buf, "%.10g", v);
    out.append(buf, static_cast<std::size_t>(n));
  }
}

}  // namespace

HistoryTable::HistoryTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
  if (columns_.empty()) throw RunError("history table needs at least one column");
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (columns_[i].empty()) throw RunError(msg() << "history table column " << i << " has no name");
  }
}

void HistoryTable::add_row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw RunError(msg() << "history table row has " << values.size() << " values, expected "
                         << columns_.size() << " (" << columns_.front() << " ... "
                         << columns_.back() << ")");
  }
  values_.insert(values_.end(), values.begin(), values.end());
}

void HistoryTable::write_csv(const std::filesystem::path& path) const { write_text_atomically(path, csv_text(0, true)); }

std::string HistoryTable::csv_text(std::size_t first_row, bool with_header) const {
  std::string text;
  const std::size_t ncol = columns_.size();
  const std::size_t first = std::min(first_row * ncol, values_.size());
  text.reserve(16 * ((with_header ? ncol : 0) + values_.size() - first));
  if (with_header) {
    for (std::size_t c = 0; c < ncol; ++c) {
      if (c > 0) text += ',';
      append_csv_field(text, columns_[c]);
    }
    text += '\n';
  }
  for (std::size_t i = first; i < values_.size(); ++i) {
    append_number(text, values_[i]);
    text += (i % ncol == ncol - 1) ? '\n' : ',';
  }
  return text;
}

int HistoryTable::column_index(std::string_view name) const {
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c] == name) return int(c);
  return -1;
}

namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') {
      if (quoted && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else {
        quoted = !quoted;
      }
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

HistoryTable read_history_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(msg() << path.string() << ": cannot open the CSV file; allowed a path to a readable file");
  std::string line;
  std::size_t line_no = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line != "\r") header = split_csv_line(line);
  }
  if (header.empty()) throw InputError(msg() << path.string() << ": no header line; allowed a CSV with named columns");
  HistoryTable table(header);
  std::vector<double> row(header.size());
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line == "\r") continue;
    const auto fields = split_csv_line(line);
    if (fields.size() != header.size())
      throw InputError(msg() << path.string() << ":" << line_no << ": " << fields.size() << " fields; allowed "
                             << header.size() << " (one per column of the header)");
    for (std::size_t c = 0; c < fields.size(); ++c) {
      char* end = nullptr;
      row[c] = std::strtod(fields[c].c_str(), &end);
      if (fields[c].empty() || *end != '\0')
        throw InputError(msg() << path.string() << ":" << line_no << ": column '" << header[c] << "': '" << fields[c]
                               << "' is not a number; allowed a decimal number, nan or inf");
    }
    table.add_row(row);
  }
  return table;
}

}  // namespace plyimpact::output
