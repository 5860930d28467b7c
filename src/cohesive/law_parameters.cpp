#include "cohesive/law_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace plyimpact::cohesive {
namespace {

bool uses_energy(TiebreakOption o) { return o != TiebreakOption::StressCcrit; }

// "NFLS is missing (Pa, > 0)" / "NFLS must be > 0 Pa (got -2e+06)"; true when usable.
bool require_positive(std::vector<std::string>& out, const char* name, double value, const char* unit) {
  if (std::isnan(value)) {
    out.push_back(msg() << name << " is missing (" << unit << ", > 0)");
    return false;
  }
  if (!(value > 0) || !std::isfinite(value)) {
    out.push_back(msg() << name << " must be > 0 " << unit << " (got " << value << ")");
    return false;
  }
  return true;
}

// Onset opening sigma/K below the final opening 2G/sigma of the bilinear law of one mode.
void require_softening(std::vector<std::string>& out, const char* mode, const char* strength, double sigma,
                       const char* stiffness, double k, const char* energy, double g) {
  const double onset = sigma / k;
  const double final_opening = 2 * g / sigma;
  if (onset < final_opening) return;
  out.push_back(msg() << mode << ": the onset opening " << strength << "/" << stiffness << " = " << onset
                      << " m is not below the final opening 2 " << energy << "/" << strength << " = "
                      << final_opening << " m (2G/sigma <= sigma/K: the law would snap back); raise " << energy
                      << " or " << stiffness << ", or lower " << strength);
}

}  // namespace

std::vector<std::string> validate_traction_law(const TractionLawParams& p, const LawFieldNames& nm) {
  std::vector<std::string> out;
  const auto o = p.option;
  if (o != TiebreakOption::StressCcrit && o != TiebreakOption::DiscreteCrack && o != TiebreakOption::MixedMode) {
    out.push_back(msg() << "OPTION " << int(o) << " is not implemented (allowed: 6, 7, 9)");
    return out;
  }
  const bool nfls = require_positive(out, nm.NFLS, p.NFLS, "Pa");
  const bool sfls = require_positive(out, nm.SFLS, p.SFLS, "Pa");
  const bool cn = require_positive(out, nm.CN, p.CN, "Pa/m");
  bool gic = true, giic = true;
  if (uses_energy(o)) {
    gic = require_positive(out, nm.ERATEN, p.ERATEN, "J/m^2");
    giic = require_positive(out, nm.ERATES, p.ERATES, "J/m^2");
  }
  bool ct2cn = true;
  if (o == TiebreakOption::MixedMode) ct2cn = require_positive(out, nm.CT2CN, p.CT2CN, "(ratio)");
  if (!(p.FS >= 0) || !std::isfinite(p.FS)) out.push_back(msg() << "FS must be >= 0 (got " << p.FS << ")");

  const double kt = o == TiebreakOption::MixedMode ? p.CT2CN * p.CN : p.CN;
  const char* kt_name = o == TiebreakOption::MixedMode ? nm.shear_stiffness : nm.CN;
  switch (o) {
    case TiebreakOption::StressCcrit: {
      if (!require_positive(out, "PARAM (CCRIT)", p.PARAM, "m")) break;
      if (nfls && cn && !(p.NFLS / p.CN < p.PARAM))
        out.push_back(msg() << "mode I: the onset opening NFLS/CN = " << p.NFLS / p.CN
                            << " m is not below CCRIT = " << p.PARAM << " m; raise PARAM (CCRIT) or CN, or lower NFLS");
      if (sfls && cn && !(p.SFLS / p.CN < p.PARAM))
        out.push_back(msg() << "mode II: the onset opening SFLS/CN = " << p.SFLS / p.CN
                            << " m is not below CCRIT = " << p.PARAM << " m; raise PARAM (CCRIT) or CN, or lower SFLS");
      break;
    }
    case TiebreakOption::DiscreteCrack:
      if (std::isnan(p.PARAM)) break;  // blank: friction angle 0
      if (!(p.PARAM >= 0 && p.PARAM < 90))
        out.push_back(msg() << "PARAM (friction angle) must be in [0, 90) degrees (got " << p.PARAM << ")");
      break;
    case TiebreakOption::MixedMode:
      if (!std::isnan(p.PARAM) && (p.PARAM == 0 || !std::isfinite(p.PARAM)))
        out.push_back(msg() << nm.PARAM << " must be > 0 (power-law exponent) or < 0 (Benzeggagh-Kenane, eta = |"
                            << nm.PARAM << "|); got " << p.PARAM);
      break;
  }
  if (uses_energy(o) && cn && ct2cn) {
    if (nfls && gic) require_softening(out, "mode I", nm.NFLS, p.NFLS, nm.CN, p.CN, nm.ERATEN, p.ERATEN);
    if (sfls && giic) require_softening(out, "mode II", nm.SFLS, p.SFLS, kt_name, kt, nm.ERATES, p.ERATES);
  }
  return out;
}

void require_valid_traction_law(const TractionLawParams& p, const std::string& where) {
  const auto problems = validate_traction_law(p);
  if (problems.empty()) return;
  std::string text = where + ": ";
  for (std::size_t i = 0; i < problems.size(); ++i) text += (i ? "; " : "") + problems[i];
  throw InputError(text);
}

double process_zone_strength(double transverse_modulus, double g_c, double segment_length, double elements_in_zone) {
  return std::sqrt(9 * std::numbers::pi * transverse_modulus * g_c / (32 * elements_in_zone * segment_length));
}

TractionLawParams scale_strengths_to_length(TractionLawParams p, double transverse_modulus, double segment_area,
                                            double elements_in_zone) {
  if (!uses_energy(p.option)) return p;
  const double length = std::sqrt(segment_area);
  p.NFLS = std::min(p.NFLS, process_zone_strength(transverse_modulus, p.ERATEN, length, elements_in_zone));
  p.SFLS = std::min(p.SFLS, process_zone_strength(transverse_modulus, p.ERATES, length, elements_in_zone));
  return p;
}

}  // namespace plyimpact::cohesive
