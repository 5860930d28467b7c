// Directional stable step of anisotropic one-point hexahedra; see directional_step.hpp.
#include "solver/directional_step.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "element/hex8.hpp"

namespace plyimpact::solver {

namespace {

bool keeps_material_speed(const model::Model& model, const model::ElementBlock& block) {
  if (block.rigid || block.elform != 1 || block.ihq == 4 || block.ihq == 5) return true;
  return !model.materials[block.material].has_axes();
}

// Stiffness in material axes as an Eigen matrix (engineering-shear Voigt, symmetric).
Eigen::Matrix<double, 6, 6> to_matrix(const std::array<double, 36>& C) {
  Eigen::Matrix<double, 6, 6> m;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) m(i, j) = 0.5 * (C[6 * i + j] + C[6 * j + i]);
  return m;
}

}  // namespace

double constant_strain_eigenvalue(const std::array<double, 36>& C, const double (&b)[3][8]) {
  // A = sum_k B_k B_k^T with the strain rows of node k: xx yy zz xy yz zx (engineering shear).
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  for (int k = 0; k < 8; ++k) {
    const double bx = b[0][k], by = b[1][k], bz = b[2][k];
    Eigen::Matrix<double, 6, 3> Bk;
    Bk << bx, 0, 0, 0, by, 0, 0, 0, bz, by, bx, 0, 0, bz, by, bz, 0, bx;
    A += Bk * Bk.transpose();
  }
  // lambda(A C) = lambda(L^T A L) with C = L L^T (C positive definite: the card checks refuse others).
  const Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(to_matrix(C));
  const Eigen::Matrix<double, 6, 6> L = llt.matrixL();
  const Eigen::Matrix<double, 6, 6> S = L.transpose() * A * L;
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>(S, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

std::vector<double> step_wave_speeds(const model::Model& model, const model::ElementBlock& block) {
  if (keeps_material_speed(model, block)) return {};
  const model::Material& mat = model.materials[block.material];
  const std::array<double, 36> C =
      mat.kind == model::MaterialKind::CompositeDamage ? mat.composite.C : mat.c_material;  // material axes
  std::vector<double> speed(block.size(), mat.wave_speed);
  bool any_slower = false;
  for (std::size_t e = 0; e < block.size(); ++e) {
    element::NodeVec x, bg;
    model::gather_reference(model.X, &block.conn[8 * e], x);
    const double V = element::hex8_mean_gradient(x, bg);
    const double L = V / element::hex8_max_face_area(x);
    // Gradients in material axes: b_m = Q b with the rows of Q the material axes a, b, c.
    const auto& Q = model.orientations[block.orientation[e]].axes;
    double bm[3][8];
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a) bm[a][k] = Q[3 * a] * bg[0][k] + Q[3 * a + 1] * bg[1][k] + Q[3 * a + 2] * bg[2][k];
    const double omega = std::sqrt(8.0 * constant_strain_eigenvalue(C, bm) / mat.density);
    const double c_step = 0.5 * L * omega;
    if (c_step < speed[e]) {
      speed[e] = c_step;
      any_slower = true;
    }
  }
  if (!any_slower) return {};
  return speed;
}

}  // namespace plyimpact::solver
