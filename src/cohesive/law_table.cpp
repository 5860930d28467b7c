#include "cohesive/law_table.hpp"

#include <map>
#include <utility>

#include "core/error.hpp"

namespace plyimpact::cohesive {

LawTable::LawTable(const TractionLawParams& card, std::size_t count, const std::vector<double>& nfls,
                   const std::vector<double>& sfls)
    : laws_{make_traction_law(card)}, index_(count, 0) {
  if (nfls.empty() && sfls.empty()) return;
  if (nfls.size() != count || sfls.size() != count)
    throw InputError(msg() << "interface strengths: " << nfls.size() << " NFLS and " << sfls.size() << " SFLS for "
                           << count << " points");
  std::map<std::pair<double, double>, std::uint32_t> seen{{{card.NFLS, card.SFLS}, 0}};
  for (std::size_t k = 0; k < count; ++k) {
    const auto [it, added] = seen.emplace(std::pair{nfls[k], sfls[k]}, std::uint32_t(laws_.size()));
    if (added) {
      TractionLawParams p = card;
      p.NFLS = nfls[k];
      p.SFLS = sfls[k];
      require_valid_traction_law(p, msg() << "interface point " << k << " (its own NFLS " << nfls[k] * 1e-6
                                          << " MPa, SFLS " << sfls[k] * 1e-6 << " MPa)");
      laws_.push_back(make_traction_law(p));
    }
    index_[k] = it->second;
  }
}

std::size_t LawTable::num_lowered() const {
  std::size_t n = 0;
  for (std::uint32_t i : index_) {
    const TractionLaw& law = laws_[i];
    if (law.delta_n0 < card().delta_n0 || law.delta_s0 < card().delta_s0) ++n;
  }
  return n;
}

}  // namespace plyimpact::cohesive
