// Reading a DCB record from CSV. See dcb_record.hpp.
#include "fracture/dcb_record.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/error.hpp"
#include "core/units.hpp"

namespace plyimpact::fracture {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\"");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\"");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(sep, start);
    out.push_back(trim(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start)));
    if (end == std::string_view::npos) return out;
    start = end + 1;
  }
}

std::string join(const std::vector<std::string_view>& names) {
  std::string out;
  for (auto n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

struct Header {
  char sep = ',';
  std::size_t load = 0, opening = 0, crack = 0;
  std::size_t count = 0;
};

Header read_header(std::string_view line, const std::string& where, const DcbColumns& c) {
  Header h;
  h.sep = line.find(',') != std::string_view::npos   ? ','
          : line.find(';') != std::string_view::npos ? ';'
          : line.find('\t') != std::string_view::npos ? '\t'
                                                       : ',';
  const auto names = split(line, h.sep);
  h.count = names.size();
  auto find = [&](const std::string& name, const char* role, const char* option) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw InputError(msg() << where << ": no column '" << name << "' (" << role << "); found columns " << join(names)
                             << "; allowed any of these, chosen with " << option << " NAME");
    return std::size_t(it - names.begin());
  };
  h.load = find(c.load, "load P", "--load");
  h.opening = find(c.opening, "opening delta", "--opening");
  h.crack = find(c.crack, "crack length a", "--crack");
  return h;
}

double field(const std::vector<std::string_view>& fields, std::size_t i, const std::string& column,
             const std::string& where) {
  double v = 0;
  try {
    v = units::parse_number(fields[i]);
  } catch (const units::UnitError&) {
    throw InputError(msg() << where << ": column '" << column << "': '" << fields[i]
                           << "' is not a number; allowed a finite decimal number");
  }
  return v;
}

}  // namespace

DcbRecord parse_dcb_record(std::string_view text, const std::string& file_label, const DcbColumns& columns,
                           const DcbUnits& units) {
  DcbRecord rec;
  rec.file = file_label;
  std::optional<Header> header;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (line.empty() || line.front() == '#') continue;
    const std::string where = msg() << file_label << ":" << line_no;
    if (!header) {
      header = read_header(line, where, columns);
      continue;
    }
    const auto fields = split(line, header->sep);
    if (fields.size() != header->count)
      throw InputError(msg() << where << ": " << fields.size() << " fields but the header has " << header->count
                             << " columns; allowed one value per column");
    DcbRow row;
    row.line = line_no;
    row.point.P = field(fields, header->load, columns.load, where) * units.force;
    row.point.delta = field(fields, header->opening, columns.opening, where) * units.length;
    row.point.a = field(fields, header->crack, columns.crack, where) * units.length;
    rec.rows.push_back(row);
  }
  if (!header)
    throw InputError(msg() << file_label << ": no header line; allowed a CSV whose first line names the columns ("
                           << columns.load << ", " << columns.opening << ", " << columns.crack << ")");
  return rec;
}

DcbRecord read_dcb_record(const std::string& path, const DcbColumns& columns, const DcbUnits& units) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(msg() << path << ": cannot open the data file; allowed a path to a readable CSV file");
  std::ostringstream s;
  s << in.rdbuf();
  return parse_dcb_record(s.str(), path, columns, units);
}

DcbRecord smoothed_record(const DcbRecord& record, int half_width) {
  DcbRecord out = record;
  const long n = long(record.rows.size());
  for (long i = 0; i < n; ++i) {
    const long lo = std::max(0L, i - half_width), hi = std::min(n - 1, i + half_width);
    double P = 0, delta = 0;
    for (long j = lo; j <= hi; ++j) P += record.rows[j].point.P, delta += record.rows[j].point.delta;
    out.rows[i].point.P = P / double(hi - lo + 1);
    out.rows[i].point.delta = delta / double(hi - lo + 1);
  }
  return out;
}

std::vector<DcbRow> propagation_points(const DcbRecord& record, PropagationRule rule) {
  std::vector<DcbRow> out;
  for (std::size_t i = 0; i < record.rows.size(); ++i) {
    const DcbRow& row = record.rows[i];
    if (i > 0) {
      const DcbRow& prev = record.rows[i - 1];
      const bool decreases = rule == PropagationRule::all_rows ? !(row.point.a > prev.point.a) : row.point.a < prev.point.a;
      if (decreases)
        throw InputError(msg() << record.file << ":" << row.line << ": crack length " << row.point.a << " m after "
                               << prev.point.a << " m on line " << prev.line << "; allowed a crack length that "
                               << (rule == PropagationRule::all_rows ? "increases from row to row"
                                                                     : "never decreases (the record of one test)"));
    }
    const bool grows = rule == PropagationRule::all_rows || (i > 0 && row.point.a > record.rows[i - 1].point.a);
    if (!grows) continue;
    if (!(row.point.P > 0) || !(row.point.delta > 0) || !(row.point.a > 0))
      throw InputError(msg() << record.file << ":" << row.line << ": propagation point with load " << row.point.P
                             << " N, opening " << row.point.delta << " m, crack length " << row.point.a
                             << " m; allowed positive values (the compliance delta/P must exist)");
    out.push_back(row);
  }
  if (out.size() < 3)
    throw InputError(msg() << record.file << ": " << out.size() << " propagation point(s) ("
                           << (rule == PropagationRule::all_rows ? "rows" : "rows where the crack length increases")
                           << "); allowed at least 3 (each method fits a line through them)");
  return out;
}

}  // namespace plyimpact::fracture
