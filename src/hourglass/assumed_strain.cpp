#include "hourglass/assumed_strain.hpp"

#include <cmath>

#include "element/hex8.hpp"
#include "hourglass/element_elasticity.hpp"
#include "material/composite_damage.hpp"

namespace plyimpact::hourglass {

namespace {

// Compliance of an orthotropic material in its axes: normal block S[a][c] (1/E_a on the diagonal,
// -nu_ac/E_a off it) and the inverse shear moduli 1/G_ab, 1/G_bc, 1/G_ca (Voigt order ab, bc, ca).
struct Compliance {
  double S[3][3] = {};
  double invG[3] = {};
};

// From a stiffness in material axes (orthotropic or isotropic: no normal-shear coupling): invert
// the normal 3x3 block; the shear moduli are the diagonal shear entries.
Compliance orthotropic_compliance(const material::Stiffness6& C) {
  const double m[9] = {C[0], C[1], C[2], C[6], C[7], C[8], C[12], C[13], C[14]};
  double inv[9];
  element::inverse3(m, inv);
  Compliance c;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) c.S[a][b] = inv[3 * a + b];
  c.invG[0] = 1 / C[21], c.invG[1] = 1 / C[28], c.invG[2] = 1 / C[35];
  return c;
}

// 1/E(n) = sum_ac S_ac n_a^2 n_c^2 + sum_{a<b} n_a^2 n_b^2 / G_ab (n in material axes).
double inverse_young(const Compliance& c, const double n[3]) {
  double s = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) s += c.S[a][b] * n[a] * n[a] * n[b] * n[b];
  constexpr int kPair[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int p = 0; p < 3; ++p) s += n[kPair[p][0]] * n[kPair[p][0]] * n[kPair[p][1]] * n[kPair[p][1]] * c.invG[p];
  return s;
}

// 1/G(n, m) = 4 sum_ac S_ac p_a p_c + sum_{a<b} (n_a m_b + n_b m_a)^2 / G_ab, p_a = n_a m_a.
double inverse_shear(const Compliance& c, const double n[3], const double m[3]) {
  double s = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) s += 4 * c.S[a][b] * n[a] * m[a] * n[b] * m[b];
  constexpr int kPair[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int p = 0; p < 3; ++p) {
    const int a = kPair[p][0], b = kPair[p][1];
    const double t = n[a] * m[b] + n[b] * m[a];
    s += t * t * c.invG[p];
  }
  return s;
}

// The compliance of the degradation table (composite_damage.cpp item 2) for the lost components.
Compliance without(Compliance c, int lost) {
  namespace L = material::lost_component;
  for (int k : {0, 1}) {
    if (!(lost & (k == 0 ? L::kAa : L::kBb))) continue;
    for (int j = 0; j < 3; ++j)
      if (j != k) c.S[k][j] = c.S[j][k] = 0;
    c.S[k][k] /= kLostComponentResidual;
  }
  if (lost & L::kAb) c.invG[0] /= kLostComponentResidual;
  return c;
}

void element_moduli(const Compliance& comp, const double (&n)[3][3], double* m) {
  for (int i = 0; i < 3; ++i) m[i] = 1 / inverse_young(comp, n[i]);
  m[3] = 1 / inverse_shear(comp, n[0], n[1]);
  m[4] = 1 / inverse_shear(comp, n[1], n[2]);
  m[5] = 1 / inverse_shear(comp, n[2], n[0]);
}

}  // namespace

std::vector<double> assumed_strain_moduli(const model::Model& model, const model::ElementBlock& block) {
  const Compliance comp = orthotropic_compliance(stiffness_in_material_axes(model.materials[block.material]));
  std::vector<double> out(6 * block.size());
  for (std::size_t e = 0; e < block.size(); ++e) {
    double n[3][3];
    element_axes_in_material_axes(model, block, e, n);
    element_moduli(comp, n, &out[6 * e]);
  }
  return out;
}

void assumed_strain_element_moduli(const model::Model& model, const model::ElementBlock& block, std::size_t e,
                                   int lost, double (&m)[6]) {
  const Compliance comp = orthotropic_compliance(stiffness_in_material_axes(model.materials[block.material]));
  double n[3][3];
  element_axes_in_material_axes(model, block, e, n);
  element_moduli(without(comp, lost), n, m);
}

void rescale_assumed_strain_forces(double (&Q)[12], const double (&m_old)[6], const double (&m_new)[6], double a,
                                   double b, double c) {
  double r[6];
  for (int i = 0; i < 6; ++i) r[i] = m_new[i] / m_old[i];
  constexpr int kNormal[3][3] = {{0, 2, 3}, {4, 5, 7}, {9, 10, 11}};  // Q[4 i + alpha] of axis i's modes
  for (int i = 0; i < 3; ++i)
    for (int k : kNormal[i]) Q[k] *= r[i];
  const double ia = 1 / a, ib = 1 / b, ic = 1 / c;
  const double sxy = (ia * Q[1] + ib * Q[6] - ic * Q[8]) / (2 * ia * ib);
  const double syz = (Q[6] - ia * sxy) / ic, szx = (Q[1] - ib * sxy) / ic;
  const double txy = r[3] * sxy, tyz = r[4] * syz, tzx = r[5] * szx;
  Q[1] = ib * txy + ic * tzx;
  Q[6] = ia * txy + ic * tyz;
  Q[8] = ib * tyz + ia * tzx;
}

}  // namespace plyimpact::hourglass
