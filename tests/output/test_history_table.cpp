// HistoryTable: the CSV parses back to the stored numbers (10 significant digits), non-finite
// values have one spelling each, and a row of the wrong length is refused without side effects.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "output/history_table.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using plyimpact::RunError;
using plyimpact::output::HistoryTable;

using plyimpact::test::ScratchDir;
using plyimpact::test::slurp;

namespace {

std::vector<std::string> read_lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
  return cells;
}

constexpr double kRelTol = 1e-9;  // %.10g keeps 10 significant digits: error <= 5e-10 relative

}  // namespace

TEST(HistoryTable, CsvParsesBackToTheRows) {
  ScratchDir dir;
  HistoryTable table({"time", "kinetic_energy", "contact_force"});
  table.reserve(8);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::vector<double>> rows{
      {0.0, 12.5, 0.0},
      {1.0 / 3.0 * 1e-6, 12.499999123456789, -3.14159265358979e4},
      {2e-6, 1e-300, 6.02214076e23},
      {3e-6, nan, -nan},
      {4e-6, inf, -inf},
  };
  for (const auto& r : rows) table.add_row(r);
  EXPECT_EQ(table.rows(), rows.size());
  EXPECT_EQ(table.values().size(), rows.size() * 3);

  const fs::path file = dir.path() / "history.csv";
  table.write_csv(file);
  const auto lines = read_lines(file);
  ASSERT_EQ(lines.size(), 1 + rows.size());
  EXPECT_EQ(lines[0], "time,kinetic_energy,contact_force");
  for (std::size_t r = 0; r < rows.size(); ++r) {
    SCOPED_TRACE(lines[1 + r]);
    const auto cells = split(lines[1 + r]);
    ASSERT_EQ(cells.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c) {
      const double expected = rows[r][c];
      char* end = nullptr;
      const double got = std::strtod(cells[c].c_str(), &end);
      EXPECT_EQ(*end, '\0') << "trailing characters in '" << cells[c] << "'";
      if (std::isnan(expected)) {
        EXPECT_EQ(cells[c], "nan");  // also for a negative NaN (glibc would print "-nan")
      } else if (std::isinf(expected)) {
        EXPECT_EQ(cells[c], expected > 0 ? "inf" : "-inf");
      } else {
        EXPECT_NEAR(got, expected, kRelTol * std::abs(expected)) << "column " << c;
      }
    }
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"history.csv"});
}

TEST(HistoryTable, WrongRowLengthThrowsAndAddsNothing) {
  HistoryTable table({"time", "energy"});
  table.add_row(std::vector<double>{0.0, 1.0});
  EXPECT_THROW(table.add_row(std::vector<double>{1.0}), RunError);
  EXPECT_THROW(table.add_row(std::vector<double>{1.0, 2.0, 3.0}), RunError);
  EXPECT_EQ(table.rows(), 1u);
  EXPECT_EQ(table.values().size(), 2u);
}

TEST(HistoryTable, RejectsBadColumns) {
  EXPECT_THROW(HistoryTable({}), RunError);
  EXPECT_THROW(HistoryTable({"time", ""}), RunError);
}

TEST(HistoryTable, QuotesAwkwardColumnNames) {
  ScratchDir dir;
  HistoryTable table({"time", "force, N", "say \"hi\""});
  table.write_csv(dir.path() / "h.csv");
  const auto lines = read_lines(dir.path() / "h.csv");
  ASSERT_EQ(lines.size(), 1u);  // header only
  EXPECT_EQ(lines[0], "time,\"force, N\",\"say \"\"hi\"\"\"");
}
