// The directional stable step of anisotropic one-point hexahedra (solver/directional_step.hpp).
//
// Independent answers:
//   - analytic eigenvalues of the constant-strain element: a box of side t along z has the
//     thickness mode omega = 2 c_z / t, c_z^2 = C33 / rho when the in-plane sides are long (the
//     other modes' share falls as (t / h)^2), and an isotropic cube's fastest mode is the
//     dilatation, omega^2 = 12 K / (rho h^2) (Flanagan & Belytschko 1981), faster than L / c's
//     2c / h by sqrt(3K / (lambda + 2 mu)) = 1.36 at nu = 0.3, so the cube keeps L / c;
//   - the stability limit itself: central differences are stable for omega_max dt <= 2. A free ply
//     plate of one-point elements (IHQ 6, QM 1: the stiffest hourglass form the directional step
//     allows) is started with random nodal velocities, so that every mode, hourglass modes
//     included, is excited, and run without bulk viscosity at a fixed step. At 0.98 of the computed
//     step its energy must stay bounded for 20,000 cycles; at 1.05 it must grow by orders of
//     magnitude within them. Both together say the computed step lies within 5 % below the true
//     limit: neither unsafe nor needlessly short. (Measured the same with IHQ 2: bounded at 0.98,
//     1.6e6 at 1.05.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <utility>

#include "hourglass/element_elasticity.hpp"
#include "material/elastic.hpp"
#include "solver/directional_step.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kRho = 1550;

// T800S/M21 ply card (configs/low_velocity_impact.yaml) as *MAT_002, SI units.
std::string ply_scene(double beta_deg, double h, double t, int n, int ihq, int elform = 1) {
  return "units: SI\ncontrol: {termination_time: 1, energy_ratio_limit: 0}\nmaterials:\n"
         "  m: {card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895, PRCB: 0.53,"
         " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
         "sections:\n  s: {ELFORM: " + std::to_string(elform) + ", IHQ: " + std::to_string(ihq) + ", QM: " + std::string(ihq == 6 ? "1" : "0.1") + ", Q1: 0, Q2: 0}\n"
         "parts:\n  p: {material: m, section: s, beta: " + std::to_string(beta_deg) + "}\n"
         "mesh:\n  boxes:\n    - {part: p, size: [" + std::to_string(n * h) + ", " + std::to_string(n * h) + ", " +
         std::to_string(t) + "], elements: [" + std::to_string(n) + ", " + std::to_string(n) + ", 1]}\n";
}

TEST(DirectionalStep, ThinPlyTakesTheThicknessWave) {
  const double t = 0.25e-3;
  for (double beta : {0.0, 45.0, 90.0}) {
    // In-plane sides 100 t: the in-plane modes' share of the largest eigenvalue is below 1e-3.
    const model::Model model = test::model_from_yaml(ply_scene(beta, 100 * t, t, 1, 6), "ply.yaml");
    const auto& blk = model.blocks[0];
    const auto speed = solver::step_wave_speeds(model, blk);
    ASSERT_EQ(speed.size(), 1u);
    const material::Stiffness6 C = hourglass::stiffness_in_material_axes(model.materials[blk.material]);
    const double c33 = std::sqrt(C[6 * 2 + 2] / kRho);
    std::cout << "ply at " << beta << " deg: step wave speed " << speed[0] << " m/s, sqrt(C33/rho) " << c33
              << " m/s, material's fastest " << model.materials[blk.material].wave_speed << " m/s\n";
    EXPECT_NEAR(speed[0] / c33, 1.0, 2e-3);
    EXPECT_LT(speed[0], 0.3 * model.materials[blk.material].wave_speed);
  }
}

TEST(DirectionalStep, IsotropicCubeDilatationIsFasterThanLOverC) {
  const double lambda = 115.4e9, mu = 76.9e9, h = 1e-3;  // steel-like, nu = 0.3
  material::Stiffness6 C{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) C[6 * i + j] = lambda + (i == j ? 2 * mu : 0.0);
    C[6 * (i + 3) + i + 3] = mu;
  }
  double b[3][8];
  const double s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) b[i][k] = s[k][i] / (4 * h);  // mean gradient of a cube of side h
  const double omega2 = 8 * solver::constant_strain_eigenvalue(C, b) / kRho;
  const double bulk = lambda + 2 * mu / 3;
  EXPECT_NEAR(omega2 / (12 * bulk / (kRho * h * h)), 1.0, 1e-12);
}

// Largest |E / E0 - 1| in the first and in the second half of `cycles` at a fixed step `factor`
// times the computed one (infinite once the energy is not finite).
struct Excursion {
  double first = 0, second = 0;
};

Excursion energy_excursion(double beta, double factor, int cycles, int elform = 1) {
  model::Model model = test::model_from_yaml(ply_scene(beta, 2.5e-3, 0.25e-3, 4, 6, elform), "plate.yaml");
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);  // m/s: small strains, linear response
  for (double& v : model.v0) v = u(rng);
  solver::Solver s(model);
  const double dt = factor * s.state().dt_next_half / model.control.tssfac;
  const double e0 = s.state().initial_total_energy;
  Excursion r;
  for (int i = 0; i < cycles; ++i) {
    s.state().dt_next_half = dt;
    s.step();
    const double e = std::abs(s.balance().total() / e0 - 1);
    double& worst = i < cycles / 2 ? r.first : r.second;
    worst = std::isfinite(e) ? std::max(worst, e) : INFINITY;
    if (!(worst < 1e6)) break;
  }
  return r;
}

// Stable: the energy's excursion does not grow from the first to the second half of the run (it is
// the leapfrog's bounded oscillation of modes near the limit, ~0.3 of E0 at 0.98 with random
// velocities, 0.01 at 0.3: it scales with (omega dt)^2). Unstable: it grows by orders of magnitude.
TEST(DirectionalStep, ComputedStepSitsJustBelowTheStabilityLimit) {
  for (double beta : {0.0, 45.0}) {
    const Excursion below = energy_excursion(beta, 0.98, 20000), above = energy_excursion(beta, 1.05, 20000);
    std::cout << "ply plate at " << beta << " deg: energy excursion " << below.first << " then " << below.second
              << " at 0.98 x step; " << above.first << " then " << above.second << " at 1.05 x step\n";
    EXPECT_LT(below.second, 1.1 * below.first) << "bounded at 0.98 of the step";
    EXPECT_LT(below.second, 1.0);
    EXPECT_GT(std::max(above.first, above.second), 1e3) << "unstable at 1.05 of the step";
  }
}

// ELFORM 2 and -2 take their step from the whole element stiffness (24 x 24 eigenvalue): the same
// drive of every mode must be bounded at 0.98 and grow at 1.05.
TEST(DirectionalStep, FullyIntegratedStepSitsJustBelowTheStabilityLimit) {
  for (const auto& [elform, beta] : {std::pair{2, 0.0}, std::pair{2, 45.0}, std::pair{-2, 0.0}, std::pair{-2, 45.0}}) {
    const Excursion below = energy_excursion(beta, 0.98, 20000, elform),
                    above = energy_excursion(beta, 1.05, 20000, elform);
    std::cout << "ELFORM " << elform << " ply plate at " << beta << " deg: energy excursion " << below.first << " then "
              << below.second << " at 0.98 x step; " << above.first << " then " << above.second << " at 1.05 x step\n";
    EXPECT_LT(below.second, 1.1 * below.first) << "bounded at 0.98 of the step";
    EXPECT_LT(below.second, 1.0);
    EXPECT_GT(std::max(above.first, above.second), 1e3) << "unstable at 1.05 of the step";
  }
}

// A thin ELFORM 2 ply's fastest mode is its thickness mode, as the one-point element's: the
// parasitic shear of its bending modes acts over the in-plane lengths.
TEST(DirectionalStep, FullyIntegratedThinPlyTakesTheThicknessWave) {
  const double t = 0.25e-3;
  for (double beta : {0.0, 45.0, 90.0}) {
    const model::Model model = test::model_from_yaml(ply_scene(beta, 100 * t, t, 1, 6, 2), "ply.yaml");
    const auto& blk = model.blocks[0];
    const auto speed = solver::step_wave_speeds(model, blk);
    ASSERT_EQ(speed.size(), 1u);
    const material::Stiffness6 C = hourglass::stiffness_in_material_axes(model.materials[blk.material]);
    EXPECT_NEAR(speed[0] / std::sqrt(C[6 * 2 + 2] / kRho), 1.0, 2e-3);
  }
}

}  // namespace
}  // namespace plyimpact
