#include "run/coupon_probe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace plyimpact::run {

namespace {

const std::vector<Index>& nodes_of(const model::Model& model, const std::string& name) {
  for (const auto& s : model.node_sets)
    if (s.name == name) return s.nodes;
  throw RunError(msg() << "coupon: no node set '" << name << "' in the model");
}

double mean_displacement(const std::vector<Index>& nodes, const solver::State& s, const std::vector<double>& X,
                         int axis) {
  if (nodes.empty()) return 0.0;  // the ground
  double sum = 0;
  for (Index n : nodes) sum += s.x[3 * std::size_t(n) + axis] - X[3 * std::size_t(n) + axis];
  return sum / double(nodes.size());
}

}  // namespace

CouponProbe::CouponProbe(const model::Model& model) : model_(model) {
  const config::CouponSpec& c = *model.coupon;
  axis_ = c.axis;
  origin_ = c.crack_origin;
  interface_ = c.interface;
  load_sign_ = c.load == c.upper ? 1.0 : -1.0;
  if (!c.upper.empty()) upper_ = nodes_of(model, c.upper);
  if (!c.lower.empty()) lower_ = nodes_of(model, c.lower);
  reaction_ = -1;
  for (std::size_t k = 0; k < model.constrained_sets.size(); ++k)
    if (model.node_sets[model.constrained_sets[k]].name == c.load) reaction_ = int(k);
  if (reaction_ < 0) throw RunError(msg() << "coupon: the load set '" << c.load << "' carries no boundary condition");
  const auto itf = std::find_if(model.interfaces.begin(), model.interfaces.end(),
                                [&](const model::Interface& i) { return i.id == c.interface; });
  if (itf == model.interfaces.end() || !itf->tiebreak)
    throw RunError(msg() << "coupon: interface " << c.interface << " has no tiebreak pairs or cohesive elements in the model");
}

const CouponProbe::Found& CouponProbe::find(const solver::Solver& solver) const {
  if (found_.source) return found_;
  for (const auto& c : solver.contributors()) {
    const auto* source = dynamic_cast<const interface::InterfaceSampleSource*>(c.get());
    for (std::size_t i = 0; source && i < source->num_interfaces(); ++i) {
      const interface::InterfaceLayout& l = source->layout(i);
      if (l.id != interface_ || !l.contact.empty()) continue;
      found_.source = source;
      found_.index = i;
      // Rows of points: distinct x within a tolerance far below any segment length.
      auto& rows = found_.rows;
      for (std::size_t p = 0; p < l.size(); ++p) rows.push_back(l.reference[3 * p]);
      std::sort(rows.begin(), rows.end());
      const double tol = 1e-9 * std::max(1.0, std::abs(rows.empty() ? 1.0 : rows.back()));
      rows.erase(std::unique(rows.begin(), rows.end(), [&](double a, double b) { return b - a < tol; }), rows.end());
      return found_;
    }
  }
  return found_;
}

double CouponProbe::load(const solver::Solver& solver) const {
  return load_sign_ * solver.state().reaction[3 * std::size_t(reaction_) + axis_];
}

double CouponProbe::opening(const solver::Solver& solver) const {
  const auto& s = solver.state();
  return mean_displacement(upper_, s, model_.X, axis_) - mean_displacement(lower_, s, model_.X, axis_);
}

// The furthest separated row, then midway to the next row: the separated point's tributary strip
// is traction-free up to there (its neighbour ahead still carries the bond). For pairs and corner
// points the rows are the nodes'; for 2 x 2 Gauss points midway between the two rows of a segment is
// its mid-line and midway between rows of neighbouring segments is their common node (a uniform mesh),
// which are the bounds of each point's quadrant.
double CouponProbe::crack_length(const solver::Solver& solver) const {
  const Found& f = find(solver);
  if (!f.source) return 0.0;
  const interface::InterfaceLayout& l = f.source->layout(f.index);
  const std::vector<double>& damage = f.source->damage(f.index);
  double front = -std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < damage.size(); ++p)
    if (damage[p] >= 1) front = std::max(front, l.reference[3 * p]);
  if (!std::isfinite(front)) return 0.0;
  const auto next = std::upper_bound(f.rows.begin(), f.rows.end(), front + 1e-9 * std::max(1.0, std::abs(front)));
  if (next != f.rows.end()) front = 0.5 * (front + *next);
  return front - origin_;
}

void CouponProbe::values(const solver::Solver& solver, std::vector<double>& row) const {
  row.insert(row.end(), {load(solver), opening(solver), crack_length(solver)});
}

}  // namespace plyimpact::run
