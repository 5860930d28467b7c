// `plyimpact study STUDY.yaml [-j N] [--threads T] [-o DIR] [--dry-run | --collect |
// --emit slurm|parallel]`: parameter sweeps and mesh-convergence studies (study/study.hpp).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace plyimpact::app {

extern const char* const kStudyUsage;

/// `args`: the words after "study". Returns the exit code: 0 all cases finished, 2 some failed or
/// are pending, 64 bad usage; an invalid study file or case throws InputError.
int study_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace plyimpact::app
