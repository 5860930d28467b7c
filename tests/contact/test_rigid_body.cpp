// Rigid bodies (*MAT_020, model builder and solver/rigid_body): mass, centre and inertia of the
// lumped nodal masses against hand sums; the initial rigid motion fitted to nodal velocities; a
// torque-free symmetric top against Euler's precession, seen through the slaved nodes; CON1/CON2
// fix translations/rotations; a prescribed velocity is followed exactly.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>

#include "core/error.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

std::string scene(const std::string& card_extra, const std::string& extra) {
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
         "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
         "  rig: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3" + card_extra + "}\n"
         "sections:\n  s: {ELFORM: 2}\n"
         "parts:\n  body: {material: rig, section: s}\n  other: {material: steel, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: body, origin: [0, 0, 0], size: [0.01, 0.02, 0.03], elements: [1, 2, 3]}\n"
         "    - {part: other, origin: [1, 1, 1], size: [0.01, 0.01, 0.01], elements: [2, 2, 2]}\n"
         "node_sets:\n  body_nodes: {part: body}\n" + extra;
}

// Lumped-mass sums over a uniform grid of n elements along an edge of length a (node weights h/2
// at the ends, h inside): sum m x^2 / M about the centre is the trapezoid rule for x^2,
// a^2 / 12 (1 + 2 / n^2). docs/theory.md section 9: the rigid body is the sum of its lumped nodal masses.
double lumped_square(double a, int n) { return a * a / 12 * (1 + 2.0 / (n * n)); }

// Body box 0.01 x 0.02 x 0.03 m, elements 1 x 2 x 3, steel: hand values to round-off (1e-12).
TEST(RigidBody, MassCentreAndInertiaAreThoseOfTheLumpedNodalMasses) {
  const model::Model model = test::model_from_yaml(scene("", ""), "mass.yaml");
  ASSERT_EQ(model.rigid_bodies.size(), 1u);
  const auto& body = model.rigid_bodies[0];
  const double M = 7850 * 0.01 * 0.02 * 0.03;
  const double sx = lumped_square(0.01, 1), sy = lumped_square(0.02, 2), sz = lumped_square(0.03, 3);
  EXPECT_NEAR(body.mass, M, 1e-12 * M);
  EXPECT_NEAR(body.centre[0], 0.005, 1e-15);
  EXPECT_NEAR(body.centre[1], 0.010, 1e-15);
  EXPECT_NEAR(body.centre[2], 0.015, 1e-15);
  const double want[9] = {M * (sy + sz), 0, 0, 0, M * (sx + sz), 0, 0, 0, M * (sx + sy)};
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(body.inertia[k], want[k], 1e-12 * M * (sy + sz)) << "inertia " << k;
}

// Nodal initial velocities that are not a rigid motion (bottom face -V, top face +V along x, the
// layers between at rest) become the rigid motion that carries the same momentum and angular
// momentum: v_cm = 0, omega_y = h_y / I_yy with h_y = sum m r_z v_x = 2 (M/6) (c/2) V (each end
// layer holds M/6 of the mass with three elements along z). The slaved nodes start with
// v_cm + omega x r. Hand values, to round-off.
TEST(RigidBody, InitialSpinIsTheRigidMotionWithTheNodesMomentum) {
  const double V = 2.0;
  const model::Model model = test::model_from_yaml(
      scene("", "  top: {plane: {axis: z, value: 0.03}}\n  bottom: {plane: {axis: z, value: 0}}\n"
                "initial_velocity:\n  - {node_set: top, velocity: [2, 0, 0]}\n"
                "  - {node_set: bottom, velocity: [-2, 0, 0]}\n"),
      "spin0.yaml");
  const auto& body = model.rigid_bodies[0];
  const double M = 7850 * 0.01 * 0.02 * 0.03;
  const double wy = 2 * (M / 6) * 0.015 * V / (M * (lumped_square(0.01, 1) + lumped_square(0.03, 3)));
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(body.velocity[d], 0.0, 1e-12);
  EXPECT_NEAR(body.angular_velocity[0], 0.0, 1e-9);
  EXPECT_NEAR(body.angular_velocity[1], wy, 1e-12 * wy);
  EXPECT_NEAR(body.angular_velocity[2], 0.0, 1e-9);
  for (Index n : body.nodes) {  // v = omega x r, r from the centre (0.005, 0.01, 0.015)
    const double rx = model.X[3 * n] - 0.005, rz = model.X[3 * n + 2] - 0.015;
    EXPECT_NEAR(model.v0[3 * n], wy * rz, 1e-12 * wy * 0.03);
    EXPECT_NEAR(model.v0[3 * n + 1], 0.0, 1e-12 * wy * 0.03);
    EXPECT_NEAR(model.v0[3 * n + 2], -wy * rx, 1e-12 * wy * 0.03);
  }
}

// Torque-free symmetric top, checked through the slaved nodes only (not the integrator's own
// angular momentum): a 0.02 x 0.02 x 0.04 m box (2 x 2 x 4 elements; I1 = I2 = M (s_x + s_z),
// I3 = 2 M s_x with the lumped sums above) spun at omega0 = (300, 0, 200) rad/s with a drift.
// Analytic motion (Euler): H = I omega0 stays fixed in space and the symmetry axis precesses about
// it at |H| / I1 (316 rad/s: one turn in 0.02 s).
// - H from the nodes: sum m r x v with r at the mid-step positions and v the chord velocities is
//   I(t^{n+1/2}) omega^{n+1/2} to second order, while the update takes omega^{n+1/2} from I(t^n):
//   the two differ by at most dt |omega| / 2 relative (1.4e-4 here), an offset that must not grow.
// - Axis from two nodes on it: the same choice gives a first-order phase error of about
//   T dt |omega| Omega / 2 ~ 9e-4 rad after T = 0.02 s (dt 0.76 us, Omega the precession rate).
// - Centre of mass: uniform motion, to round-off; rigidity: distances between nodes kept.
TEST(RigidBody, TorqueFreeSymmetricTopPrecessesAsEuler) {
  const std::string yaml = std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
      "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "  rig: {card: MAT_020, RO: 7850, E: 210e9, PR: 0.3}\nsections:\n  s: {ELFORM: 2}\n"
      "parts:\n  body: {material: rig, section: s}\n  other: {material: steel, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: body, origin: [0, 0, 0], size: [0.02, 0.02, 0.04], elements: [2, 2, 4]}\n"
      "    - {part: other, origin: [1, 1, 1], size: [0.01, 0.01, 0.01], elements: [2, 2, 2]}\n";
  model::Model model = test::model_from_yaml(yaml, "top.yaml");
  ASSERT_EQ(model.rigid_bodies.size(), 1u);
  auto& body = model.rigid_bodies[0];
  const Eigen::Vector3d w0(300.0, 0.0, 200.0), vcm(1.0, -2.0, 0.5);
  body.velocity = {vcm[0], vcm[1], vcm[2]};
  body.angular_velocity = {w0[0], w0[1], w0[2]};
  const double M = 7850 * 0.02 * 0.02 * 0.04;
  const double sxy = lumped_square(0.02, 2), sz = lumped_square(0.04, 4);
  const double I1 = M * (sxy + sz), I3 = 2 * M * sxy;
  const Eigen::Vector3d H0(I1 * w0[0], I1 * w0[1], I3 * w0[2]);
  auto node_at = [&](double x, double y, double z) {
    for (Index n : body.nodes)
      if (std::abs(model.X[3 * n] - x) + std::abs(model.X[3 * n + 1] - y) + std::abs(model.X[3 * n + 2] - z) < 1e-9)
        return n;
    ADD_FAILURE() << "no node at (" << x << ", " << y << ", " << z << ")";
    return Index(0);
  };
  const Index bottom = node_at(0.01, 0.01, 0), top = node_at(0.01, 0.01, 0.04);
  solver::Solver solver(model);
  const double T = 0.02;
  double worst_h = 0;
  std::vector<double> x_prev = solver.state().x;
  while (solver.state().time < T) {
    x_prev = solver.state().x;
    solver.step();
    const auto& x = solver.state().x;
    const auto& v = solver.state().v;
    Eigen::Vector3d c = Eigen::Vector3d::Zero(), h = Eigen::Vector3d::Zero();
    for (Index n : body.nodes)
      c += model.mass[n] * 0.5 * (Eigen::Vector3d(&x[3 * n]) + Eigen::Vector3d(&x_prev[3 * n])) / M;
    for (Index n : body.nodes) {
      const Eigen::Vector3d r = 0.5 * (Eigen::Vector3d(&x[3 * n]) + Eigen::Vector3d(&x_prev[3 * n])) - c;
      h += model.mass[n] * r.cross(Eigen::Vector3d(&v[3 * n]));
    }
    worst_h = std::max(worst_h, (h - H0).norm() / H0.norm());
  }
  const double t = solver.state().time;
  const auto& x = solver.state().x;
  const Eigen::Vector3d axis = (Eigen::Vector3d(&x[3 * top]) - Eigen::Vector3d(&x[3 * bottom])).normalized();
  const Eigen::Vector3d want = Eigen::AngleAxisd(H0.norm() / I1 * t, H0.normalized()) * Eigen::Vector3d::UnitZ();
  std::cout << "symmetric top: max |H_nodes - H0| / |H0| " << worst_h << ", axis error " << (axis - want).norm()
            << " after " << H0.norm() / I1 * t << " rad of precession\n";
  const double dt = t / double(solver.state().cycle), wn = w0.norm();
  EXPECT_LT(worst_h, dt * wn / 2);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(axis[d], want[d], t * dt * wn * H0.norm() / I1 / 2) << "axis component " << d;
  const auto& s = solver.rigid_bodies()[0];
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(s.x[d], (d == 2 ? 0.02 : 0.01) + vcm[d] * t, 1e-12);
  auto dist = [&](Index a, Index b) { return (Eigen::Vector3d(&x[3 * a]) - Eigen::Vector3d(&x[3 * b])).norm(); };
  EXPECT_NEAR(dist(body.nodes.front(), body.nodes.back()),
              (Eigen::Vector3d(&model.X[3 * body.nodes.front()]) - Eigen::Vector3d(&model.X[3 * body.nodes.back()])).norm(),
              1e-12);
}

TEST(RigidBody, CardConstraintsAndPrescribedVelocity) {
  // CON1 = 4 (x and y fixed), CON2 = 7 (no rotation); z prescribed at 3 m/s; gravity acts along x.
  const model::Model model = test::model_from_yaml(
      scene(", CMO: 1, CON1: 4, CON2: 7",
            "gravity: [9.81, 0, 0]\nrigid_bodies:\n  - {part: body, velocity: {dofs: [z], value: 3}}\n"),
      "constrained.yaml");
  solver::Solver solver(model);
  const auto x0 = solver.rigid_bodies()[0].x;
  test::run_until(solver, 1e-3);
  const auto& s = solver.rigid_bodies()[0];
  EXPECT_NEAR(s.x[0], x0[0], 1e-15);
  EXPECT_NEAR(s.x[1], x0[1], 1e-15);
  EXPECT_NEAR(s.x[2], x0[2] + 3e-3, 1e-12);
  EXPECT_EQ(s.omega[0], 0.0);
}

TEST(RigidBody, BadInputIsRefused) {
  EXPECT_THROW(test::model_from_yaml(scene(", CON1: 4", ""), "bad.yaml"), InputError);  // CON1 without CMO
  EXPECT_THROW(test::model_from_yaml(scene("", "boundary_conditions:\n  - {node_set: body_nodes, fix: [x]}\n"),
                                     "bad2.yaml"),
               InputError);
  EXPECT_THROW(test::model_from_yaml(scene("", "rigid_bodies:\n  - {part: other}\n"), "bad3.yaml"), InputError);
}

}  // namespace
}  // namespace plyimpact
