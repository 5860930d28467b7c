// Longitudinal wave in a long bar under uniaxial strain (every node's y and z fixed), the left end
// pushed at a constant v0 from t = 0. One-dimensional elastodynamics gives a step front that moves
// at c = sqrt(M / rho), M the P-wave modulus along the bar, with the stress sigma_xx = -rho c v0
// behind it (momentum balance across the front: the bar behind it moves at v0, the growth rate of
// its momentum rho c v0 A equals the applied force). Three materials: MAT_001 steel (M = lambda +
// 2 mu) and a MAT_002 carbon ply with the fibre along (M = C11) and across (M = C22) the bar, C the
// inverse of the compliance built here from the card constants. Measured: (a) the arrival time of
// the half-plateau level at the element in the middle of the bar against x / c, (b) the front speed
// from the arrival at two stations (independent of the start-up transient), (c) the plateau stress
// behind the front against -rho c v0 (both with the leading finite-strain correction, see below),
// (d) the stable time step against TSSFAC L / c_max (cubes, L = V / A_max = h), with and without
// the bulk-viscosity term of the pushed first element. ELFORM 1, IHQ 4, bulk viscosity on.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "support.hpp"

namespace plyimpact {
namespace {

constexpr int kElements = 400;  // along x; cross-section 1 x 1 element
constexpr double kH = 1e-3;     // element edge (m): cubes
constexpr double kLength = kElements * kH;
constexpr double kV0 = 1.0;     // m/s: strain v0/c ~ 1e-4 to 4e-4, geometric nonlinearity ~1e-4 relative
constexpr double kQ1 = 1.5, kQ2 = 0.06;  // bulk viscosity defaults (on)

// T800S/M21-like ply (SI).
constexpr double kRoPly = 1550, kEA = 157e9, kEB = 8.5e9, kEC = 8.5e9, kPRBA = 0.019, kPRCA = 0.019, kPRCB = 0.53,
                 kGAB = 4.2e9, kGBC = 2.2e9, kGCA = 4.2e9;
constexpr double kRoSteel = 7850, kESteel = 210e9, kNuSteel = 0.3;

struct WaveCase {
  const char* name;
  const char* material_yaml;  // the material card, mapping body
  const char* beta;           // part ply angle
  double rho;
  double modulus;   // M along the bar (computed independently below)
  double c_max;     // fastest wave speed of the material (drives the stable step)
};

// gtest prints the parameter in test names and logs: the case name, not the bytes.
void PrintTo(const WaveCase& c, std::ostream* os) { *os << c.name; }

// Orthotropic stiffness in material axes (a, b, c) from the LS-DYNA card constants; Voigt aa bb cc
// ab bc ca, engineering shear. Minor ratios: S12 = -PRBA/EB, S13 = -PRCA/EC, S23 = -PRCB/EC.
Eigen::Matrix<double, 6, 6> ply_stiffness() {
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
  S(0, 0) = 1 / kEA, S(1, 1) = 1 / kEB, S(2, 2) = 1 / kEC;
  S(0, 1) = S(1, 0) = -kPRBA / kEB;
  S(0, 2) = S(2, 0) = -kPRCA / kEC;
  S(1, 2) = S(2, 1) = -kPRCB / kEC;
  S(3, 3) = 1 / kGAB, S(4, 4) = 1 / kGBC, S(5, 5) = 1 / kGCA;
  return S.inverse();
}

std::vector<WaveCase> cases() {
  const double M_steel = kESteel * (1 - kNuSteel) / ((1 + kNuSteel) * (1 - 2 * kNuSteel));
  const auto C = ply_stiffness();
  // The fibre direction is the fastest direction of this ply: off the fibre the quasi-P modulus
  // is about C11 cos^4 + 2 (C12 + 2 C66) sin^2 cos^2 + C22 sin^4, and C12 + 2 C66 = 15 GPa and
  // C22 = 12 GPa are far below C11 = 162 GPa, so there is no off-axis maximum: c_max =
  // sqrt(C11 / rho) for both ply orientations (the stable-step check below compares it with the
  // solver's own sphere search).
  static const std::string steel = "{card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}";
  static const std::string ply =
      "{card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}";
  return {
      {"Steel", steel.c_str(), "0", kRoSteel, M_steel, std::sqrt(M_steel / kRoSteel)},
      {"PlyFibreAlongBar", ply.c_str(), "0", kRoPly, C(0, 0), std::sqrt(C(0, 0) / kRoPly)},
      // beta = 90 deg rotates a onto global y about c = z: b lies along the bar, M = C22.
      {"PlyFibreAcrossBar", ply.c_str(), "90", kRoPly, C(1, 1), std::sqrt(C(0, 0) / kRoPly)},
  };
}

std::string scene_yaml(const WaveCase& c) {
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\nmaterials:\n  m: ") + c.material_yaml +
         "\nsections:\n  s: {ELFORM: 1, IHQ: 4, QM: 0.1, Q1: 1.5, Q2: 0.06}\n"
         "parts:\n  bar: {material: m, section: s, beta: " + c.beta + "}\n"
         "mesh:\n  boxes:\n    - {part: bar, size: [" + std::to_string(kLength) + ", " + std::to_string(kH) + ", " +
         std::to_string(kH) + "], elements: [" + std::to_string(kElements) + ", 1, 1]}\n"
         "node_sets:\n  left: {plane: {axis: x, value: 0}}\n  all_nodes: all\n"
         "boundary_conditions:\n"
         "  - {node_set: all_nodes, fix: [y, z]}\n"
         "  - {node_set: left, velocity: {dofs: [x], value: " + std::to_string(kV0) + "}}\n";
}

// Reference x of element e's centroid.
double centroid_x(const model::Model& m, std::size_t e) {
  double x = 0;
  for (int k = 0; k < 8; ++k) x += m.X[3 * std::size_t(m.blocks[0].conn[8 * e + k])];
  return x / 8;
}

class WaveSpeed : public ::testing::TestWithParam<WaveCase> {};

TEST_P(WaveSpeed, FrontSpeedPlateauStressAndStableStep) {
  const WaveCase wc = GetParam();
  const model::Model model = test::model_from_yaml(scene_yaml(wc), std::string(wc.name) + ".yaml");
  ASSERT_EQ(model.blocks.size(), 1u);
  ASSERT_EQ(model.blocks[0].size(), std::size_t(kElements));
  const double rho = wc.rho, M = wc.modulus, c = std::sqrt(M / rho);
  const double sigma_plateau = -rho * c * kV0;  // analytic stress behind the front
  const double tssfac = model.control.tssfac;

  // (d) Stable step. Unloaded copy: every element at rest, so the step is TSSFAC h / c_max exactly
  // (cube: V / A_max = h). The solver finds c_max by a sphere search accurate to 1e-10 in modulus;
  // 1e-9 covers it and round-off.
  {
    model::Model rest = model;
    for (auto& curve : rest.curves) std::fill(curve.y.begin(), curve.y.end(), 0.0);
    const solver::Solver s0(rest);
    EXPECT_NEAR(s0.state().dt_next_half, tssfac * kH / wc.c_max, 1e-9 * tssfac * kH / wc.c_max);
  }
  solver::Solver s(model);
  {
    // Loaded: element 1 is compressed at tr D = -v0 / h by the pushed end, so LS-DYNA's step with
    // bulk viscosity applies: h / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 h |tr D| (c = c_max).
    const double Q = kQ2 * wc.c_max + kQ1 * kH * (kV0 / kH);
    const double dt = tssfac * kH / (Q + std::sqrt(Q * Q + wc.c_max * wc.c_max));
    EXPECT_NEAR(s.state().dt_next_half, dt, 1e-9 * dt);
    std::cout << "[" << wc.name << "] stable step " << s.state().dt_next_half << " s (h / c_max = " << kH / wc.c_max
              << " s); first-step Courant number along the bar c dt / h = " << c * s.state().dt_next_half / kH << "\n";
  }

  // Stations: elements whose centroids are nearest L/4, L/2 (arrival) and the plateau window.
  const std::size_t ne = model.blocks[0].size();
  auto element_at = [&](double x) {
    std::size_t best = 0;
    for (std::size_t e = 0; e < ne; ++e)
      if (std::abs(centroid_x(model, e) - x) < std::abs(centroid_x(model, best) - x)) best = e;
    return best;
  };
  const std::size_t e1 = element_at(0.25 * kLength), e2 = element_at(0.5 * kLength);
  const double x1 = centroid_x(model, e1), x2 = centroid_x(model, e2);
  const auto& stress = s.state().blocks[0].stress;  // one point per element, xx first
  const double threshold = 0.5 * sigma_plateau;
  double t1 = -1, t2 = -1;
  double prev1 = 0, prev2 = 0, t_prev = 0;
  // Front at 0.75 L at the end: the reflection from the free right end is far away.
  const double t_end = 0.75 * kLength / c;
  const auto wall0 = std::chrono::steady_clock::now();
  while (s.state().time < t_end) {
    s.step();
    const double t = s.state().time, s1 = stress[6 * e1], s2 = stress[6 * e2];
    // First time the element stress passes half the plateau (compression: from above to below).
    if (t1 < 0 && s1 <= threshold) t1 = t_prev + (t - t_prev) * (prev1 - threshold) / (prev1 - s1);
    if (t2 < 0 && s2 <= threshold) t2 = t_prev + (t - t_prev) * (prev2 - threshold) / (prev2 - s2);
    prev1 = s1, prev2 = s2, t_prev = t;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  ASSERT_GT(t1, 0) << "front never reached x = " << x1;
  ASSERT_GT(t2, 0) << "front never reached x = " << x2;

  // (c) Plateau: mean and extremes over elements from 0.1 L to 0.6 L at t_end (front at 0.75 L,
  // so the window ends ~60 elements behind it and starts 40 elements from the loaded end).
  double sum = 0, lo = 1e300, hi = -1e300;
  int count = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    const double x = centroid_x(model, e);
    if (x < 0.1 * kLength || x > 0.6 * kLength) continue;
    sum += stress[6 * e];
    lo = std::min(lo, stress[6 * e]);
    hi = std::max(hi, stress[6 * e]);
    ++count;
  }
  const double plateau = sum / count;

  // Reference including the leading geometric nonlinearity (strain e = -v0/c is 1e-4 to 4e-4, so
  // this is a 1e-4 effect, kept because the plateau tolerance below is tighter). In uniaxial strain
  // with stretch lambda = 1 + e the two stress updates give sigma = M (e + beta e^2 + O(e^3)):
  //   MAT_001 hypoelastic, D = lambda'/lambda: sigma = M ln(lambda)             -> beta = -1/2;
  //   MAT_002 total Lagrangian: sigma = F S F^T/J = lambda M (lambda^2 - 1)/2     -> beta = +3/2.
  // The jump conditions (Lagrangian) sigma = -rho0 U v0, v0 = -U e, with sigma(e)/e = M (1 + beta e)
  // give U = c (1 + beta e / 2) and sigma = -rho0 c v0 (1 + beta e / 2); a compression fan instead of
  // a shock (beta > 0) differs only at O(e^2). (The first Piola stress P_xx = J sigma_xx / lambda
  // equals sigma_xx in uniaxial strain, so the Cauchy element stress is the right quantity.)
  const double beta = model.materials[0].kind == model::MaterialKind::IsotropicElastic ? -0.5 : 1.5;
  const double e = -kV0 / c;
  const double U = c * (1 + 0.5 * beta * e);
  const double sigma_ref = -rho * U * kV0;

  const double err_arrival = (t2 - x2 / U) / (x2 / U);
  const double c_measured = (x2 - x1) / (t2 - t1);
  const double err_speed = (c_measured - U) / U;
  const double err_plateau = (plateau - sigma_ref) / sigma_ref;
  const double err_plateau_linear = (plateau - sigma_plateau) / sigma_plateau;
  const double ripple = std::max(hi - plateau, plateau - lo) / std::abs(sigma_plateau);
  std::cout << std::setprecision(6) << "[" << wc.name << "] c = " << c << " m/s (finite-strain U = " << U
            << "), rho c v0 = " << -sigma_plateau << " Pa\n  arrival at x = " << x2 << ": " << t2
            << " s vs x/U = " << x2 / U << " s: error " << err_arrival << " = " << err_arrival * x2 / kH
            << " h\n  front speed from stations " << x1 << ", " << x2 << ": " << c_measured << " m/s: error "
            << err_speed << " (against c: " << (c_measured - c) / c << ")\n  plateau over " << count
            << " elements " << plateau << " Pa: error " << err_plateau << " (against rho c v0: " << err_plateau_linear
            << "), ripple max |sigma - mean| " << ripple << " of rho c v0\n  " << s.state().cycle
            << " cycles, wall " << wall << " s\n";
  RecordProperty("arrival_error", std::to_string(err_arrival));
  RecordProperty("speed_error", std::to_string(err_speed));
  RecordProperty("plateau_error", std::to_string(err_plateau));
  RecordProperty("cycles", std::to_string(s.state().cycle));
  RecordProperty("wall_s", std::to_string(wall));

  // (a) The half-level point of the front moves at U (the long-wave limit of the lumped-mass
  // central-difference lattice is exact), but its position carries an offset of order one element:
  // start-up (the end node, mass rho A h / 2, is accelerated impulsively, putting the mean front up
  // to h/2 ahead while the first element's stress ramps up over a few cycles) and the front's
  // shape: the linear bulk viscosity spreads it diffusively, symmetrically, over
  // sqrt(4 Q2 h c_max x / c) ~ 7 h (steel) to ~13 h (fibre across: c_max / c ~ 3.7) at x = 200 h,
  // which does not move the half level, while lattice dispersion (coefficient 1 - Courant^2, ~0.95
  // for the fibre-across case) adds an Airy tail of scale (x (1 - C^2) h^2 / 8)^(1/3) ~ 3 h whose
  // half level sits a fraction of that off. Bound: 1 h at x = 200 h, i.e. 0.5 %.
  EXPECT_LT(std::abs(err_arrival), 1.0 * kH / x2);
  // (b) The start-up offset cancels between two stations 99 h apart; what remains is the change of
  // the dispersive offset between them (Airy scale 2.3 h -> 2.9 h for the fibre-across case, a
  // fraction of that difference): 0.25 h over 99 h = 0.25 %.
  EXPECT_LT(std::abs(err_speed), 0.25 * kH / (x2 - x1));
  // (c) The jump is fixed by momentum balance once the front is steady; the 200-element mean
  // averages out the ringing behind the front (damped by the linear q; its peak |sigma - mean| is
  // printed as ripple). Residuals: O(e^2) ~ 1e-7 from the reference, the ringing's residual mean.
  // Bound 1e-4 (the uncorrected finite-strain term alone is 2.7e-4 for the fibre-across bar, so
  // this resolves the constitutive update's large-strain form).
  EXPECT_LT(std::abs(err_plateau), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Bar, WaveSpeed, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<WaveCase>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace plyimpact
