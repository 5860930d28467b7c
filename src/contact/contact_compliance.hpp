// How compliant a penalty contact is against the bodies it joins (for `check`). The springs form a
// layer between the surfaces: under a contact pressure p a node with tributary area A and spring k
// sinks by p A / k, so the layer's compliance per unit pressure is c = 1 / sum_sides (k / A) (the
// contact nodes of both sides carry the pressure in parallel in a two-way contact). For SOFT 0
// on a solid, k = SLSFAC K A^2 / V = SLSFAC K A / t, so c = t / (SLSFAC K) for one side: the layer
// is as compliant as a slab of thickness t / SLSFAC of the element's bulk modulus.
// Against a Hertz contact of radius a (modulus E*, 1/E* = sum (1 - nu^2) / E over the deformable
// sides, indentation d = a^2 / R under the force F, pressure p = p0 sqrt(1 - r^2 / a^2),
// p0 = 3 F / (2 pi a^2)), the layer adds to the approach, to first order in c (reciprocal theorem:
// the added complementary energy), (1 / F) int c p^2 dA = 9 c F / (8 pi a^2), i.e. relative to d
//   eps = 3 E* c / (2 pi a).
// A compliance d = d_H (1 + eps) lowers the Hertz constant by (1 + eps)^(3/2), so the impact's
// peak force scales by (1 + eps)^(-3/5) and its indentation and duration by (1 + eps)^(3/5)
// (Johnson, Contact Mechanics, 1985, section 11.4: F_max ~ K^(2/5), d_max ~ K^(-2/5)).
// The estimate keeps Hertz's patch and pressure; the springs widen the patch and flatten the
// pressure (on springs alone the patch is sqrt(2) wider at the same approach), so it is an upper
// bound: measured on the Hertz impact, the springs' effect is 1.5 to 2.5 times smaller
// (tests/contact/test_contact_compliance).
#pragma once

#include "contact/penalty_contact.hpp"
#include "model/model.hpp"

#include <string>

namespace plyimpact::contact {

struct PenaltyCompliance {
  double layer = 0;   // m/Pa, c: the springs' penetration per unit contact pressure (0: no spring)
  double e_star = 0;  // Pa, Hertz modulus of the two sides (0: both rigid)
  // Relative compliance the springs add to a Hertz contact of radius a.
  double eps(double a) const { return a > 0 ? 1.5 * e_star * layer / (3.141592653589793 * a) : 0.0; }
  // Contact radius at which eps reaches the given value (smaller contacts are distorted more).
  double radius_at(double eps_limit) const { return 1.5 * e_star * layer / (3.141592653589793 * eps_limit); }
};

// Peak-force error of a Hertz impact with the added compliance eps, (1 + eps)^(-3/5) - 1 (< 0).
double peak_force_error(double eps);
// Indentation (and duration) error, (1 + eps)^(3/5) - 1 (> 0).
double indentation_error(double eps);
// eps beyond which check warns: the bound says the peak force is more than 10 % low,
// (1 + eps)^(-3/5) = 0.90; the bound being about twice the real effect, that is a loss of ~5 %.
double eps_warning_limit();

// Estimated over the contact zone: the nodes of each side within one element of the other side's
// bounding box at the model's reference positions (those the first impact loads).
PenaltyCompliance penalty_compliance(const model::Model& model, const PenaltyContact& contact);

// Hertz contact radius of a sphere of radius R and mass m striking at v a body of modulus E*:
// a = sqrt(R d_max), d_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5).
double hertz_impact_radius(double e_star, double R, double m, double v);

}  // namespace plyimpact::contact

namespace plyimpact::contact {

// check's lines for one contact: the layer's compliance, its effect on the impactor's Hertz
// contact when the scene has a round-nosed impactor (else the contact radius below which the bound
// exceeds 10 % of the peak force), and a warning past eps_warning_limit with the SLSFAC that
// brings the bound back to 10 % (SOFT 0).
std::string compliance_lines(const model::Model& model, const PenaltyContact& contact, const config::Scene& scene);

}  // namespace plyimpact::contact
