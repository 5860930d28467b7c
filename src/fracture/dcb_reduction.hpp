// Mode I interlaminar fracture toughness from a double cantilever beam (DCB) test: the three data
// reductions of ASTM D5528 (modified beam theory, compliance calibration, modified compliance
// calibration) applied to the propagation points (crack length a, load P, opening delta) of one
// specimen, giving the resistance curve G_Ic(a) by each method and the fits behind them.
// Units: SI throughout (m, N, m/N, J/m^2). Equations as numbered in the seed's section 8.1:
//   MBT  G = 3 P delta / (2 b (a + |Delta|))      (8.2); Delta = x-intercept of C^(1/3) against a
//   CC   G = n P delta / (2 b a)                  (8.3); n = slope of log C against log a  (C = alpha a^n, 8.4)
//   MCC  G = 3 P^2 C^(2/3) / (2 A1 b h)           (8.5); A1 = slope of a/h against C^(1/3)  (8.6)
// with C = delta / P, b the specimen width and h its (total) thickness. Sources: ASTM D5528 (Mode I
// Interlaminar Fracture Toughness of Unidirectional Fiber-Reinforced Polymer Matrix Composites,
// editions -01 and -13, its calculation section) and the seed's eqs. 8.1-8.6. Why the fits are
// these lines: corrected beam theory gives C = 8 (a + Delta)^3 / (E b h_arm^3), so C^(1/3) is linear
// in a with x-intercept -Delta (MBT) and a/h is linear in C^(1/3) (MCC, h cancels in eq. 8.5); CC
// takes the exponent of the power law that best fits the record on log-log axes.
#pragma once

#include <span>
#include <vector>

namespace plyimpact::fracture {

/// One propagation point: crack length a (m), load P (N), load-point opening delta (m).
struct DcbPoint {
  double a = 0, P = 0, delta = 0;
};

/// Specimen width b and total thickness h (m).
struct DcbSpecimen {
  double width = 0, thickness = 0;
};

/// Least-squares line y = slope x + intercept, with the coefficient of determination R^2.
struct LineFit {
  double slope = 0, intercept = 0, r2 = 0;
};

/// Ordinary least squares through (x_i, y_i); needs at least 2 points with distinct x.
/// R^2 = 1 - SS_res / SS_tot (1 when all y are equal and the line fits them exactly).
/// @throws InputError when x has fewer than 2 distinct values
LineFit fit_line(std::span<const double> x, std::span<const double> y);

struct DcbReduction {
  std::vector<DcbPoint> points;  // the propagation points reduced, in order
  std::vector<double> compliance;                    // C = delta / P (m/N), per point
  std::vector<double> G_mbt, G_cc, G_mcc;            // J/m^2, per point
  LineFit mbt_fit;  // C^(1/3) (m^(1/3) N^(-1/3)) against a (m)
  LineFit cc_fit;   // ln C against ln a
  LineFit mcc_fit;  // a / h against C^(1/3)
  double delta_x_intercept = 0;  // x-intercept of the MBT fit (m); beam theory makes it negative
  double Delta = 0;              // |delta_x_intercept| (m), the crack length correction of eq. 8.2
  double n = 0;                  // CC exponent
  double A1 = 0;                 // MCC slope (N^(1/3) m^(-1/3))
};

/// Applies the three reductions to `points` (at least 3, a strictly increasing, P and delta > 0).
/// @throws InputError when the points cannot be reduced (the caller checks and locates bad rows first)
DcbReduction reduce_dcb(std::span<const DcbPoint> points, const DcbSpecimen& specimen);

}  // namespace plyimpact::fracture
