// Richardson extrapolation of a quantity computed on three meshes h1 > h2 > h3 (coarse to fine),
// assuming q(h) = q* + C h^p in the asymptotic range. The observed order p solves
//   (q1 - q2) / (q2 - q3) = (h1^p - h2^p) / (h2^p - h3^p),
// which for a constant refinement ratio r = h1/h2 = h2/h3 is p = log((q1 - q2)/(q2 - q3)) / log(r)
// (Roache, "Verification and Validation in Computational Science and Engineering", 1998, ch. 5;
// Celik et al., J. Fluids Eng. 130 (2008) 078001 for unequal ratios). For unequal ratios the
// right-hand side grows monotonically with p and p is found by bisection. Then
//   q* = q3 + (q3 - q2) / ((h2/h3)^p - 1).
// The sequence is flagged as outside the asymptotic range when the differences change sign
// (oscillatory or non-monotone convergence: no p), when they are both zero (nothing to
// extrapolate), or when p falls outside the stated plausible band.
#pragma once

#include <string>
#include <vector>

namespace plyimpact::study {

struct RichardsonResult {
  bool extrapolated = false;  // q* and p are valid numbers
  double order = 0;           // observed p (NaN when undefined)
  double value = 0;           // q* (NaN when undefined)
  double ratio_coarse = 0, ratio_fine = 0;  // h1/h2, h2/h3
  bool asymptotic = false;    // extrapolated and p inside the band
  std::vector<std::string> flags;  // why the sequence is not asymptotic
};

/// h: mesh sizes, strictly decreasing; q: the quantity on each. order_lo/hi: plausible band of p.
RichardsonResult richardson(const double h[3], const double q[3], double order_lo, double order_hi);

}  // namespace plyimpact::study
