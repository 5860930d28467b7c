#include "interface/interface_tiebreaks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <omp.h>

#include "element/hex8.hpp"
#include "interface/process_zone.hpp"

namespace plyimpact::interface {

namespace {

// Below this fraction of the elements' step the interface's bound is worth a warning.
constexpr double kInterfaceStepWarnRatio = 0.5;

// A separated pair pressed deeper than this fraction of the thinnest element on either side of its
// interface is released (cohesive::TiebreakPairsSpec::release_depth): the fraction LS-DYNA's
// penalty contacts use by default for solids (PENMAX 0.4 of the element thickness).
constexpr double kReleaseDepthFraction = 0.4;

// Whether X (x, y) lies in the pre-crack region of `spec` (closed, with a round-off margin).
bool in_precrack(const config::InterfaceLawSpec& spec, const double* X) {
  const double tol = 1e-9 * std::max(spec.precrack_x[1], spec.precrack_y[1]);
  return X[0] >= spec.precrack_x[0] - tol && X[0] <= spec.precrack_x[1] + tol && X[1] >= spec.precrack_y[0] - tol &&
         X[1] <= spec.precrack_y[1] + tol;
}

// Pairs whose lower node lies in the pre-crack region.
std::vector<char> precrack_pairs(const model::Model& model, const model::Interface& itf) {
  std::vector<char> in(itf.num_pairs(), 0);
  const auto& spec = *itf.tiebreak;
  if (!spec.has_precrack) return in;
  for (std::size_t p = 0; p < in.size(); ++p) in[p] = in_precrack(spec, &model.X[3 * std::size_t(itf.lower_nodes[p])]);
  return in;
}

const char* option_name(cohesive::TiebreakOption o) {
  switch (o) {
    case cohesive::TiebreakOption::StressCcrit: return "OPTION 6 (stress onset, linear softening to CCRIT)";
    case cohesive::TiebreakOption::DiscreteCrack:
      return "OPTION 7 (assumed law: OPTION 9 bilinear with alpha = 1, K_t = K_n, friction tan(PARAM); "
             "LS-DYNA's own law not documented, see docs/delamination.md)";
    case cohesive::TiebreakOption::MixedMode: return "OPTION 9 (bilinear mixed mode)";
  }
  return "";
}

}  // namespace

std::string tiebreak_law_text(const cohesive::TractionLawParams& p) {
  std::ostringstream s;
  s << option_name(p.option) << ", NFLS " << p.NFLS * 1e-6 << " MPa, SFLS " << p.SFLS * 1e-6 << " MPa";
  if (p.option != cohesive::TiebreakOption::StressCcrit)
    s << ", ERATEN " << p.ERATEN << " J/m^2, ERATES " << p.ERATES << " J/m^2";
  if (!std::isnan(p.PARAM)) s << ", PARAM " << p.PARAM;
  s << ", CN " << p.CN * 1e-12 << " kN/mm^3";
  if (p.option == cohesive::TiebreakOption::MixedMode) s << ", CT2CN " << p.CT2CN;
  return s.str();
}

namespace {

bool is_cohesive(const model::Interface& itf) {
  return itf.tiebreak && itf.tiebreak->model == config::InterfaceLawSpec::Model::Cohesive;
}

std::string mat138_text(const cohesive::Mat138Params& p, const cohesive::TractionLawParams& law) {
  std::ostringstream s;
  s << "*MAT_138 cohesive elements (8-node, " << (p.INTFAIL > 0 ? "2x2 Gauss" : "4 Newton-Cotes (corner)")
    << " points; the OPTION 9 law), EN " << p.EN * 1e-12
    << " kN/mm^3, ET " << p.ET * 1e-12 << " kN/mm^3, T " << law.NFLS * 1e-6 << " MPa, S " << law.SFLS * 1e-6
    << " MPa, GIC " << p.GIC << " J/m^2, GIIC " << p.GIIC << " J/m^2, XMU " << p.XMU;
  if (p.RO > 0) s << ", RO " << p.RO << " kg/m^2";
  return s.str();
}

}  // namespace

cohesive::CohesiveElements make_interface_cohesive(const model::Model& model, const model::Interface& itf) {
  const std::vector<Index> faces = cohesive::pair_faces_from_segments(itf.lower_nodes, itf.lower_segments);
  cohesive::CohesiveElementsSpec spec;
  spec.integration = itf.tiebreak->mat138.INTFAIL > 0 ? cohesive::CohesiveIntegration::Gauss
                                                      : cohesive::CohesiveIntegration::NewtonCotes;
  const std::size_t ne = faces.size() / 4;
  spec.nodes.resize(8 * ne);
  for (std::size_t e = 0; e < ne; ++e)
    for (int a = 0; a < 4; ++a) {
      const Index pair = faces[4 * e + a];
      spec.nodes[8 * e + a] = itf.lower_nodes[pair];
      spec.nodes[8 * e + 4 + a] = itf.upper_nodes[pair];
    }
  SegmentStrengths strengths = segment_strengths(model, itf);
  spec.nfls = std::move(strengths.nfls);
  spec.sfls = std::move(strengths.sfls);
  cohesive::CohesiveElements elements(itf.tiebreak->law, std::move(spec), model.X.data(), model.mass.data());
  const auto& law = *itf.tiebreak;
  if (law.has_precrack) {
    std::vector<double> at(3 * elements.num_points());
    elements.point_positions(model.X.data(), at.data());
    for (std::size_t p = 0; p < elements.num_points(); ++p)
      if (in_precrack(law, &at[3 * p])) elements.separate_point(p);
  }
  return elements;
}

// kReleaseDepthFraction times the smallest characteristic length V / A_max (for a ply element, its
// thickness) of the elements with a node on the interface, at the reference geometry.
static double interface_release_depth(const model::Model& model, const model::Interface& itf) {
  std::vector<char> on(model.num_nodes(), 0);
  for (const auto* nodes : {&itf.lower_nodes, &itf.upper_nodes})
    for (Index node : *nodes) on[std::size_t(node)] = 1;
  double length = std::numeric_limits<double>::infinity();
  for (const auto& blk : model.blocks) {
    if (blk.rigid) continue;
    for (std::size_t e = 0; e < blk.size(); ++e) {
      const Index* conn = &blk.conn[8 * e];
      if (!std::any_of(conn, conn + 8, [&](Index n) { return on[std::size_t(n)] != 0; })) continue;
      element::NodeVec x;
      model::gather_reference(model.X, conn, x);
      length = std::min(length, element::hex8_volume(x) / element::hex8_max_face_area(x));
    }
  }
  return kReleaseDepthFraction * length;
}

cohesive::TiebreakPairs make_interface_pairs(const model::Model& model, const model::Interface& itf) {
  cohesive::TiebreakPairsSpec spec;
  spec.lower = itf.lower_nodes;
  spec.upper = itf.upper_nodes;
  spec.area = itf.area;
  spec.faces = cohesive::pair_faces_from_segments(itf.lower_nodes, itf.lower_segments);
  spec.normals = itf.normal;
  spec.release_depth = interface_release_depth(model, itf);
  SegmentStrengths strengths = pair_strengths(model, itf);
  spec.nfls = std::move(strengths.nfls);
  spec.sfls = std::move(strengths.sfls);
  cohesive::TiebreakPairs pairs(itf.tiebreak->law, std::move(spec), model.X.data(), model.mass.data());
  const std::vector<char> separated = precrack_pairs(model, itf);
  for (std::size_t p = 0; p < separated.size(); ++p)
    if (separated[p]) pairs.separate_pair(p);
  return pairs;
}

model::Subsystem InterfaceTiebreaks::describe(const model::Model& model) {
  std::size_t tagged = 0, pairs = 0;
  for (const auto& itf : model.interfaces) {
    pairs += itf.num_pairs();
    if (itf.tiebreak) ++tagged;
  }
  if (model.interfaces.empty())
    return {"delamination", false, "left out: no delaminating interface, so no interface node is duplicated"};
  if (tagged == 0)
    return {"delamination", false,
            std::to_string(model.interfaces.size()) + " interface(s) tagged with " + std::to_string(pairs) +
                " node pairs, merged (interfaces: model: merged): the plies are bonded and cannot delaminate; "
                "model: tiebreak gives them a law"};
  // One clause per run of interfaces with the same law: "interfaces 1, 2, 3: <law>".
  std::ostringstream d;
  d << tagged << " delaminating interface(s) with a law, " << pairs << " node pairs";
  double dt_min = std::numeric_limits<double>::infinity(), precrack = 0;
  int dt_id = 0;
  std::string last_law;
  for (const auto& itf : model.interfaces) {
    if (!itf.tiebreak) continue;
    double step = 0;
    std::string law;
    if (is_cohesive(itf)) {
      const cohesive::CohesiveElements kernel = make_interface_cohesive(model, itf);
      law = mat138_text(itf.tiebreak->mat138, itf.tiebreak->law);
      if (const auto t = strengths_text(segment_strengths(model, itf), itf, "elements"); !t.empty()) law += ", " + t;
      for (std::size_t p = 0; p < kernel.num_points(); ++p)
        if (kernel.damage()[p] >= 1) precrack += kernel.point_area(p);
      step = kernel.stable_step();
    } else {
      const cohesive::TiebreakPairs kernel = make_interface_pairs(model, itf);
      law = tiebreak_law_text(itf.tiebreak->law);
      if (const auto t = strengths_text(pair_strengths(model, itf), itf, "pairs"); !t.empty()) law += ", " + t;
      for (std::size_t p = 0; p < kernel.size(); ++p)
        if (kernel.damage()[p] >= 1) precrack += kernel.area(p);
      step = kernel.stable_step();
    }
    if (law != last_law) d << "; " << law << ": interface " << itf.id;
    else d << ", " << itf.id;
    last_law = law;
    if (step < dt_min) {
      dt_min = step;
      dt_id = itf.id;
    }
  }
  if (precrack > 0) d << "; pre-crack " << precrack << " m^2";
  d << "; stiffest pair step " << dt_min << " s (interface " << dt_id
    << ", no TSSFAC), combined with the element step as contact springs are";
  return {"delamination", true, d.str()};
}

InterfaceTiebreaks::InterfaceTiebreaks(const model::Model& model, double dt_element) : model_(&model) {
  stable_step_ = std::numeric_limits<double>::infinity();
  for (const auto& itf : model.interfaces) {
    if (!itf.tiebreak) continue;
    if (is_cohesive(itf)) {
      cohesive_.push_back(make_interface_cohesive(model, itf));
      cohesive_ids_.push_back(itf.id);
      layouts_.push_back(cohesive_layout(model, itf, cohesive_.back()));
      columns_.emplace_back(true, cohesive_.size() - 1);
      stable_step_ = std::min(stable_step_, cohesive_.back().stable_step());
    } else {
      pairs_.push_back(make_interface_pairs(model, itf));
      ids_.push_back(itf.id);
      pair_interfaces_.push_back(&itf);
      layouts_.push_back(pair_layout(model, itf));
      columns_.emplace_back(false, pairs_.size() - 1);
      stable_step_ = std::min(stable_step_, pairs_.back().stable_step());
    }
  }
  // Interfaces may run in parallel when no node belongs to two of them (one element through each
  // ply: a ply's lower and upper faces have distinct nodes).
  std::vector<char> seen(model.num_nodes(), 0);
  for (const auto& itf : model.interfaces) {
    if (!itf.tiebreak) continue;
    for (const auto* nodes : {&itf.lower_nodes, &itf.upper_nodes})
      for (Index node : *nodes) {
        if (seen[std::size_t(node)]) across_interfaces_ = false;
        seen[std::size_t(node)] = 1;
      }
  }
  // Sharing control of the step with the elements is normal for the seed's CN on thin plies (the
  // two bounds combine, solver::combined_step; `check` prints both): a warning only when the
  // interface more than halves the step, i.e. at least doubles the run's cost.
  if (stable_step_ < kInterfaceStepWarnRatio * dt_element) {
    std::ostringstream w;
    w << "interface stiffness controls the step: the stiffest tiebreak pair or cohesive node pair alone allows " << stable_step_ << " s against the elements' "
      << dt_element << " s, so the step is " << solver::combined_step(dt_element, stable_step_)
      << " s before TSSFAC (a CN lower by a factor k lengthens the interface's bound by sqrt(k))";
    warnings_.push_back(w.str());
  }
}

void InterfaceTiebreaks::on_erosion(const solver::AliveMask& alive, const std::vector<double>& /*x*/) {
  if (pairs_.empty()) return;
  const model::Model& model = *model_;
  std::vector<char> held(model.num_nodes(), 0);  // 1: some live deformable element holds the node
  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    const auto& blk = model.blocks[b];
    if (blk.rigid) continue;
    const std::vector<char>& mask = alive[b];
    for (std::size_t e = 0; e < blk.size(); ++e)
      if (mask.empty() || mask[e])
        for (int k = 0; k < 8; ++k) held[std::size_t(blk.conn[8 * e + k])] = 1;
  }
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const model::Interface& itf = *pair_interfaces_[i];
    for (std::size_t p = 0; p < itf.num_pairs(); ++p)
      if (!pairs_[i].released(p) && (!held[std::size_t(itf.lower_nodes[p])] || !held[std::size_t(itf.upper_nodes[p])]))
        pairs_[i].release_pair(p);
  }
}

void InterfaceTiebreaks::mark_held_nodes(std::vector<char>& held) const {
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const model::Interface& itf = *pair_interfaces_[i];
    for (std::size_t p = 0; p < itf.num_pairs(); ++p)
      if (!pairs_[i].released(p)) held[std::size_t(itf.lower_nodes[p])] = held[std::size_t(itf.upper_nodes[p])] = 1;
  }
  for (const auto& e : cohesive_)
    for (Index node : e.nodes()) held[std::size_t(node)] = 1;
}

void InterfaceTiebreaks::apply(const solver::ForceContext& c) {
  // One interface per iteration: with no node shared between interfaces each node's force gets
  // the contributions of one interface only, added in that interface's own fixed order, so the
  // forces do not depend on the thread count (and an interface's own parallel loop, nested here,
  // runs on this iteration's thread). One parallel region for all interfaces instead of one each.
  // Static, not dynamic: the interfaces are stacked in ply order like the element pass's chunks, so
  // each thread gets the interfaces inside the plies whose elements it computes, and their nodes'
  // lines stay in its cache (dynamic handed an interface to either thread, cycle by cycle).
  const long np = long(pairs_.size()), nk = np + long(cohesive_.size());
#pragma omp parallel for schedule(static) if (across_interfaces_ && nk > 1 && omp_get_max_threads() > 1)
  for (long k = 0; k < nk; ++k) {
    if (k < np) pairs_[std::size_t(k)].apply(c.x, c.v, c.f, c.dt);
    else cohesive_[std::size_t(k - np)].apply(c.x, c.v, c.f, c.dt);
  }
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& p : pairs_) dt = std::min(dt, p.stable_step());
  for (const auto& e : cohesive_) dt = std::min(dt, e.stable_step());
  stable_step_ = dt;
}

void InterfaceTiebreaks::energies(std::span<double> out) const {
  double elastic = 0, dissipated = 0;
  for (const auto& p : pairs_) {
    elastic += p.elastic_energy();
    dissipated += p.dissipated_energy();
  }
  for (const auto& e : cohesive_) {
    elastic += e.elastic_energy();
    dissipated += e.dissipated_energy();
  }
  out[0] = elastic;
  out[1] = dissipated;
}

double InterfaceTiebreaks::delaminated_area() const {
  double a = 0;
  for (const auto& p : pairs_) a += p.separated_area();
  for (const auto& e : cohesive_) a += e.separated_area();
  return a;
}

std::vector<std::string> InterfaceTiebreaks::history_columns() const {
  std::vector<std::string> cols{"delaminated_area"};
  for (const auto& [is_cohesive_column, k] : columns_)
    cols.push_back("delaminated_area_" + std::to_string(is_cohesive_column ? cohesive_ids_[k] : ids_[k]));
  return cols;
}

void InterfaceTiebreaks::history_values(std::vector<double>& row) const {
  row.push_back(delaminated_area());
  for (std::size_t i = 0; i < columns_.size(); ++i) row.push_back(delaminated_area(i));
}

void InterfaceTiebreaks::sample(std::size_t i, const double* x, cohesive::PairSample* out) const {
  const auto& [is_cohesive_column, k] = columns_[i];
  if (is_cohesive_column) cohesive_[k].sample(x, out);
  else pairs_[k].sample(x, out);
}

double InterfaceTiebreaks::delaminated_area(std::size_t i) const {
  const auto& [is_cohesive_column, k] = columns_[i];
  return is_cohesive_column ? cohesive_[k].separated_area() : pairs_[k].separated_area();
}

const std::vector<double>& InterfaceTiebreaks::damage(std::size_t i) const {
  const auto& [is_cohesive_column, k] = columns_[i];
  return is_cohesive_column ? cohesive_[k].damage() : pairs_[k].damage();
}

void InterfaceTiebreaks::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "interfaces");
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    StateGroup one(visitor, "interface " + std::to_string(ids_[i]));
    pairs_[i].visit_state(visitor);
  }
  for (std::size_t i = 0; i < cohesive_.size(); ++i) {
    StateGroup one(visitor, "cohesive interface " + std::to_string(cohesive_ids_[i]));
    cohesive_[i].visit_state(visitor);
  }
}

}  // namespace plyimpact::interface
