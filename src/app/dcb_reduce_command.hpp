// `plyimpact dcb-reduce DATA.csv --width B --thickness H [options] [-o DIR]`: the ASTM D5528
// reduction (fracture/dcb_reduction.hpp) of a DCB record from a test machine or a simulated DCB,
// written as a CSV R-curve, a JSON summary of the fits and a PNG plot.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace plyimpact::app {

extern const char* const kDcbReduceUsage;

/// `args`: the words after "dcb-reduce". Returns the exit code (0 done, 64 bad usage); bad data
/// throws InputError, output failures RunError (the caller reports both).
int dcb_reduce_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace plyimpact::app
