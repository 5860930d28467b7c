// The laws of an interface whose points share one card but may each have their own peak tractions
// NFLS and SFLS (strengths lowered per segment length so that the process zone spans a given
// number of segments: process_zone_strength in law_parameters.hpp). The distinct laws are kept once
// and every item (a tiebreak pair, a cohesive element) holds the index of its own, so a kernel with
// one strength pays one table lookup per damaged point and nothing more.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cohesive/law_parameters.hpp"
#include "cohesive/traction_law.hpp"

namespace plyimpact::cohesive {

class LawTable {
 public:
  LawTable() = default;
  // `count` items: item k with NFLS = nfls[k] and SFLS = sfls[k] (Pa), or all with the card's when
  // both lists are empty. Throws InputError when a list has the wrong size or a law made with its
  // strengths is not valid (validate_traction_law; the message names the item).
  LawTable(const TractionLawParams& card, std::size_t count, const std::vector<double>& nfls = {},
           const std::vector<double>& sfls = {});

  const TractionLaw& card() const { return laws_.front(); }  // the card's own strengths
  const TractionLaw& of(std::size_t item) const { return laws_[index_[item]]; }
  std::size_t size() const { return index_.size(); }
  std::size_t num_laws() const { return laws_.size(); }
  // Pa: the peak tractions of item k (NFLS = delta_n0 K_n, SFLS = delta_s0 K_t).
  double nfls(std::size_t item) const { return of(item).delta_n0 * of(item).kn; }
  double sfls(std::size_t item) const { return of(item).delta_s0 * of(item).kt; }
  // Items whose strengths are below the card's.
  std::size_t num_lowered() const;

 private:
  std::vector<TractionLaw> laws_;     // [0]: the card's; then each distinct (NFLS, SFLS) once
  std::vector<std::uint32_t> index_;  // (count) into laws_
};

}  // namespace plyimpact::cohesive
