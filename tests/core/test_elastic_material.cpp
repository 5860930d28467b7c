// *MAT_001 / *MAT_002 constants: the orthotropic stiffness inverts the LS-DYNA compliance (minor
// ratios), inadmissible combinations are refused before the run, the wave modulus is lambda + 2 mu
// for an isotropic material and bounds the P-wave modulus in every direction for an orthotropic
// one, and rotating the axes by 90 degrees about c swaps the a and b stiffnesses.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "core/error.hpp"
#include "material/elastic.hpp"
#include "model/material_builder.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

config::MatOrthotropicElastic t800() {
  config::MatOrthotropicElastic m;
  m.RO = 1550, m.EA = 157e9, m.EB = 8.5e9, m.EC = 8.5e9, m.PRBA = 0.01895, m.PRCA = 0.01895, m.PRCB = 0.53;
  m.GAB = 4.2e9, m.GBC = 2.2e9, m.GCA = 4.2e9;
  return m;
}

TEST(ElasticMaterial, OrthotropicStiffnessInvertsTheCardCompliance) {
  const auto m = t800();
  const auto C = model::orthotropic_stiffness(m, {});
  Eigen::Matrix<double, 6, 6> Cm;
  for (int i = 0; i < 36; ++i) Cm(i / 6, i % 6) = C[i];
  // Uniaxial stress along b: eps_a = -PRBA sigma_b / EB (the card's definition of PRBA).
  Eigen::Matrix<double, 6, 1> sigma = Eigen::Matrix<double, 6, 1>::Zero();
  sigma[1] = 1e6;
  const Eigen::Matrix<double, 6, 1> eps = Cm.inverse() * sigma;
  EXPECT_NEAR(eps[1], 1e6 / m.EB, 1e-12 * eps[1]);
  EXPECT_NEAR(eps[0], -m.PRBA * 1e6 / m.EB, 1e-10 * std::abs(eps[0]));
  EXPECT_NEAR(eps[2], -m.PRCB * 1e6 / m.EC, 1e-10 * std::abs(eps[2]));
  EXPECT_NEAR(Cm(3, 3), m.GAB, 1e-6 * m.GAB);
}

TEST(ElasticMaterial, NonPositiveDefiniteConstantsAreRefused) {
  // Each ratio alone is below sqrt(Ei/Ej) = 1, but together (nu = 0.6 in all three planes of an
  // isotropic-like card) 1 - 3 nu^2 - 2 nu^3 < 0.
  auto m = t800();
  m.EA = m.EB = m.EC = 10e9;
  m.PRBA = m.PRCA = m.PRCB = 0.6;
  config::SourceLocation where{"plate.yaml", 12, 5, "materials.ply"};
  try {
    model::orthotropic_stiffness(m, where);
    FAIL() << "should have been refused";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("plate.yaml:12:5: materials.ply"), std::string::npos) << msg;
    EXPECT_NE(msg.find("not positive definite"), std::string::npos) << msg;
  }
}

TEST(ElasticMaterial, WaveModulusIsExactForIsotropyAndBoundsOrthotropy) {
  // Isotropic card entered as MAT_002: the maximum over directions is lambda + 2 mu exactly.
  config::MatOrthotropicElastic iso;
  const double E = 200e9, nu = 0.3, G = E / (2 * (1 + nu));
  iso.EA = iso.EB = iso.EC = E, iso.PRBA = iso.PRCA = iso.PRCB = nu, iso.GAB = iso.GBC = iso.GCA = G;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  EXPECT_NEAR(material::max_wave_modulus(model::orthotropic_stiffness(iso, {})), M, 1e-9 * M);
  // Orthotropic: at least the largest axial modulus C11, and no direction sampled at random exceeds it.
  const auto C = model::orthotropic_stiffness(t800(), {});
  const double bound = material::max_wave_modulus(C);
  EXPECT_GE(bound, C[0] * (1 - 1e-12));
  for (int k = 0; k < 200; ++k) {
    Eigen::Vector3d n(std::sin(1.3 * k), std::cos(0.7 * k + 1), std::sin(2.1 * k + 0.5));
    n.normalize();
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    constexpr int v[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
    for (int i = 0; i < 3; ++i)
      for (int kk = 0; kk < 3; ++kk)
        for (int j = 0; j < 3; ++j)
          for (int l = 0; l < 3; ++l) A(i, kk) += C[6 * v[i][j] + v[kk][l]] * n[j] * n[l];
    EXPECT_LE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(A).eigenvalues().maxCoeff(), bound * (1 + 1e-12));
  }
}

TEST(ElasticMaterial, RotationByNinetyDegreesSwapsAxes) {
  const auto Cm = model::orthotropic_stiffness(t800(), {});
  material::MaterialAxes axes;
  axes.AOPT = 2;
  const double x[3][8] = {};
  const Mat3 q = material::material_axes(axes, M_PI / 2, x);  // a along global y
  EXPECT_NEAR(q[1], 1.0, 1e-15);
  const auto Cg = material::rotate_to_global(Cm, q);
  EXPECT_NEAR(Cg[6 * 1 + 1], Cm[0], 1e-9 * Cm[0]);   // C_yy,yy = C_aa,aa
  EXPECT_NEAR(Cg[0], Cm[6 * 1 + 1], 1e-9 * Cm[0]);   // C_xx,xx = C_bb,bb
  EXPECT_NEAR(Cg[6 * 3 + 3], Cm[6 * 3 + 3], 1e-9 * Cm[0]);  // in-plane shear unchanged
  EXPECT_NEAR(Cg[6 * 4 + 4], Cm[6 * 5 + 5], 1e-9 * Cm[0]);  // yz takes ca
}

}  // namespace
}  // namespace plyimpact
