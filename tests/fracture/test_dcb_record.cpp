// Reading DCB records: which rows are propagation points, column choice, units, and the refusals
// (missing column, bad number, decreasing crack length, too few points) with file and line.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "beam_theory_dcb.hpp"
#include "core/error.hpp"
#include "fracture/dcb_record.hpp"

namespace plyimpact {
namespace {

using fracture::DcbColumns;
using fracture::DcbUnits;
using fracture::parse_dcb_record;
using fracture::PropagationRule;
using fracture::propagation_points;

std::string row(double t, double P, double d, double a) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%.17g,0\n", t, P, d, a);
  return buf;
}

// What a simulated DCB writes: loading at the pre-crack length a0 (the first rows, P from 0),
// then one row per output time while the front advances.
std::string simulated_history(const test::BeamTheoryDcb& dcb, int loading_rows, int growth_rows) {
  std::string text = "time,load,opening,crack_length,kinetic_energy\n";
  const double a0 = 50e-3;
  const auto peak = dcb.at(a0);
  for (int i = 0; i < loading_rows; ++i) {
    const double f = double(i) / (loading_rows - 1);
    text += row(i * 1e-4, f * peak.P, f * peak.delta, a0);
  }
  for (int j = 1; j <= growth_rows; ++j) {
    const auto p = dcb.at(a0 + j * 2e-3);
    text += row((loading_rows + j) * 1e-4, p.P, p.delta, p.a);
  }
  return text;
}

std::string error_of(const std::string& text, PropagationRule rule = PropagationRule::crack_growth,
                     DcbColumns columns = {}) {
  try {
    propagation_points(parse_dcb_record(text, "dcb.csv", columns, {}), rule);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(DcbRecord, PropagationPointsAreTheRowsWhereTheCrackGrows) {
  test::BeamTheoryDcb dcb;
  const auto rec = parse_dcb_record(simulated_history(dcb, 6, 10), "history.csv", {}, {});
  ASSERT_EQ(rec.rows.size(), 16u);
  const auto pts = propagation_points(rec, PropagationRule::crack_growth);
  ASSERT_EQ(pts.size(), 10u) << "the 6 loading rows at a0 are not propagation points";
  EXPECT_EQ(pts.front().line, 8) << "header on line 1, loading rows on lines 2-7";
  std::vector<fracture::DcbPoint> points;
  for (const auto& p : pts) points.push_back(p.point);
  const auto r = fracture::reduce_dcb(points, {dcb.width, dcb.thickness});
  for (double g : r.G_mbt) EXPECT_NEAR(g / dcb.G_Ic, 1.0, 1e-10) << "text round trip at 17 digits is exact enough";
  EXPECT_NEAR(r.Delta, dcb.Delta, 1e-9);
}

TEST(DcbRecord, TestMachineSheetInMillimetresWithOwnColumnNames) {
  // A sheet listing only the propagation marks: semicolons, mm and N, comment lines, every row used.
  test::BeamTheoryDcb dcb;
  std::string text = "# specimen 3\nForce [N];Crosshead [mm];a [mm]\n";
  for (double a = 50; a <= 80; a += 5) {
    const auto p = dcb.at(a * 1e-3);
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.17g; %.17g; %.17g\n", p.P, p.delta * 1e3, a);
    text += buf;
  }
  const DcbColumns cols{"Force [N]", "Crosshead [mm]", "a [mm]"};
  const auto rec = parse_dcb_record(text, "sheet.csv", cols, DcbUnits{1e-3, 1.0});
  const auto pts = propagation_points(rec, PropagationRule::all_rows);
  ASSERT_EQ(pts.size(), 7u);
  EXPECT_NEAR(pts[0].point.a, 50e-3, 1e-15);
  EXPECT_EQ(pts[0].line, 3);
  EXPECT_NEAR(pts[0].point.delta / dcb.at(50e-3).delta, 1.0, 1e-14);
}

TEST(DcbRecord, MissingColumnNamesTheColumnsFound) {
  const std::string e = error_of("time,load,opening\n0,1,2\n");
  EXPECT_NE(e.find("dcb.csv:1: no column 'crack_length'"), std::string::npos) << e;
  EXPECT_NE(e.find("found columns time, load, opening"), std::string::npos) << e;
  EXPECT_NE(e.find("--crack"), std::string::npos) << e;
}

TEST(DcbRecord, BadNumberAndShortRowNameTheLine) {
  EXPECT_NE(error_of("load,opening,crack_length\n1,2,3\n1,abc,3\n").find("dcb.csv:3: column 'opening': 'abc'"),
            std::string::npos);
  EXPECT_NE(error_of("load,opening,crack_length\n1,2\n").find("dcb.csv:2: 2 fields but the header has 3"),
            std::string::npos);
}

TEST(DcbRecord, DecreasingCrackLengthIsRefusedAtItsLine) {
  const std::string text = "load,opening,crack_length\n1,1e-3,0.050\n1,2e-3,0.051\n1,3e-3,0.0505\n1,4e-3,0.052\n";
  const std::string e = error_of(text);
  EXPECT_NE(e.find("dcb.csv:4: crack length 0.0505 m after 0.051 m on line 3"), std::string::npos) << e;
  // Every row a propagation point: a repeated length is refused too.
  const std::string e2 = error_of("load,opening,crack_length\n1,1e-3,0.05\n1,2e-3,0.05\n1,3e-3,0.06\n",
                                  PropagationRule::all_rows);
  EXPECT_NE(e2.find("dcb.csv:3:"), std::string::npos) << e2;
}

TEST(DcbRecord, FewerThanThreePropagationPoints) {
  const std::string e = error_of("load,opening,crack_length\n1,1e-3,0.05\n1,2e-3,0.05\n1,3e-3,0.06\n1,3e-3,0.07\n");
  EXPECT_NE(e.find("dcb.csv: 2 propagation point(s)"), std::string::npos) << e;
  EXPECT_NE(e.find("at least 3"), std::string::npos) << e;
}

TEST(DcbRecord, PropagationPointWithoutLoadIsRefused) {
  const std::string e = error_of("load,opening,crack_length\n1,1e-3,0.05\n0,2e-3,0.06\n1,3e-3,0.07\n1,3e-3,0.08\n");
  EXPECT_NE(e.find("dcb.csv:3: propagation point with load 0 N"), std::string::npos) << e;
}

}  // namespace
}  // namespace plyimpact
