// Material axes of an orthotropic element as the model builder sets them, on a distorted hex8
// (no face parallel to another, no edge along a global axis), for AOPT 0 (the default of the
// scene loader: nodes 1-2-4) and AOPT 3 (a = V x mid-surface normal), each with a BETA angle.
// Independent references (LS-DYNA keyword manual, *MAT_002 AOPT):
//  - AOPT 0: a along node 1 -> 2; c normal to the plane of the edges 1 -> 2 and 1 -> 4 (their cross
//    product's side); b = c x a, so b lies in that plane on the side of node 4;
//  - AOPT 3: c normal to the element's mid-surface, taken here as the cross product of its
//    diagonals ((n3 + n7) - (n1 + n5)) x ((n4 + n8) - (n2 + n6)); a along V x c;
//  - BETA (part angle, or MANGLE for AOPT 3) turns a and b about c by that angle.
// The stiffness of the element in global axes is then checked by turning it back: a unit strain
// along each material component (engineering shear), rotated to global axes with the axes found,
// must give the column of the material stiffness inverted here from the card's compliance
// (PRBA = nu_ba, the minor ratio, so S12 = -PRBA / EB). Tolerances: round-off (1e-12 on unit
// vectors, 1e-12 of EA on stiffness entries).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEA = 157e9, kEB = 8.5e9, kEC = 9.1e9, kPRBA = 0.019, kPRCA = 0.021, kPRCB = 0.53;
constexpr double kGAB = 4.2e9, kGBC = 2.2e9, kGCA = 4.6e9;

// Corners 1..8 of the distorted element (mm), LS-DYNA order: 1-4 bottom, 5-8 above them.
const double kCorners[8][3] = {{0, 0, 0},       {1.0, 0.3, 0.1}, {1.2, 1.3, 0.2},  {0.1, 1.0, -0.1},
                               {0.05, 0.1, 1.0}, {1.1, 0.2, 1.2}, {1.0, 1.1, 1.15}, {-0.1, 0.9, 0.9}};

Eigen::Vector3d corner(int k) { return 1e-3 * Eigen::Vector3d(kCorners[k][0], kCorners[k][1], kCorners[k][2]); }

model::Model distorted_element(const std::string& axes, double part_beta_deg) {
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1.0e-6}\nmaterials:\n"
      "  ply: {card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 9.1e9, PRBA: 0.019, PRCA: 0.021, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.6e9" + axes + "}\n"
      "sections:\n  s: {ELFORM: 1}\nparts:\n  p: {material: ply, section: s, beta: " + std::to_string(part_beta_deg) +
      "}\nmesh:\n  boxes: [{part: p, size: [1.0e-3, 1.0e-3, 1.0e-3], elements: [1, 1, 1]}]\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "axes.yaml");
  mesh::Mesh mesh = mesh::mesh_boxes(scene);
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) mesh.coords[3 * std::size_t(mesh.hex[k]) + i] = corner(k)[i];
  return model::build_model(scene, mesh);
}

Eigen::Matrix3d axes_of(const model::Model& m) {  // rows a, b, c
  const auto& ax = m.orientations[m.blocks[0].orientation[0]].axes;
  Eigen::Matrix3d q;
  q << ax[0], ax[1], ax[2], ax[3], ax[4], ax[5], ax[6], ax[7], ax[8];
  return q;
}

Eigen::Matrix<double, 6, 6> material_stiffness() {
  Eigen::Matrix<double, 6, 6> s = Eigen::Matrix<double, 6, 6>::Zero();
  s(0, 0) = 1 / kEA, s(1, 1) = 1 / kEB, s(2, 2) = 1 / kEC;
  s(0, 1) = s(1, 0) = -kPRBA / kEB;
  s(0, 2) = s(2, 0) = -kPRCA / kEC;
  s(1, 2) = s(2, 1) = -kPRCB / kEC;
  s(3, 3) = 1 / kGAB, s(4, 4) = 1 / kGBC, s(5, 5) = 1 / kGCA;  // ab, bc, ca
  return s.inverse();
}

// Voigt (xx yy zz xy yz zx) <-> tensor; `engineering`: shear entries are 2 e_ij (strains).
Eigen::Matrix3d tensor(const Eigen::Matrix<double, 6, 1>& v, bool engineering) {
  const double f = engineering ? 0.5 : 1.0;
  Eigen::Matrix3d t;
  t << v[0], f * v[3], f * v[5], f * v[3], v[1], f * v[4], f * v[5], f * v[4], v[2];
  return t;
}
Eigen::Matrix<double, 6, 1> voigt(const Eigen::Matrix3d& t) {
  Eigen::Matrix<double, 6, 1> v;
  v << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(2, 0);
  return v;
}

void expect_orthonormal_right_handed(const Eigen::Matrix3d& q) {
  EXPECT_NEAR((q * q.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(q.determinant(), 1.0, 1e-12);
}

// The global stiffness of the element, turned back into the material axes q, is the card's.
void expect_stiffness_in_axes(const model::Model& m, const Eigen::Matrix3d& q) {
  const auto& cg = m.orientations[m.blocks[0].orientation[0]].c_global;
  const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> C(cg.data());
  const Eigen::Matrix<double, 6, 6> want = material_stiffness();
  for (int j = 0; j < 6; ++j) {
    Eigen::Matrix<double, 6, 1> em = Eigen::Matrix<double, 6, 1>::Zero();
    em[j] = 1;
    const Eigen::Matrix3d eg = q.transpose() * tensor(em, true) * q;  // material -> global
    Eigen::Matrix<double, 6, 1> eg_v = voigt(eg);
    for (int k = 3; k < 6; ++k) eg_v[k] *= 2;  // engineering shear
    const Eigen::Matrix3d sg = tensor(C * eg_v, false);
    const Eigen::Matrix<double, 6, 1> sm = voigt(q * sg * q.transpose());
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(sm[i], want(i, j), 1e-12 * kEA) << "C(" << i << ", " << j << ")";
  }
}

TEST(MaterialAxes, AoptZeroFollowsNodesOneTwoFourOfADistortedElement) {
  for (double beta_deg : {0.0, 30.0}) {
    const model::Model m = distorted_element("", beta_deg);  // no AOPT on the card: the loader's 0
    const Eigen::Matrix3d q = axes_of(m);
    const Eigen::Vector3d e12 = corner(1) - corner(0), e14 = corner(3) - corner(0);
    const Eigen::Vector3d c = e12.cross(e14).normalized();
    const Eigen::Vector3d a0 = e12.normalized(), b0 = c.cross(a0);
    ASSERT_GT(b0.dot(e14), 0);
    const double beta = beta_deg * kPi / 180;
    const Eigen::Vector3d a = std::cos(beta) * a0 + std::sin(beta) * b0, b = -std::sin(beta) * a0 + std::cos(beta) * b0;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(q(0, i), a[i], 1e-12) << "beta " << beta_deg << ", a" << i;
      EXPECT_NEAR(q(1, i), b[i], 1e-12) << "beta " << beta_deg << ", b" << i;
      EXPECT_NEAR(q(2, i), c[i], 1e-12) << "beta " << beta_deg << ", c" << i;
    }
    expect_orthonormal_right_handed(q);
    expect_stiffness_in_axes(m, q);
  }
}

TEST(MaterialAxes, AoptThreeIsVCrossTheMidSurfaceNormalOfADistortedElement) {
  const Eigen::Vector3d V = Eigen::Vector3d(0.3, 1.0, 0.2);
  for (double mangle : {0.0, -45.0}) {  // the card's BETA (MANGLE on *MAT_054)
    const model::Model m = distorted_element(", AOPT: 3, V: [0.3, 1.0, 0.2], BETA: " + std::to_string(mangle), 0);
    const Eigen::Matrix3d q = axes_of(m);
    const Eigen::Vector3d d1 = (corner(2) + corner(6)) - (corner(0) + corner(4));
    const Eigen::Vector3d d2 = (corner(3) + corner(7)) - (corner(1) + corner(5));
    const Eigen::Vector3d c = d1.cross(d2).normalized();
    const Eigen::Vector3d a0 = V.cross(c).normalized(), b0 = c.cross(a0);
    const double beta = mangle * kPi / 180;
    const Eigen::Vector3d a = std::cos(beta) * a0 + std::sin(beta) * b0, b = -std::sin(beta) * a0 + std::cos(beta) * b0;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(q(0, i), a[i], 1e-12) << "MANGLE " << mangle << ", a" << i;
      EXPECT_NEAR(q(1, i), b[i], 1e-12) << "MANGLE " << mangle << ", b" << i;
      EXPECT_NEAR(q(2, i), c[i], 1e-12) << "MANGLE " << mangle << ", c" << i;
    }
    expect_orthonormal_right_handed(q);
    expect_stiffness_in_axes(m, q);
  }
}

}  // namespace
}  // namespace plyimpact
