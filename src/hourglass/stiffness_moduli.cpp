#include <Eigen/Dense>
#include <cmath>

#include "element/hex8.hpp"
#include "hourglass/assumed_strain.hpp"
#include "hourglass/element_elasticity.hpp"
#include "hourglass/stiffness.hpp"

namespace plyimpact::hourglass {

namespace {

// Voigt index of the tensor pair (i, j): xx yy zz xy yz zx.
constexpr int kVoigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};

// rho c^2 of the fastest wave along n (material axes): the largest eigenvalue of the acoustic
// tensor A_ik = C_ijkl n_j n_l (engineering-shear Voigt C: C_ijkl = C[v(ij)][v(kl)]).
double wave_modulus_along(const material::Stiffness6& C, const double n[3]) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l) A(i, k) += C[6 * kVoigt[i][j] + kVoigt[k][l]] * n[j] * n[l];
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(A, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

// w_j = sum_k (e_j . b_k)^2 for the element axes e_j (j = 0..2) of element e at t = 0, with the
// centre gradient b_k = J^-T dN_k/dxi: the share of sum b^2 that varies along e_j.
void gradient_weights(const model::Model& model, const model::ElementBlock& block, std::size_t e, double (&w)[3]) {
  double J[9] = {};
  for (int k = 0; k < 8; ++k) {
    const double* X = &model.X[3 * std::size_t(block.conn[8 * e + k])];
    for (int i = 0; i < 3; ++i) {
      J[3 * i] += 0.125 * X[i] * element::kXi[k];
      J[3 * i + 1] += 0.125 * X[i] * element::kEta[k];
      J[3 * i + 2] += 0.125 * X[i] * element::kZeta[k];
    }
  }
  double Ji[9];
  element::inverse3(J, Ji);  // Ji[3 c + i] = dxi_c/dx_i
  double Jc[9][1];
  for (int i = 0; i < 9; ++i) Jc[i][0] = J[i];
  double Ef[9][1], ha[1], hb[1], hc[1];
  element_frame(Jc, 0, Ef, ha, hb, hc);
  for (int j = 0; j < 3; ++j) {
    w[j] = 0;
    for (int k = 0; k < 8; ++k) {
      const double dN[3] = {0.125 * element::kXi[k], 0.125 * element::kEta[k], 0.125 * element::kZeta[k]};
      double bj = 0;  // e_j . b_k, b_k,i = sum_c dN_c dxi_c/dx_i
      for (int i = 0; i < 3; ++i) bj += Ef[3 * j + i][0] * (dN[0] * Ji[i] + dN[1] * Ji[3 + i] + dN[2] * Ji[6 + i]);
      w[j] += bj * bj;
    }
  }
}

}  // namespace

std::vector<double> stiffness_hourglass_moduli(const model::Model& model, const model::ElementBlock& block) {
  const material::Stiffness6 C = stiffness_in_material_axes(model.materials[block.material]);
  std::vector<double> out(block.size());
  for (std::size_t e = 0; e < block.size(); ++e) {
    double n[3][3], w[3];
    element_axes_in_material_axes(model, block, e, n);
    gradient_weights(model, block, e, w);
    double num = 0, den = 0;
    for (int j = 0; j < 3; ++j) num += wave_modulus_along(C, n[j]) * w[j], den += w[j];
    out[e] = num / den;
  }
  return out;
}

}  // namespace plyimpact::hourglass
