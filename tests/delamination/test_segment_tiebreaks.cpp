// Tiebreak on non-matching meshes: slave nodes tied to points of master segments.
//  - Tying (seed section 7.5.4): a node within a segment's projection and nearer than
//    0.6 (t_master + t_slave) (eq. 7.40) is tied; the others are reported with the reason. On a flat
//    interface the tied point is the node's orthogonal projection, so sum N_k x_k equals the node's
//    in-plane position exactly (round-off), and the tributary areas add up to the tied slave area.
//  - Kinematics: a rigid rotation of both sides gives no opening and no force (the frame turns with
//    the master segment and the accepted gap is held in it); forces conserve momentum to round-off.
//  - Law: a uniform opening below onset gives K_n delta A in total; a monotonic opening to complete
//    separation dissipates G_Ic A (mode I) or G_IIc A (mode II). The tie uses the same law function
//    as the matching pairs, which is exact for any step along a ray (docs/delamination.md), so the
//    tolerance is round-off (1e-9 relative).
//  - Releasing a tie moves its stored energy to the dissipated energy: elastic + dissipated unchanged.
//  - 1 and 2 threads give bit-identical forces and energies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <omp.h>
#include <vector>

#include "cohesive/segment_tiebreaks.hpp"
#include "core/error.hpp"
#include "interface/segment_tying.hpp"

namespace plyimpact {
namespace {

using cohesive::SegmentTiebreaks;
using interface::TyingSurfaces;
using interface::UntiedNode;

// A flat n x n grid of quads over [0, L]^2 at height z; faces outward up (normal +z) or down.
struct Grid {
  std::vector<double> x;       // appended to a shared coordinate array
  std::vector<Index> faces;
  Index first = 0;
};

Grid add_grid(std::vector<double>& x, int n, double L, double z, bool normal_up, double x0 = 0) {
  Grid g;
  g.first = Index(x.size() / 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) x.insert(x.end(), {x0 + L * i / n, L * j / n, z});
  const auto id = [&](int i, int j) { return g.first + Index(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (normal_up) g.faces.insert(g.faces.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      else g.faces.insert(g.faces.end(), {id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  return g;
}

TyingSurfaces surfaces(const Grid& slave, double t_slave, const Grid& master, double t_master) {
  TyingSurfaces s;
  s.slave_faces = slave.faces;
  s.slave_thickness.assign(slave.faces.size() / 4, t_slave);
  s.master_faces = master.faces;
  s.master_thickness.assign(master.faces.size() / 4, t_master);
  return s;
}

cohesive::TractionLawParams law() {
  cohesive::TractionLawParams p;
  p.option = cohesive::TiebreakOption::MixedMode;
  p.NFLS = 60e6;
  p.SFLS = 50e6;
  p.ERATEN = 765;
  p.ERATES = 1250;
  p.CN = 1e14;
  p.CT2CN = 1;
  p.PARAM = 1;
  return p;
}

constexpr double L = 2e-3;  // m, interface side

// Master: the top of a lower body (4 x 4 faces, normal up); slave: the bottom of an upper body
// (3 x 3 faces, normal down), with a gap.
struct TwoGrids {
  std::vector<double> x;
  Grid master, slave;
  explicit TwoGrids(double gap, int n_master = 4, int n_slave = 3, double slave_x0 = 0) {
    master = add_grid(x, n_master, L, 0, true);
    slave = add_grid(x, n_slave, L, gap, false, slave_x0);
  }
};

TEST(SegmentTying, NonMatchingMeshesTieEveryNodeAtItsProjection) {
  TwoGrids g(0.0);
  const auto r = interface::tie_slave_nodes(surfaces(g.slave, 0.5e-3, g.master, 0.5e-3), g.x.data());
  EXPECT_EQ(r.slave_nodes, 16u);
  ASSERT_EQ(r.ties.size(), 16u);
  EXPECT_TRUE(r.untied.empty());
  double area = 0;
  for (const auto& t : r.ties) {
    area += t.area;
    double N[4], xm[3] = {0, 0, 0};
    const double xi = t.xi, eta = t.eta;
    N[0] = 0.25 * (1 - xi) * (1 - eta);
    N[1] = 0.25 * (1 + xi) * (1 - eta);
    N[2] = 0.25 * (1 + xi) * (1 + eta);
    N[3] = 0.25 * (1 - xi) * (1 + eta);
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) xm[i] += N[a] * g.x[3 * std::size_t(t.master[a]) + i];
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(xm[i], g.x[3 * std::size_t(t.slave) + i], 1e-15);
  }
  EXPECT_NEAR(area, L * L, 1e-12 * L * L);
}

TEST(SegmentTying, GapCriterionIsSixTenthsOfTheThicknesses) {
  // t_m = t_s = 0.5 mm: tolerance 0.6 mm.
  for (const double gap : {0.59e-3, 0.61e-3}) {
    TwoGrids g(gap);
    const auto r = interface::tie_slave_nodes(surfaces(g.slave, 0.5e-3, g.master, 0.5e-3), g.x.data());
    if (gap < 0.6e-3) {
      EXPECT_EQ(r.ties.size(), 16u) << gap;
    } else {
      EXPECT_TRUE(r.ties.empty()) << gap;
      ASSERT_EQ(r.untied.size(), 16u);
      EXPECT_EQ(r.untied[0].reason, UntiedNode::Reason::TooFar);
      EXPECT_NEAR(r.untied[0].distance, gap, 1e-15);
      EXPECT_NEAR(r.untied[0].tolerance, 0.6e-3, 1e-15);
      EXPECT_NE(interface::tying_summary(r, g.x.data()).find("farther than 0.6 (t_master + t_slave)"), std::string::npos);
    }
  }
}

TEST(SegmentTying, NodesBeyondTheMasterAreReportedAndCarryNoArea) {
  // Slave shifted by half its size in x: the nodes with x > L lie outside every master projection;
  // the nodes at x = L are tied but only the faces with all corners tied give area.
  TwoGrids g(0.0, 4, 2, 0.5 * L);
  const auto r = interface::tie_slave_nodes(surfaces(g.slave, 0.5e-3, g.master, 0.5e-3), g.x.data());
  std::size_t outside = 0;
  for (const auto& u : r.untied) outside += u.reason == UntiedNode::Reason::OutsideProjection;
  EXPECT_EQ(outside, 3u);  // the column x = 1.5 L
  double area = 0;
  for (const auto& t : r.ties) area += t.area;
  EXPECT_NEAR(area, 0.5 * L * L, 1e-12 * L * L);  // the two faces over the master
  EXPECT_EQ(r.ties.size(), 6u);
}

TEST(SegmentTying, FacesThatDoNotFaceTheMasterAreIgnored) {
  // The slave surface with its normal up (the top of the upper body seen from below) ties nothing.
  std::vector<double> x;
  const Grid master = add_grid(x, 4, L, 0, true);
  const Grid slave = add_grid(x, 3, L, 0.1e-3, true);
  const auto r = interface::tie_slave_nodes(surfaces(slave, 0.5e-3, master, 0.5e-3), x.data());
  EXPECT_EQ(r.slave_nodes, 0u);
  EXPECT_TRUE(r.ties.empty());
}

// Rotation about the axis (1, 1, 1) / sqrt 3 by angle a.
void rotate(std::vector<double>& x, double a) {
  const double k[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  const double c = std::cos(a), s = std::sin(a);
  for (std::size_t n = 0; n < x.size() / 3; ++n) {
    double* p = &x[3 * n];
    const double kp = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
    const double cr[3] = {k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0]};
    for (int i = 0; i < 3; ++i) p[i] = p[i] * c + cr[i] * s + k[i] * kp * (1 - c);
  }
}

SegmentTiebreaks make(const TwoGrids& g, double t = 0.5e-3) {
  const auto r = interface::tie_slave_nodes(surfaces(g.slave, t, g.master, t), g.x.data());
  const std::vector<double> mass(g.x.size() / 3, 1e-6);
  return SegmentTiebreaks(law(), r.ties, g.x.data(), mass.data());
}

TEST(SegmentTiebreaks, RigidRotationWithAGapGivesNoForce) {
  TwoGrids g(0.2e-3);  // an accepted gap of 0.2 mm
  SegmentTiebreaks ties = make(g);
  std::vector<double> x = g.x;
  rotate(x, 0.5 * std::numbers::pi);
  std::vector<double> f(x.size(), 0.0);
  ties.apply(x.data(), f.data());
  for (double v : f) EXPECT_NEAR(v, 0.0, 1e-9 * law().NFLS * L * L);
  EXPECT_EQ(ties.elastic_energy(), ties.elastic_energy());
  EXPECT_LT(ties.elastic_energy(), 1e-18);
}

TEST(SegmentTiebreaks, UniformOpeningBelowOnsetGivesKnDeltaA) {
  TwoGrids g(0.0);
  SegmentTiebreaks ties = make(g);
  std::vector<double> x = g.x;
  const double delta = 0.3 * law().NFLS / law().CN;
  for (std::size_t n = std::size_t(g.slave.first); n < x.size() / 3; ++n) x[3 * n + 2] += delta;
  std::vector<double> f(x.size(), 0.0);
  ties.apply(x.data(), f.data());
  double slave_z = 0, total[3] = {0, 0, 0};
  for (std::size_t n = 0; n < x.size() / 3; ++n) {
    for (int i = 0; i < 3; ++i) total[i] += f[3 * n + i];
    if (Index(n) >= g.slave.first) slave_z += f[3 * n + 2];
  }
  const double expected = law().CN * delta * L * L;
  EXPECT_NEAR(slave_z, -expected, 1e-12 * expected);  // pulls the slave back
  for (double t : total) EXPECT_NEAR(t, 0.0, 1e-12 * expected);
  EXPECT_NEAR(ties.elastic_energy(), 0.5 * law().CN * delta * delta * L * L, 1e-12 * expected * delta);
}

double separate(bool shear) {
  TwoGrids g(0.0);
  SegmentTiebreaks ties = make(g);
  std::vector<double> x = g.x, f(x.size());
  const double step = 0.5e-7;  // m per pass; separation near 2 G / sigma = 25 um (mode I)
  for (int k = 1; k <= 2000; ++k) {
    std::fill(f.begin(), f.end(), 0.0);
    for (std::size_t n = std::size_t(g.slave.first); n < x.size() / 3; ++n) x[3 * n + (shear ? 0 : 2)] += step;
    ties.apply(x.data(), f.data());
  }
  EXPECT_NEAR(ties.separated_area(), L * L, 1e-12 * L * L);
  return ties.dissipated_energy();
}

TEST(SegmentTiebreaks, CompleteSeparationDissipatesTheCriticalEnergy) {
  EXPECT_NEAR(separate(false), law().ERATEN * L * L, 1e-9 * law().ERATEN * L * L);
  EXPECT_NEAR(separate(true), law().ERATES * L * L, 1e-9 * law().ERATES * L * L);
}

TEST(SegmentTiebreaks, ReleaseKeepsTheEnergyInTheBalance) {
  TwoGrids g(0.0);
  SegmentTiebreaks ties = make(g);
  std::vector<double> x = g.x, f(x.size(), 0.0);
  for (std::size_t n = std::size_t(g.slave.first); n < x.size() / 3; ++n) x[3 * n + 2] += 0.2e-6;
  ties.apply(x.data(), f.data());
  const double before = ties.elastic_energy() + ties.dissipated_energy();
  ASSERT_GT(ties.elastic_energy(), 0);
  ties.release(0);
  EXPECT_NEAR(ties.elastic_energy() + ties.dissipated_energy(), before, 1e-15 * before);
  std::fill(f.begin(), f.end(), 0.0);
  ties.apply(x.data(), f.data());
  EXPECT_NEAR(ties.elastic_energy() + ties.dissipated_energy(), before, 1e-12 * before);
  EXPECT_GT(ties.separated_area(), 0);
}

TEST(SegmentTiebreaks, StepOfACornerTieIsTheMatchingPairStep) {
  // Matching meshes: every tie sits on a master corner (N = 1 there), so dt = 2 / sqrt(k A (2 / m)),
  // smallest for the largest area: an interior node, a quarter of four faces.
  TwoGrids g(0.0, 3, 3);
  SegmentTiebreaks ties = make(g);
  const double a_interior = (L / 3) * (L / 3);
  const double expected = 2 / std::sqrt(law().CN * a_interior * 2 / 1e-6);
  EXPECT_NEAR(ties.stable_step(), expected, 1e-12 * expected);
}

TEST(SegmentTiebreaks, BitIdenticalForOneAndTwoThreads) {
  // 64 x 64 slave nodes on a 50 x 50 master: more than two chunks of ties.
  std::vector<double> x;
  const Grid master = add_grid(x, 50, L, 0, true);
  const Grid slave = add_grid(x, 63, L, 0, false);
  const auto r = interface::tie_slave_nodes(surfaces(slave, 0.04e-3, master, 0.04e-3), x.data());
  ASSERT_GT(r.ties.size(), 2048u);
  const std::vector<double> mass(x.size() / 3, 1e-6);
  std::vector<double> moved = x;
  for (std::size_t n = std::size_t(slave.first); n < x.size() / 3; ++n) {
    moved[3 * n] += 1e-6 * std::sin(double(n));
    moved[3 * n + 2] += 2e-7 * (1 + std::cos(double(n)));
  }
  std::vector<std::vector<double>> forces;
  std::vector<double> energies;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    SegmentTiebreaks ties(law(), r.ties, x.data(), mass.data());
    std::vector<double> f(x.size(), 0.0);
    for (int k = 0; k < 3; ++k) ties.apply(moved.data(), f.data());
    forces.push_back(f);
    energies.push_back(ties.elastic_energy() + ties.dissipated_energy());
  }
  omp_set_num_threads(1);
  EXPECT_EQ(forces[0], forces[1]);
  EXPECT_EQ(energies[0], energies[1]);
}

TEST(SegmentTiebreaks, RefusesATieOutsideItsSegment) {
  TwoGrids g(0.0);
  auto r = interface::tie_slave_nodes(surfaces(g.slave, 0.5e-3, g.master, 0.5e-3), g.x.data());
  r.ties[0].xi = 1.5;
  const std::vector<double> mass(g.x.size() / 3, 1e-6);
  EXPECT_THROW(SegmentTiebreaks(law(), r.ties, g.x.data(), mass.data()), InputError);
}

}  // namespace
}  // namespace plyimpact
