// The node-pair tiebreak kernel: a pair between two masses integrated by central difference (written
// here), its frame from the interface faces, the stable step, thread determinism and restart.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <algorithm>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "cohesive/tiebreak_pairs.hpp"
#include "core/error.hpp"
#include "law_paths.hpp"
#include "pair_patch.hpp"

namespace plyimpact::cohesive {
namespace {

// One pair, nodes 0 (lower) and 1 (upper) at the origin, normal +z.
TiebreakPairsSpec single_pair(double area) {
  TiebreakPairsSpec s;
  s.lower = {0};
  s.upper = {1};
  s.area = {area};
  s.normals = {0, 0, 1};
  return s;
}

struct Balance {
  double max_drift = 0;    // J, largest |KE + elastic + dissipated - reference|
  double bound = 0;        // J, the error bound derived from the run (see run_two_masses)
  double max_momentum = 0; // N s, largest |P - P_0|
  double scheme = 0, kinks = 0;  // the two parts of the bound
};

// Central difference for two point masses joined by the kernel, from velocities v (6 values):
//   a_n = f(x_n)/m;  v_n = v_{n-1/2} + dt/2 a_n;  v_{n+1/2} = v_n + dt/2 a_n;  x_{n+1} = x_n + dt v_{n+1/2}.
// Energy error bound. Between full steps the kinetic energy changes by
//   dKE = 1/2 (F_n + F_{n+1}) . (dx - dt^2 (a_n - a_{n+1}) / 4),
// and the law's dE + dD equals the trapezoid work 1/2 (F_n + F_{n+1}) . dx exactly wherever its
// traction is linear in the opening over the step (the elastic, secant, penalty and softening
// branches all are). So the drift is at most sum |F_n + F_{n+1}| dt^2 |a_n - a_{n+1}| / 8 (the scheme
// term, accumulated from the run) plus, at each step that crosses a kink of the law (onset,
// separation, closing, reopening, stick-slip and back, at most 8 here), the trapezoid error of a
// continuous piecewise-linear traction, |k_1 - k_2| dx^2 / 8 <= k_max A (v_rel dt)^2 / 4.
Balance run_two_masses(TiebreakPairs& pairs, const double mass[2], double v[6], double x[6], double dt, int steps,
                       const std::function<void(int, double*)>& kick = nullptr) {
  Balance b;
  double f[6] = {0};
  pairs.apply(x, v, f, dt);
  double a[6];
  for (int i = 0; i < 6; ++i) a[i] = f[i] / mass[i / 3];
  auto energy = [&](const double* vel) {
    double ke = 0;
    for (int i = 0; i < 6; ++i) ke += 0.5 * mass[i / 3] * vel[i] * vel[i];
    return ke + pairs.elastic_energy() + pairs.dissipated_energy();
  };
  auto momentum = [&](const double* vel, int k) { return mass[0] * vel[k] + mass[1] * vel[3 + k]; };
  double reference = energy(v);
  double p0[3] = {momentum(v, 0), momentum(v, 1), momentum(v, 2)};
  double sum_corr = 0, v_rel_max = 0;
  const double k_max = pairs.law().k_max * pairs.area(0);
  double f_prev[6];
  std::memcpy(f_prev, f, sizeof f);
  for (int n = 0; n < steps; ++n) {
    double vh[6];
    for (int i = 0; i < 6; ++i) vh[i] = v[i] + 0.5 * dt * a[i];
    for (int i = 0; i < 6; ++i) x[i] += dt * vh[i];
    std::fill(f, f + 6, 0.0);
    pairs.apply(x, vh, f, dt);
    double a_new[6];
    for (int i = 0; i < 6; ++i) a_new[i] = f[i] / mass[i / 3];
    for (int i = 0; i < 6; ++i) v[i] = vh[i] + 0.5 * dt * a_new[i];
    double corr = 0;
    for (int i = 0; i < 6; ++i) corr += std::abs(f_prev[i] + f[i]) * std::abs(a[i] - a_new[i]);
    sum_corr += corr * dt * dt / 8;
    v_rel_max = std::max(v_rel_max, std::sqrt(std::pow(v[3] - v[0], 2) + std::pow(v[4] - v[1], 2) + std::pow(v[5] - v[2], 2)));
    std::memcpy(a, a_new, sizeof a);
    std::memcpy(f_prev, f, sizeof f);
    if (kick) {
      const double before = energy(v);
      kick(n, v);  // an external impulse: the energy reference moves with it
      reference += energy(v) - before;
      for (int k = 0; k < 3; ++k) p0[k] = momentum(v, k);
    }
    b.max_drift = std::max(b.max_drift, std::abs(energy(v) - reference));
    for (int k = 0; k < 3; ++k) b.max_momentum = std::max(b.max_momentum, std::abs(momentum(v, k) - p0[k]));
  }
  b.scheme = sum_corr;
  b.kinks = 8 * k_max * (v_rel_max * dt) * (v_rel_max * dt) / 4;
  b.bound = b.scheme + b.kinks;
  return b;
}

// Two 0.25 mm T800S/M21 ply nodes over 1 mm^2 (m = rho A h / 2 each) on the Table 8.6 law, flung
// apart in mixed mode, separated, then thrown back together with sliding: momentum to round-off and
// kinetic + elastic + dissipated conserved within the derived bound.
TEST(TiebreakKernel, TwoMassesConserveMomentumAndEnergyThroughSeparationAndFrictionalContact) {
  auto p = test::table_8_6_option9();
  p.FS = 0.3;
  const double area = 1e-6, m = 1550 * area * 0.25e-3 / 2;
  const double x0[6] = {0, 0, 0, 0, 0, 0};
  const double mass[2] = {m, m};
  TiebreakPairs pairs(p, single_pair(area), x0, mass);
  const double dt = 0.02 * pairs.stable_step();
  double x[6] = {0, 0, 0, 0, 0, 0};
  double v[6] = {-40, 0, -100, 40, 0, 100};  // relative: 80 m/s shear, 200 m/s opening
  int flipped_at = -1;
  double closest = 0;  // smallest normal opening after the flip
  auto kick = [&](int n, double* vel) {
    // Once separated and 20 um apart, reverse the normal velocities: the plies meet again, sliding.
    if (flipped_at < 0 && pairs.damage()[0] >= 1 && x[5] - x[2] > 20e-6) {
      vel[2] = -vel[2];
      vel[5] = -vel[5];
      flipped_at = n;
    }
    if (flipped_at >= 0) closest = std::min(closest, x[5] - x[2]);
  };
  const auto b = run_two_masses(pairs, mass, v, x, dt, 6000, kick);
  ASSERT_GE(flipped_at, 0) << "the pair never separated";
  EXPECT_EQ(pairs.damage()[0], 1.0);
  EXPECT_LT(closest, 0.0) << "the plies should have come back into contact";
  EXPECT_GT(pairs.dissipated_energy(), p.ERATEN * area);  // mixed-mode G_c > G_Ic, plus friction
  EXPECT_LE(b.max_momentum, 1e-12 * m * 200);
  EXPECT_LE(b.max_drift, b.bound) << "bound " << b.bound << " J";
  std::printf("two masses: dt = %.3g s (0.02 of the pair step), energy drift %.3g J, derived bound %.3g J "
              "(scheme %.3g + kinks %.3g), dissipated %.4g J (G_Ic A = %.4g J)\n",
              dt, b.max_drift, b.bound, b.scheme, b.kinks, pairs.dissipated_energy(), p.ERATEN * area);
}

// A separated pair stands for two faces in contact only while its nodes have slid apart by less
// than its tributary width (|u_t| <= sqrt(A)) and it is not pressed deeper than its release depth. Independent
// answer: the penalty K_n A |u_n| inside those limits, nothing beyond them, and the energy the
// spring held booked as dissipated when it is let go (beyond, the "normal
// opening" is a long slide or a separation projected on a turned normal: the default scene's energy
// jumps came from a pair 29 mm apart reading 29 um of compression, and from one 1.25 mm apart
// reading 0.43 mm on a normal 58 degrees off).
TEST(TiebreakKernel, SeparatedPairCarriesContactOnlyWithinReachAndReleaseDepth) {
  const auto p = test::table_8_6_option9();
  const double area = 1e-6, m = 1e-6;  // reach: 1 mm
  const double x0[6] = {0, 0, 0, 0, 0, 0}, mass[2] = {m, m}, v[6] = {};
  TiebreakPairsSpec spec = single_pair(area);
  spec.release_depth = 2e-6;  // m
  TiebreakPairs pairs(p, spec, x0, mass);
  double f[6] = {};
  const double open[6] = {0, 0, 0, 0, 0, 1e-3};  // 1 mm apart: far beyond the law's final opening
  pairs.apply(open, v, f, 1e-9);
  ASSERT_EQ(pairs.damage()[0], 1.0);
  const double kn = pairs.law().kn;
  struct Case {
    double slide, depth;  // m
    bool carries;
  };
  for (const Case c : {Case{0.9e-3, 1e-6, true}, Case{1.1e-3, 1e-6, false}, Case{0.0, 1.9e-6, true},
                       Case{0.0, 2.1e-6, false}}) {
    const double x[6] = {0, 0, 0, c.slide, 0, -c.depth};
    std::fill(f, f + 6, 0.0);
    const double held = pairs.elastic_energy(), dissipated = pairs.dissipated_energy();
    pairs.apply(x, v, f, 1e-9);
    // Let go, the penalty energy it held stays in the balance as dissipated (no friction here).
    if (!c.carries) {
      EXPECT_NEAR(pairs.dissipated_energy() - dissipated, held, 1e-9 * held + 1e-30);
    }
    const double expected = c.carries ? kn * area * c.depth : 0.0;  // N, pushing the upper node up
    EXPECT_NEAR(f[5], expected, 1e-9 * kn * area * c.depth) << "slide " << c.slide << " m, depth " << c.depth << " m";
    EXPECT_NEAR(pairs.elastic_energy(), c.carries ? 0.5 * kn * area * c.depth * c.depth : 0.0,
                1e-6 * kn * area * c.depth * c.depth)
        << "slide " << c.slide << " m, depth " << c.depth << " m";
  }
  // Released for good (its ply eroded away): what it held is booked at once, and it carries
  // nothing from then on, even pressed within reach and depth.
  const double pressed[6] = {0, 0, 0, 0, 0, -1e-6};
  pairs.apply(pressed, v, f, 1e-9);
  const double held = pairs.elastic_energy(), dissipated = pairs.dissipated_energy();
  ASSERT_GT(held, 0.0);
  pairs.release_pair(0);
  EXPECT_NEAR(pairs.dissipated_energy() - dissipated, held, 1e-9 * held);
  std::fill(f, f + 6, 0.0);
  pairs.apply(pressed, v, f, 1e-9);
  EXPECT_EQ(f[5], 0.0);
  EXPECT_EQ(pairs.elastic_energy(), 0.0);
  EXPECT_NEAR(pairs.dissipated_energy() - dissipated, held, 1e-9 * held) << "booked once";
  spec.release_depth = 0;
  EXPECT_THROW(TiebreakPairs(p, spec, x0, mass), InputError);
}

// The pair's stable step is the true limit of central difference for the pair alone: a small
// elastic vibration (shear, the stiffer direction with CT2CN = 2) stays bounded just below it and
// grows just above it.
TEST(TiebreakKernel, StableStepIsTheCentralDifferenceLimitOfThePair) {
  auto p = test::table_8_6_option9();
  p.CT2CN = 2;
  p.SFLS = 120e6;
  const double area = 1e-6, m[2] = {2e-7, 3e-7};
  const double x0[6] = {0, 0, 0, 0, 0, 0};
  TiebreakPairs probe(p, single_pair(area), x0, m);
  const double k = p.CT2CN * p.CN * area;
  EXPECT_NEAR(probe.stable_step(), 2 / std::sqrt(k * (1 / m[0] + 1 / m[1])), 1e-15);
  EXPECT_EQ(probe.stable_step_pair(), 0);
  for (double factor : {0.99, 1.02}) {
    TiebreakPairs pairs(p, single_pair(area), x0, m);
    double x[6] = {0, 0, 0, 1e-8, 0, 0};  // 10 nm shear, far below the 0.6 um onset
    double v[6] = {0, 0, 0, 0, 0, 0};
    const auto b = run_two_masses(pairs, m, v, x, factor * pairs.stable_step(), 400);
    (void)b;
    // Below the limit the discrete oscillation stays within x_0 / sqrt(1 - (omega dt / 2)^2) = 7.1 x_0;
    // above it, it grows until it reaches the onset opening (60 x_0) and damages the pair.
    if (factor < 1) {
      EXPECT_LT(std::abs(x[3] - x[0]), 7.2e-8);
    }
    EXPECT_EQ(pairs.damage()[0] > 0, factor > 1);
  }
}

// A 3 x 3 grid of pairs on a plane tilted 30 degrees: the normal comes from the faces, the
// tributary areas are a quarter of each adjacent face, and opening along the normal is pure mode I.
TEST(TiebreakKernel, FacesGiveTheNormalAndTheTributaryAreas) {
  const double a = 0.5e-3, th = std::numbers::pi / 6;
  const double normal[3] = {0, -std::sin(th), std::cos(th)};  // e_x x e_y'
  auto [s, x] = test::pair_patch_3x3(a, {0, std::cos(th), std::sin(th)});
  std::vector<double> mass(18, 1e-7);
  // The same faces as the mesher gives them: quads of lower-side nodes (here node = pair index).
  std::vector<Index> lower_segments;
  for (Index q : s.faces) lower_segments.push_back(s.lower[q]);
  EXPECT_EQ(pair_faces_from_segments(s.lower, lower_segments), s.faces);
  EXPECT_THROW(pair_faces_from_segments(s.lower, {0, 1, 4, 12}), InputError);  // 12 is an upper node
  const auto p = test::table_8_6_option9();
  TiebreakPairs pairs(p, s, x.data(), mass.data());
  const double full = a * a;
  const double expected_area[9] = {full / 4, full / 2, full / 4, full / 2, full, full / 2, full / 4, full / 2, full / 4};
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(pairs.area(k), expected_area[k], 1e-15 * full);
  const double delta = 0.5 * p.NFLS / p.CN;  // elastic
  for (int q = 0; q < 9; ++q)
    for (int k = 0; k < 3; ++k) x[3 * (9 + q) + k] += delta * normal[k];
  std::vector<double> f(x.size(), 0.0);
  pairs.apply(x.data(), nullptr, f.data(), 0);
  std::vector<PairSample> samples(9);
  pairs.sample(x.data(), samples.data());
  for (int q = 0; q < 9; ++q) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(f[3 * (9 + q) + k], -pairs.area(q) * p.CN * delta * normal[k], 1e-9 * full * p.NFLS);
      EXPECT_EQ(f[3 * q + k], -f[3 * (9 + q) + k]);  // equal and opposite
    }
    EXPECT_NEAR(samples[q].opening[0], delta, 1e-12 * delta);
    EXPECT_NEAR(std::hypot(samples[q].opening[1], samples[q].opening[2]), 0.0, 1e-12 * delta);
    EXPECT_NEAR(samples[q].mixity, 0.0, 1e-20);
  }
  EXPECT_NEAR(pairs.elastic_energy(), 0.5 * p.CN * delta * delta * 4 * full, 1e-12 * p.CN * delta * delta * full);
}

// A pair released because erosion took its ply away no longer moves its neighbours' normals: its
// nodes are wherever the eroded ply left them (here thrown a metre off), so a face with that corner
// keeps the vector area it had when the pair was released. A flat 3 x 3 grid of pairs (normal +z),
// corner pair 0 released and its nodes moved far away, the other pairs opened along z by delta in
// the elastic range: every remaining pair must open in pure mode I with its force along z (to
// round-off), the three that share the cut face (1, 3, 4) included. Recomputing that face turned
// their normals by 125 degrees.
TEST(TiebreakKernel, AReleasedPairsFacesKeepTheirLastShape) {
  const double a = 0.5e-3;
  auto [s, x] = test::pair_patch_3x3(a);
  std::vector<double> mass(18, 1e-7);
  const auto p = test::table_8_6_option9();
  TiebreakPairs pairs(p, s, x.data(), mass.data());
  pairs.release_pair(0);
  for (int node : {0, 9})
    for (int k = 0; k < 3; ++k) x[3 * node + k] = 1.0 + k;
  const double delta = 0.5 * p.NFLS / p.CN;  // elastic
  for (int q = 1; q < 9; ++q) x[3 * (9 + q) + 2] += delta;
  std::vector<double> f(x.size(), 0.0);
  pairs.apply(x.data(), nullptr, f.data(), 0);
  std::vector<PairSample> samples(9);
  pairs.sample(x.data(), samples.data());
  for (int q = 1; q < 9; ++q) {
    EXPECT_NEAR(samples[q].opening[0], delta, 1e-12 * delta) << "pair " << q;
    EXPECT_NEAR(std::hypot(samples[q].opening[1], samples[q].opening[2]), 0.0, 1e-12 * delta) << "pair " << q;
    EXPECT_NEAR(std::hypot(f[3 * (9 + q)], f[3 * (9 + q) + 1]), 0.0, 1e-12 * std::abs(f[3 * (9 + q) + 2])) << "pair " << q;
  }
  EXPECT_EQ(f[0], 0.0);  // the released pair carries nothing
}

// A 64 x 64 grid (4096 pairs, parallel above 2048) driven through damage: forces, energies and
// history are bit-identical with 1 and 2 threads (fixed chunks, summed in order).
// apply() takes the undamaged pairs below every onset in SIMD lanes and the others through the
// law pair by pair. Whatever path a pair takes, its force, damage and largest opening must be the
// law's own to the last bit. Reference: traction_update on each pair's opening, with the frame of
// a flat interface (normal +z: t_1 = +y, t_2 = -x, so the opening is (d_z, d_y, -d_x) and the force
// on the lower node area (-t_2, t_1, t_n), exactly). 2,500 pairs (two full blocks of 1024 and a
// partial one), loaded, then partly unloaded (openings below their maximum, which are above the
// elastic limit: the lanes must keep the maximum) and partly pressed; every fifth pair starts
// separated. Energies: the same sums in the same order, to 1e-12.
// Pairs of one kernel in SIMD lanes and on the general path, against traction_update point by
// point: forces bit for bit, damage and energy. With `own_strengths` every pair has its own NFLS and
// SFLS (0.3 to 1 of the card's, as process_zone_elements gives a graded mesh), and the reference is
// a law made from those strengths alone, so a lane that took a neighbour's elastic limit or law fails.
void check_simd_lanes(bool own_strengths) {
  const int np = 2500;
  TiebreakPairsSpec s;
  std::vector<double> x0(2 * np * 3, 0.0), mass(2 * np, 1e-7);
  for (int p = 0; p < np; ++p) {
    s.lower.push_back(p);
    s.upper.push_back(np + p);
    s.area.push_back(1e-7 * (1 + 0.001 * p));
    s.normals.insert(s.normals.end(), {0, 0, 1});
    x0[3 * p] = x0[3 * (np + p)] = 1e-3 * p;
  }
  const auto params = test::table_8_6_option9();
  std::vector<TractionLaw> own(np, make_traction_law(params));
  if (own_strengths)
    for (int p = 0; p < np; ++p) {
      TractionLawParams q = params;
      q.NFLS *= 0.3 + 0.7 * ((p * 53) % 97) / 96.0;
      q.SFLS *= 0.3 + 0.7 * ((p * 29) % 89) / 88.0;
      s.nfls.push_back(q.NFLS);
      s.sfls.push_back(q.SFLS);
      own[std::size_t(p)] = make_traction_law(q);
    }
  TiebreakPairs pairs(params, s, x0.data(), mass.data());
  if (own_strengths) EXPECT_GT(pairs.laws().num_laws(), 1000u);
  std::vector<PointHistory> h(np);
  for (int p = 0; p < np; p += 5) {
    pairs.separate_pair(std::size_t(p));
    h[std::size_t(p)].damage = 1;
  }
  for (int pass = 0; pass < 2; ++pass) {
    SCOPED_TRACE(pass == 0 ? "loading" : "unloading");
    std::vector<double> x = x0, f(x.size(), 0.0);
    for (int p = 0; p < np; ++p) {  // from 0.1 to 2 onsets, every direction; the second pass 0.7 of it
      const double onset = own[std::size_t(p)].delta_n0;  // 0.6 um at the card's NFLS
      const double scale = (pass == 0 ? 1.0 : 0.7) * onset * (0.1 + 1.9 * ((p * 37) % 101) / 100.0);
      const double d[3] = {scale * std::sin(0.7 * p), scale * std::cos(1.3 * p), scale * std::sin(0.3 * p + 1)};
      for (int i = 0; i < 3; ++i) x[3 * (np + p) + i] += d[i];
    }
    pairs.apply(x.data(), nullptr, f.data(), 0.0);
    double elastic = 0;
    for (int p = 0; p < np; ++p) {
      const std::size_t lo = 3 * std::size_t(p), up = 3 * std::size_t(np + p);
      const double d[3] = {x[up] - x[lo] - 0.0, x[up + 1] - x[lo + 1] - 0.0, x[up + 2] - x[lo + 2] - 0.0};
      const double u[3] = {d[2], d[1], -d[0]};
      PointResponse r;
      traction_update(own[std::size_t(p)], u, h[std::size_t(p)], r);
      const double area = pairs.area(std::size_t(p));
      const double expected[3] = {area * -r.traction[2], area * r.traction[1], area * r.traction[0]};
      for (int i = 0; i < 3; ++i) {
        ASSERT_EQ(f[lo + i], expected[i]) << "pair " << p << " component " << i;
        ASSERT_EQ(f[up + i], -expected[i]) << "pair " << p << " component " << i;
      }
      ASSERT_EQ(pairs.damage()[std::size_t(p)], h[std::size_t(p)].damage) << "pair " << p;
      elastic += area * r.elastic_energy;
    }
    EXPECT_NEAR(pairs.elastic_energy(), elastic, 1e-12 * elastic);
    // Both paths were taken: some pairs damaged, most not.
    int damaged = 0;
    for (double dmg : pairs.damage()) damaged += dmg > 0 && dmg < 1;
    EXPECT_GT(damaged, 100);
    EXPECT_LT(damaged, np / 2);
  }
}

TEST(TiebreakKernel, PairsInSimdLanesGetTheLawsOwnResults) { check_simd_lanes(false); }
TEST(TiebreakKernel, PairsWithTheirOwnStrengthsGetTheirOwnLawsResults) { check_simd_lanes(true); }

TEST(TiebreakKernel, OneAndTwoThreadsGiveBitIdenticalResults) {
  const int n = 64, np = n * n;
  const double a = 0.5e-3;
  TiebreakPairsSpec s;
  std::vector<double> x0(2 * np * 3, 0.0), mass(2 * np, 1e-7);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int p = n * j + i;
      s.lower.push_back(p);
      s.upper.push_back(np + p);
      x0[3 * p] = x0[3 * (np + p)] = i * a;
      x0[3 * p + 1] = x0[3 * (np + p) + 1] = j * a;
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const Index q = n * j + i;
      s.faces.insert(s.faces.end(), {q, q + 1, q + n + 1, q + n});
    }
  auto p = test::table_8_6_option9();
  p.PARAM = -1.8;  // B-K, the pow branch
  p.FS = 0.2;
  auto run = [&](int threads, std::vector<double>& f_out, std::vector<double>& damage, double energies[2]) {
    omp_set_num_threads(threads);
    TiebreakPairs pairs(p, s, x0.data(), mass.data());
    std::vector<double> x = x0, f(x.size());
    for (int step = 1; step <= 40; ++step) {
      for (int q = 0; q < np; ++q) {  // a smooth opening field that grows, shears and closes some pairs
        const double phase = 0.01 * q;
        x[3 * (np + q) + 0] = x0[3 * (np + q)] + step * 1e-6 * std::sin(phase);
        x[3 * (np + q) + 2] = step * 1.5e-6 * std::cos(3 * phase);
      }
      std::fill(f.begin(), f.end(), 0.0);
      pairs.apply(x.data(), nullptr, f.data(), 1e-9);
    }
    f_out = f;
    damage = pairs.damage();
    energies[0] = pairs.elastic_energy();
    energies[1] = pairs.dissipated_energy();
  };
  std::vector<double> f1, f2, d1, d2;
  double e1[2], e2[2];
  run(1, f1, d1, e1);
  run(2, f2, d2, e2);
  omp_set_num_threads(1);
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(d1, d2);
  EXPECT_EQ(e1[0], e2[0]);
  EXPECT_EQ(e1[1], e2[1]);
  EXPECT_GT(e1[1], 0.0);
  const auto separated = std::count(d1.begin(), d1.end(), 1.0);
  EXPECT_GT(separated, 0);
  EXPECT_LT(separated, np);
}

// Records every block by name; replays them into another object.
class Recorder : public StateVisitor {
 public:
  std::map<std::string, std::vector<char>> blocks;
  bool write_back = false;
  void enter(std::string_view g) override { prefix_ += std::string(g) + "/"; }
  void leave() override { prefix_.erase(prefix_.rfind('/', prefix_.size() - 2) + 1); }
  void block(std::string_view name, std::size_t elem, std::size_t count, void* data, Resize, void*) override {
    auto& b = blocks[prefix_.substr(0, prefix_.size()) + std::string(name)];
    if (write_back) {
      std::memcpy(data, b.data(), elem * count);
    } else {
      b.assign(static_cast<char*>(data), static_cast<char*>(data) + elem * count);
    }
  }

 private:
  std::string prefix_;
};

TEST(TiebreakKernel, VisitStateNamesTheHistoryAndARestartContinuesIdentically) {
  auto p = test::table_8_6_option9();
  p.FS = 0.3;
  const double area = 1e-6, m[2] = {1e-7, 1e-7};
  const double x0[6] = {0, 0, 0, 0, 0, 0};
  TiebreakPairs a(p, single_pair(area), x0, m);
  double x[6] = {0, 0, 0, 0, 0, 0}, v[6] = {-30, 10, -90, 30, -10, 90};
  run_two_masses(a, m, v, x, 1e-10, 2000);
  Recorder rec;
  a.visit_state(rec);
  for (const char* name : {"max_opening", "damage", "slip_1", "slip_2", "stick_energy", "dissipated_energy"})
    EXPECT_EQ(rec.blocks.count(std::string("tiebreak pairs/") + name), 1u) << name;
  TiebreakPairs b(p, single_pair(area), x0, m);
  rec.write_back = true;
  b.visit_state(rec);
  double xa[6], va[6];
  std::memcpy(xa, x, sizeof x);
  std::memcpy(va, v, sizeof v);
  run_two_masses(a, m, va, xa, 1e-10, 500);
  run_two_masses(b, m, v, x, 1e-10, 500);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(xa[i], x[i]);
  EXPECT_EQ(a.dissipated_energy(), b.dissipated_energy());
  EXPECT_EQ(a.damage(), b.damage());
}

TEST(TiebreakKernel, BadSpecsAreRefused) {
  const auto p = test::table_8_6_option9();
  const double x0[6] = {0, 0, 0, 0, 0, 0}, m[2] = {1, 1};
  auto s = single_pair(1e-6);
  s.area = {0};
  EXPECT_THROW(TiebreakPairs(p, s, x0, m), InputError);
  s = single_pair(1e-6);
  s.normals.clear();
  EXPECT_THROW(TiebreakPairs(p, s, x0, m), InputError);
  s = single_pair(1e-6);
  s.upper = {0};
  EXPECT_THROW(TiebreakPairs(p, s, x0, m), InputError);
}

}  // namespace
}  // namespace plyimpact::cohesive
