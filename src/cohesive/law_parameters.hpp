// Parameters of the interface traction-separation laws, under their LS-DYNA card names
// (*CONTACT_..._TIEBREAK card 4: OPTION, NFLS, SFLS, PARAM, ERATEN, ERATES, CT2CN, CN; *MAT_138:
// T = NFLS, S = SFLS, XMU = PARAM, GIC = ERATEN, GIIC = ERATES, EN = CN, ET = CT2CN * CN), their
// validation with messages that quote the numbers, and the optional strength reduction that makes
// the cohesive process zone span a given number of segments. Units SI: Pa, Pa/m, J/m^2, m.
// The laws themselves are described in docs/delamination.md and implemented in traction_law.hpp.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace plyimpact::cohesive {

// Tiebreak OPTION values implemented. *MAT_138 uses the OPTION 9 law.
enum class TiebreakOption : int {
  StressCcrit = 6,   // stress onset (NFLS, SFLS), damage linear in the opening up to CCRIT = PARAM
  DiscreteCrack = 7, // ERATEN/ERATES bilinear law; PARAM = friction angle (deg); see the header of traction_law.hpp
  MixedMode = 9,     // bilinear mixed-mode law of *MAT_138; PARAM > 0 power law, < 0 Benzeggagh-Kenane
};

inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

struct TractionLawParams {
  TiebreakOption option = TiebreakOption::MixedMode;
  double NFLS = kMissing;    // Pa, normal (mode I) peak traction
  double SFLS = kMissing;    // Pa, shear (mode II) peak traction
  double PARAM = kMissing;   // OPTION 6: CCRIT (m); 7: friction angle (deg); 9: exponent (blank: 1)
  double ERATEN = kMissing;  // J/m^2, mode I energy release rate (OPTION 7, 9)
  double ERATES = kMissing;  // J/m^2, mode II energy release rate (OPTION 7, 9)
  double CN = kMissing;      // Pa/m, normal stiffness; for OPTION 6 and 7 the caller's penalty stiffness per area
  double CT2CN = 1.0;        // ET / EN (OPTION 9 only; 6 and 7 use CN in shear too)
  double FS = 0.0;           // Coulomb coefficient after separation (OPTION 6, 9; OPTION 7 uses tan(PARAM))
};

// The card names the messages use for the fields of TractionLawParams: the tiebreak's by default;
// *MAT_138 (mat138_parameters.hpp) reads the same law under its own names.
struct LawFieldNames {
  const char* NFLS = "NFLS";
  const char* SFLS = "SFLS";
  const char* PARAM = "PARAM";
  const char* ERATEN = "ERATEN";
  const char* ERATES = "ERATES";
  const char* CN = "CN";
  const char* CT2CN = "CT2CN";
  const char* shear_stiffness = "(CT2CN CN)";  // K_t of OPTION 9
};

// Every problem with the parameters, one message each, naming the card field, its unit and the
// numbers; empty when the law is usable. The scene loader prefixes file:line:col and the key.
std::vector<std::string> validate_traction_law(const TractionLawParams& p, const LawFieldNames& names = {});

// Throws InputError("<where>: <first problem>; <second> ...") when validate_traction_law finds any.
void require_valid_traction_law(const TractionLawParams& p, const std::string& where);

// The PARAM of OPTION 9 when the card leaves it blank (LS-DYNA's default, 1.0 = linear power law).
inline constexpr double kDefaultMixedModeExponent = 1.0;

// Peak traction below which a bilinear cohesive zone spans `elements_in_zone` segments of length
// `segment_length` (Turon, Davila, Camanho & Costa 2007, Eng. Fract. Mech. 74:1665, the cohesive-zone
// length l_cz = M E G_c / tau^2 with M = 9 pi / 32, solved for tau with l_cz = N l_e):
//   tau_N = sqrt(9 pi E G_c / (32 N l_e)).
// E is the ply modulus transverse to the interface (E_c for a laminate). Turon et al. recommend
// N >= 3 (more for accurate peak loads).
double process_zone_strength(double transverse_modulus, double g_c, double segment_length, double elements_in_zone);

// The law with NFLS and SFLS lowered to process_zone_strength (with ERATEN and ERATES) where that is
// smaller; G_c and the stiffness are kept, so the dissipated energy is unchanged. The characteristic
// length is sqrt(segment area), as for LS-DYNA's NFLS/SFLS curves of OPTION 9 and *MAT_138 T/S < 0.
// Only for the energy-based laws (OPTION 7, 9); OPTION 6 is returned unchanged (its energy is set
// by NFLS and CCRIT).
TractionLawParams scale_strengths_to_length(TractionLawParams p, double transverse_modulus, double segment_area,
                                            double elements_in_zone);

}  // namespace plyimpact::cohesive
