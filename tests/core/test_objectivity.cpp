// Objectivity: a stressed element rotated rigidly by 90 degrees about z must carry its stress along
// (sigma_xx = s becomes sigma_yy = s); for *MAT_002 the stress of the stretch is computed by hand
// (total-Lagrangian, below) before and after the rotation. The element kernels are driven directly with an exact rigid
// rotation per step, x^{n+1} = R(theta) x^n. With the mid-step velocity gradient, L is exactly skew
// and the Hughes-Winget rotation equals R(theta), so the result is exact up to round-off. Round-off
// enters as strain noise of ~eps_mach per step (coordinates are rounded), i.e. stress noise of
// ~E eps_mach per step: tolerance 10 E eps_mach N (~1 Pa here, 1e-6 of the stress), whereas an
// end-of-step rate would leave an error of order E theta (~1e5 Pa).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "solver/element_update.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

struct RotationCase {
  int elform, ihq;
  bool ortho;
};

class Objectivity : public ::testing::TestWithParam<RotationCase> {};

TEST_P(Objectivity, StressRotatesWithRigidBody) {
  const RotationCase c = GetParam();
  const std::string mat = c.ortho ? "  m: {card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: "
                                    "0.019, PRCB: 0.53, GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1,0,0], D: [0,1,0]}\n"
                                  : "  m: {card: MAT_001, RO: 7800, E: 200e9, PR: 0.3}\n";
  const model::Model model = test::model_from_yaml(
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n" + mat + "sections:\n  s: {ELFORM: " +
      std::to_string(c.elform) + ", IHQ: " + std::to_string(c.ihq) +
      ", Q1: 0, Q2: 0}\nparts:\n  p: {material: m, section: s}\nmesh:\n  boxes:\n    - {part: p, origin: [-0.5, -0.5, "
      "-0.5], size: [1, 1, 1], elements: [1, 1, 1]}\n");
  const auto& blk = model.blocks[0];
  solver::BlockState st = solver::initial_block_state(model, 0);
  std::vector<double> x = model.X, v(x.size()), f(x.size());

  double expected_yy = 0, expected_xx = 0, expected_zz = 0;
  const double dt = 1e-6;
  if (c.ortho) {
    // Total Lagrangian: stretch along x first, F = diag(l, 1, 1), l = 1.001. By hand: Green strain
    // E = (l^2 - 1) / 2, S = C E (first column of the card's stiffness, inverted here from its
    // compliance; PRBA is the minor ratio nu_ba, so S12 = -PRBA / EB), sigma = F S F^T / J:
    // sigma_xx = l C11 E, sigma_yy = C21 E / l, sigma_zz = C31 E / l.
    const double l = 1.001, green = 0.5 * (l * l - 1);
    Eigen::Matrix3d compliance;
    compliance << 1 / 157e9, -0.019 / 8.5e9, -0.019 / 8.5e9, -0.019 / 8.5e9, 1 / 8.5e9, -0.53 / 8.5e9, -0.019 / 8.5e9,
        -0.53 / 8.5e9, 1 / 8.5e9;
    const Eigen::Matrix3d C = compliance.inverse();  // normal block (shear decouples)
    for (std::size_t n = 0; n < x.size() / 3; ++n) x[3 * n] *= l;
    for (std::size_t n = 0; n < x.size(); ++n) v[n] = (x[n] - model.X[n]) / dt;
    solver::ChunkResult r;
    solver::update_elements(model, blk, st, 0, 1, x.data(), v.data(), f.data(), dt, r);
    expected_yy = l * C(0, 0) * green;  // the old sigma_xx, carried to yy by the rotation
    expected_xx = C(1, 0) * green / l;
    expected_zz = C(2, 0) * green / l;
    for (int g = 0; g < blk.points(); ++g) {
      EXPECT_NEAR(st.stress[6 * g], expected_yy, 1e-12 * expected_yy) << "stretched, before the rotation";
      EXPECT_NEAR(st.stress[6 * g + 1], expected_xx, 1e-12 * expected_yy) << "stretched, before the rotation";
    }
  } else {
    for (int g = 0; g < blk.points(); ++g) st.stress[6 * g] = 1e6;
    expected_yy = 1e6;
  }
  const int steps = 2000;
  const double theta = 0.5 * M_PI / steps, ct = std::cos(theta), sn = std::sin(theta);
  for (int n = 0; n < steps; ++n) {
    for (std::size_t k = 0; k < x.size() / 3; ++k) {
      const double x0 = x[3 * k], y0 = x[3 * k + 1];
      const double x1 = ct * x0 - sn * y0, y1 = sn * x0 + ct * y0;
      v[3 * k] = (x1 - x0) / dt;
      v[3 * k + 1] = (y1 - y0) / dt;
      v[3 * k + 2] = 0;
      x[3 * k] = x1;
      x[3 * k + 1] = y1;
    }
    solver::ChunkResult r;
    std::fill(f.begin(), f.end(), 0.0);
    solver::update_elements(model, blk, st, 0, 1, x.data(), v.data(), f.data(), dt, r);
    ASSERT_LT(r.bad_element, 0);
  }
  const double modulus = c.ortho ? 157e9 : 200e9;
  const double tol = 10 * modulus * std::numeric_limits<double>::epsilon() * steps;
  const double s = std::abs(expected_yy);
  for (int g = 0; g < blk.points(); ++g) {
    const double* sg = &st.stress[6 * g];
    if (c.ortho) {
      // The x-stretched block now stretches along y: sigma_yy takes the old sigma_xx, sigma_xx the
      // old sigma_yy.
      EXPECT_NEAR(sg[1], expected_yy, tol);
      EXPECT_NEAR(sg[0], expected_xx, tol);
      EXPECT_NEAR(sg[2], expected_zz, tol);
    } else {
      EXPECT_NEAR(sg[1], expected_yy, tol);
      EXPECT_NEAR(sg[0], 0.0, tol);
      EXPECT_NEAR(sg[2], 0.0, tol);
    }
    EXPECT_NEAR(sg[3], 0.0, tol);
    EXPECT_NEAR(sg[4], 0.0, tol);
    EXPECT_NEAR(sg[5], 0.0, tol);
  }
  // A rigid rotation does no work: no stress power and no hourglass deformation.
  EXPECT_NEAR(st.hourglass_energy[0], 0.0, 1e-12 * s);
}

INSTANTIATE_TEST_SUITE_P(Hex8, Objectivity,
                         ::testing::Values(RotationCase{1, 4, false}, RotationCase{1, 2, false}, RotationCase{2, 2, false},
                                           RotationCase{1, 5, true}, RotationCase{2, 2, true}),
                         [](const auto& info) {
                           return std::string(info.param.ortho ? "MAT002" : "MAT001") + "_ELFORM" +
                                  std::to_string(info.param.elform) + "_IHQ" + std::to_string(info.param.ihq);
                         });

}  // namespace
}  // namespace plyimpact
