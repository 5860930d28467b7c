// Test support for studies: the scratch folder of the output tests (tests/output/scratch_dir.hpp),
// file writing, and the plyimpact executable the study runs its cases with.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.hpp"

namespace plyimpact::test {

inline const std::filesystem::path kProgram = PLYIMPACT_BINARY_DIR "/src/app/plyimpact";

/// Writes `text` to `path` and returns the path.
inline std::filesystem::path write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

}  // namespace plyimpact::test
