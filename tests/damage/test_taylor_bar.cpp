// Taylor bar: an elasto-plastic copper cylinder hits a frictionless planar rigid wall (*MAT_003
// bilinear isotropic, ELFORM 1 with LS-DYNA's default hourglass IHQ 1, QM 0.1, and ELFORM 2;
// *RIGIDWALL_PLANAR),
// a quarter model on two symmetry planes.
//
// Problem (ANSYS Mechanical APDL Technology Demonstration Guide, ch. 17 "Metal Bar Impacting a
// Rigid Wall", 17.2 Problem Description, ansyshelp.ansys.com .../ans_tec/tecmetalbarprobdesc.html):
// copper bar, L0 = 32.4 mm, r0 = 3.2 mm, v0 = 227 m/s along its axis, 1 mm from a rigid
// frictionless wall. Density 8930 kg/m^3 is consistent with the same guide's rigid-impact total
// energy, 239.61 J (17.7.1, tecmetalbarresults.html): 0.5 rho pi r0^2 L0 v0^2 = 239.8 J (0.08 %
// off, their meshed volume). The bilinear material (E = 117 GPa, nu = 0.35, sigma_y = 400 MPa,
// E_t = 100 MPa, the data customarily used for this benchmark since Kamoulakos's NAFEMS version)
// is the input of the problem. The published finite-element final length and mushroom radius
// (about 21.4-21.7 mm and 7.0-7.2 mm in the literature) could not be confirmed from a source we can
// cite, so they are NOT asserted; they are printed next to ours for the record.
//
// Independent answer: Taylor's (1948) one-dimensional rigid-plastic theory, extended with the
// linear hardening of the card across the plastic front (as in Lee & Tupper 1954). The rigid rear
// of length X moves at u and decelerates at rho X du/dt = -sigma_y; the plastic front (at h from the
// wall) leaves the material at rest with engineering strain e; mass and momentum across the front:
//   e = u / (u + dh/dt),   sigma_d(e) / (1 - e) - sigma_y = rho u^2 / e,
//   sigma_d = sigma_y + E_p ln(1 / (1 - e)),  E_p = E E_t / (E - E_t);
// dX/dt = -u / e. Integrated until u = 0: final length L1 = X + h (21.25 mm; 20.79 mm without the
// hardening). The theory ignores elasticity (sigma_y/E = 0.3 %), radial inertia and the multiaxial
// flow in the mushroom; its known weakness is the impact face, whose radius it puts at
// r0 / sqrt(1 - e(v0)) = 4.98 mm, far below what 2-D/3-D calculations and experiments show (the
// face keeps spreading after the front has passed). So:
// - final length within 4 % of the 1-D theory. Justification: leaving the hardening out of the
//   same theory moves L1 by 2.2 %, i.e. the model-form uncertainty of a 1-D account of this flow is
//   of that order; plus the discretisation error (below, < 1 %).
// - face radius above the 1-D value, a lower bound (the face keeps at least the strain the front
//   gave it). No independent upper bound is known to us; the radius must instead converge: it may
//   change by at most 3 % between the two meshes.
// - volume: plastic flow is isochoric, so the deformed bar keeps its volume up to elastic strains
//   (below SIGY / K = 0.3 %): the final length and radii must account for the same copper.
// Meshes: O-grid quarter cylinder (n x n core, two n x k ring blocks, nz layers along the axis).
// Measured on this machine (one core), final length / face radius / wall time:
//   n k nz = 2 1 27 (216 hexes):  21.78 mm / 6.80 mm / 0.4 s
//            3 2 40 (840):        21.64    / 7.09    / 3.0 s   <- asserted, coarse
//            4 3 54 (2160):       21.59    / 7.20    / 14 s    <- asserted, fine
//            6 4 80 (6720):       21.55    / 7.26    / 99 s, only at TSSFAC 0.6: at 0.9 the run goes
//                                 unstable at 56 us, at 0.8 a core element on the axis by the face
//                                 inverts at 88 us (the most crushed elements of the bar)
//   ELFORM 2:  2 1 27 (216):      21.62    / 7.18    / 2.6 s   <- asserted, against the fine one
//              3 2 40 (840):      21.56    / 7.23    / 19 s
// A Richardson fit through the three (h ~ 1/n; orders 1.6 and 1.8) puts the converged values at
// 21.49 mm and 7.37 mm: the coarse mesh is 0.7 % long and 3.7 % narrow, the fine one 0.4 % and
// 2.2 %. (The unconfirmed literature values, ~21.4-21.5 mm and ~7.0-7.1 mm, are of that order.)
// The stiffness hourglass forms (IHQ 4/5, Flanagan-Belytschko
// scaling with the elastic rho c^2) resist the mushroom far too much in this flow: at QM 0.1 the
// 840-hex mesh gives 20.28 mm / 4.85 mm (face radius below even the 1-D bound), at QM 0.01 still
// 21.16 / 6.38 mm, and refining moves the radius by 16 %. The viscous forms IHQ 1-3 agree with
// each other (21.63-21.64 mm, 7.02-7.09 mm). Use IHQ 1-3 for metal impactors.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>

#include "../core/support.hpp"
#include "cylinder_mesh.hpp"

namespace plyimpact {
namespace {

constexpr double kRho = 8930, kE = 117e9, kNu = 0.35, kSigy = 400e6, kEt = 100e6;
constexpr double kL0 = 32.4e-3, kR0 = 3.2e-3, kV0 = 227;

struct TaylorPrediction {
  double final_length = 0, stop_time = 0, face_strain = 0;
};

// Strain e behind the front for a rear speed u: the momentum jump, solved by bisection (its left
// side minus right side increases monotonically in e on (0, 1)).
double front_strain(double u, double sigy, double ep) {
  double lo = 1e-14, hi = 1 - 1e-12;
  for (int it = 0; it < 64; ++it) {  // 2^-64: below double precision
    const double e = 0.5 * (lo + hi);
    const double sd = sigy + ep * std::log(1 / (1 - e));
    const double g = sd / (1 - e) - sigy - kRho * u * u / e;
    (g > 0 ? hi : lo) = e;
  }
  return 0.5 * (lo + hi);
}

TaylorPrediction taylor_1d(double sigy, double ep) {
  double X = kL0, u = kV0, h = 0, t = 0;
  const double dt = 5e-10;  // 1.6e5 explicit Euler steps over ~80 us: error ~1e-5 relative (checked at dt/4)
  TaylorPrediction p;
  p.face_strain = front_strain(kV0, sigy, ep);
  while (u > 0) {
    const double e = front_strain(u, sigy, ep);
    const double hdot = u * (1 - e) / e;
    X -= dt * u / e;
    h += dt * hdot;
    u -= dt * sigy / (kRho * X);
    t += dt;
  }
  p.final_length = X + h;
  p.stop_time = t;
  return p;
}

struct TaylorResult {
  double final_length = 0, face_radius = 0, wall_seconds = 0, energy_ratio = 0, kinetic_fraction = 0;
  double volume_change = 0;  // final / initial volume - 1
  long elements = 0, cycles = 0;
};

// ELFORM 1 with IHQ 1 (LS-DYNA's defaults, QM 0.1), or ELFORM 2 (no hourglass control needed).
TaylorResult run_taylor(int n, int k, int nz, int elform, double t_end) {
  const std::string yaml =
      "units: SI\n"
      "control: {termination_time: " + std::to_string(t_end) + "}\n"
      "materials:\n  cu: {card: MAT_003, RO: 8930, E: 117e9, PR: 0.35, SIGY: 400e6, ETAN: 100e6, BETA: 1}\n" +
      (elform == 2 ? "sections:\n  s: {ELFORM: 2}\n" : "sections:\n  s: {ELFORM: 1, IHQ: 1, QM: 0.1}\n") +
      "parts:\n  bar: {material: cu, section: s}\n"
      // The box only satisfies the scene reader; the mesh handed to build_model is the O-grid.
      "mesh:\n  boxes: [{part: bar, size: [3.2e-3, 3.2e-3, 32.4e-3], elements: [1, 1, 1]}]\n"
      "node_sets:\n  x0: {plane: {axis: x, value: 0}}\n  y0: {plane: {axis: y, value: 0}}\n"
      "boundary_conditions:\n  - {node_set: x0, fix: [x]}\n  - {node_set: y0, fix: [y]}\n"
      "initial_velocity:\n  - {part: bar, velocity: [0, 0, -227]}\n"
      "rigid_walls:\n  - {name: anvil, point: [0, 0, -1.0e-3], normal: [0, 0, 1]}\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "taylor_bar.yaml");
  const mesh::Mesh mesh = test::quarter_cylinder(kR0, kL0, n, k, nz);
  const model::Model model = model::build_model(scene, mesh);
  solver::Solver s(model);
  const double ke0 = s.balance().kinetic();
  const auto t0 = std::chrono::steady_clock::now();
  test::run_until(s, t_end);
  TaylorResult r;
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.elements = long(mesh.num_elements());
  r.cycles = s.state().cycle;
  r.energy_ratio = s.energy_ratio();
  r.kinetic_fraction = s.balance().kinetic() / ke0;
  // Final length: rear-face centre minus impact-face centre (both on the axis, node 0 of their
  // layer); face radius: the largest radius of the nodes of the original impact face.
  const std::size_t layer = mesh.num_nodes() / std::size_t(nz + 1);
  const auto& x = s.state().x;
  r.final_length = x[3 * (nz * layer) + 2] - x[2];
  for (std::size_t i = 0; i < layer; ++i) r.face_radius = std::max(r.face_radius, std::hypot(x[3 * i], x[3 * i + 1]));
  r.volume_change = test::hex_volume(x, mesh.hex) / test::hex_volume(mesh.coords, mesh.hex) - 1;
  return r;
}

// Checks the test's own reference (front_strain, taylor_1d), not project code: the answer the
// bar is compared with must itself be right.
TEST(TaylorBar, ReferenceTheoryMatchesItsClosedFormWithoutHardening) {
  // The 1-D theory itself: without hardening, Taylor's relation rho v0^2 / sigma_y = e^2 / (1 - e)
  // at the face has the closed-form root e = (-a + sqrt(a^2 + 4a)) / 2, a = rho v0^2 / sigma_y.
  const double a = kRho * kV0 * kV0 / kSigy;
  EXPECT_NEAR(front_strain(kV0, kSigy, 0), 0.5 * (-a + std::sqrt(a * a + 4 * a)), 1e-12);
  const TaylorPrediction pp = taylor_1d(kSigy, 0), hard = taylor_1d(kSigy, kE * kEt / (kE - kEt));
  std::cout << "1-D theory: perfectly plastic L1 = " << pp.final_length * 1e3 << " mm (stops at " << pp.stop_time * 1e6
            << " us); with the card's hardening L1 = " << hard.final_length * 1e3 << " mm (stops at "
            << hard.stop_time * 1e6 << " us), face radius r0/sqrt(1-e) = "
            << kR0 / std::sqrt(1 - hard.face_strain) * 1e3 << " mm\n";
  EXPECT_GT(hard.final_length, pp.final_length);  // hardening can only stiffen the flow
}

TEST(TaylorBar, CopperBarAgainstTaylorTheory) {
  const TaylorPrediction theory = taylor_1d(kSigy, kE * kEt / (kE - kEt));
  const double r_low = kR0 / std::sqrt(1 - theory.face_strain);
  // End time: 1 mm of flight (4.4 us), then the 1-D theory stops the rear at ~78 us; 105 us leaves
  // time for the elastic ring-down (the length is measured between the faces, wall or no wall).
  const double t_end = 105e-6;
  const TaylorResult coarse = run_taylor(3, 2, 40, 1, t_end);
  const TaylorResult fine = run_taylor(4, 3, 54, 1, t_end);
  const TaylorResult full = run_taylor(2, 1, 27, 2, t_end);  // ELFORM 2, eight points with history each
  for (const auto* r : {&coarse, &fine, &full}) {
    std::cout << "Taylor bar, " << r->elements << " hexes (quarter), " << r->cycles << " cycles, " << r->wall_seconds
              << " s: final length " << r->final_length * 1e3 << " mm (1-D theory " << theory.final_length * 1e3
              << ", difference " << 100 * (r->final_length / theory.final_length - 1) << " %; literature about"
              << " 21.4-21.7, unconfirmed), face radius " << r->face_radius * 1e3 << " mm (1-D lower bound "
              << r_low * 1e3 << "; literature about 7.0-7.2, unconfirmed), energy ratio " << r->energy_ratio
              << ", KE left " << 100 * r->kinetic_fraction << " %, volume change " << 100 * r->volume_change << " %\n";
    EXPECT_NEAR(r->final_length, theory.final_length, 0.04 * theory.final_length);
    EXPECT_GT(r->face_radius, r_low);
    // The frictionless kinematic wall takes out exactly the normal momentum of the nodes it stops and
    // books that as rigid-wall energy; with hourglass and bulk viscosity counted the balance closes
    // to the 3e-4 measured; 0.5 % is the usual bound of an explicit run with this much plastic flow.
    EXPECT_NEAR(r->energy_ratio, 1.0, 0.005);
    EXPECT_LT(r->kinetic_fraction, 0.05);  // nearly all the kinetic energy went into plastic work
    // Plastic flow keeps the volume: length and face radius must describe the same amount of
    // copper (a shortening without the matching spread would show here). What remains is elastic:
    // residual pressures below the yield stress, |dV/V| <= SIGY / K = 0.31 % (measured <= 0.04 %).
    EXPECT_LT(std::abs(r->volume_change), kSigy * 3 * (1 - 2 * kNu) / kE);
  }
  const double dl = fine.final_length / coarse.final_length - 1, dr = fine.face_radius / coarse.face_radius - 1;
  std::cout << "mesh change coarse -> fine: length " << 100 * dl << " %, face radius " << 100 * dr << " %\n";
  // Discretisation: a converging pair changes by less than what we claim for the answer: 1 % on the
  // length (measured 0.25 %), 3 % on the face radius (measured 1.6 %).
  EXPECT_LT(std::abs(dl), 0.01);
  EXPECT_LT(std::abs(dr), 0.03);
  // ELFORM 2 on the 216-hex mesh against ELFORM 1 on the fine one: two formulations must meet at
  // the answer within their discretisation errors (fine ELFORM 1: 0.4 % and 2.2 % from the
  // extrapolated values; measured differences 0.2 % and 0.3 %): 1 % and 3 %.
  std::cout << "ELFORM 2 (216 hexes) against ELFORM 1 (2160): length " << 100 * (full.final_length / fine.final_length - 1)
            << " %, face radius " << 100 * (full.face_radius / fine.face_radius - 1) << " %\n";
  EXPECT_NEAR(full.final_length, fine.final_length, 0.01 * fine.final_length);
  EXPECT_NEAR(full.face_radius, fine.face_radius, 0.03 * fine.face_radius);
}

}  // namespace
}  // namespace plyimpact
