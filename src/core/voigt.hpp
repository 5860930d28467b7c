// Symmetric second-order tensors in Voigt order (xx yy zz xy yz zx), shared by the element
// kernels and the material routines.
#pragma once

namespace plyimpact {

// out = R t R^T (out may be t). With R the incremental rotation it carries a stress along with the
// material; with R = Q (rows: material axes a, b, c) it gives the components in material axes.
inline void rotate_voigt(const double R[9], const double t[6], double out[6]) {
  const double T[9] = {t[0], t[3], t[5], t[3], t[1], t[4], t[5], t[4], t[2]};
  double RT[9];  // R T
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) RT[3 * i + j] = R[3 * i] * T[j] + R[3 * i + 1] * T[3 + j] + R[3 * i + 2] * T[6 + j];
  auto at = [&](int i, int j) { return RT[3 * i] * R[3 * j] + RT[3 * i + 1] * R[3 * j + 1] + RT[3 * i + 2] * R[3 * j + 2]; };
  out[0] = at(0, 0), out[1] = at(1, 1), out[2] = at(2, 2), out[3] = at(0, 1), out[4] = at(1, 2), out[5] = at(2, 0);
}

}  // namespace plyimpact
