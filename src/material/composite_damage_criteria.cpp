// Chang-Chang / Tsai-Wu criteria of *MAT_054/055. See composite_damage_criteria.hpp.
#include "material/composite_damage_criteria.hpp"

namespace plyimpact::material {

double shear_ratio(double tau, double sc, double gab, double alph) {
  // The ALPH term enters as in MAT_022 (the only LS-DYNA text seen, SCR22): the ratio of the
  // complementary shear energies at tau and at SC. With ALPH = 0 it is exactly (tau/SC)^2.
  const double t2 = tau * tau, s2 = sc * sc;
  return (t2 / (2 * gab) + 0.75 * alph * t2 * t2) / (s2 / (2 * gab) + 0.75 * alph * s2 * s2);
}

CompositeCriteria composite_criteria(int crit, double beta, double alph, double gab, const CompositeStrengths& s,
                                     double s_aa, double s_bb, double s_ab) {
  CompositeCriteria c;
  const double tau_bar = shear_ratio(s_ab, s.SC, gab, alph);
  if (s_aa >= 0) {
    const double r = s_aa / s.XT;
    c.fibre_tension = r * r + beta * tau_bar - 1;
  } else {
    const double r = s_aa / s.XC;
    c.fibre_compression = r * r - 1;
  }
  if (crit == 55) {
    const double yy = s.YC * s.YT;
    const double e = s_bb * s_bb / yy + tau_bar + (s.YC - s.YT) * s_bb / yy - 1;
    (s_bb >= 0 ? c.matrix_tension : c.matrix_compression) = e;
  } else if (s_bb >= 0) {
    const double r = s_bb / s.YT;
    c.matrix_tension = r * r + tau_bar - 1;
  } else {
    const double h = s_bb / (2 * s.SC), q = s.YC / (2 * s.SC);
    c.matrix_compression = h * h + (q * q - 1) * s_bb / s.YC + tau_bar - 1;
  }
  return c;
}

}  // namespace plyimpact::material
