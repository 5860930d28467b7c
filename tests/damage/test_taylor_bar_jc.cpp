// Taylor bar with *MAT_015 (Johnson-Cook, adiabatic heating) and *EOS_GRUNEISEN against a published
// test: an OFHC copper cylinder, L0 = 25.4 mm, D0 = 7.62 mm, fired at 190 m/s at room temperature
// (295 K) against a rigid anvil. Recovered shape (Zerilli & Armstrong, J. Appl. Phys. 61 (1987) 1816,
// the cylinder-impact test of their copper figure, as digitised in B. Banerjee's collection of
// high-rate data, github.com/bbanerjee/HighRateExptData, TaylorData/DAT/CuZerilli.dat): final
// length 16.2 mm, impact-face diameter 13.56 mm (the same collection gives 18.69 / 10.67 mm at
// 146 m/s and 19.56 / 9.91 mm at 130 m/s for the companion tests).
// Material: Johnson & Cook's OFHC copper (Johnson & Cook 1983, 7th Int. Symp. Ballistics, Table 1):
// A 90 MPa, B 292 MPa, N 0.31, C 0.025 (EPSO 1/s), M 1.09, TM 1356 K, CP 383 J/(kg K), G 46 GPa,
// rho 8960 kg/m^3; Gruneisen EOS of copper (Steinberg 1996: C 3940 m/s, S1 1.489, GAMAO 2.02, A 0.47).
// Johnson & Cook fitted these constants to torsion and Hopkinson-bar data, not to this test; the
// cylinder tests are the usual check of how well they carry over.
// Model: quarter O-grid (two symmetry planes), ELFORM 1 with IHQ 1 (the viscous form; the stiffness
// forms resist the mushroom, see test_taylor_bar.cpp), frictionless *RIGIDWALL_PLANAR, TQC = 1
// (all plastic work heats: *MAT_015 has no Taylor-Quinney field).
// Measured (this machine, quarter model): 1440 hexes: 17.29 mm / 14.35 mm; 567 hexes: 17.30 / 14.11;
// face up to 559 K, energy ratio 0.9995. Our model is converged to well under the gap to the test
// (length -0.06 %, diameter +1.6 % from 567 to 1440 hexes), so the gap, +6.7 % in length and +5.8 %
// in diameter, is the Johnson-Cook fit carried to a test it was not fitted to, plus the anvil's
// friction, which the frictionless wall leaves out (it would hold the face in: smaller diameter).
// The 1987 paper that published the test proposed its model because the Johnson-Cook one is too
// stiff for copper in this test; we found no published figure of that error to hold ours against.
// Tolerances:
// - length and face diameter within 8 % of the test: the model-form gap measured here (6.7 %, 5.8 %)
//   with the digitised figure's reading (about 0.1 mm) and our mesh error (below 2 %) on top;
//   a wrong flow stress, rate or thermal term by tens of percent moves them well outside (the
//   bilinear 400 MPa copper of test_taylor_bar.cpp gives 21.6 of 32.4 mm, a different regime);
// - meshes: length within 1 %, diameter within 5 % between the two meshes (measured 0.06 %, 1.6 %);
// - energy: balance within 0.5 %, under 5 % kinetic energy left, the face heated but solid;
// - volume: plastic flow is isochoric; the elastic remainder is below sigma_y / K = 0.3 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "../core/support.hpp"
#include "cylinder_mesh.hpp"
#include "material/johnson_cook.hpp"

namespace plyimpact {
namespace {

constexpr double kL0 = 25.4e-3, kR0 = 3.81e-3, kV0 = 190;
constexpr double kTestLength = 16.2e-3, kTestDiameter = 13.56e-3;

struct Result {
  double length = 0, diameter = 0, energy_ratio = 0, kinetic_fraction = 0, max_temperature = 0, seconds = 0;
  double max_plastic_strain = 0, volume_change = 0;
  long elements = 0;
};

Result run_bar(int n, int k, int nz, double t_end, double v0 = kV0, double mu = 0) {
  const std::string yaml =
      "units: SI\n"
      "control: {termination_time: " + std::to_string(t_end) + "}\n"
      "materials:\n"
      "  cu: {card: MAT_015, RO: 8960, G: 46 GPa, A: 90 MPa, B: 292 MPa, N: 0.31, C: 0.025, EPSO: 1, M: 1.09,\n"
      "       TM: 1356, TR: 295, CP: 383,\n"
      "       eos: {card: EOS_GRUNEISEN, C: 3940, S1: 1.489, GAMAO: 2.02, A: 0.47}}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 1, QM: 0.1}\n"
      "parts:\n  bar: {material: cu, section: s}\n"
      // The box only satisfies the scene reader; the mesh handed to build_model is the O-grid.
      "mesh:\n  boxes: [{part: bar, size: [3.81e-3, 3.81e-3, 25.4e-3], elements: [1, 1, 1]}]\n"
      "node_sets:\n  x0: {plane: {axis: x, value: 0}}\n  y0: {plane: {axis: y, value: 0}}\n"
      "boundary_conditions:\n  - {node_set: x0, fix: [x]}\n  - {node_set: y0, fix: [y]}\n"
      "initial_velocity:\n  - {part: bar, velocity: [0, 0, " + std::to_string(-v0) + "]}\n"
      "rigid_walls:\n  - {name: anvil, point: [0, 0, -0.5e-3], normal: [0, 0, 1], friction: " + std::to_string(mu) + "}\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "taylor_bar_jc.yaml");
  const mesh::Mesh mesh = test::quarter_cylinder(kR0, kL0, n, k, nz);
  const model::Model model = model::build_model(scene, mesh);
  solver::Solver s(model);
  const double ke0 = s.balance().kinetic();
  const auto t0 = std::chrono::steady_clock::now();
  test::run_until(s, t_end);
  Result r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.elements = long(mesh.num_elements());
  r.energy_ratio = s.energy_ratio();
  r.kinetic_fraction = s.balance().kinetic() / ke0;
  const std::size_t layer = mesh.num_nodes() / std::size_t(nz + 1);
  const auto& x = s.state().x;
  r.length = x[3 * (nz * layer) + 2] - x[2];
  double face = 0;
  for (std::size_t i = 0; i < layer; ++i) face = std::max(face, std::hypot(x[3 * i], x[3 * i + 1]));
  r.diameter = 2 * face;
  r.volume_change = test::hex_volume(x, mesh.hex) / test::hex_volume(mesh.coords, mesh.hex) - 1;
  const auto& hist = s.state().blocks[0].history;
  const double TR = model.materials[0].johnson_cook.TR;
  for (std::size_t e = 0; e < mesh.num_elements(); ++e) {
    const double* h = &hist[e * material::kJohnsonCookHistory];
    r.max_temperature = std::max(r.max_temperature, TR + h[material::jc_history::kTemperatureRise]);
    r.max_plastic_strain = std::max(r.max_plastic_strain, h[material::jc_history::kPlasticStrain]);
  }
  return r;
}

TEST(TaylorBarJohnsonCook, OfhcCopperAt190MetresPerSecondAgainstTheTest) {
  // 2.6 us of flight to the wall, the rear stops at about 60 us; 90 us covers the ring-down.
  const double t_end = 90e-6;
  const Result coarse = run_bar(3, 2, 27, t_end);
  const Result fine = run_bar(4, 3, 36, t_end);
  for (const Result* r : {&coarse, &fine}) {
    std::cout << "JC Taylor bar, " << r->elements << " hexes (quarter), " << r->seconds << " s: final length "
              << r->length * 1e3 << " mm (test " << kTestLength * 1e3 << ", " << 100 * (r->length / kTestLength - 1)
              << " %), face diameter " << r->diameter * 1e3 << " mm (test " << kTestDiameter * 1e3 << ", "
              << 100 * (r->diameter / kTestDiameter - 1) << " %), max temperature " << r->max_temperature
              << " K, max plastic strain " << r->max_plastic_strain << ", energy ratio " << r->energy_ratio
              << ", KE left " << 100 * r->kinetic_fraction << " %, volume change " << 100 * r->volume_change << " %\n";
    EXPECT_NEAR(r->length, kTestLength, 0.08 * kTestLength);
    EXPECT_NEAR(r->diameter, kTestDiameter, 0.08 * kTestDiameter);
    // Plastic flow keeps the volume; what is left is elastic, |dV/V| below sigma_y / K ~ 0.3 %.
    EXPECT_LT(std::abs(r->volume_change), 0.003);
    EXPECT_NEAR(r->energy_ratio, 1.0, 0.005);
    EXPECT_LT(r->kinetic_fraction, 0.05);
    EXPECT_GT(r->max_temperature, 295 + 50);  // the face heats by the plastic work (hundreds of K)
    EXPECT_LT(r->max_temperature, 1356);      // and stays solid
  }
  std::cout << "mesh change coarse -> fine: length " << 100 * (fine.length / coarse.length - 1) << " %, diameter "
            << 100 * (fine.diameter / coarse.diameter - 1) << " %\n";
  EXPECT_NEAR(fine.length, coarse.length, 0.01 * fine.length);
  EXPECT_NEAR(fine.diameter, coarse.diameter, 0.05 * fine.diameter);
}

// The test series the 190 m/s shot belongs to (same bar, same copper, same collection: 130, 146
// and 190 m/s). Two checks that do not depend on the size of the model-form gap:
// - the final length's sensitivity to the impact speed, dL/dV over 130-190 m/s: the test gives
//   -55.9 mm per km/s over a 3.35 mm span read to about 0.1 mm per end, so +-6 % is the reading;
//   with our mesh error (< 1 %) the slope must match within 10 % (measured: 0.3 %). It tells the
//   rate term apart: with C = 0 the slope is 12 % steeper (and the lengths within 2 % of the test),
//   while switching the thermal softening off moves it by 2 % only.
// - the face diameter depends mostly on the anvil's friction, which the test does not report:
//   the measured diameter must lie between our frictionless wall (the face slides freely: an
//   upper bound) and a wall with Coulomb friction 0.5 (a dry steel-on-copper value that nearly
//   holds the face: a lower bound). Friction moves the length by under 2 %.
// The length stays 5.6-6.8 % long at every speed, too stiff rather than too soft: the direction
// Zerilli & Armstrong (1987) reported for Johnson & Cook's copper on these tests, and the C = 0
// run above places it in the rate term C ln(rate), extrapolated here from the torsion and
// Hopkinson-bar rates it was fitted to.
TEST(TaylorBarJohnsonCook, OfhcCopperSeriesSlopeAndFrictionBracket) {
  struct Shot {
    double v, length, diameter;
  };
  const Shot shots[] = {{130, 19.558e-3, 9.906e-3}, {146, 18.694e-3, 10.668e-3}, {190, 16.205e-3, 13.564e-3}};
  const double t_end = 90e-6;
  double length_low = 0, length_high = 0;
  for (const Shot& shot : shots) {
    const Result free_face = run_bar(3, 2, 27, t_end, shot.v, 0.0);
    const Result held_face = run_bar(3, 2, 27, t_end, shot.v, 0.5);
    std::cout << shot.v << " m/s: length " << free_face.length * 1e3 << " mm (test " << shot.length * 1e3 << ", "
              << 100 * (free_face.length / shot.length - 1) << " %), face diameter " << held_face.diameter * 1e3
              << " (friction 0.5) to " << free_face.diameter * 1e3 << " mm (frictionless), test "
              << shot.diameter * 1e3 << " mm\n";
    EXPECT_NEAR(free_face.length, shot.length, 0.08 * shot.length);
    EXPECT_GT(free_face.length, shot.length);  // the published direction: too stiff, not too soft
    EXPECT_LT(held_face.diameter, shot.diameter);
    EXPECT_GT(free_face.diameter, shot.diameter);
    if (shot.v == 130) length_low = free_face.length;
    if (shot.v == 190) length_high = free_face.length;
  }
  const double test_slope = (shots[2].length - shots[0].length) / (shots[2].v - shots[0].v);
  const double slope = (length_high - length_low) / (shots[2].v - shots[0].v);
  std::cout << "dL/dV " << slope * 1e6 << " mm per km/s (test " << test_slope * 1e6 << ")\n";
  EXPECT_NEAR(slope, test_slope, 0.10 * std::abs(test_slope));
}

}  // namespace
}  // namespace plyimpact
