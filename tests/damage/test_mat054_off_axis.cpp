// *MAT_054 single point with the ply rotated in the x-y plane: uniaxial sigma_x in global axes
// (every other global stress zero, the coupling strain gamma_xy free), rotated to the material
// axes by the test. Checks the off-axis modulus (Jones, Mechanics of Composite Materials, off-axis compliance)
//   1/Ex = cos^4/E1 + (1/G12 - 2 nu12/E1) sin^2 cos^2 + sin^4/E2,   nu12 = PRBA EA/EB,
// and the failure load from the criteria with sigma_aa = s c^2, sigma_bb = s s^2, |sigma_ab| = s s c.
// Tolerances as in test_mat054_single_element.cpp (1e-10 on moduli), failure bracket 1e-7.
#include <gtest/gtest.h>

#include <cmath>

#include "mat054_support.hpp"

namespace plyimpact::test {
namespace {

// Failure bracket 1e-7 (not 1e-9 as on axis): with five coupled free strains the driver's lateral
// solve is exact only to ~1e-9 of the stress, i.e. about the 1e-9 distance to the surface.
constexpr double kLo = 1 - 1e-7, kHi = 1 + 1e-7;

struct OffAxisCase {
  const char* name;
  bool seed_vectors;  // the Figure 7.3 card's own A and D (a -45 degree ply) through material_axes
  double theta_deg;   // otherwise: a = (cos, sin, 0)
};

Eigen::Matrix3d axes_of(const OffAxisCase& c, const config::MatCompositeDamage& m) {
  Eigen::Matrix3d q;
  if (c.seed_vectors) {
    const double x_ref[3][8] = {};
    const Mat3 r = material::material_axes(model::material_axes_of(m.axes), m.axes.BETA, x_ref);
    for (int i = 0; i < 9; ++i) q(i / 3, i % 3) = r[i];
  } else {
    const double t = c.theta_deg * M_PI / 180;
    q << std::cos(t), std::sin(t), 0, -std::sin(t), std::cos(t), 0, 0, 0, 1;
  }
  return q;
}

class OffAxis : public ::testing::TestWithParam<OffAxisCase> {};

TEST_P(OffAxis, ModulusAndMatrixFailureUnderUniaxialTensionAndCompression) {
  const auto m = t800_criteria_only();
  const Eigen::Matrix3d q = axes_of(GetParam(), m);
  const double c = q(0, 0), s = q(0, 1);  // a = (cos, sin, 0) in global axes
  const double c2 = c * c, s2 = s * s, sc = std::abs(s * c);
  const double nu12 = m.PRBA * m.EA / m.EB;
  const double ex = 1 / (c2 * c2 / m.EA + (1 / m.GAB - 2 * nu12 / m.EA) * s2 * c2 + s2 * s2 / m.EB);

  // Tension: matrix tension (s s^2/YT)^2 + (s sc/SC)^2 = 1 governs; the fibre criterion must not.
  const double st = 1 / std::hypot(s2 / m.YT, sc / m.SC);
  ASSERT_LT(std::pow(st * c2 / m.XT, 2) + m.BETA * std::pow(st * sc / m.SC, 2), 1.0);
  // Compression: sigma_bb = -p s^2, sigma_ab = p sc; e_d = 0 is a quadratic in p (q = YC/2SC).
  const double qq = m.YC / (2 * m.SC);
  const double a2 = std::pow(s2 / (2 * m.SC), 2) + std::pow(sc / m.SC, 2), a1 = -(qq * qq - 1) * s2 / m.YC;
  const double sp = (-a1 + std::sqrt(a1 * a1 + 4 * a2)) / (2 * a2);
  ASSERT_LT(sp * c2, m.XC);

  for (int sign : {+1, -1}) {
    SCOPED_TRACE(sign > 0 ? "tension" : "compression");
    const double strength = sign > 0 ? st : sp;
    const int flag = sign > 0 ? H::kMatrixTension : H::kMatrixCompression;
    PointDriver d(m, q);
    const double eps_f = sign * strength / ex;
    d.uniaxial_to(0, 0.5 * eps_f, 50);
    EXPECT_NEAR(d.stress()[0] / d.strain()[0], ex, 1e-10 * ex);
    if (sc > 1e-3 && c2 != s2) {  // generic angle: uniaxial sigma_x shears the element
      EXPECT_GT(std::abs(d.strain()[3]), 1e-3 * std::abs(d.strain()[0]));
    }
    d.uniaxial_to(0, kLo * eps_f, 50);
    EXPECT_EQ(d.flag(flag), 1.0);
    EXPECT_NEAR(d.stress()[0], kLo * sign * strength, 1e-10 * strength);
    d.uniaxial_step(0, (kHi - kLo) * eps_f);
    EXPECT_EQ(d.flag(flag), 0.0);
    // After the matrix failure bb and ab are gone and the fibres alone cannot carry sigma_x at an
    // angle with sigma_y = 0: the point is a mechanism (stress zero, strain undetermined). The
    // driver resolves that reliably only at 45 degrees, where the lateral equations stay
    // symmetric; at a generic angle its Newton solve wanders along the mechanism, so the
    // post-failure state is checked at 45 degrees only.
    if (std::abs(c2 - s2) < 1e-9) {
      EXPECT_EQ(d.flag(H::kFibreTension), 1.0);
      EXPECT_EQ(d.flag(H::kFibreCompression), 1.0);
      d.uniaxial_step(0, 0.1 * eps_f);
      EXPECT_NEAR(d.stress()[0], 0.0, 1e-3);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Mat054, OffAxis,
                         ::testing::Values(OffAxisCase{"seed_card_minus45", true, 0},
                                           OffAxisCase{"plus45", false, 45}, OffAxisCase{"plus30", false, 30}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace plyimpact::test
