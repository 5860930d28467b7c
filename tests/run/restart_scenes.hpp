// Support for the restart, signal and output-folder tests: small scenes that exercise every kind of
// run state, running the command line in-process or as a child process, and reading result files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/application.hpp"

namespace plyimpact::test {

namespace fs = std::filesystem;

// A 10 x 10 mm [0/90]s *MAT_054 plate with strain-based erosion, clamped on its edges, struck at
// 300 m/s by a rigid steel sphere through an eroding contact: contact springs, erosion (alive
// masks, rebuilt contact surfaces), *MAT_054 damage history and a rigid body all carry state
// across a restart. About 200 cycles.
inline const char* kImpactScene = R"(units: mm-t-s-MPa
control: {termination_time: 6.0e-6}
output: {interval: 1.0e-6, history_interval: 5.0e-8}
materials:
  ply:
    card: MAT_054
    RO: 1548 kg/m^3
    EA: 117.9 GPa
    EB: 8.825 GPa
    EC: 8.825 GPa
    PRBA: 0.025
    PRCA: 0.025
    PRCB: 0.3
    GAB: 5.51 GPa
    GBC: 2.53 GPa
    GCA: 5.51 GPa
    AOPT: 2
    A: [1, 0, 0]
    D: [0, 1, 0]
    XT: 1.103 GPa
    XC: 1.034 GPa
    YT: 0.055 GPa
    YC: 0.25 GPa
    SC: 0.07 GPa
    BETA: 1
    DFAILT: 9.35e-3
    DFAILC: -8.77e-3
    DFAILM: 0.028
    DFAILS: 0.03
  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}
sections:
  ply: {ELFORM: 1, IHQ: 4, QM: 0.1}
laminate:
  length: 10
  width: 10
  ply_thickness: 0.25
  stacking: "[0/90]s"
  material: ply
  section: ply
  element_size: 1
  interfaces: none
  supports:
    edges: {clamped: [x0, x1, y0, y1], fix: [x, y, z]}
impactor:
  shape: sphere
  diameter: 4
  mass: 0.002 kg
  gap: 0.05
  velocity: 300 m/s
  element_size: 1
  rigid: true
  material: steel
contacts:
  - name: impact
    type: eroding_surface_to_surface
    surfaces: [impactor, [ply_1_0, ply_2_90, ply_3_90, ply_4_0]]
    SOFT: 1
)";

// The same plate of *MAT_002 plies with a tiebreak interface between the 0 and 90 plies (OPTION 9,
// softening), struck at 100 m/s: the interface's pair state carries across the restart.
inline const char* kTiebreakScene = R"(units: mm-t-s-MPa
control: {termination_time: 3.0e-6}
output: {interval: 1.0e-6, history_interval: 5.0e-8}
materials:
  ply: {card: MAT_002, RO: 1600 kg/m^3, EA: 120 GPa, EB: 10 GPa, EC: 10 GPa, PRBA: 0.025, PRCA: 0.025,
        PRCB: 0.45, GAB: 5 GPa, GBC: 3.5 GPa, GCA: 5 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}
  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}
sections:
  ply: {ELFORM: 1, IHQ: 4, QM: 0.1}
laminate:
  length: 8
  width: 8
  ply_thickness: 0.25
  stacking: [0, 90, 90, 0]
  material: ply
  section: ply
  element_size: 1
  interfaces: {select: angle-change, model: tiebreak, OPTION: 9, NFLS: 60 MPa, SFLS: 50 MPa, ERATEN: 765 J/m^2,
               ERATES: 1250 J/m^2, PARAM: 1, CN: 100 kN/mm^3, CT2CN: 1}
  supports:
    edges: {clamped: [x0, x1, y0, y1], fix: [x, y, z]}
impactor:
  shape: sphere
  diameter: 3
  mass: 0.002 kg
  gap: 0.05
  velocity: 100 m/s
  element_size: 1
  rigid: true
  material: steel
contacts:
  - name: impact
    type: automatic_surface_to_surface
    surfaces: [impactor, [ply_1_0, ply_2_90, ply_3_90, ply_4_0]]
    SOFT: 1
)";

// A fresh directory per test and process, removed afterwards.
class TestDir {
 public:
  TestDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    std::replace(name.begin(), name.end(), '/', '_');
    path_ = fs::temp_directory_path() / ("plyimpact_run_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TestDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TestDir(const TestDir&) = delete;
  TestDir& operator=(const TestDir&) = delete;
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

inline fs::path write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

inline std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct CommandResult {
  int code = 0;
  std::string out, err;
};

// `plyimpact <args>` in this process.
inline CommandResult plyimpact(const std::vector<std::string>& args) {
  std::ostringstream o, e;
  CommandResult r;
  r.code = app::run_application(args, o, e);
  r.out = o.str();
  r.err = e.str();
  return r;
}

// The frame files a .pvd lists, in order.
inline std::vector<std::string> pvd_frames(const fs::path& pvd) {
  std::vector<std::string> files;
  const std::string text = read_file(pvd);
  for (std::size_t p = text.find("file=\""); p != std::string::npos; p = text.find("file=\"", p + 1)) {
    const std::size_t start = p + 6;
    files.push_back(text.substr(start, text.find('"', start) - start));
  }
  return files;
}

// A number after "key": in a JSON text (the first occurrence), NaN when absent.
inline double json_number(const std::string& json, const std::string& key) {
  const std::size_t p = json.find("\"" + key + "\": ");
  return p == std::string::npos ? std::nan("") : std::strtod(json.c_str() + p + key.size() + 4, nullptr);
}

}  // namespace plyimpact::test
