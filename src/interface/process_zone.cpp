#include "interface/process_zone.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "cohesive/law_parameters.hpp"
#include "contact/geometry.hpp"
#include "core/error.hpp"

namespace plyimpact::interface {

namespace {

// Reference area of each lower segment of `itf` (the contact module's bilinear segment area).
std::vector<double> segment_areas(const model::Model& model, const model::Interface& itf) {
  const std::size_t ns = itf.lower_segments.size() / 4;
  std::vector<double> area(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    double xq[12];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) xq[3 * a + i] = model.X[3 * std::size_t(itf.lower_segments[4 * s + a]) + i];
    area[s] = contact::quad_area(xq);
  }
  return area;
}

// The strengths of items whose characteristic areas are `areas`.
SegmentStrengths strengths_for(const model::Interface& itf, const std::vector<double>& areas) {
  SegmentStrengths out;
  const auto& spec = *itf.tiebreak;
  out.nfls.resize(areas.size());
  out.sfls.resize(areas.size());
  for (std::size_t k = 0; k < areas.size(); ++k) {
    const cohesive::TractionLawParams p =
        cohesive::scale_strengths_to_length(spec.law, itf.transverse_modulus, areas[k], spec.process_zone_elements);
    out.nfls[k] = p.NFLS;
    out.sfls[k] = p.SFLS;
  }
  return out;
}

// Whether the interface asks for the strengths; refuses the key where no ply modulus is known (an
// interface that is not a laminate's), rather than leave the card's strengths in silence.
bool active(const model::Interface& itf) {
  if (!itf.tiebreak || !(itf.tiebreak->process_zone_elements > 0)) return false;
  if (!(itf.transverse_modulus > 0))
    throw InputError(config::at(itf.tiebreak->where)
                     << "process_zone_elements needs the through-thickness modulus of the plies of interface " << itf.id
                     << ", which is not known here; allowed on the interfaces of a laminate: section");
  return true;
}

}  // namespace

SegmentStrengths pair_strengths(const model::Model& model, const model::Interface& itf) {
  if (!active(itf)) return {};
  const std::vector<double> seg = segment_areas(model, itf);
  // Pair of each lower node: the segments name nodes, the pairs are indexed by their lower node.
  std::vector<Index> pair_of(model.num_nodes(), -1);
  for (std::size_t p = 0; p < itf.num_pairs(); ++p) pair_of[std::size_t(itf.lower_nodes[p])] = Index(p);
  std::vector<double> sum(itf.num_pairs(), 0.0), count(itf.num_pairs(), 0.0);
  for (std::size_t s = 0; s < seg.size(); ++s)
    for (int a = 0; a < 4; ++a) {
      const Index p = pair_of[std::size_t(itf.lower_segments[4 * s + a])];
      if (p < 0) continue;
      sum[std::size_t(p)] += seg[s];
      count[std::size_t(p)] += 1;
    }
  std::vector<double> mean(itf.num_pairs());
  for (std::size_t p = 0; p < mean.size(); ++p) mean[p] = count[p] > 0 ? sum[p] / count[p] : itf.area[p];
  return strengths_for(itf, mean);
}

SegmentStrengths segment_strengths(const model::Model& model, const model::Interface& itf) {
  if (!active(itf)) return {};
  return strengths_for(itf, segment_areas(model, itf));
}

std::string strengths_text(const SegmentStrengths& s, const model::Interface& itf, const char* items) {
  if (s.nfls.empty()) return "";
  const auto& law = itf.tiebreak->law;
  std::size_t lowered = 0;
  for (std::size_t k = 0; k < s.nfls.size(); ++k)
    if (s.nfls[k] < law.NFLS || s.sfls[k] < law.SFLS) ++lowered;
  const auto [n_lo, n_hi] = std::minmax_element(s.nfls.begin(), s.nfls.end());
  const auto [s_lo, s_hi] = std::minmax_element(s.sfls.begin(), s.sfls.end());
  std::ostringstream t;
  t << std::setprecision(3) << "strengths for " << itf.tiebreak->process_zone_elements << " segments in the process zone (E "
    << itf.transverse_modulus * 1e-9 << " GPa): NFLS " << *n_lo * 1e-6 << "-" << *n_hi * 1e-6 << " MPa, SFLS "
    << *s_lo * 1e-6 << "-" << *s_hi * 1e-6 << " MPa, lowered at " << lowered << " of " << s.nfls.size() << " "
    << items;
  return t.str();
}

}  // namespace plyimpact::interface
