// Test support for the interoperability tests: a scratch directory per test, whole-file reading
// and running a loaded scene to its end (results in a folder), as `plyimpact run` does.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "config/scene.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "run/run.hpp"

namespace plyimpact::test {

inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto p = std::filesystem::temp_directory_path() /
                 ("plyimpact_interop_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
                  std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

// Runs the scene (mesh included) and returns the text of its history.csv.
inline std::string run_history(const config::Scene& scene, const std::filesystem::path& dir) {
  const mesh::Mesh m = mesh::mesh_scene(scene);
  const model::Model model = model::build_model(scene, m);
  run::RunOptions options;
  options.output_dir = dir;
  const auto report = run::run_model(model, options);
  EXPECT_TRUE(report.completed) << report.stop_reason;
  return read_file(report.history);
}

}  // namespace plyimpact::test
