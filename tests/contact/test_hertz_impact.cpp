// Hertz impact: a rigid sphere (MAT_020)
// of radius R and mass m hits a thick elastic MAT_001 block at v0. Reference (Johnson, Contact
// Mechanics, 1985, section 11.4; quasi-static Hertz contact of a rigid sphere on an elastic
// half-space, E* = E / (1 - nu^2)):
//   F = (4/3) E* sqrt(R) d^(3/2)
//   d_max = (15 m v0^2 / (16 E* sqrt(R)))^(2/5),  F_max = (4/3) E* sqrt(R) d_max^(3/2),
//   t_c   = 2.9432 (m^2 / (E*^2 R v0))^(1/5)
// Set-up (quarter model, symmetry conditions on x = 0 and y = 0): aluminium-like block E = 70 GPa,
// nu = 0.3, rho = 2700; R = 10 mm, m = 8.2 g (a glass-density sphere; only the mass matters for a
// rigid body), v0 = 10 m/s. Then d_max = 0.100 mm, a = sqrt(R d_max) = 1.00 mm = R / 10 (Hertz's
// small-contact assumption: errors O((a/R)^2) ~ 1 %), F_max = 10.3 kN, t_c = 30.2 us.
// The rigid sphere is the bottom cap of the sphere, built here as a one-element-thick MAT_020 hex
// shell over the block's own fine grid (r <= 1.25 a), its mass set to m / 4 (quarter), x, y and
// the rotations fixed by symmetry. The block (ELFORM 1 with IHQ 3, Flanagan-Belytschko viscous
// hourglass control: the stiffness forms IHQ 4/5 make the graded mesh's long thin elements too
// stiff, IHQ 5 gives +7 % on F_max at a/h = 12; one-point elements cost several times less than ELFORM 2
// for errors of the same size) is a
// tensor-product grid: uniform h over 1.25 a laterally and 0.75 a in depth (the Hertz stress
// field), graded by 1.5 per element out to L = 24 a; bottom fixed, sides free. Meshes: h = a/3,
// a/6, a/12 (3, 6, 12 elements across the contact radius a).
// Contact: automatic surface to surface, SOFT 0, SLSFAC 0.5 (the default 0.1 is a robustness
// choice, not an accuracy one). Time step: the solver combines the element step with the active
// contact springs (solver.cpp, combined_step); the approach runs at the element step. TSSFAC 0.9
// (LS-DYNA's default). The graded block has elements of aspect 130 where the lateral grading
// meets the uniform top layers; they are stable at 0.9 because the bulk viscosity uses the step's
// length L = V / A_max (docs/theory.md section 3; tests/core/test_bulk_viscosity_step.cpp): with
// V^(1/3) their thickness mode would be damped at xi = 1.54, whose explicit limit is 0.30 L/c.
// ELFORM 2 at a/h = 12 still needs TSSFAC 0.7 (it gains energy in the contact zone at 0.8-0.9).
//
// Measured: indentation d = approach of the sphere since its pole reached the block's top surface
// (relative to the fixed base), contact force F = 4 x the z contact force on the quarter sphere,
// contact duration = time with F > 0. Errors against the formulas above, wall time per mesh.
//
// Error sources and tolerance (finest mesh):
//  - Penalty compliance: a block surface node carries k = SLSFAC K A^2 / V = SLSFAC K h, so the
//    penalty layer adds a penetration p h / (SLSFAC K) under the pressure p. At the centre
//    (p0 = 2 E* a / (pi R)) relative to d = a^2 / R: eps = (2 / pi) E* / (SLSFAC K) (h / a) =
//    1.68 h / a, i.e. 14 % at a/h = 12 for one pass; the two-way search adds the sphere's nodes
//    against the block's segments in parallel, which about halves it (7 %). A compliance
//    d = d_H (1 + eps) lowers the effective Hertz constant by (1 + eps)^(3/2); d_max and t_c scale
//    with it to the power -2/5, F_max to +2/5: errors ~ 0.6 eps, about 4 %.
//  - Mesh: the pressure p0 sqrt(1 - r^2 / a^2) over 12 elements per a; the cap is faceted on the
//    same grid, sag h^2 / (8 R) = 0.9 um = 0.9 % of d_max.
//  - Finite block: the fixed base at depth L = 24 a adds (Boussinesq point load, displacement of
//    the half-space at depth L on the axis, F (1 + nu)(3 - 2 nu) / (2 pi E L)) a compliance of
//    0.73 a / L = 3 % of d_H at the peak, i.e. ~ +2 % on d_max and t_c, -2 % on F_max. The block is
//    quasi-static: a P wave crosses L in 4 us, t_c = 30 us (~ 4 round trips); the energy Hertz
//    impact radiates into a half-space (Hunter 1957, 1.04 (v0 / c_0)^(3/5)) is 2.5 %, and here it
//    is reflected back, not lost.
// Together at most ~ 6 %, and the two largest terms (penalty layer, finite block) are compliances
// with known signs: d_max too large, F_max too small. Asserted on every mesh: 0 < d_max error and
// F_max error < 0; on the finest mesh d_max error < 6 % and F_max error > -6 % (measured +0.9 % and
// -2.6 %; +6.5 / -4.6 % at a/h = 3). The same compliances lengthen t_c, but its measured error
// changes sign (+3.1, +1.1, -0.1 %): another effect of about 1 % (the contact duration counted
// from the first to the last cycle with a force) is not in the budget, so t_c keeps the two-sided
// 6 %. The largest of the three errors decreases from mesh to mesh; the energy ratio is within 1 %.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kE = 70e9, kNu = 0.3, kRho = 2700;
constexpr double kR = 0.01, kMass = 8.2e-3, kV0 = 10.0;
constexpr double kGap0 = 1e-6;   // initial gap between the pole and the block (0.1 us of approach)
constexpr double kSlsfac = 0.5, kTssfac = 0.9;

struct Hertz {
  double e_star = kE / (1 - kNu * kNu);
  double d_max = std::pow(15 * kMass * kV0 * kV0 / (16 * e_star * std::sqrt(kR)), 0.4);
  double f_max = 4.0 / 3.0 * e_star * std::sqrt(kR) * std::pow(d_max, 1.5);
  double t_c = 2.9432 * std::pow(kMass * kMass / (e_star * e_star * kR * kV0), 0.2);
  double a = std::sqrt(kR * d_max);
};

// Node coordinates along one axis: uniform h up to `fine`, then growing by `ratio` up to `length`.
std::vector<double> axis(double h, double fine, double length, double ratio) {
  std::vector<double> c{0.0};
  while (c.back() < fine - 1e-9 * h) c.push_back(c.back() + h);
  double s = h;
  while (c.back() < length) {
    s *= ratio;
    c.push_back(c.back() + s);
  }
  return c;
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

struct Result {
  double d_max = 0, f_max = 0, t_c = 0, wall = 0, energy_ratio_err = 0, dt = 0;
  std::size_t elements = 0;
  long cycles = 0;
};

Result run(int per_a) {
  const Hertz hz;
  const double a = hz.a, h = a / per_a;
  const std::vector<double> ax = axis(h, 1.25 * a, 24 * a, 1.5);
  const std::vector<double> az = axis(h, 0.75 * a, 24 * a, 1.5);
  const double L = ax.back(), D = az.back();
  char lbuf[64];
  std::snprintf(lbuf, sizeof lbuf, "%.9g", L);
  const std::string Ls = lbuf;
  std::snprintf(lbuf, sizeof lbuf, "%.9g", -D);
  const std::string Ds = lbuf;
  const std::string yaml =
      std::string("units: SI\ncontrol: {termination_time: 1.0, tssfac: ") + num(kTssfac) + "}\n" +
      "materials:\n  al: {card: MAT_001, RO: 2700, E: 70e9, PR: 0.3}\n"
      "  rig: {card: MAT_020, RO: 2700, E: 7e12, PR: 0.3}\n"   // E: contact stiffness of the cap only
      "sections:\n  s: {ELFORM: 1, IHQ: 3}\n"
      "parts:\n  block: {material: al, section: s}\n  cap: {material: rig, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"   // placeholders: the mesh is built below
      "    - {part: block, size: [1, 1, 1], elements: [1, 1, 1]}\n"
      "    - {part: cap, origin: [0, 0, 2], size: [1, 1, 1], elements: [1, 1, 1]}\n"
      "node_sets:\n"
      "  sym_x: {box: {min: [0, 0, " + Ds + "], max: [0, " + Ls + ", 0]}}\n"
      "  sym_y: {box: {min: [0, 0, " + Ds + "], max: [" + Ls + ", 0, 0]}}\n"
      "  base: {box: {min: [0, 0, " + Ds + "], max: [" + Ls + ", " + Ls + ", " + Ds + "]}}\n"
      "boundary_conditions:\n  - {node_set: sym_x, fix: [x]}\n  - {node_set: sym_y, fix: [y]}\n"
      "  - {node_set: base, fix: [x, y, z]}\n"
      "initial_velocity:\n  - {part: cap, velocity: [0, 0, -10]}\n"
      "rigid_bodies:\n  - {part: cap, fix: [x, y, rx, ry, rz]}\n"
      "contacts:\n  - {name: hertz, type: automatic_surface_to_surface, surfaces: [cap, block], SOFT: 0, "
      "SLSFAC: " + num(kSlsfac) + "}\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "hertz.yaml");
  int block_part = -1, cap_part = -1;
  for (int p = 0; p < int(scene.parts.size()); ++p) (scene.parts[p].name == "block" ? block_part : cap_part) = p;

  mesh::Mesh mesh;
  const std::size_t nx = ax.size(), nz = az.size();
  auto bnode = [&](std::size_t i, std::size_t j, std::size_t k) { return Index((k * nx + j) * nx + i); };
  for (std::size_t k = 0; k < nz; ++k)   // k = 0 at the base (z = -D), k = nz - 1 at the top (z = 0)
    for (std::size_t j = 0; j < nx; ++j)
      for (std::size_t i = 0; i < nx; ++i) mesh.coords.insert(mesh.coords.end(), {ax[i], ax[j], -az[nz - 1 - k]});
  for (std::size_t k = 0; k + 1 < nz; ++k)
    for (std::size_t j = 0; j + 1 < nx; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        mesh.hex.insert(mesh.hex.end(), {bnode(i, j, k), bnode(i + 1, j, k), bnode(i + 1, j + 1, k),
                                         bnode(i, j + 1, k), bnode(i, j, k + 1), bnode(i + 1, j, k + 1),
                                         bnode(i + 1, j + 1, k + 1), bnode(i, j + 1, k + 1)});
        mesh.element_part.push_back(block_part);
      }
  // Rigid cap over the fine grid: bottom on the sphere (pole kGap0 above the block at the origin).
  std::size_t nc = 0;
  while (nc < nx && ax[nc] <= 1.25 * a * (1 + 1e-9)) ++nc;
  const Index offset = Index(mesh.coords.size() / 3);
  auto cnode = [&](std::size_t i, std::size_t j, std::size_t k) { return offset + Index((k * nc + j) * nc + i); };
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t j = 0; j < nc; ++j)
      for (std::size_t i = 0; i < nc; ++i) {
        const double r2 = ax[i] * ax[i] + ax[j] * ax[j];
        const double zb = kGap0 + kR - std::sqrt(kR * kR - r2);
        mesh.coords.insert(mesh.coords.end(), {ax[i], ax[j], zb + k * 0.25 * a});
      }
  for (std::size_t j = 0; j + 1 < nc; ++j)
    for (std::size_t i = 0; i + 1 < nc; ++i) {
      mesh.hex.insert(mesh.hex.end(), {cnode(i, j, 0), cnode(i + 1, j, 0), cnode(i + 1, j + 1, 0), cnode(i, j + 1, 0),
                                       cnode(i, j, 1), cnode(i + 1, j, 1), cnode(i + 1, j + 1, 1),
                                       cnode(i, j + 1, 1)});
      mesh.element_part.push_back(cap_part);
    }
  model::Model model = model::build_model(scene, mesh);
  EXPECT_EQ(model.rigid_bodies.size(), 1u);
  model.rigid_bodies[0].mass = kMass / 4;  // quarter of the sphere; rotations are fixed

  Result r;
  r.elements = mesh.num_elements();
  const auto t0 = std::chrono::steady_clock::now();
  solver::Solver solver(model);
  const double z0 = solver.rigid_bodies()[0].x[2];
  r.dt = solver.state().dt_next_half;
  double t_first = -1, t_last = -1;
  while (solver.state().time < kGap0 / kV0 + 1.5 * hz.t_c) {
    solver.step();
    ++r.cycles;
    const double t = solver.state().time;
    const double f = 4 * solver.rigid_bodies()[0].contact_force[2];
    const double d = z0 - solver.rigid_bodies()[0].x[2] - kGap0;
    r.d_max = std::max(r.d_max, d);
    r.f_max = std::max(r.f_max, f);
    if (f > 0) {
      if (t_first < 0) t_first = t;
      t_last = t;
    }
    r.energy_ratio_err = std::max(r.energy_ratio_err, std::abs(solver.energy_ratio() - 1));
    if (t_first > 0 && f <= 0 && t > t_first + 0.5 * hz.t_c) break;  // separated
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.t_c = t_last - t_first;
  return r;
}

TEST(HertzImpact, RigidSphereOnElasticBlockConvergesToHertz) {
  const Hertz hz;
  std::cout << std::setprecision(4) << "Hertz: a = " << hz.a * 1e3 << " mm, d_max = " << hz.d_max * 1e6
            << " um, F_max = " << hz.f_max << " N, t_c = " << hz.t_c * 1e6 << " us\n";
  const int meshes[] = {3, 6, 12};
  std::vector<double> worst;
  for (int per_a : meshes) {
    const Result r = run(per_a);
    const double ed = r.d_max / hz.d_max - 1, ef = r.f_max / hz.f_max - 1, et = r.t_c / hz.t_c - 1;
    worst.push_back(std::max({std::abs(ed), std::abs(ef), std::abs(et)}));
    std::cout << "  a/h = " << std::setw(2) << per_a << ": " << std::setw(7) << r.elements << " elements, "
              << std::setw(5) << r.cycles << " cycles (dt " << r.dt * 1e9 << " ns), wall " << std::setw(6) << r.wall << " s | d_max "
              << r.d_max * 1e6 << " um (" << std::showpos << 100 * ed << " %), F_max " << std::noshowpos << r.f_max
              << " N (" << std::showpos << 100 * ef << " %), t_c " << std::noshowpos << r.t_c * 1e6 << " us ("
              << std::showpos << 100 * et << std::noshowpos << " %), max |ratio - 1| " << r.energy_ratio_err
              << "\n";
    EXPECT_LT(r.energy_ratio_err, 0.01);
    EXPECT_GT(ed, 0.0) << "the added compliances can only deepen the indentation";
    EXPECT_LT(ef, 0.0) << "the added compliances can only lower the peak force";
    if (per_a == 12) {
      EXPECT_LT(ed, 0.06);
      EXPECT_GT(ef, -0.06);
      EXPECT_LT(std::abs(et), 0.06);
    }
  }
  EXPECT_LT(worst[1], worst[0]);
  EXPECT_LT(worst[2], worst[1]);
}

}  // namespace
}  // namespace plyimpact
