// Test support for studies: a scratch folder per test, file writing, and the plyimpact executable
// the study runs its cases with.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace plyimpact::test {

inline const std::filesystem::path kProgram = PLYIMPACT_BINARY_DIR "/src/app/plyimpact";

class StudyDir {
 public:
  StudyDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    std::replace(name.begin(), name.end(), '/', '_');
    path_ = std::filesystem::temp_directory_path() / ("plyimpact_study_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~StudyDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  StudyDir(const StudyDir&) = delete;
  StudyDir& operator=(const StudyDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::ofstream(p) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace plyimpact::test
