// The command-line front end: parses arguments, loads and checks a scene, builds the model and runs
// it. Every error is caught here once and printed as one line; the exit code says what happened
// (0 done, 1 bad input, 2 run stopped early, 64 bad command line).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace plyimpact::app {

int run_application(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace plyimpact::app
