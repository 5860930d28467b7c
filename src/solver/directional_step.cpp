// Directional stable step of anisotropic one-point hexahedra; see directional_step.hpp.
#include "solver/directional_step.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "element/hex8.hpp"
#include "element/hex8_ans.hpp"

namespace plyimpact::solver {

namespace {

bool keeps_material_speed(const model::Model& model, const model::ElementBlock& block) {
  if (block.rigid || block.elform > 2 || (block.elform == 1 && (block.ihq == 4 || block.ihq == 5))) return true;
  return !model.materials[block.material].has_axes();
}

// Stiffness in material axes as an Eigen matrix (engineering-shear Voigt, symmetric).
Eigen::Matrix<double, 6, 6> to_matrix(const std::array<double, 36>& C) {
  Eigen::Matrix<double, 6, 6> m;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) m(i, j) = 0.5 * (C[6 * i + j] + C[6 * j + i]);
  return m;
}

// Strain rows of node k (xx yy zz xy yz zx, engineering shear) for the gradient (bx, by, bz).
Eigen::Matrix<double, 6, 3> strain_rows(double bx, double by, double bz) {
  Eigen::Matrix<double, 6, 3> Bk;
  Bk << bx, 0, 0, 0, by, 0, 0, 0, bz, by, bx, 0, 0, bz, by, bz, 0, bx;
  return Bk;
}

// omega_max^2 rho / 8 of the element whose reference nodes are x, in the material axes Q (rows a,
// b, c): the constant-strain limit for ELFORM 1, the whole B-bar stiffness for ELFORM 2 and -2
// (thin: ELFORM -2's thin natural direction, -1 for ELFORM 2).
double element_eigenvalue(const std::array<double, 36>& C, const double* Q, const element::NodeVec& x, int elform,
                          int thin) {
  const auto to_axes = [Q](const double (&b)[3][8], double (&bm)[3][8]) {
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a) bm[a][k] = Q[3 * a] * b[0][k] + Q[3 * a + 1] * b[1][k] + Q[3 * a + 2] * b[2][k];
  };
  if (elform == 1) {
    element::NodeVec bg;
    element::hex8_mean_gradient(x, bg);
    double bm[3][8];
    to_axes(bg, bm);
    return constant_strain_eigenvalue(C, bm);
  }
  element::NodeVec xm;  // the nodes in material axes: every gradient and base vector comes out in them
  to_axes(x, xm);
  return fully_integrated_eigenvalue(C, xm, thin);
}

}  // namespace

Eigen::Matrix<double, 24, 24> fully_integrated_stiffness(const std::array<double, 36>& C, const element::NodeVec& x,
                                                         int thin) {
  Eigen::Matrix<double, 24, 24> K = Eigen::Matrix<double, 24, 24>::Zero();
  double B[8][3][8], detj[8], J[8][9];
  if (!element::hex8_gauss_gradients(x, B, detj, J)) return K;  // refused by the mesh checks before any run
  element::AnsRows ans;
  if (thin >= 0) element::hex8_ans_shear_rows(x, thin, ans);
  // B-bar: every point's volumetric strain is the element mean, or for ELFORM -2 the mean of its
  // layer (the four points on its side of the mid-surface; element_hex8_selective.cpp).
  const auto layer = [&](int g) { return thin >= 0 ? element::ans_layer(g, thin) : 0; };
  double V[2] = {}, bbar[2][3][8] = {};
  for (int g = 0; g < 8; ++g) {
    V[layer(g)] += detj[g];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 8; ++k) bbar[layer(g)][i][k] += detj[g] * B[g][i][k];
  }
  for (int y = 0; y < 2; ++y)
    for (auto& row : bbar[y])
      for (double& b : row) b = V[y] > 0 ? b / V[y] : 0.0;
  const Eigen::Matrix<double, 6, 6> Cm = to_matrix(C);
  for (int g = 0; g < 8; ++g) {
    Eigen::Matrix<double, 6, 24> Bg;
    for (int k = 0; k < 8; ++k) {
      Eigen::Matrix<double, 6, 3> Bk = strain_rows(B[g][0][k], B[g][1][k], B[g][2][k]);
      for (int j = 0; j < 3; ++j) Bk.block<3, 1>(0, j).array() += (bbar[layer(g)][j][k] - B[g][j][k]) / 3.0;
      if (thin >= 0) {
        // ELFORM -2: the assumed-shear change of the rate, made deviatoric as the element does
        // (its B-bar correction follows it), with engineering shear.
        double Jinv[9];
        element::inverse3(J[g], Jinv);
        for (int j = 0; j < 3; ++j) {
          const double dd[2] = {ans[g][0][j][k], ans[g][1][j][k]};
          double dD[6];
          element::ans_cartesian_rate(Jinv, thin, dd, dD);
          const double mean = (dD[0] + dD[1] + dD[2]) / 3.0;
          for (int q = 0; q < 6; ++q) Bk(q, j) += q < 3 ? dD[q] - mean : 2 * dD[q];
        }
      }
      Bg.block<6, 3>(0, 3 * k) = Bk;
    }
    K.noalias() += detj[g] * Bg.transpose() * Cm * Bg;
  }
  return K;
}

double fully_integrated_eigenvalue(const std::array<double, 36>& C, const element::NodeVec& x, int thin) {
  const Eigen::Matrix<double, 24, 24> K = fully_integrated_stiffness(C, x, thin);
  const double V = element::hex8_volume(x);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 24, 24>>(K, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff() / V;
}

double constant_strain_eigenvalue(const std::array<double, 36>& C, const double (&b)[3][8]) {
  // A = sum_k B_k B_k^T with the strain rows of node k: xx yy zz xy yz zx (engineering shear).
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  for (int k = 0; k < 8; ++k) {
    const Eigen::Matrix<double, 6, 3> Bk = strain_rows(b[0][k], b[1][k], b[2][k]);
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
    element::NodeVec x;
    model::gather_reference(model.X, &block.conn[8 * e], x);
    const double L = element::hex8_volume(x) / element::hex8_max_face_area(x);
    // Gradients in material axes: b_m = Q b with the rows of Q the material axes a, b, c.
    const double* Q = model.orientations[block.orientation[e]].axes.data();
    const int thin = block.thin_axis.empty() ? -1 : int(block.thin_axis[e]);
    const double omega = std::sqrt(8.0 * element_eigenvalue(C, Q, x, block.elform, thin) / mat.density);
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
