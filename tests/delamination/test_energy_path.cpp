// Is the energy a point books (elastic now + dissipated so far) the work its tractions did? Along
// a ray (fixed mixity) the law's dissipation formula is exact for any step (docs/delamination.md,
// "Energy bookkeeping"); a point of a plate under impact, though, softens while its mixity turns.
// Here a point of the seed's Table 8.6 law (OPTION 9, power law alpha = 1 and B-K eta = 2) is
// driven along a curved path: the opening's magnitude grows to beyond the final opening while its
// direction turns from mostly mode I to mostly mode II (and, a second path, back), in N equal
// steps. The booked energy is compared with the trapezoid work of the law's own tractions.
// Independent answer: as N grows, the trapezoid work converges to the path integral of the traction
// (second order in the step), so booked - work must converge too; its limit is the bookkeeping's
// own error for a turning mixity. Along such a path the traction is linear in the opening except
// at the onset kink and where the point separates, so the trapezoid's error is the corner cut off at
// those steps, O(1/N^2) relative; the loosest bound to assert is first order: each tenfold refinement
// must shrink |booked - work| at least tenfold, and at N = 1e5 it must be below 1e-6 of the work. A
// booking error that does not vanish with the step (a wrong mixed-mode dissipation) would stall at
// its own size; the default scene's creep is 3.5e-3. Measured: +2e-3 at N = 100, below 1e-9 at
// N = 1e5, booked above the work (the trapezoid cuts the corner at the peak).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "law_paths.hpp"

namespace plyimpact::cohesive::test {
namespace {

// Opening at s in [0, 1]: magnitude s * 1.3 delta_F(pure I), direction turning from theta0 to theta1
// (angle from the normal towards shear 1).
void opening_at(double s, double scale, double theta0, double theta1, double u[3]) {
  const double theta = theta0 + (theta1 - theta0) * s;
  u[0] = s * scale * std::cos(theta);
  u[1] = s * scale * std::sin(theta);
  u[2] = 0;
}

struct Balance {
  double work = 0, booked = 0;
};

Balance run(const TractionLaw& law, int steps, double theta0, double theta1) {
  const double scale = 1.3 * 2 * law.gic / (law.kn * law.delta_n0) * 2;  // past separation at any mixity here
  PointHistory h;
  std::vector<PathPoint> path;
  PathPoint start;
  path.push_back(start);
  for (int i = 1; i <= steps; ++i) {
    PathPoint p;
    opening_at(double(i) / steps, scale, theta0, theta1, p.u);
    traction_update(law, p.u, h, p.r);
    path.push_back(p);
  }
  const PathWork w = work_along(path);
  return {w.normal + w.shear, path.back().r.elastic_energy + w.dissipated};
}

TEST(EnergyPath, BookedEnergyIsTheWorkOfTheTractionsWhileTheMixityTurns) {
  TractionLawParams power = table_8_6_option9(), bk = table_8_6_option9();
  bk.PARAM = -2;
  const double deg = std::numbers::pi / 180;
  const struct {
    const char* name;
    TractionLawParams p;
    double theta0, theta1;
  } cases[] = {{"power law, I -> II", power, 10 * deg, 80 * deg},
               {"power law, II -> I", power, 80 * deg, 10 * deg},
               {"B-K, I -> II", bk, 10 * deg, 80 * deg},
               {"B-K, II -> I", bk, 80 * deg, 10 * deg}};
  for (const auto& c : cases) {
    const TractionLaw law = make_traction_law(c.p);
    double last = 0;
    for (int steps : {100, 1000, 10000, 100000}) {
      const Balance b = run(law, steps, c.theta0, c.theta1);
      const double mismatch = (b.booked - b.work) / b.work;
      std::printf("%-20s N %6d: work %.6g J/m^2, booked %.6g J/m^2, (booked - work) / work %+.3e\n", c.name, steps,
                  b.work, b.booked, mismatch);
      if (last != 0) {
        EXPECT_LT(std::abs(mismatch), 0.1 * std::abs(last)) << c.name << ", N " << steps;
      }
      last = mismatch;
    }
    EXPECT_LT(std::abs(last), 1e-6) << c.name;
  }
}

}  // namespace
}  // namespace plyimpact::cohesive::test
