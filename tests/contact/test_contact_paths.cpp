// Contact paths not covered elsewhere (contact/penalty_contact), each against an independent answer:
//  - SOFT 2 stiffness value: two single-element cubes (densities rho1, rho2, so segment masses
//    m_i = rho_i h^3 / 2, half the element's) pressed delta = 1e-3 h into each other with
//    DTSTIF, SLSFAC, SFS and SFM all set. Every node of the two facing faces penetrates the other
//    face at a corner by delta (both passes), so the force on the upper cube is
//    4 delta (k_A + k_B), k_A,B = 0.5 SLSFAC {SFS, SFM} m1 m2 / (m1 + m2) / DTSTIF^2 (docs/theory.md section 10
//    section 8.2). One pass, no time integration: to round-off (1e-12).
//  - ENMASS 1: eroding contact, a punch of three elements falls onto a base; one punch element is
//    deleted, which leaves four nodes without elements. With ENMASS 1 they stay in contact as mass
//    points: they never go deeper into the base (measured from the base's current top face below
//    them, which moves away under the punch) than the energy bound delta = v0 sqrt(m / k) (a mass
//    at the closing speed v0 on its penalty spring; the face moving away only lowers it) and bounce off
//    (they end up moving up relative to the free base, which the punch has pushed down); total
//    momentum is conserved to round-off. With ENMASS 0 nothing holds them, so they leave the
//    calculation where they were (solver.hpp, remove_freed_nodes): at rest, never moving again,
//    their kinetic energy 4 m v0^2 / 2 booked as eroded. The punch is side B of the contact
//    (`surfaces: [base, punch]`): an orphan keeps its own side.
//  - Single-surface contact between two stacked boxes (separate bodies), pushed together in
//    uniaxial strain (x, y fixed everywhere; base fixed, top driven down by a slow, smooth velocity
//    ramp). Quasi-static series springs: F = u / (C_blocks + C_contact), C_blocks = (L1 + L2) / (M A)
//    (M: P-wave modulus), C_contact = 1 / (2 k (n + 1)^2) with k = SLSFAC K h per node (SOFT 0,
//    cubes: A^2 / V = h) and both passes acting on every coincident node pair of the (n + 1)^2
//    pairs. One element across (n = 1), so all four pairs are corners and the interface closes
//    uniformly: with n = 2 the penalty puts equal forces on corner, edge and centre nodes (k is
//    per node), whereas a uniform stress needs 1/16, 1/8, 1/4 of the load there, so the faces
//    do not stay flat and the uniform series-spring formula is 5 % off (measured; the penalty
//    force itself matched 2 k delta per pair exactly). Tolerance 1 %: the ramp lasts ~20 periods
//    of the lowest mode (T ~ 1.3 us), so the residual oscillation is of order (T / T_ramp)^2.
//    The VTU point field contact_force (run/frame_builder) must hold +F on the upper box's
//    nodes and -F on the lower box's (to round-off).
//  - A small laminate (`laminate:` section, gmsh) hit by the mesher's rigid surface-only impactor
//    (`impactor:` section, sphere) for a few hundred cycles: the impulse of the contact force on the
//    body equals its momentum change (m dv = F dt, to 1e-9: the same numbers the body integrates),
//    the plate's contact forces are the body's with the opposite sign (to round-off), and the
//    energy ratio stays within 2 % of 1 (penalty work booked by the trapezoid rule, the plate's
//    hourglass control).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <numeric>

#include "contact/penalty_contact.hpp"
#include "mesh/scene_mesher.hpp"
#include "run/frame_builder.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

TEST(Soft2, StiffnessIsHalfSlsfacSfReducedSegmentMassOverDtSquared) {
  constexpr double h = 0.01, rho1 = 7850, rho2 = 2700, dtstif = 2e-7, slsfac = 0.3, sfs = 1.5, sfm = 0.7;
  const std::string yaml = std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
                           "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
                           "  al: {card: MAT_001, RO: 2700, E: 70e9, PR: 0.3}\n"
                           "sections:\n  s: {ELFORM: 2}\n"
                           "parts:\n  lower: {material: steel, section: s}\n  upper: {material: al, section: s}\n"
                           "mesh:\n  merge_nodes: false\n  boxes:\n"
                           "    - {part: lower, size: [0.01, 0.01, 0.01], elements: [1, 1, 1]}\n"
                           "    - {part: upper, origin: [0, 0, 0.01], size: [0.01, 0.01, 0.01], elements: [1, 1, 1]}\n"
                           "contacts:\n  - {name: c, type: automatic_surface_to_surface, surfaces: [lower, upper], "
                           "SOFT: 2, SLSFAC: 0.3, SFS: 1.5, SFM: 0.7, DTSTIF: 2e-7}\n";
  const model::Model model = test::model_from_yaml(yaml, "soft2.yaml");
  const double delta = 1e-3 * h;
  std::vector<double> x = model.X, v(x.size(), 0.0), f(x.size(), 0.0);
  std::vector<char> upper(model.num_nodes(), 0);  // the boxes' nodes at z = h coincide: go by element
  for (Index nd : model.blocks[model.parts[1].block].conn) upper[std::size_t(nd)] = 1;
  // The upper cube has moved delta into the lower one in this step (a penetration that no step's
  // motion made is not a spring: apply offsets it).
  for (std::size_t i = 0; i < model.num_nodes(); ++i)
    if (upper[i]) x[3 * i + 2] -= delta, v[3 * i + 2] = -delta / 1e-9;
  contact::PenaltyContact pc(model, model.contacts[0], x, 1e-9);  // dt_initial unused: DTSTIF given
  pc.apply(x.data(), v.data(), f.data(), 1e-9);
  double f_upper = 0, f_lower = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i) (upper[i] ? f_upper : f_lower) += f[3 * i + 2];
  const double m1 = 0.5 * rho1 * h * h * h, m2 = 0.5 * rho2 * h * h * h, mu = m1 * m2 / (m1 + m2);
  const double k_a = 0.5 * slsfac * sfs * mu / (dtstif * dtstif), k_b = 0.5 * slsfac * sfm * mu / (dtstif * dtstif);
  const double expected = 4 * delta * (k_a + k_b);
  std::cout << "SOFT 2: force on the upper cube " << f_upper << " N, expected " << expected << " N, active "
            << pc.forces().active << "\n";
  EXPECT_EQ(pc.forces().active, 8u);
  EXPECT_NEAR(f_upper, expected, 1e-12 * expected);
  EXPECT_NEAR(f_lower, -expected, 1e-12 * expected);
}

std::string punch_scene(int enmass) {
  // TSSFAC 0.6: a row of single elements (the punch) is beyond its Courant limit at 0.9, like a
  // lone element (0.734 for nu = 0.3), and blows up from round-off within 40 cycles.
  return std::string("units: SI\ncontrol: {termination_time: 1.0, tssfac: 0.6}\n") +
         "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
         "sections:\n  s: {ELFORM: 2}\n"
         "parts:\n  base: {material: steel, section: s}\n  punch: {material: steel, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: base, origin: [0, 0, 0], size: [0.004, 0.004, 0.001], elements: [4, 4, 1]}\n"
         "    - {part: punch, origin: [0.0005, 0.0015, 0.0011], size: [0.003, 0.001, 0.001], elements: [3, 1, 1]}\n"
         "initial_velocity:\n  - {part: punch, velocity: [0, 0, -10]}\n"
         "contacts:\n  - {name: c, type: eroding_surface_to_surface, surfaces: [base, punch], SOFT: 0, ENMASS: " +
         std::to_string(enmass) + "}\n";
}

TEST(Enmass, OrphanNodesStayInContactAsMassPoints) {
  constexpr double v0 = 10.0, top = 0.001;
  for (int enmass : {1, 0}) {
    const model::Model model = test::model_from_yaml(punch_scene(enmass), "enmass.yaml");
    solver::Solver solver(model);
    // Elements: 16 of the base (ids 1-16), then the punch's three (17-19, x fastest); deleting 19
    // (x in [2.5, 3.5] mm) leaves four orphans at x = 3.5 mm.
    solver.delete_elements({19});
    std::vector<Index> orphans;
    for (std::size_t i = 0; i < model.num_nodes(); ++i)
      if (std::abs(model.X[3 * i] - 0.0035) < 1e-9 && model.X[3 * i + 2] > 0.00105) orphans.push_back(Index(i));
    ASSERT_EQ(orphans.size(), 4u);
    auto momentum = [&] {
      double p = 0;
      for (std::size_t i = 0; i < model.num_nodes(); ++i) p += model.mass[i] * solver.state().v[3 * i + 2];
      return p;
    };
    const double p0 = momentum();
    const double m_orphan = model.mass[orphans[0]];
    // The base's top face below an orphan (x = 3.5 mm, y = 1.5 or 2.5 mm lies at the centre of a
    // 1 mm base face): the mean of that face's four corner nodes, for the depth relative to the
    // base, which itself moves and deforms under the punch.
    auto base_node = [&](double X, double Y) {
      for (std::size_t i = 0; i < model.num_nodes(); ++i)
        if (std::abs(model.X[3 * i] - X) + std::abs(model.X[3 * i + 1] - Y) + std::abs(model.X[3 * i + 2] - top) < 1e-9 &&
            model.mass[i] > 0 && i < model.num_nodes() && std::find(orphans.begin(), orphans.end(), Index(i)) == orphans.end())
          return i;
      ADD_FAILURE() << "no base node at (" << X << ", " << Y << ")";
      return std::size_t(0);
    };
    std::vector<std::pair<Index, std::array<std::size_t, 4>>> below;
    for (Index n : orphans)
      if (model.X[3 * std::size_t(n) + 2] < 0.00115) {  // the lower orphans, which meet the base
        const double y0 = model.X[3 * std::size_t(n) + 1] - 0.0005;
        below.push_back({n, {base_node(0.003, y0), base_node(0.004, y0), base_node(0.003, y0 + 0.001),
                             base_node(0.004, y0 + 0.001)}});
      }
    ASSERT_EQ(below.size(), 2u);
    double z_min = 1e9, depth = 0, max_dp = 0;
    // The lowest orphans reach the base after 0.1 mm / 10 m/s = 10 us; run to 30 us.
    while (solver.state().time < 30e-6) {
      solver.step();
      const auto& x = solver.state().x;
      for (Index n : orphans) z_min = std::min(z_min, x[3 * std::size_t(n) + 2]);
      for (const auto& [n, face] : below) {
        double surface = 0;
        for (std::size_t c : face) surface += 0.25 * x[3 * c + 2];
        depth = std::max(depth, surface - x[3 * std::size_t(n) + 2]);
      }
      max_dp = std::max(max_dp, std::abs(momentum() - p0));
    }
    double vz = 0, pb = 0, mb = 0;
    for (Index n : orphans) vz += 0.25 * solver.state().v[3 * std::size_t(n) + 2];
    for (Index n : model.blocks[model.parts[0].block].conn) {  // base, centre-of-mass velocity
      pb += model.mass[std::size_t(n)] * solver.state().v[3 * std::size_t(n) + 2] / 8;
      mb += model.mass[std::size_t(n)] / 8;
    }
    const double v_base = pb / mb;  // (each base node counted once per element it belongs to: fine, the
                                    // base moves almost rigidly; this is a reference, not a test value)
    // Penalty stiffness of an orphan: its own node stiffness (SOFT 0, PENOPT 1: min with the base
    // segment, same material and size: k = 0.1 K h).
    const double K = 210e9 / (3 * (1 - 2 * 0.3)), k = 0.1 * K * 0.001;
    const double bound = v0 * std::sqrt(m_orphan / k);
    std::cout << "ENMASS " << enmass << ": deepest orphan at " << (top - z_min) * 1e6 << " um below the base's original top, "
              << depth * 1e6 << " um into the base (bound " << bound * 1e6 << " um), mean orphan velocity now " << vz
              << " m/s (base " << v_base
              << " m/s), max |dp| / p0 "
              << max_dp / std::abs(p0) << "\n";
    EXPECT_LT(max_dp / std::abs(p0), 1e-12);
    if (enmass == 1) {
      EXPECT_LT(depth, bound);
      EXPECT_GT(vz, v_base);  // bounced off the base (which the punch has set moving down)
    } else {
      EXPECT_EQ(solver.state().removed_node_count(), 4);
      EXPECT_NEAR(solver.state().eroded_kinetic_energy, 4 * 0.5 * m_orphan * v0 * v0, 1e-12 * m_orphan * v0 * v0);
      EXPECT_NEAR(z_min, top + 1e-4, 1e-12);  // the lower orphans stayed where they were removed
      EXPECT_EQ(vz, 0.0);
    }
  }
}

TEST(SingleSurface, StackedBoxesPushedTogetherActAsSeriesSprings) {
  constexpr double h = 0.001, E = 210e9, nu = 0.3;
  constexpr int n = 1;  // elements across; each box n x n x 2 (see the note above on n > 1)
  const std::string yaml = std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
                           "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
                           "sections:\n  s: {ELFORM: 2}\n"
                           "parts:\n  lower: {material: steel, section: s}\n  upper: {material: steel, section: s}\n"
                           "mesh:\n  merge_nodes: false\n  boxes:\n"
                           "    - {part: lower, size: [0.001, 0.001, 0.002], elements: [1, 1, 2]}\n"
                           "    - {part: upper, origin: [0, 0, 0.002], size: [0.001, 0.001, 0.002], elements: [1, 1, 2]}\n"
                           "node_sets:\n  all_nodes: all\n  base: {plane: {axis: z, value: 0}}\n"
                           "  top: {plane: {axis: z, value: 0.004}}\n"
                           "boundary_conditions:\n  - {node_set: all_nodes, fix: [x, y]}\n"
                           "  - {node_set: base, fix: [z]}\n"
                           "  - {node_set: top, velocity: {dofs: [z], curve: [[0, 0], [5e-6, -0.0095], [1e-5, -0.0345], "
                           "[1.5e-5, -0.0655], [2e-5, -0.0905], [2.5e-5, -0.1], [1, -0.1]]}}\n"
                           "contacts:\n  - {name: stack, type: automatic_single_surface, parts: [lower, upper]}\n";
  const model::Model model = test::model_from_yaml(yaml, "stack.yaml");
  solver::Solver solver(model);
  EXPECT_EQ(solver.initial_penetrations()[0].count, 0u);
  std::size_t top_node = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i)
    if (model.X[3 * i + 2] > 0.004 - 1e-9) top_node = i;
  const double K = E / (3 * (1 - 2 * nu)), M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double A = (n * h) * (n * h);
  const double c_blocks = 2 * (2 * h) / (M * A), k = 0.1 * K * h;
  const double c_contact = 1.0 / (2 * k * (n + 1) * (n + 1));
  double max_err = 0, f_end = 0, f_pred_end = 0;
  while (solver.state().time < 50e-6) {
    solver.step();
    if (solver.state().time < 30e-6) continue;
    const double u = model.X[3 * top_node + 2] - solver.state().x[3 * top_node + 2];
    const double f_pred = u / (c_blocks + c_contact);
    f_end = solver.contacts()[0].forces().normal;
    f_pred_end = f_pred;
    max_err = std::max(max_err, std::abs(f_end / f_pred - 1));
  }
  std::cout << "single surface: contact force " << f_end << " N, series-spring prediction " << f_pred_end
            << " N (contact compliance " << c_contact / (c_blocks + c_contact) * 100
            << " % of the total), max relative deviation over 30-50 us " << max_err << ", active "
            << solver.contacts()[0].forces().active << "\n";
  EXPECT_EQ(solver.contacts()[0].forces().active, std::size_t(2 * (n + 1) * (n + 1)));
  EXPECT_LT(max_err, 0.01);
  // Output: the frame's point field contact_force carries the last cycle's contact forces: +F on
  // the upper box's nodes, -F on the lower box's (F = the transmitted normal force), nothing else.
  const output::Frame frame = run::make_frame(solver);
  const output::Field* cf = nullptr;
  for (const auto& fld : frame.point_fields)
    if (fld.name == "contact_force") cf = &fld;
  ASSERT_NE(cf, nullptr);
  ASSERT_EQ(cf->values.size(), 3 * model.num_nodes());
  std::vector<char> upper(model.num_nodes(), 0);
  for (Index nd : model.blocks[model.parts[1].block].conn) upper[std::size_t(nd)] = 1;
  double fz_upper = 0, fz_lower = 0, f_lateral = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i) {
    (upper[i] ? fz_upper : fz_lower) += cf->values[3 * i + 2];
    f_lateral += std::abs(cf->values[3 * i]) + std::abs(cf->values[3 * i + 1]);
  }
  EXPECT_NEAR(fz_upper, f_end, 1e-12 * f_end);
  EXPECT_NEAR(fz_lower, -f_end, 1e-12 * f_end);
  EXPECT_LT(f_lateral, 1e-12 * f_end);
}

TEST(LaminateImpactor, RigidSurfaceImpactorOnSmallLaminate) {
  const std::string yaml =
      "units: mm-t-s-MPa\ncontrol: {termination_time: 1.0}\n"
      "materials:\n  ply: {card: MAT_002, RO: 1.55e-9, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.01895, "
      "PRCA: 0.01895, PRCB: 0.53, GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
      "sections:\n  ply: {ELFORM: 1, IHQ: 2, QM: 0.1}\n"
      "laminate:\n  length: 30\n  width: 30\n  ply_thickness: 0.5\n  stacking: \"[0/90]s\"\n  material: ply\n"
      "  section: ply\n  element_size: 2\n  interfaces: none\n"
      "  supports:\n    window: {window: [24, 24]}\n"
      "impactor:\n  shape: sphere\n  diameter: 10\n  mass: 0.05 kg\n  gap: 0.02\n  velocity: 2 m/s\n"
      "  element_size: 1.5\n  rigid: true\n"
      "contacts:\n  - {name: impact, type: automatic_surface_to_surface, surfaces: [impactor, [ply_1_0, ply_2_90, "
      "ply_3_90, ply_4_0]], SOFT: 1}\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "laminate_impactor.yaml");
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  ASSERT_EQ(model.rigid_bodies.size(), 1u);
  ASSERT_FALSE(model.impactor_quads.empty());
  solver::Solver solver(model);
  const double m = model.rigid_bodies[0].mass;
  const double v_start = solver.rigid_bodies()[0].v[2];
  std::vector<char> on_body(model.num_nodes(), 0);
  for (Index n : model.rigid_bodies[0].nodes) on_body[std::size_t(n)] = 1;
  // Impulse: the body's v^{n+1/2} = v^{n-1/2} + dt^n F^n / m, so sum dt^n F^n / m = v_end - v_start.
  double impulse = 0, max_balance = 0, peak = 0, max_ratio_err = 0;
  int cycles = 0;
  while (cycles < 600) {
    const double dt_n = 0.5 * (solver.state().dt_prev_half + solver.state().dt_next_half);
    solver.step();
    ++cycles;
    const auto& body = solver.rigid_bodies()[0];
    impulse += dt_n * body.force[2];
    const auto& c = solver.contacts()[0];
    // The contact force on the plate nodes (side B) balances the body's (side A resultant).
    double plate = 0;
    for (std::size_t u = 0; u < c.force_nodes().size(); ++u)
      if (!on_body[std::size_t(c.force_nodes()[u])]) plate += c.node_forces()[3 * u + 2];
    max_balance = std::max(max_balance, std::abs(plate + c.forces().resultant[2]));
    peak = std::max(peak, std::abs(c.forces().resultant[2]));
    max_ratio_err = std::max(max_ratio_err, std::abs(solver.energy_ratio() - 1));
  }
  const double dv = solver.rigid_bodies()[0].v[2] - v_start;
  std::cout << "laminate + impactor: " << cycles << " cycles to " << solver.state().time << " s, peak contact force "
            << peak << " N, body dv " << dv << " m/s vs impulse / m " << impulse / m << ", contact energy "
            << solver.balance().value("contact") << " J, max |ratio - 1| " << max_ratio_err << "\n";
  EXPECT_GT(peak, 0.0);
  EXPECT_GT(dv, 0.0);  // the plate slows the body (downward velocity becomes less negative)
  EXPECT_NEAR(dv, impulse / m, 1e-9 * std::abs(v_start));
  EXPECT_LT(max_balance, 1e-9 * peak);
  EXPECT_LT(max_ratio_err, 0.02);
}

}  // namespace
}  // namespace plyimpact
