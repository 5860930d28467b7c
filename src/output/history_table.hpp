// Time-history table (energies, contact force, deflection ... one row per output step) written as
// CSV for regression gold files and plotting. Rows live in one contiguous row-major vector so
// appending a row in the time loop allocates only when the vector grows (call reserve() to avoid
// even that). The CSV is replaced atomically, so a plot script never reads a torn file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace plyimpact::output {

class HistoryTable {
 public:
  /// Column names, in order; at least one, none empty.
  explicit HistoryTable(std::vector<std::string> columns);

  /// Appends one row; `values.size()` must equal the number of columns (else plyimpact::RunError).
  void add_row(std::span<const double> values);
  void reserve(std::size_t rows) { values_.reserve(rows * columns_.size()); }

  // columns_ is only empty in a moved-from table.
  std::size_t rows() const { return columns_.empty() ? 0 : values_.size() / columns_.size(); }
  const std::vector<std::string>& columns() const { return columns_; }
  /// Index of the named column, or -1.
  int column_index(std::string_view name) const;
  /// Value at (row, column).
  double at(std::size_t row, std::size_t column) const { return values_[row * columns_.size() + column]; }
  /// Row-major, shape (rows(), columns().size()).
  std::span<const double> values() const { return values_; }

  /// Atomically writes a header line and one line per row, values as %.10g; NaN is written as
  /// "nan" and infinities as "inf"/"-inf" (strtod and numpy read both back).
  void write_csv(const std::filesystem::path& path) const;

  /// The CSV text write_csv writes, from row `first_row` on, with or without the header line (a
  /// writer that appends rows to a file as they come).
  std::string csv_text(std::size_t first_row, bool with_header) const;

 private:
  std::vector<std::string> columns_;
  std::vector<double> values_;
};

/// Reads back a CSV written by HistoryTable::write_csv (a header line, then numeric rows; "nan",
/// "inf" accepted).
/// @throws InputError naming file:line when the file cannot be read, a row has the wrong number of
///         fields or a field is not a number
HistoryTable read_history_csv(const std::filesystem::path& path);

}  // namespace plyimpact::output
