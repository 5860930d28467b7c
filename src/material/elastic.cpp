#include "material/elastic.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace plyimpact::material {

IsotropicConstants isotropic_constants(double E, double PR) {
  IsotropicConstants c;
  c.mu = E / (2.0 * (1.0 + PR));
  c.lambda = E * PR / ((1.0 + PR) * (1.0 - 2.0 * PR));
  c.bulk = E / (3.0 * (1.0 - 2.0 * PR));
  return c;
}

namespace {

// Compliance in material axes with the LS-DYNA minor ratios: eps_a = s_a/EA - PRBA s_b/EB - PRCA s_c/EC ...
Eigen::Matrix<double, 6, 6> compliance(const OrthotropicConstants& m) {
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
  S(0, 0) = 1.0 / m.EA;
  S(1, 1) = 1.0 / m.EB;
  S(2, 2) = 1.0 / m.EC;
  S(0, 1) = S(1, 0) = -m.PRBA / m.EB;
  S(0, 2) = S(2, 0) = -m.PRCA / m.EC;
  S(1, 2) = S(2, 1) = -m.PRCB / m.EC;
  S(3, 3) = 1.0 / m.GAB;
  S(4, 4) = 1.0 / m.GBC;
  S(5, 5) = 1.0 / m.GCA;
  return S;
}

}  // namespace

double orthotropic_determinant(const OrthotropicConstants& m) {
  const double nu_ab = m.PRBA * m.EA / m.EB, nu_ac = m.PRCA * m.EA / m.EC, nu_bc = m.PRCB * m.EB / m.EC;
  return 1.0 - nu_ab * m.PRBA - nu_bc * m.PRCB - nu_ac * m.PRCA - 2.0 * m.PRBA * m.PRCB * nu_ac;
}

bool admissible(const OrthotropicConstants& m) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(compliance(m));
  return orthotropic_determinant(m) > 0.0 && eig.eigenvalues().minCoeff() > 0.0;
}

Stiffness6 orthotropic_stiffness(const OrthotropicConstants& m) {
  const Eigen::Matrix<double, 6, 6> C = compliance(m).inverse();
  Stiffness6 out;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) out[6 * i + j] = 0.5 * (C(i, j) + C(j, i));
  return out;
}

namespace {

// Voigt index of the tensor pair (i, j): xx yy zz xy yz zx.
constexpr int kVoigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};

// Engineering-shear Voigt strain vector of a symmetric tensor.
void tensor_to_strain(const double t[3][3], double e[6]) {
  e[0] = t[0][0];
  e[1] = t[1][1];
  e[2] = t[2][2];
  e[3] = 2 * t[0][1];
  e[4] = 2 * t[1][2];
  e[5] = 2 * t[2][0];
}

}  // namespace

Stiffness6 rotate_to_global(const Stiffness6& cm, const Mat3& q) {
  // Column m of the global stiffness is the global stress produced by unit global strain m:
  // rotate the strain into material axes, apply cm, rotate the stress back. Exact, no Voigt
  // transformation matrices to get wrong.
  Stiffness6 cg{};
  for (int m = 0; m < 6; ++m) {
    double eps[3][3] = {};  // tensor strain of unit engineering strain m
    const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
    const int i0 = pairs[m][0], j0 = pairs[m][1];
    if (i0 == j0) {
      eps[i0][j0] = 1.0;
    } else {
      eps[i0][j0] = eps[j0][i0] = 0.5;
    }
    double em[3][3] = {};  // Q eps Q^T
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double s = 0;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) s += q[3 * a + i] * eps[i][j] * q[3 * b + j];
        em[a][b] = s;
      }
    double ev[6], sv[6];
    tensor_to_strain(em, ev);
    for (int r = 0; r < 6; ++r) {
      sv[r] = 0;
      for (int c = 0; c < 6; ++c) sv[r] += cm[6 * r + c] * ev[c];
    }
    double sm[3][3];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) sm[a][b] = sv[kVoigt[a][b]];
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) {
        double s = 0;  // (Q^T sm Q)_ij
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) s += q[3 * a + i] * sm[a][b] * q[3 * b + j];
        cg[6 * kVoigt[i][j] + m] = s;
      }
  }
  return cg;
}

namespace {

double acoustic_max_eigenvalue(const Stiffness6& c, const Eigen::Vector3d& n) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      double s = 0;
      for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l) s += c[6 * kVoigt[i][j] + kVoigt[k][l]] * n[j] * n[l];
      A(i, k) = s;
    }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly);
  return eig.eigenvalues().maxCoeff();
}

}  // namespace

double max_wave_modulus(const Stiffness6& c) {
  // Fibonacci sampling of the sphere, then a shrinking pattern search around the best samples.
  const int n_samples = 4000;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<std::pair<double, Eigen::Vector3d>> best;
  for (int s = 0; s < n_samples; ++s) {
    const double z = 1.0 - 2.0 * (s + 0.5) / n_samples;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Eigen::Vector3d n(r * std::cos(golden * s), r * std::sin(golden * s), z);
    best.emplace_back(acoustic_max_eigenvalue(c, n), n);
  }
  for (Eigen::Vector3d axis : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)})
    best.emplace_back(acoustic_max_eigenvalue(c, axis), axis);
  std::partial_sort(best.begin(), best.begin() + 6, best.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });
  double result = best.front().first;
  for (int candidate = 0; candidate < 6; ++candidate) {
    Eigen::Vector3d n = best[candidate].second;
    double value = best[candidate].first;
    for (double step = 0.05; step > 1e-10; step *= 0.5) {
      bool improved = true;
      while (improved) {
        improved = false;
        for (int d = 0; d < 3; ++d)
          for (double sign : {-1.0, 1.0}) {
            Eigen::Vector3d trial = n;
            trial[d] += sign * step;
            trial.normalize();
            const double v = acoustic_max_eigenvalue(c, trial);
            if (v > value) {
              value = v;
              n = trial;
              improved = true;
            }
          }
      }
    }
    result = std::max(result, value);
  }
  return result;
}

namespace {

Eigen::Vector3d unit(const Eigen::Vector3d& v) {
  const double n = v.norm();
  return n > 0 ? Eigen::Vector3d(v / n) : v;
}

Eigen::Vector3d node(const double x[3][8], int k) { return {x[0][k], x[1][k], x[2][k]}; }

}  // namespace

Mat3 material_axes(const MaterialAxes& axes, double beta, const double x[3][8]) {
  Eigen::Vector3d a, b, c;
  if (axes.AOPT == 2) {
    a = unit(Eigen::Vector3d(axes.A[0], axes.A[1], axes.A[2]));
    const Eigen::Vector3d d(axes.D[0], axes.D[1], axes.D[2]);
    c = unit(a.cross(d));
    b = c.cross(a);
  } else if (axes.AOPT == 3) {
    // Mid-surface normal: direction of increasing zeta (faces 1-2-3-4 -> 5-6-7-8).
    Eigen::Vector3d dxi = Eigen::Vector3d::Zero(), deta = Eigen::Vector3d::Zero();
    for (int k = 0; k < 8; ++k) {
      static constexpr double xi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
      static constexpr double eta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
      dxi += xi[k] * node(x, k);
      deta += eta[k] * node(x, k);
    }
    c = unit(dxi.cross(deta));
    a = unit(Eigen::Vector3d(axes.V[0], axes.V[1], axes.V[2]).cross(c));
    b = c.cross(a);
  } else {  // AOPT 0
    a = unit(node(x, 1) - node(x, 0));
    const Eigen::Vector3d d = node(x, 3) - node(x, 0);
    c = unit(a.cross(d));
    b = c.cross(a);
  }
  const double cb = std::cos(beta), sb = std::sin(beta);
  const Eigen::Vector3d ar = cb * a + sb * b;
  const Eigen::Vector3d br = -sb * a + cb * b;
  return {ar[0], ar[1], ar[2], br[0], br[1], br[2], c[0], c[1], c[2]};
}

}  // namespace plyimpact::material
