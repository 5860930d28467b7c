#include "cohesive/traction_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace plyimpact::cohesive {

TractionLaw make_traction_law(const TractionLawParams& p) {
  require_valid_traction_law(p, "tiebreak law");
  TractionLaw law;
  law.option = p.option;
  law.kn = p.CN;
  law.kt = p.option == TiebreakOption::MixedMode ? p.CT2CN * p.CN : p.CN;
  law.delta_n0 = p.NFLS / law.kn;
  law.delta_s0 = p.SFLS / law.kt;
  law.k_max = std::max(law.kn, law.kt);
  law.elastic_limit = std::min(law.delta_n0, law.delta_s0) * (1 - 1e-12);
  law.mu = p.FS;
  switch (p.option) {
    case TiebreakOption::StressCcrit:
      law.ccrit = p.PARAM;
      break;
    case TiebreakOption::DiscreteCrack: {
      law.gic = p.ERATEN;
      law.giic = p.ERATES;
      law.alpha = 1;  // assumed, see the header
      const double angle_deg = std::isnan(p.PARAM) ? 0.0 : p.PARAM;
      law.mu = std::tan(angle_deg * std::numbers::pi / 180);
      break;
    }
    case TiebreakOption::MixedMode: {
      law.gic = p.ERATEN;
      law.giic = p.ERATES;
      const double param = std::isnan(p.PARAM) ? kDefaultMixedModeExponent : p.PARAM;
      if (param > 0)
        law.alpha = param;
      else
        law.bk_eta = -param;
      break;
    }
  }
  return law;
}

}  // namespace plyimpact::cohesive
