// *MAT_054 / *MAT_055 material point. See composite_damage.hpp.
//
// Choices where the sources are ambiguous (docs/theory.md section 7):
//  1. Degradation as stress limits. Every degraded in-plane component (aa, bb, ab) lives in a box
//     [lo, hi]: intact (-inf, inf); removed [0, 0]; residual limit on the failed side only. The
//     trial stress uses the undamaged stiffness and is projected onto the box by the normal-stress
//     return C_JJ dp_J = trial_J - bound_J (J = violated normal components). For a removed
//     component this is exactly the reduced stiffness of the degradation table (the Schur
//     complement, i.e. E = 0 and the nu involving it = 0, as the card's degradation table), and the coupled stresses
//     (bb, cc) lose their share of the removed one at the moment of failure.
//  2. Degradation table (6.4): fibre tension removes aa, bb and ab (the ply carries no in-plane
//     load); fibre compression removes aa; matrix tension or compression removes bb and ab. A
//     failed mode's own component (aa for fibre modes, bb and ab for matrix modes) is removed only
//     when its SLIM is 0; with SLIM > 0 it keeps its stiffness and is held at |stress| <= SLIM x
//     strength on the failed side (elastic-ideally plastic, "no less than SLIM x strength" while
//     loading continues). bb and ab after fibre tension failure are always removed.
//  3. SLIM blank/0 = no floor (the stress drops to zero), not OpenRadioss's 1.0.
//  4. NCYRED: the limit falls linearly from the stress at failure to SLIM x strength over NCYRED
//     cycles (cycle k after failure: floor + (start - floor) max(0, 1 - k/NCYRED)); blank/0/1 = the
//     drop happens in the failure cycle. A removed component is removed once the ramp ends.
//  5. The ab limit starts at the first matrix failure (either sign) and uses SLIMS x SC.
//  6. Criteria (composite_damage_criteria): evaluated on the stress after the existing limits,
//     at the end of the cycle; sigma_aa = 0 counts as tension (as the card's criteria: sigma_aa >= 0), so with
//     BETA = 1 pure shear meets the fibre-tension criterion at SC as well. The ALPH shear ratio
//     tau_bar of MAT_022 enters every criterion (MAT_022 text), not only matrix tension (OR127).
//     CRIT 55 failure sets e_m for sigma_bb >= 0 and e_d (with FBRT/YCFAC) for sigma_bb < 0.
//     Failures found in a cycle change the limits of the same cycle; the criteria are re-checked
//     until no new mode fails (so a YCFAC-reduced XC acts at once).
//  7. FBRT/YCFAC after e_d = 0: XC <- YCFAC x YC, and XT <- FBRT x XT when FBRT > 0 (KW texts).
//  8. ALPH: tangent shear modulus 1/(1/GAB + 3 ALPH tau^2) at the stress of the start of the cycle.
//  9. Through-thickness: sigma_cc is elastic (coupled to aa/bb through the stiffness and the return
//     of item 1) and enters no criterion; bc and ca are elastic in total form,
//     tau = (1 - d) g G gamma_total, with d the transverse shear damage and g = SOFTG on a
//     crashfront (secant: d acts on the whole stress, not only on later increments). All vanish
//     with erosion. OpenRadioss's extra sigma_cc matrix checks are not copied.
// 10. Transverse shear damage: gamma_t = 1/2 sqrt(gamma_bc^2 + gamma_ca^2) (tensor magnitude, as
//     OR127); d = (gamma_t - EPSF)/(|EPSR| - EPSF) clipped to [0, TSMD], never decreasing; EPSF = 0
//     switches it off; EPSR < 0 erodes when d = TSMD.
// 11. Erosion: DFAILT = 0 -> on fibre-tension failure (other modes only degrade). DFAILT > 0 ->
//     eps_aa >= DFAILT, eps_aa <= DFAILC (DFAILC < 0; 0 = off), |eps_bb| >= DFAILM (0 = off),
//     |gamma_ab|/2 >= DFAILS (tensorial, KW "maximum tensorial shear strain"; 0 = off); DFAILM and
//     DFAILS act only when DFAILT > 0 (DC054). Strains are the totals in material axes.
// 12. EFS > 0: eps_eff = sqrt(4/3 (e_aa^2 + e_bb^2 + e_cc^2 + e_aa e_bb + e_bb e_cc + e_cc e_aa +
//     e_ab^2 + e_bc^2 + e_ca^2)) with tensor shears (OR127's 3D form; the in-plane form of
//     its in-plane form when the c components vanish).
// 13. TFAIL: <= 0 off; (0, 0.1] element step < TFAIL; > 0.1 element step / initial step < TFAIL.
// 14. Crashfront: once ctx.crashfront is seen the point stays a crashfront point; with TFAIL > 0,
//     XT, XC, YT, YC, SC are multiplied by SOFT and GBC, GCA by SOFTG (SOFTG gated like SOFT).
// 15. Erosion order when several causes meet in one cycle: fibre tension, DFAILT, DFAILC, DFAILM,
//     DFAILS, EFS, transverse shear, TFAIL (the first is reported).
#include "material/composite_damage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace plyimpact::material {
namespace {

namespace H = composite_history;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Limit slots of history kRampCycles / kRampStart.
constexpr int kAaTension = 0, kAaCompression = 1, kBbTension = 2, kBbCompression = 3, kAbShear = 4;

// Stress box of the degradable components aa, bb, ab (index 0, 1, 2).
struct Box {
  double lo[3] = {-kInf, -kInf, -kInf};
  double hi[3] = {kInf, kInf, kInf};
};

struct Limit {
  double cap;    // current magnitude of the limit
  bool removed;  // no floor and the ramp is over: the component is gone on both sides
};

Limit limit(const CompositeDamageParams& p, const double* h, int slot, double floor) {
  const double k = h[H::kRampCycles + slot], start = h[H::kRampStart + slot];
  const double n = static_cast<double>(p.NCYRED);
  const double cap = floor + (start - floor) * std::max(0.0, 1.0 - k / n);
  return {cap, floor == 0.0 && k >= n};
}

bool failed(const double* h, int flag) { return h[flag] == 0.0; }

Box degradation_box(const CompositeDamageParams& p, const double* h, const CompositeStrengths& s) {
  Box b;
  const bool ft = failed(h, H::kFibreTension);
  // aa: own component of both fibre modes.
  bool zero = false;
  if (ft) {
    const Limit l = limit(p, h, kAaTension, p.SLIMT1 * s.XT);
    zero |= l.removed;
    b.hi[0] = l.cap;
  }
  if (failed(h, H::kFibreCompression)) {
    const Limit l = limit(p, h, kAaCompression, p.SLIMC1 * s.XC);
    zero |= l.removed;
    b.lo[0] = -l.cap;
  }
  if (zero) b.lo[0] = b.hi[0] = 0;
  // bb: own component of both matrix modes, removed with fibre tension.
  zero = ft;
  if (failed(h, H::kMatrixTension)) {
    const Limit l = limit(p, h, kBbTension, p.SLIMT2 * s.YT);
    zero |= l.removed;
    b.hi[1] = l.cap;
  }
  if (failed(h, H::kMatrixCompression)) {
    const Limit l = limit(p, h, kBbCompression, p.SLIMC2 * s.YC);
    zero |= l.removed;
    b.lo[1] = -l.cap;
  }
  if (zero) b.lo[1] = b.hi[1] = 0;
  // ab: limited from the first matrix failure, removed with fibre tension.
  zero = ft;
  if (h[H::kRampCycles + kAbShear] > 0) {
    const Limit l = limit(p, h, kAbShear, p.SLIMS * s.SC);
    zero |= l.removed;
    b.lo[2] = -l.cap;
    b.hi[2] = l.cap;
  }
  if (zero) b.lo[2] = b.hi[2] = 0;
  return b;
}

// Projects the trial stress onto the box: shear by clipping (ab is uncoupled in material axes),
// normal stresses by a "plastic" strain along the violated normal components, which keeps the
// return consistent with the orthotropic coupling (see item 1 above).
void project(const Stiffness6& C, const Box& b, const double trial[6], double out[6]) {
  std::copy(trial, trial + 6, out);
  out[3] = std::clamp(trial[3], b.lo[2], b.hi[2]);
  bool active[2] = {false, false};
  double target[2] = {0, 0};
  for (int pass = 0; pass < 2; ++pass) {
    bool added = false;
    for (int i = 0; i < 2; ++i) {
      if (active[i]) continue;
      if (out[i] > b.hi[i]) {
        active[i] = true, target[i] = b.hi[i], added = true;
      } else if (out[i] < b.lo[i]) {
        active[i] = true, target[i] = b.lo[i], added = true;
      }
    }
    if (!added) return;
    double dp[2] = {0, 0};  // plastic strain on aa, bb
    if (active[0] && active[1]) {
      const double a = C[0], bq = C[1], c = C[7], det = a * c - bq * bq;  // normal block is positive definite
      const double r0 = trial[0] - target[0], r1 = trial[1] - target[1];
      dp[0] = (c * r0 - bq * r1) / det;
      dp[1] = (a * r1 - bq * r0) / det;
    } else {
      const int i = active[0] ? 0 : 1;
      dp[i] = (trial[i] - target[i]) / C[7 * i];
    }
    for (int r = 0; r < 3; ++r) out[r] = trial[r] - C[6 * r] * dp[0] - C[6 * r + 1] * dp[1];
    for (int i = 0; i < 2; ++i)
      if (active[i]) out[i] = target[i];  // exact, not within round-off
  }
}

CompositeDamageCause erosion_cause(const CompositeDamageParams& p, const double* h,
                                   const CompositeDamageContext& ctx) {
  using C = CompositeDamageCause;
  const double* e = h + H::kStrain;
  if (p.DFAILT == 0 && failed(h, H::kFibreTension)) return C::FibreTension;
  // The point's own strain erodes at the scaled limits; with a neighbourhood the card's limits
  // erode where the neighbourhood's mean strain reaches them.
  const int reached = composite_damage_strain_limits(p, e, ctx.erosion_scale) | ctx.mean_limits;
  for (C c : {C::DFAILT, C::DFAILC, C::DFAILM, C::DFAILS, C::EFS})
    if (reached & (1 << int(c))) return c;
  if (p.EPSF > 0 && p.EPSR < 0 && h[H::kTransverseShearDamage] >= p.TSMD) return C::TransverseShear;
  if (p.TFAIL > 0 && ctx.element_dt > 0) {
    if (p.TFAIL <= 0.1 ? ctx.element_dt < p.TFAIL
                       : (ctx.initial_dt > 0 && ctx.element_dt / ctx.initial_dt < p.TFAIL))
      return C::TFAIL;
  }
  return C::None;
}

}  // namespace

int composite_damage_strain_limits(const CompositeDamageParams& p, const double e[6], double k) {
  using C = CompositeDamageCause;
  const auto bit = [](C c) { return 1 << int(c); };
  int reached = 0;
  if (p.DFAILT > 0) {
    if (e[0] >= p.DFAILT * k) reached |= bit(C::DFAILT);
    if (p.DFAILC < 0 && e[0] <= p.DFAILC * k) reached |= bit(C::DFAILC);
    if (p.DFAILM > 0 && std::abs(e[1]) >= p.DFAILM * k) reached |= bit(C::DFAILM);
    if (p.DFAILS > 0 && 0.5 * std::abs(e[3]) >= p.DFAILS * k) reached |= bit(C::DFAILS);
  }
  if (p.EFS > 0) {
    const double ab = 0.5 * e[3], bc = 0.5 * e[4], ca = 0.5 * e[5];
    const double q = e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[0] * e[1] + e[1] * e[2] + e[2] * e[0] + ab * ab +
                     bc * bc + ca * ca;
    if (std::sqrt(4.0 / 3.0 * q) >= p.EFS * k) reached |= bit(C::EFS);
  }
  return reached;
}

const char* composite_damage_cause_name(CompositeDamageCause c) {
  switch (c) {
    case CompositeDamageCause::None: return "none";
    case CompositeDamageCause::FibreTension: return "fibre tension";
    case CompositeDamageCause::DFAILT: return "DFAILT";
    case CompositeDamageCause::DFAILC: return "DFAILC";
    case CompositeDamageCause::DFAILM: return "DFAILM";
    case CompositeDamageCause::DFAILS: return "DFAILS";
    case CompositeDamageCause::EFS: return "EFS";
    case CompositeDamageCause::TFAIL: return "TFAIL";
    case CompositeDamageCause::TransverseShear: return "transverse shear (EPSR)";
  }
  return "unknown";
}

int composite_damage_lost_components(const double* h) {
  using namespace lost_component;
  int lost = 0;
  if (failed(h, H::kFibreTension)) lost |= kAa | kBb | kAb;
  if (failed(h, H::kFibreCompression)) lost |= kAa;
  if (failed(h, H::kMatrixTension) || failed(h, H::kMatrixCompression)) lost |= kBb | kAb;
  return lost;
}

void composite_damage_init(const CompositeDamageParams& p, double* h) {
  std::fill(h, h + kCompositeDamageHistory, 0.0);
  h[H::kFibreTension] = h[H::kFibreCompression] = h[H::kMatrixTension] = h[H::kMatrixCompression] = 1.0;
  h[H::kXT] = p.strength.XT;
  h[H::kXC] = p.strength.XC;
  for (int i = 0; i < 4; ++i) h[H::kCriteria + i] = -1.0;
}

CompositeDamageResult composite_damage_update(const CompositeDamageParams& p, const double de[6], double s[6],
                                              double* h, const CompositeDamageContext& ctx) {
  if (h[H::kCause] != 0) {  // eroded earlier: stays stress free
    std::fill(s, s + 6, 0.0);
    return {true, static_cast<int>(h[H::kCause])};
  }
  double* eps = h + H::kStrain;
  for (int i = 0; i < 6; ++i) eps[i] += de[i];
  if (ctx.crashfront) h[H::kCrashfront] = 1.0;
  const bool soft = h[H::kCrashfront] != 0 && p.TFAIL > 0;

  if (p.EPSF > 0) {
    const double gt = 0.5 * std::hypot(eps[4], eps[5]);
    const double d = std::clamp((gt - p.EPSF) / (std::abs(p.EPSR) - p.EPSF), 0.0, p.TSMD);
    h[H::kTransverseShearDamage] = std::max(h[H::kTransverseShearDamage], d);
  }
  for (int k = 0; k < 5; ++k)
    if (h[H::kRampCycles + k] > 0) h[H::kRampCycles + k] += 1;

  // Trial stress: undamaged stiffness for the normal block, tangent modulus for ab (ALPH).
  const Stiffness6& C = p.C;
  double trial[6];
  for (int r = 0; r < 3; ++r) trial[r] = s[r] + C[6 * r] * de[0] + C[6 * r + 1] * de[1] + C[6 * r + 2] * de[2];
  trial[3] = s[3] + de[3] / (1.0 / p.GAB + 3.0 * p.ALPH * s[3] * s[3]);
  const double g = (1.0 - h[H::kTransverseShearDamage]) * (soft ? p.SOFTG : 1.0);
  trial[4] = g * p.GBC * eps[4];
  trial[5] = g * p.GCA * eps[5];

  auto strengths = [&] {
    const double f = soft ? p.SOFT : 1.0;
    return CompositeStrengths{f * h[H::kXT], f * h[H::kXC], f * p.strength.YT, f * p.strength.YC, f * p.strength.SC};
  };
  CompositeStrengths st = strengths();
  double out[6];
  // Each pass can only fail more modes, so four modes bound the passes.
  for (int pass = 0; pass < 5; ++pass) {
    project(C, degradation_box(p, h, st), trial, out);
    const CompositeCriteria c = composite_criteria(p.CRIT, p.BETA, p.ALPH, p.GAB, st, out[0], out[1], out[3]);
    const double values[4] = {c.fibre_tension, c.fibre_compression, c.matrix_tension, c.matrix_compression};
    bool fresh = false;
    for (int m = 0; m < 4; ++m) {
      if (failed(h, m)) continue;  // frozen at the failure value
      h[H::kCriteria + m] = values[m];
      if (values[m] < 0) continue;
      h[m] = 0.0;
      fresh = true;
      // The limit of the mode's own component starts at the stress it failed at.
      const int slot = m;  // flags and slots share the order fibre t/c, matrix t/c
      h[H::kRampCycles + slot] = 1;
      h[H::kRampStart + slot] = std::abs(out[m < 2 ? 0 : 1]);
      if (m >= 2 && h[H::kRampCycles + kAbShear] == 0) {
        h[H::kRampCycles + kAbShear] = 1;
        h[H::kRampStart + kAbShear] = std::abs(out[3]);
      }
      if (m == H::kMatrixCompression) {
        h[H::kXC] = p.YCFAC * p.strength.YC;
        if (p.FBRT > 0) h[H::kXT] = p.FBRT * p.strength.XT;
      }
    }
    if (!fresh) break;
    st = strengths();
  }
  std::copy(out, out + 6, s);

  const CompositeDamageCause cause = erosion_cause(p, h, ctx);
  if (cause != CompositeDamageCause::None) {
    h[H::kCause] = static_cast<double>(cause);
    std::fill(s, s + 6, 0.0);
    return {true, static_cast<int>(cause)};
  }
  return {};
}

}  // namespace plyimpact::material
