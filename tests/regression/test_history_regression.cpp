// Regression: each scene of tests/data/regression is run with `plyimpact run` and its history.csv
// compared with the stored reference <scene>.history.csv, column by column.
// Tolerance: |new - reference| <= 1e-6 of the largest |reference| value of that column (plus the
// smallest normal double, for all-zero columns). Why 1e-6: the file keeps 10 significant digits
// (1e-10); the scenes are short (< 1000 cycles) and smooth (no failure, no release of contact
// springs by a threshold), so round-off from another compiler, flags or thread count stays at the
// file's precision: perturbing the input by 1e-12 (the modulus EA) moved no column by more than
// 5e-10 of its scale. A change of the physics (a modulus, a formula term, a stiffness) moves the columns by
// 1e-4 or more. The columns themselves must match by name and order: a new or renamed column is
// a change of the file format and needs a new reference.
// Regenerate (after a deliberate change, and say why in the commit):
//   PLYIMPACT_REGENERATE_REFERENCE=1 ctest --test-dir build -L regression
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "app/application.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

Table read_csv(const fs::path& path) {
  std::ifstream in(path);
  Table t;
  std::string line;
  if (!std::getline(in, line)) {
    ADD_FAILURE() << "cannot read " << path;
    return t;
  }
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) t.columns.push_back(c);
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::vector<double> values;
    for (std::string v; std::getline(row, v, ',');) values.push_back(std::strtod(v.c_str(), nullptr));
    t.rows.push_back(std::move(values));
  }
  return t;
}

class HistoryRegression : public ::testing::TestWithParam<std::string> {};  // parameter: scene stem

TEST_P(HistoryRegression, HistoryMatchesTheStoredReference) {
  const fs::path data = fs::path(PLYIMPACT_SOURCE_DIR) / "tests" / "data" / "regression";
  const fs::path scene = data / (GetParam() + ".yaml"), reference = data / (GetParam() + ".history.csv");
  const fs::path out = fs::temp_directory_path() / ("plyimpact_regression_" + GetParam() + "_" + std::to_string(::getpid()));
  fs::remove_all(out);
  std::ostringstream o, e;
  ASSERT_EQ(0, app::run_application({"run", scene.string(), "-o", out.string()}, o, e)) << e.str() << o.str();
  const fs::path produced = out / "history.csv";
  if (std::getenv("PLYIMPACT_REGENERATE_REFERENCE") != nullptr) {
    fs::copy_file(produced, reference, fs::copy_options::overwrite_existing);
    fs::remove_all(out);
    GTEST_SKIP() << "reference regenerated: " << reference;
  }
  ASSERT_TRUE(fs::exists(reference)) << "no reference " << reference << " (see the regenerate command above)";
  const Table now = read_csv(produced), ref = read_csv(reference);
  fs::remove_all(out);
  ASSERT_EQ(now.columns, ref.columns);
  ASSERT_EQ(now.rows.size(), ref.rows.size());
  for (std::size_t c = 0; c < ref.columns.size(); ++c) {
    double scale = std::numeric_limits<double>::min();
    for (const auto& r : ref.rows) scale = std::max(scale, std::abs(r[c]));
    double worst = 0;
    std::size_t at = 0;
    for (std::size_t i = 0; i < ref.rows.size(); ++i) {
      const double d = std::abs(now.rows[i][c] - ref.rows[i][c]);
      if (!(d <= worst)) worst = d, at = i;  // NaN counts as the worst
    }
    EXPECT_LE(worst, 1e-6 * scale) << "column " << ref.columns[c] << ", row " << at << ": " << now.rows[at][c]
                                   << " against " << ref.rows[at][c] << " (scale " << scale << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, HistoryRegression, ::testing::Values("ply_strip", "rigid_drop"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace plyimpact
