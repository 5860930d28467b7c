// *MAT_138 (*MAT_COHESIVE_MIXED_MODE) card fields and their translation to the bilinear mixed-mode law
// that tiebreak OPTION 9 also uses (traction_law.hpp): EN = CN, ET = CT2CN CN, T = NFLS, S = SFLS,
// GIC = ERATEN, GIIC = ERATES, XMU = PARAM (XMU > 0 power law, XMU < 0 Benzeggagh-Kenane with
// eta = |XMU|). Units SI. What the manual documents and what is assumed: docs/delamination.md.
#pragma once

#include <string>
#include <vector>

#include "cohesive/law_parameters.hpp"

namespace plyimpact::cohesive {

struct Mat138Params {
  double EN = kMissing;    // Pa/m, stiffness normal to the element's mid-surface
  double ET = kMissing;    // Pa/m, stiffness in its plane
  double GIC = kMissing;   // J/m^2, mode I energy release rate
  double GIIC = kMissing;  // J/m^2, mode II energy release rate
  double XMU = kMissing;   // exponent of the mixed-mode criterion (< 0: Benzeggagh-Kenane)
  double T = kMissing;     // Pa, peak normal traction; 0 or blank with UND: T = 2 GIC / UND
  double S = kMissing;     // Pa, peak shear traction; 0 or blank with UTD: S = 2 GIIC / UTD
  double UND = kMissing;   // m, ultimate normal opening (read only when T is 0 or blank)
  double UTD = kMissing;   // m, ultimate tangential opening (read only when S is 0 or blank)
  double RO = 0;           // kg/m^2, mass per unit mid-surface area (ROFLG = 1); 0: massless
  // > 0: 2 x 2 Gauss points; <= 0 (LS-DYNA's blank): Newton-Cotes (corner) points. Only the sign is
  // used: elements are never deleted (a failed point stays as compression-only contact).
  double INTFAIL = 0;
};

// The laws' field names as the *MAT_138 card spells them, for validate_traction_law's messages.
inline constexpr LawFieldNames kMat138Names{"T", "S", "XMU", "GIC", "GIIC", "EN", "ET/EN", "ET"};

// Every problem, one message each with the field, its unit and the numbers (the snap-back check of
// the bilinear law included); empty when usable.
std::vector<std::string> validate_mat138(const Mat138Params& p);

// Throws InputError("<where>: <problems>") when validate_mat138 finds any.
void require_valid_mat138(const Mat138Params& p, const std::string& where);

// The OPTION 9 law with the same constants (requires a valid card).
TractionLawParams traction_law_of(const Mat138Params& p);

}  // namespace plyimpact::cohesive
