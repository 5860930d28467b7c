// PNG plots of named columns of a CSV file (history.csv, a D5528 reduction, a study table), made
// headlessly by gnuplot (Debian package gnuplot-nox, pngcairo terminal; tools/install-deps.sh
// installs it). gnuplot reads the CSV itself, so nothing is copied; this module checks the column
// names first (for a clear error), writes the gnuplot script, runs gnuplot and replaces the PNG
// atomically. Not for hot paths: one process per plot.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact::output {

struct PlotSeries {
  std::string y_column;
  std::string title;  // legend entry; the column name when empty
  std::filesystem::path csv{};  // another CSV with the same x column (e.g. a fitted curve); empty: CsvPlot::csv
  bool points_only = false;     // markers without lines (measured points beside a fitted curve)
};

struct CsvPlot {
  std::filesystem::path csv;
  std::string x_column;
  std::vector<PlotSeries> series;  // at least one
  std::string title, x_label, y_label;  // labels default to the column names
  double x_scale = 1, y_scale = 1;      // plotted value = column value * scale (e.g. 1e3 for m -> mm)
  bool log_x = false, log_y = false;
  bool with_points = false;  // markers at the data points (few rows) instead of plain lines
  int width = 1000, height = 700;  // pixels
};

/// The gnuplot executable on PATH, or nothing.
std::optional<std::filesystem::path> find_gnuplot();

/// Column names of a CSV file: its first non-empty line not starting with '#', split at commas.
/// @throws InputError when the file cannot be read or has no header
std::vector<std::string> csv_columns(const std::filesystem::path& csv);

/// Runs gnuplot on the script `script(tmp)`, which must draw a PNG into the file `tmp`, and replaces
/// `png` with it atomically. `what` names the plot in errors.
/// @throws RunError when gnuplot is missing or fails (with its message) or writes an empty image
void gnuplot_png(const std::function<std::string(const std::filesystem::path& tmp)>& script,
                 const std::filesystem::path& png, const std::string& what);

/// Writes `png` from `plot`.
/// @throws InputError for an unknown column (naming the file and the columns it has),
///         RunError when gnuplot is missing or fails (with its message) or the PNG cannot be written
void plot_csv_png(const CsvPlot& plot, const std::filesystem::path& png);

}  // namespace plyimpact::output
