// The *MAT_054/055 update of the one-point element pass (CompositeDamageLanes) against the general
// point update (composite_point_update) it replaces for intact points: for random states - intact,
// about to fail, partly failed, on a crashfront, eroding - the stress, axes, history and erosion
// code of every lane must be bit-identical (the lane kernel repeats the general update's
// operations in the same order; any difference is a defect, not round-off to tolerate). The
// cards cover CRIT 54 and 55, BETA 0 and 1, ALPH > 0, strain erosion on and off, EFS and TFAIL
// with crashfront softening; half the points have their erosion strains scaled (erosion_scale).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "mat054_support.hpp"
#include "core/voigt.hpp"
#include "material/composite_damage_lanes.hpp"

namespace plyimpact::test {
namespace {

struct Lanes {
  std::vector<double> history, axes, initial_dt, erosion_scale;
};

// A rotation about a random axis by `angle` (Rodrigues), row-major.
void rotation(std::mt19937& rng, double angle, double R[9]) {
  std::normal_distribution<double> n(0, 1);
  double a[3] = {n(rng), n(rng), n(rng)};
  const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  for (double& c : a) c /= len;
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  const double r[9] = {t * a[0] * a[0] + c,        t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1],
                       t * a[0] * a[1] + s * a[2], t * a[1] * a[1] + c,        t * a[1] * a[2] - s * a[0],
                       t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], t * a[2] * a[2] + c};
  std::copy(r, r + 9, R);
}

// Compares `groups` lane groups of random points; returns how many lanes took each path (intact
// and no event in the cycle / anything else), so the test can see both were exercised.
std::pair<int, int> compare_random_points(const config::MatCompositeDamage& card, unsigned seed, int groups) {
  const material::CompositeDamageParams p = model::composite_damage_params(card, {"test", 0, 0, "mat"});
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), pick(0, 1);
  const int n = groups * kLanes;
  constexpr int kH = material::kCompositeDamageHistory;
  Lanes a;
  a.history.resize(std::size_t(n) * kH);
  a.axes.resize(std::size_t(n) * 9);
  a.initial_dt.resize(n);
  a.erosion_scale.resize(n);
  std::vector<double> stress(std::size_t(n) * 6), D(std::size_t(n) * 6), R(std::size_t(n) * 9), edt(n);
  const double dt = 1e-7;
  for (int e = 0; e < n; ++e) {
    double* h = &a.history[std::size_t(e) * kH];
    material::composite_damage_init(p, h);
    // Strains up to 1.3x the erosion limits, stresses up to 1.3x the strengths in material-axis
    // proportions, so that some lanes fail or erode in this cycle and most do not.
    for (int i = 0; i < 6; ++i) h[H::kStrain + i] = 0.012 * u(rng);
    if (pick(rng) < 0.15) h[H::kFibreCompression + int(pick(rng) * 3)] = 0.0;  // a failed mode
    if (pick(rng) < 0.2) h[H::kCrashfront] = 1.0;
    rotation(rng, 3.0 * u(rng), &a.axes[9 * std::size_t(e)]);
    double sm[6] = {card.XT * 0.7 * u(rng), card.YT * 0.8 * u(rng), card.YT * u(rng),
                    card.SC * 0.8 * u(rng), card.SC * u(rng),      card.SC * u(rng)};
    const double* Q = &a.axes[9 * std::size_t(e)];
    double Qt[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Qt[3 * i + j] = Q[3 * j + i];
    rotate_voigt(Qt, sm, &stress[6 * std::size_t(e)]);  // material -> global axes
    for (int i = 0; i < 6; ++i) D[6 * std::size_t(e) + i] = 2e4 * u(rng);  // up to 2e-3 strain per step
    rotation(rng, 1e-3 * u(rng), &R[9 * std::size_t(e)]);
    a.initial_dt[e] = 4e-8;
    // Half the elements shorter than an erosion reference length: their limits up to three times
    // the card's, so lanes between the card's limit and the scaled one stay in the fast path.
    a.erosion_scale[e] = pick(rng) < 0.5 ? 1.0 : 1.0 + 2.0 * pick(rng);
    edt[e] = 4e-8 * (0.05 + pick(rng));
  }
  Lanes b = a;  // reference copy for the general update

  int fast = 0, general = 0;
  for (int g = 0; g < groups; ++g) {
    Index elem[kLanes];
    bool ok[kLanes];
    alignas(64) double Dl[6][kLanes], trD[kLanes], Rl[9][kLanes], Jx[9][kLanes] = {}, dte[kLanes];
    alignas(64) double s_old[6][kLanes], s_new[6][kLanes];
    for (int l = 0; l < kLanes; ++l) {
      const Index e = g * kLanes + l;
      elem[l] = e, ok[l] = true;
      for (int i = 0; i < 6; ++i) Dl[i][l] = D[6 * std::size_t(e) + i], s_old[i][l] = stress[6 * std::size_t(e) + i];
      for (int i = 0; i < 9; ++i) Rl[i][l] = R[9 * std::size_t(e) + i];
      trD[l] = Dl[0][l] + Dl[1][l] + Dl[2][l];
      dte[l] = edt[e];
    }
    int erode[kLanes] = {};
    material::CompositeDamageLanes lanes(p, a.history.data(), a.axes.data(), a.initial_dt.data(),
                                         a.erosion_scale.data(), material::ErosionNeighbourhoodView{}, 1, 10);
    lanes.update(material::LanePoint{elem, kLanes, ok, dt, Dl, trD, Rl, Jx, dte}, s_old, s_new, erode);
    for (int l = 0; l < kLanes; ++l) {
      const Index e = elem[l];
      if (erode[l] == 0) lanes.commit(e, l);
      // The general update of the same point.
      double* hb = &b.history[std::size_t(e) * kH];
      const bool intact_before = material::composite_damage_intact(hb);
      double Qn[9], sl[6], Dp[6];
      material::rotate_axes(&b.axes[9 * std::size_t(e)], &R[9 * std::size_t(e)], Qn);
      for (int i = 0; i < 6; ++i) sl[i] = stress[6 * std::size_t(e) + i], Dp[i] = D[6 * std::size_t(e) + i];
      material::CompositeDamageContext ctx;
      ctx.element_dt = edt[e];
      ctx.initial_dt = b.initial_dt[e];
      ctx.erosion_scale = b.erosion_scale[e];
      double crit_before[4];
      std::copy_n(hb + H::kCriteria, 4, crit_before);
      const auto res = material::composite_point_update(p, &b.axes[9 * std::size_t(e)], Qn, Dp, dt, ctx, sl, hb);
      if (!res.erode) std::copy_n(Qn, 9, &b.axes[9 * std::size_t(e)]);
      const bool event = res.erode || !material::composite_damage_intact(hb);
      (intact_before && !event ? fast : general) += 1;

      EXPECT_EQ(erode[l], res.erode ? 10 + res.cause : 0) << "element " << e;
      for (int i = 0; i < 6; ++i)
        EXPECT_EQ(std::memcmp(&s_new[i][l], &sl[i], sizeof(double)), 0)
            << "element " << e << " stress " << i << ": " << s_new[i][l] << " vs " << sl[i];
      EXPECT_EQ(std::memcmp(&a.history[std::size_t(e) * kH], hb, sizeof(double) * kH), 0) << "element " << e;
      EXPECT_EQ(std::memcmp(&a.axes[9 * std::size_t(e)], &b.axes[9 * std::size_t(e)], sizeof(double) * 9), 0)
          << "element " << e;
    }
  }
  return {fast, general};
}

TEST(Mat054Lanes, IntactLanesMatchTheGeneralUpdateBitForBit) {
  struct Case {
    const char* name;
    config::MatCompositeDamage card;
  };
  std::vector<Case> cases;
  cases.push_back({"T800S/M21, strain erosion (CRIT 54, BETA 1)", t800_card()});
  cases.push_back({"T800S/M21, criteria only (DFAILT 0)", t800_criteria_only()});
  cases.push_back({"BMS8-212 (BETA 0, DFAILS)", bms8212_card()});
  config::MatCompositeDamage c55 = t800_card();
  c55.CRIT = 55, c55.ALPH = 1e-25 /* Pa^-3: shear nonlinear near SC */, c55.EFS = 0.015;
  cases.push_back({"CRIT 55, ALPH, EFS", c55});
  config::MatCompositeDamage soft = t800_card();
  soft.TFAIL = 0.5, soft.SOFT = 0.6, soft.SOFTG = 0.7;  // ratio limit; crashfront softening
  cases.push_back({"TFAIL ratio, SOFT, SOFTG", soft});
  config::MatCompositeDamage tabs = t800_card();
  tabs.TFAIL = 2e-8;  // absolute step limit (s)
  cases.push_back({"TFAIL absolute", tabs});
  for (std::size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(cases[k].name);
    const auto [fast, general] = compare_random_points(cases[k].card, 1234u + unsigned(k), 32);
    // Both paths must have been exercised for the comparison to mean anything.
    EXPECT_GE(fast, 32) << "lanes on the intact path";
    EXPECT_GE(general, 16) << "lanes on the general path";
  }
}

}  // namespace
}  // namespace plyimpact::test
