// The Hertz impact scene of test_hertz_impact (see there for the set-up and the reference): a
// rigid spherical cap on a graded elastic block, quarter model, built mesh by mesh.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support.hpp"

namespace plyimpact::test::hertz {

constexpr double kE = 70e9, kNu = 0.3, kRho = 2700;
constexpr double kR = 0.01, kMass = 8.2e-3, kV0 = 10.0;
constexpr double kGap0 = 1e-6;   // initial gap between the pole and the block (0.1 us of approach)
constexpr double kSlsfac = 0.5, kTssfac = 0.9;  // SLSFAC of the convergence test

struct Hertz {
  double e_star = kE / (1 - kNu * kNu);
  double d_max = std::pow(15 * kMass * kV0 * kV0 / (16 * e_star * std::sqrt(kR)), 0.4);
  double f_max = 4.0 / 3.0 * e_star * std::sqrt(kR) * std::pow(d_max, 1.5);
  double t_c = 2.9432 * std::pow(kMass * kMass / (e_star * e_star * kR * kV0), 0.2);
  double a = std::sqrt(kR * d_max);
};

// Node coordinates along one axis: uniform h up to `fine`, then growing by `ratio` up to `length`.
inline std::vector<double> axis(double h, double fine, double length, double ratio) {
  std::vector<double> c{0.0};
  while (c.back() < fine - 1e-9 * h) c.push_back(c.back() + h);
  double s = h;
  while (c.back() < length) {
    s *= ratio;
    c.push_back(c.back() + s);
  }
  return c;
}

inline std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

struct Result {
  double d_max = 0, f_max = 0, t_c = 0, wall = 0, energy_ratio_err = 0, dt = 0;
  std::size_t elements = 0;
  long cycles = 0;
};

// The model at a/h = per_a with the contact's SLSFAC.
inline model::Model build(int per_a, double slsfac = kSlsfac) {
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
      "SLSFAC: " + num(slsfac) + "}\n";
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
  return model;
}

// The impact until separation: peak indentation and force, contact duration, energy.
inline Result run(const model::Model& model) {
  const Hertz hz;
  Result r;
  r.elements = model.num_elements();
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

}  // namespace plyimpact::test::hertz
