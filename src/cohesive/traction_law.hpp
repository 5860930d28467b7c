// Interface traction-separation laws as pure point functions: (law, opening in the interface frame,
// history) -> (traction, new history, damage, mode mixity, energies, secant stiffnesses). The history
// is five plain doubles, so a run can be written and read back. One law serves the tiebreak pairs and
// (later) the *MAT_138 cohesive element. Units SI; opening and traction are (normal, shear 1, shear 2),
// the normal positive in opening.
//
// Common structure (seed eqs. 7.41-7.49; Camanho & Davila 2002, NASA/TM-2002-211737):
//   delta_I = <delta_n>, delta_II = |(delta_s1, delta_s2)|, delta = sqrt(delta_I^2 + delta_II^2),
//   direction cosines c^2 = delta_I^2 / delta^2, s^2 = delta_II^2 / delta^2 (beta = s / c),
//   onset  delta_0 = delta_I0 delta_II0 / sqrt(c^2 delta_II0^2 + s^2 delta_I0^2)
//          (eq. 7.46; the quadratic traction criterion (t_I/NFLS)^2 + (t_II/SFLS)^2 = 1 on this ray),
//   damage d = delta_F (delta_m - delta_0) / (delta_m (delta_F - delta_0)) (eq. 7.49), delta_m the
//          largest delta so far; d never decreases (a change of mixity cannot heal the point),
//   tractions t_n = (1 - d) K_n delta_n (delta_n > 0) or K_n delta_n (compression: penalty, no damage),
//          t_s = (1 - d) K_t delta_s: unloading and reloading follow the damaged secant.
// The laws differ in the final opening delta_F:
//   OPTION 9 / *MAT_138 power law (PARAM = alpha > 0), from (G_I/G_Ic)^alpha + (G_II/G_IIc)^alpha = 1:
//          delta_F = (2 / delta_0) [ (K_n c^2 / G_Ic)^alpha + (K_t s^2 / G_IIc)^alpha ]^(-1/alpha)
//          (eq. 7.48 written with c, s; the seed's printing of 7.48 drops the factor 2 that G = 1/2 sigma delta_F needs);
//   OPTION 9 Benzeggagh-Kenane (PARAM < 0, eta = |PARAM|; B&K 1996):
//          G_c = G_Ic + (G_IIc - G_Ic) (G_II / G_T)^eta, G_II / G_T = K_t s^2 / K_eff, K_eff = K_n c^2 + K_t s^2,
//          delta_F = 2 G_c / (delta_0 K_eff);
//   OPTION 6: delta_F = CCRIT (PARAM) for every mixity. This is the manual's "damage is a linear function
//          of the maximum distance C, complete at C = CCRIT" read as: the traction falls linearly from
//          the stress onset to zero at C = CCRIT (LS-DYNA's damage D = (C - C_0)/(CCRIT - C_0) scales the
//          onset traction, which is the secant law above with delta_F = CCRIT). ASSUMPTION: that D starts
//          at the stress onset C_0 rather than at C = 0 is not stated in the manual; K_t = K_n = CN.
//   OPTION 7: ASSUMPTION (the manual gives only "DYCOSS discrete crack model, Lemmen & Meijer 2001",
//          the fields NFLS, SFLS, PARAM = friction angle in degrees, ERATEN, ERATES, and calls OPTION 9
//          its extension with power-law and B-K damage): the OPTION 9 law with alpha = 1 and K_t = K_n
//          = CN, and Coulomb friction mu = tan(PARAM) after separation. Not LS-DYNA's law, which was not
//          found; docs/delamination.md lists what is and is not known.
// After complete separation (d = 1): contact only. No tension; compression by the penalty K_n;
// Coulomb friction through an elastic stick spring K_t with a return map onto mu |t_n| (the slip
// point is the history; the friction dissipates the mean sliding traction times the slip increment,
// so that with the stick spring's energy it equals the trapezoid work of the traction). Opening again releases the stick spring (its energy counts as
// dissipated).
// Energies per unit area: elastic = the stored (1 - d) secant energy plus the compression and stick
// springs. Dissipated increment = integral of Y dd with Y = 1/2 (K_n delta_I^2 + K_t delta_II^2),
// evaluated as 1/2 K_eff delta_lo delta_hi (d_new - d_old) with delta_lo = max(delta_m, delta_0) and
// delta_hi = min(delta, delta_F): exact for any step size at constant mixity (along a ray Y dd/d delta
// is constant), so a monotonic path dissipates G_c to round-off; plus the friction and released-spring
// energy. Mode mixity reported = G_II / G_T = K_t delta_II^2 / (K_n delta_I^2 + K_t delta_II^2).
#pragma once

#include <cmath>

#include "cohesive/law_parameters.hpp"

namespace plyimpact::cohesive {

// Constants of one law, derived once from validated parameters.
struct TractionLaw {
  TiebreakOption option = TiebreakOption::MixedMode;
  double kn = 0, kt = 0;              // Pa/m, normal and shear stiffness
  double delta_n0 = 0, delta_s0 = 0;  // m, single-mode onset openings NFLS/K_n, SFLS/K_t
  double gic = 0, giic = 0;           // J/m^2
  double alpha = 1;                   // power-law exponent (bk_eta == 0)
  double bk_eta = 0;                  // > 0: Benzeggagh-Kenane with this eta
  double ccrit = 0;                   // m, OPTION 6 final opening (0 for the energy laws)
  double mu = 0;                      // Coulomb coefficient after separation
  double k_max = 0;                   // Pa/m, max(K_n, K_t): the stiffest response, for the stable step
  // m: an opening up to it starts no damage on any ray (onset_opening lies between the two
  // single-mode onsets), less 1e-12 of it for the onset's round-off; 0 = no such shortcut.
  double elastic_limit = 0;
};

// Requires validate_traction_law(p) to be empty (throws InputError otherwise).
TractionLaw make_traction_law(const TractionLawParams& p);

// Per-point history (plain doubles, named in the state of whoever owns them).
struct PointHistory {
  double max_opening = 0;  // m, largest delta = sqrt(<delta_n>^2 + delta_s^2) so far
  double damage = 0;       // d in [0, 1]; 1 = separated (contact only)
  double slip1 = 0;        // m, stick-spring anchor of the friction after separation (shear 1, shear 2)
  double slip2 = 0;
  double stick_energy = 0; // J/m^2 held by the stick spring after the last update (released on opening)
};

struct PointResponse {
  double traction[3] = {0, 0, 0};   // Pa, (normal, shear 1, shear 2), on the upper face, opposing the opening
  double damage = 0;
  double mixity = 0;                // G_II / G_T from the openings (0 pure mode I, 1 pure shear)
  double elastic_energy = 0;        // J/m^2 stored now
  double dissipated_increment = 0;  // J/m^2 dissipated by this update (damage, friction, released spring)
  double stiffness_normal = 0;      // Pa/m, secant stiffness acting now (normal, shear)
  double stiffness_shear = 0;
};

// The squared shear opening, the opening's norm and the stored secant energy, with explicit fused
// multiply-adds: every caller (the law point by point, the SIMD path of intact tiebreak pairs)
// rounds them alike, whatever the compiler would contract in each context.
inline double shear_opening_sq(double u1, double u2) noexcept { return std::fma(u2, u2, u1 * u1); }
inline double opening_norm(double ui, double us_sq) noexcept { return std::sqrt(std::fma(ui, ui, us_sq)); }
inline double secant_energy(double kn, double kt, double u0, double us_sq) noexcept {
  return 0.5 * std::fma(kn * u0, u0, kt * us_sq);
}

// Mixed-mode onset opening for direction cosines c2 = c^2, s2 = s^2 (c2 + s2 = 1).
inline double onset_opening(const TractionLaw& law, double c2, double s2) noexcept {
  const double a = law.delta_n0, b = law.delta_s0;
  return a * b / std::sqrt(c2 * b * b + s2 * a * a);
}

// Final (complete separation) opening on the same ray.
inline double final_opening(const TractionLaw& law, double c2, double s2, double onset) noexcept {
  if (law.option == TiebreakOption::StressCcrit) return law.ccrit;
  const double keff = law.kn * c2 + law.kt * s2;
  if (law.bk_eta > 0) {
    const double gc = law.gic + (law.giic - law.gic) * std::pow(law.kt * s2 / keff, law.bk_eta);
    return 2 * gc / (onset * keff);
  }
  const double a = law.kn * c2 / law.gic, b = law.kt * s2 / law.giic;
  double inv;  // [a^alpha + b^alpha]^(-1/alpha)
  if (law.alpha == 1)
    inv = 1 / (a + b);
  else if (law.alpha == 2)
    inv = 1 / std::sqrt(a * a + b * b);
  else
    inv = std::pow(std::pow(a, law.alpha) + std::pow(b, law.alpha), -1 / law.alpha);
  return 2 * inv / onset;
}

namespace detail {

// Damage growth when the opening exceeds its history maximum (delta > 0).
[[gnu::noinline]] inline void grow_damage(const TractionLaw& law, double ui, double us_sq, double open, const double u[3],
                        PointHistory& h, double& dissipated) noexcept {
  const double open_sq = open * open;
  const double c2 = ui * ui / open_sq, s2 = us_sq / open_sq;
  const double onset = onset_opening(law, c2, s2);
  if (open > onset) {
    const double fin = final_opening(law, c2, s2, onset);
    const double d_new = open >= fin ? 1.0 : fin * (open - onset) / (open * (fin - onset));
    if (d_new > h.damage) {
      const double keff = law.kn * c2 + law.kt * s2;
      const double lo = h.max_opening > onset ? h.max_opening : onset;
      const double hi = open < fin ? open : fin;
      dissipated += 0.5 * keff * lo * hi * (d_new - h.damage);
      h.damage = d_new;
      if (d_new >= 1) {  // separated now: the friction spring starts unloaded
        h.slip1 = u[1];
        h.slip2 = u[2];
      }
    }
  }
  h.max_opening = open;
}

// Contact after separation: no tension, penalty in compression, Coulomb friction (return map).
[[gnu::noinline]] inline void separated_contact(const TractionLaw& law, const double u[3], PointHistory& h, PointResponse& r) noexcept {
  const double e1 = u[1] - h.slip1, e2 = u[2] - h.slip2;
  const double trial_sq = law.kt * law.kt * (e1 * e1 + e2 * e2);  // |t_trial|^2
  r.damage = 1;
  if (u[0] >= 0) {  // open: nothing carried; a loaded stick spring lets go
    r.dissipated_increment += h.stick_energy;
    h.stick_energy = 0;
    h.slip1 = u[1];
    h.slip2 = u[2];
    r.traction[0] = r.traction[1] = r.traction[2] = 0;
    r.elastic_energy = 0;
    r.stiffness_normal = r.stiffness_shear = 0;
    return;
  }
  const double tn = law.kn * u[0];
  const double limit = -law.mu * tn;
  double t1 = law.kt * e1, t2 = law.kt * e2;
  if (trial_sq > limit * limit) {  // slides: back onto the cone, the slip point follows
    const double scale = limit / std::sqrt(trial_sq);
    t1 *= scale;
    t2 *= scale;
    h.slip1 = u[1] - t1 / law.kt;
    h.slip2 = u[2] - t2 / law.kt;
    // Work of the sliding traction over the slip, its mean over the step (|t| was
    // sqrt(2 K_t E_stick) before): with the stick energy's change this is the trapezoid work.
    const double t_before = std::sqrt(2 * law.kt * h.stick_energy);
    r.dissipated_increment += 0.5 * (t_before + limit) * (std::sqrt(trial_sq) - limit) / law.kt;
  }
  r.traction[0] = tn;
  r.traction[1] = t1;
  r.traction[2] = t2;
  h.stick_energy = 0.5 * (t1 * t1 + t2 * t2) / law.kt;
  r.elastic_energy = 0.5 * tn * u[0] + h.stick_energy;
  r.stiffness_normal = law.kn;
  r.stiffness_shear = law.kt;
}

}  // namespace detail

// One update of one point: u = opening (normal, shear 1, shear 2) in m. The common (elastic or
// secant) path is inlined into the caller's loop; damage growth and contact are out of line.
[[gnu::always_inline]] inline void traction_update(const TractionLaw& law, const double u[3], PointHistory& h, PointResponse& r) noexcept {
  const double ui = u[0] > 0 ? u[0] : 0;
  const double us_sq = shear_opening_sq(u[1], u[2]);
  const double two_ei = law.kn * ui * ui, two_eii = law.kt * us_sq;
  r.mixity = two_ei + two_eii > 0 ? two_eii / (two_ei + two_eii) : 0;
  r.dissipated_increment = 0;
  if (h.damage < 1) {
    const double open = opening_norm(ui, us_sq);
    if (open > h.max_opening) {
      // Below every onset the history only records the largest opening (grow_damage would find
      // open <= onset and do just that): most of an impact's pairs, most of the time.
      if (open <= law.elastic_limit)
        h.max_opening = open;
      else
        detail::grow_damage(law, ui, us_sq, open, u, h, r.dissipated_increment);
    }
  }
  if (h.damage >= 1) {
    detail::separated_contact(law, u, h, r);
    return;
  }
  const double keep = 1 - h.damage;
  const double kn_now = u[0] > 0 ? keep * law.kn : law.kn;
  const double kt_now = keep * law.kt;
  r.traction[0] = kn_now * u[0];
  r.traction[1] = kt_now * u[1];
  r.traction[2] = kt_now * u[2];
  r.elastic_energy = secant_energy(kn_now, kt_now, u[0], us_sq);
  r.damage = h.damage;
  r.stiffness_normal = kn_now;
  r.stiffness_shear = kt_now;
}

}  // namespace plyimpact::cohesive
