// `plyimpact plot DATA.csv --y COL[,COL...] [--x COL] [-o FILE.png] [--logx] [--logy]
// [--title T]`: a PNG of named columns of any CSV (a run's history.csv, a D5528 reduction, ...),
// made headlessly with gnuplot (output/csv_plot.hpp).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace plyimpact::app {

extern const char* const kPlotUsage;

/// `args`: the words after "plot". Returns the exit code (0 done, 64 bad usage); an unknown column
/// throws InputError, a missing or failing gnuplot RunError.
int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace plyimpact::app
