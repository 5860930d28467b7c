// Synthetic DCB propagation data from corrected beam theory: each arm a cantilever of thickness
// h_arm = H/2 built in at a distance Delta behind the crack tip, so the load-point compliance is
//   C(a) = 8 (a + Delta)^3 / (E b h_arm^3)           (k = 8 / (E b h_arm^3), C = k (a + Delta)^3)
// and, with G = P^2/(2b) dC/da held at G_Ic while the crack grows,
//   P(a) = sqrt(2 b G_Ic / (3 k)) / (a + Delta),  delta = C P.
#pragma once

#include <cmath>
#include <vector>

#include "fracture/dcb_reduction.hpp"

namespace plyimpact::test {

struct BeamTheoryDcb {
  double E = 120e9;         // Pa, flexural modulus of the arms
  double width = 25e-3;     // b, m
  double thickness = 3e-3;  // H, m (two 1.5 mm arms)
  double Delta = 4e-3;      // m, crack length correction
  double G_Ic = 300.0;      // J/m^2

  double k() const {
    const double h_arm = 0.5 * thickness;
    return 8.0 / (E * width * h_arm * h_arm * h_arm);
  }
  fracture::DcbPoint at(double a) const {
    const double C = k() * std::pow(a + Delta, 3);
    const double P = std::sqrt(2.0 * width * G_Ic / (3.0 * k())) / (a + Delta);
    return {a, P, C * P};
  }
  // Crack lengths a0, a0 + step, ..., a1 (inclusive).
  std::vector<fracture::DcbPoint> propagation(double a0, double a1, double step) const {
    std::vector<fracture::DcbPoint> out;
    for (int i = 0; a0 + i * step <= a1 * (1 + 1e-12); ++i) out.push_back(at(a0 + i * step));
    return out;
  }
};

}  // namespace plyimpact::test
