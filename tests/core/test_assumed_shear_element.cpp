// ELFORM -2, the fully integrated hexahedron with assumed natural transverse shear
// (element/hex8_ans.hpp), probed through the element pass itself: from zero stress, one pass at a
// tiny step with the nodal velocity e_j gives the forces -K e_j dt, so 24 passes give the element's
// stiffness K as the pass applies it.
//
// Independent answers:
//   - K is symmetric (the forces are the transpose of the rates: power-consistent), to 1e-8 of its
//     largest entry (one-step geometric terms are O(dt v / h) = 1e-9 here);
//   - exactly six zero eigenvalues, the rigid-body motions, on a thin box, a cube and a skewed,
//     tapered element: the tied shear adds no zero-energy mode (a spurious mode would be a seventh
//     eigenvalue at round-off level, below 1e-8 of the largest);
//   - a constant strain rate on a parallelepiped gives the same stress at every point (the patch
//     test, which tying at edge mid-points keeps for elements with parallel edges, [HS98]);
//   - the stiffness the stable step is computed from (solver/directional_step.hpp), assembled from
//     its own B-bar and tied-shear operators, is this K to 1e-8, and its largest eigenvalue the
//     step's. Both material paths are probed: *MAT_002 ties the Green-Lagrange strain (total
//     Lagrangian), *MAT_001 the rate of deformation; ELFORM 2 is checked the same way.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>
#include <string>

#include "solver/directional_step.hpp"
#include "solver/element_update.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

// One element of a transversely isotropic ply (*MAT_002, fibre along x), nodes moved from the box
// [0, a] x [0, b] x [0, c] by `shift(node)`.
const char* kPly = "{card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895,"
                  " PRCB: 0.53, GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}";
const char* kSteel = "{card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}";

model::Model one_element(double a, double b, double c, const double (*shift)[3] = nullptr, int elform = -2,
                         const char* material = kPly) {
  const std::string y =
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n  m: " + std::string(material) + "\n"
      "sections:\n  s: {ELFORM: " + std::to_string(elform) + ", Q1: 0, Q2: 0}\nparts:\n  p: {material: m, section: s}\n"
      "mesh:\n  boxes:\n    - {part: p, size: [" + std::to_string(a) + ", " + std::to_string(b) + ", " +
      std::to_string(c) + "], elements: [1, 1, 1]}\n";
  const config::Scene scene = config::load_scene_from_string(y, "element.yaml");
  mesh::Mesh mesh = mesh::mesh_boxes(scene);
  if (shift)
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i) mesh.coords[3 * std::size_t(mesh.hex[k]) + i] += shift[k][i];
  return model::build_model(scene, mesh);
}

// Forces of one pass from zero stress with nodal velocities v at step dt (node order of the model).
std::vector<double> pass_forces(const model::Model& m, const std::vector<double>& v, double dt) {
  solver::BlockState st = solver::initial_block_state(m, 0);
  std::vector<double> x = m.X, f(m.X.size(), 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += dt * v[i];
  solver::ChunkResult r;
  solver::update_elements(m, m.blocks[0], st, 0, 1, x.data(), v.data(), f.data(), dt, r);
  return f;
}

// Central difference in the velocity, -(f(+e_j) - f(-e_j)) / (2 dt): the terms of second order in
// the displacement (geometry) cancel, and a displacement of 1e-9 m keeps the round-off of x + u
// (eps x / u ~ 5e-10) well below the checks.
Eigen::MatrixXd pass_stiffness(const model::Model& m) {
  const double dt = 1e-9;
  Eigen::MatrixXd K(24, 24);
  for (int j = 0; j < 24; ++j) {
    std::vector<double> v(m.X.size(), 0.0);
    v[j] = 1.0;
    const std::vector<double> fp = pass_forces(m, v, dt);
    v[j] = -1.0;
    const std::vector<double> fm = pass_forces(m, v, dt);
    for (int i = 0; i < 24; ++i) K(i, j) = -(fp[i] - fm[i]) / (2 * dt);
  }
  return K;
}

const double kSkewed[8][3] = {{0, 0, 0},           {0.3e-3, 0.1e-3, 0},     {0.5e-3, -0.2e-3, 0.02e-3},
                              {-0.2e-3, 0.4e-3, 0}, {0.1e-3, 0.05e-3, 0},    {0.2e-3, 0, 0.03e-3},
                              {0, 0.3e-3, -0.02e-3}, {0.25e-3, -0.1e-3, 0.01e-3}};

TEST(AssumedShearElement, StiffnessIsSymmetricWithOnlyRigidBodyZeroModes) {
  struct Case {
    const char* name;
    model::Model m;
  };
  Case cases[] = {{"thin box 2.5 x 2.5 x 0.25 mm", one_element(2.5e-3, 2.5e-3, 0.25e-3)},
                  {"cube 1 mm", one_element(1e-3, 1e-3, 1e-3)},
                  {"skewed, tapered 2.5 x 2 x 0.25 mm", one_element(2.5e-3, 2e-3, 0.25e-3, kSkewed)},
                  {"the same element in ELFORM 2", one_element(2.5e-3, 2e-3, 0.25e-3, kSkewed, 2)},
                  {"the same element with *MAT_001 (rate form)", one_element(2.5e-3, 2e-3, 0.25e-3, kSkewed, -2, kSteel)}};
  for (auto& c : cases) {
    const Eigen::MatrixXd K = pass_stiffness(c.m);
    const double kmax = K.cwiseAbs().maxCoeff();
    const double asym = (K - K.transpose()).cwiseAbs().maxCoeff() / kmax;
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (K + K.transpose())).eigenvalues();
    int zeros = 0;
    for (int i = 0; i < 24; ++i) zeros += std::abs(lambda[i]) < 1e-8 * lambda[23];
    std::cout << c.name << ": asymmetry " << asym << ", zero eigenvalues " << zeros << ", seventh / largest "
              << lambda[6] / lambda[23] << "\n";
    EXPECT_LT(asym, 1e-8) << c.name;
    EXPECT_EQ(zeros, 6) << c.name;
    EXPECT_GT(lambda[6], 1e-6 * lambda[23]) << c.name;
    // The step's eigenvalue: lambda_max(K) / V in material axes (here the global ones).
    const model::Model& m = c.m;
    element::NodeVec x;
    model::gather_reference(m.X, m.blocks[0].conn.data(), x);
    std::array<double, 36> C = m.materials[0].c_material;
    if (m.materials[0].kind != model::MaterialKind::OrthotropicElastic) {
      const double E = 210e9, nu = 0.3, lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
      C = {};
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) C[6 * i + j] = lam + (i == j ? 2 * mu : 0.0);
        C[6 * (i + 3) + i + 3] = mu;
      }
    }
    const double step_lambda = solver::fully_integrated_eigenvalue(C, x, m.blocks[0].thin_axis.empty() ? -1 : m.blocks[0].thin_axis[0]);
    EXPECT_NEAR(step_lambda * m.blocks[0].volume0[0] / lambda[23], 1.0, 1e-6) << c.name;
    const Eigen::MatrixXd Ks = solver::fully_integrated_stiffness(C, x, m.blocks[0].thin_axis.empty() ? -1 : m.blocks[0].thin_axis[0]);
    Eigen::MatrixXd Kl(24, 24);  // the pass's K in the element's node order
    for (int k = 0; k < 8; ++k)
      for (int l = 0; l < 8; ++l)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) Kl(3 * k + i, 3 * l + j) = K(3 * m.blocks[0].conn[k] + i, 3 * m.blocks[0].conn[l] + j);
    const double differ = (Kl - Ks).cwiseAbs().maxCoeff() / kmax;
    std::cout << "  the pass's K against the step's: " << differ << " of the largest entry\n";
    EXPECT_LT(differ, 1e-8) << c.name;
  }
}

TEST(AssumedShearElement, ConstantStrainOnAParallelepipedGivesOneStress) {
  // Shear the box into a parallelepiped (x += 0.4 z + 0.2 y): edges stay parallel.
  double shift[8][3];
  model::Model box = one_element(2.5e-3, 2e-3, 0.25e-3);
  for (int k = 0; k < 8; ++k) {
    const double* X = &box.X[3 * std::size_t(box.blocks[0].conn[k])];
    shift[k][0] = 0.4 * X[2] + 0.2 * X[1];
    shift[k][1] = shift[k][2] = 0;
  }
  const model::Model m = one_element(2.5e-3, 2e-3, 0.25e-3, shift);
  // v = G X with a general (non-symmetric) velocity gradient: every strain component, shear included.
  const double G[9] = {1.0, 0.3, -0.7, 0.2, -0.5, 0.9, 0.4, 0.6, 0.8};
  std::vector<double> v(m.X.size());
  for (std::size_t n = 0; n < m.num_nodes(); ++n)
    for (int i = 0; i < 3; ++i)
      v[3 * n + i] = G[3 * i] * m.X[3 * n] + G[3 * i + 1] * m.X[3 * n + 1] + G[3 * i + 2] * m.X[3 * n + 2];
  solver::BlockState st = solver::initial_block_state(m, 0);
  std::vector<double> x = m.X, f(m.X.size(), 0.0);
  const double dt = 1e-5;  // strains ~1e-5: the round-off of F^T F - I (1e-16) stays at 1e-11 of them
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += dt * v[i];
  solver::ChunkResult r;
  solver::update_elements(m, m.blocks[0], st, 0, 1, x.data(), v.data(), f.data(), dt, r);
  double smax = 0, spread = 0;
  for (int g = 0; g < 8; ++g)
    for (int i = 0; i < 6; ++i) {
      smax = std::max(smax, std::abs(st.stress[i]));
      spread = std::max(spread, std::abs(st.stress[6 * g + i] - st.stress[i]));
    }
  std::cout << "parallelepiped, constant strain rate: stress spread over the points " << spread / smax << " of the largest\n";
  EXPECT_LT(spread, 1e-9 * smax);
}

}  // namespace
}  // namespace plyimpact
