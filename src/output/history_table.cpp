#include "output/history_table.hpp"

#include <cmath>
#include <cstdio>

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

void HistoryTable::write_csv(const std::filesystem::path& path) const {
  std::string text;
  text.reserve(16 * (columns_.size() + values_.size()));
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (c > 0) text += ',';
    append_csv_field(text, columns_[c]);
  }
  text += '\n';
  const std::size_t ncol = columns_.size();
  for (std::size_t i = 0; i < values_.size(); ++i) {
    append_number(text, values_[i]);
    text += (i % ncol == ncol - 1) ? '\n' : ',';
  }
  write_text_atomically(path, text);
}

}  // namespace plyimpact::output
