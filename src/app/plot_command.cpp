// plot: argument parsing onto output::CsvPlot. See plot_command.hpp.
#include "app/plot_command.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "output/csv_plot.hpp"

namespace plyimpact::app {

const char* const kPlotUsage =
    "  plot DATA.csv --y COL[,COL...] [--x COL] [-o FILE.png] [--logx] [--logy] [--title T]\n"
    "                            PNG of named columns of any CSV (e.g. a run's history.csv), made\n"
    "                            headlessly with gnuplot; x defaults to 'time' when the file has it,\n"
    "                            else its first column; FILE defaults to <DATA>_<first y>.png beside DATA\n";

int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  namespace fs = std::filesystem;
  output::CsvPlot plot;
  std::string ys, png;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    if (a == "--y" && has_value) ys = args[++i];
    else if (a == "--x" && has_value) plot.x_column = args[++i];
    else if ((a == "-o" || a == "--output") && has_value) png = args[++i];
    else if (a == "--title" && has_value) plot.title = args[++i];
    else if (a == "--logx") plot.log_x = true;
    else if (a == "--logy") plot.log_y = true;
    else if (plot.csv.empty() && !a.starts_with("-")) plot.csv = a;
    else {
      err << "plyimpact plot: unexpected argument '" << a << "'\nusage:\n" << kPlotUsage;
      return 64;
    }
  }
  std::stringstream list(ys);
  for (std::string y; std::getline(list, y, ',');)
    if (!y.empty()) plot.series.push_back({y, ""});
  if (plot.csv.empty() || plot.series.empty()) {
    err << "plyimpact plot: needs DATA.csv and --y COL\nusage:\n" << kPlotUsage;
    return 64;
  }
  if (plot.x_column.empty()) {
    const auto columns = output::csv_columns(plot.csv);
    plot.x_column = std::find(columns.begin(), columns.end(), "time") != columns.end() ? "time" : columns.front();
  }
  if (plot.title.empty()) plot.title = plot.csv.filename().string();
  if (plot.series.size() > 1) plot.y_label = "value";
  const fs::path target = png.empty() ? plot.csv.parent_path() / (plot.csv.stem().string() + "_" +
                                                                    plot.series.front().y_column + ".png")
                                      : fs::path(png);
  output::plot_csv_png(plot, target);
  out << "wrote " << target.string() << "\n";
  return 0;
}

}  // namespace plyimpact::app
