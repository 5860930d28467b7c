// Hertz impact: a rigid sphere (MAT_020)
// of radius R and mass m hits a thick elastic MAT_001 block at v0. Reference (Johnson, Contact
// Mechanics, 1985, section 11.4; quasi-static Hertz contact of a rigid sphere on an elastic
// half-space, E* = E / (1 - nu^2)):
//   F = (4/3) E* sqrt(R) d^(3/2)
//   d_max = (15 m v0^2 / (16 E* sqrt(R)))^(2/5),  F_max = (4/3) E* sqrt(R) d_max^(3/2),
//   t_c   = 2.9432 (m^2 / (E*^2 R v0))^(1/5)
// Set-up (quarter model, symmetry conditions on x = 0 and y = 0): aluminium-like block E = 70 GPa,
// nu = 0.3, rho = 2700; R = 10 mm, m = 8.2 g (a glass-density sphere; only the mass matters for a
// rigid body), v0 = 10 m/s. Then d_max = 0.100 mm, a = sqrt(R d_max) = 1.00 mm = R / 10 (Hertz's
// small-contact assumption: errors O((a/R)^2) ~ 1 %), F_max = 10.3 kN, t_c = 30.2 us.
// The rigid sphere is the bottom cap of the sphere, built here as a one-element-thick MAT_020 hex
// shell over the block's own fine grid (r <= 1.25 a), its mass set to m / 4 (quarter), x, y and
// the rotations fixed by symmetry. The block (ELFORM 1 with IHQ 3, Flanagan-Belytschko viscous
// hourglass control: the stiffness forms IHQ 4/5 make the graded mesh's long thin elements too
// stiff, IHQ 5 gives +7 % on F_max at a/h = 12; one-point elements cost several times less than ELFORM 2
// for errors of the same size) is a
// tensor-product grid: uniform h over 1.25 a laterally and 0.75 a in depth (the Hertz stress
// field), graded by 1.5 per element out to L = 24 a; bottom fixed, sides free. Meshes: h = a/3,
// a/6, a/12 (3, 6, 12 elements across the contact radius a).
// Contact: automatic surface to surface, SOFT 0, SLSFAC 0.5 (the default 0.1 is a robustness
// choice, not an accuracy one). Time step: the solver combines the element step with the active
// contact springs (solver.cpp, combined_step); the approach runs at the element step. TSSFAC 0.9
// (LS-DYNA's default). The graded block has elements of aspect 130 where the lateral grading
// meets the uniform top layers; they are stable at 0.9 because the bulk viscosity uses the step's
// length L = V / A_max (docs/theory.md section 3; tests/core/test_bulk_viscosity_step.cpp): with
// V^(1/3) their thickness mode would be damped at xi = 1.54, whose explicit limit is 0.30 L/c.
// ELFORM 2 at a/h = 12 still needs TSSFAC 0.7 (it gains energy in the contact zone at 0.8-0.9).
//
// Measured: indentation d = approach of the sphere since its pole reached the block's top surface
// (relative to the fixed base), contact force F = 4 x the z contact force on the quarter sphere,
// contact duration = time with F > 0. Errors against the formulas above, wall time per mesh.
//
// Error sources and tolerance (finest mesh):
//  - Penalty compliance: a block surface node carries k = SLSFAC K A^2 / V = SLSFAC K h, so the
//    penalty layer adds a penetration p h / (SLSFAC K) under the pressure p. At the centre
//    (p0 = 2 E* a / (pi R)) relative to d = a^2 / R: eps = (2 / pi) E* / (SLSFAC K) (h / a) =
//    1.68 h / a, i.e. 14 % at a/h = 12 for one pass; the two-way search adds the sphere's nodes
//    against the block's segments in parallel, which about halves it (7 %). A compliance
//    d = d_H (1 + eps) lowers the effective Hertz constant by (1 + eps)^(3/2); d_max and t_c scale
//    with it to the power -2/5, F_max to +2/5: errors ~ 0.6 eps, about 4 %.
//  - Mesh: the pressure p0 sqrt(1 - r^2 / a^2) over 12 elements per a; the cap is faceted on the
//    same grid, sag h^2 / (8 R) = 0.9 um = 0.9 % of d_max.
//  - Finite block: the fixed base at depth L = 24 a adds (Boussinesq point load, displacement of
//    the half-space at depth L on the axis, F (1 + nu)(3 - 2 nu) / (2 pi E L)) a compliance of
//    0.73 a / L = 3 % of d_H at the peak, i.e. ~ +2 % on d_max and t_c, -2 % on F_max. The block is
//    quasi-static: a P wave crosses L in 4 us, t_c = 30 us (~ 4 round trips); the energy Hertz
//    impact radiates into a half-space (Hunter 1957, 1.04 (v0 / c_0)^(3/5)) is 2.5 %, and here it
//    is reflected back, not lost.
// Together at most ~ 6 %, and the two largest terms (penalty layer, finite block) are compliances
// with known signs: d_max too large, F_max too small. Asserted on every mesh: 0 < d_max error and
// F_max error < 0; on the finest mesh d_max error < 6 % and F_max error > -6 % (measured +0.9 % and
// -2.6 %; +6.5 / -4.6 % at a/h = 3). The same compliances lengthen t_c, but its measured error
// changes sign (+3.1, +1.1, -0.1 %): another effect of about 1 % (the contact duration counted
// from the first to the last cycle with a force) is not in the budget, so t_c keeps the two-sided
// 6 %. The largest of the three errors decreases from mesh to mesh; the energy ratio is within 1 %.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "hertz_scene.hpp"

namespace plyimpact {
namespace {

using namespace test::hertz;

TEST(HertzImpact, RigidSphereOnElasticBlockConvergesToHertz) {
  const Hertz hz;
  std::cout << std::setprecision(4) << "Hertz: a = " << hz.a * 1e3 << " mm, d_max = " << hz.d_max * 1e6
            << " um, F_max = " << hz.f_max << " N, t_c = " << hz.t_c * 1e6 << " us\n";
  const int meshes[] = {3, 6, 12};
  std::vector<double> worst;
  for (int per_a : meshes) {
    const Result r = run(build(per_a));
    const double ed = r.d_max / hz.d_max - 1, ef = r.f_max / hz.f_max - 1, et = r.t_c / hz.t_c - 1;
    worst.push_back(std::max({std::abs(ed), std::abs(ef), std::abs(et)}));
    std::cout << "  a/h = " << std::setw(2) << per_a << ": " << std::setw(7) << r.elements << " elements, "
              << std::setw(5) << r.cycles << " cycles (dt " << r.dt * 1e9 << " ns), wall " << std::setw(6) << r.wall << " s | d_max "
              << r.d_max * 1e6 << " um (" << std::showpos << 100 * ed << " %), F_max " << std::noshowpos << r.f_max
              << " N (" << std::showpos << 100 * ef << " %), t_c " << std::noshowpos << r.t_c * 1e6 << " us ("
              << std::showpos << 100 * et << std::noshowpos << " %), max |ratio - 1| " << r.energy_ratio_err
              << "\n";
    EXPECT_LT(r.energy_ratio_err, 0.01);
    EXPECT_GT(ed, 0.0) << "the added compliances can only deepen the indentation";
    EXPECT_LT(ef, 0.0) << "the added compliances can only lower the peak force";
    if (per_a == 12) {
      EXPECT_LT(ed, 0.06);
      EXPECT_GT(ef, -0.06);
      EXPECT_LT(std::abs(et), 0.06);
    }
  }
  EXPECT_LT(worst[1], worst[0]);
  EXPECT_LT(worst[2], worst[1]);
}

}  // namespace
}  // namespace plyimpact
