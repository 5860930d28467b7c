#include "interface/interface_tiebreaks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace plyimpact::interface {

namespace {

// Sets the damage of the chosen pairs to 1 through the kernel's named history, so a pre-crack is
// ordinary run state (written and read back like any other) rather than a special case.
class SeparatePairs : public StateVisitor {
 public:
  explicit SeparatePairs(const std::vector<char>& separated) : separated_(separated) {}
  void enter(std::string_view) override {}
  void leave() override {}
  void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize, void*) override {
    if (name != "damage" || elem_size != sizeof(double) || count != separated_.size()) return;
    double* d = static_cast<double*>(data);
    for (std::size_t p = 0; p < count; ++p)
      if (separated_[p]) d[p] = 1.0;
  }

 private:
  const std::vector<char>& separated_;
};

// Pairs whose lower node lies in the pre-crack region (closed, with a round-off margin).
std::vector<char> precrack_pairs(const model::Model& model, const model::Interface& itf) {
  std::vector<char> in(itf.num_pairs(), 0);
  const auto& spec = *itf.tiebreak;
  if (!spec.has_precrack) return in;
  const double tol = 1e-9 * std::max(spec.precrack_x[1], spec.precrack_y[1]);
  for (std::size_t p = 0; p < in.size(); ++p) {
    const double* X = &model.X[3 * std::size_t(itf.lower_nodes[p])];
    in[p] = X[0] >= spec.precrack_x[0] - tol && X[0] <= spec.precrack_x[1] + tol && X[1] >= spec.precrack_y[0] - tol &&
            X[1] <= spec.precrack_y[1] + tol;
  }
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

cohesive::TiebreakPairs make_interface_pairs(const model::Model& model, const model::Interface& itf) {
  cohesive::TiebreakPairsSpec spec;
  spec.lower = itf.lower_nodes;
  spec.upper = itf.upper_nodes;
  spec.area = itf.area;
  spec.faces = cohesive::pair_faces_from_segments(itf.lower_nodes, itf.lower_segments);
  spec.normals = itf.normal;
  cohesive::TiebreakPairs pairs(itf.tiebreak->law, std::move(spec), model.X.data(), model.mass.data());
  const std::vector<char> separated = precrack_pairs(model, itf);
  SeparatePairs visitor(separated);
  pairs.visit_state(visitor);
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
  d << tagged << " tiebreak interface(s), " << pairs << " node pairs";
  double dt_min = std::numeric_limits<double>::infinity(), precrack = 0;
  int dt_id = 0;
  std::string last_law;
  for (const auto& itf : model.interfaces) {
    if (!itf.tiebreak) continue;
    const cohesive::TiebreakPairs kernel = make_interface_pairs(model, itf);
    const std::string law = tiebreak_law_text(itf.tiebreak->law);
    if (law != last_law) d << "; " << law << ": interface " << itf.id;
    else d << ", " << itf.id;
    last_law = law;
    for (std::size_t p = 0; p < kernel.size(); ++p)
      if (kernel.damage()[p] >= 1) precrack += kernel.area(p);
    if (kernel.stable_step() < dt_min) {
      dt_min = kernel.stable_step();
      dt_id = itf.id;
    }
  }
  if (precrack > 0) d << "; pre-crack " << precrack << " m^2";
  d << "; stiffest pair step " << dt_min << " s (interface " << dt_id
    << ", no TSSFAC), combined with the element step as contact springs are";
  return {"delamination", true, d.str()};
}

InterfaceTiebreaks::InterfaceTiebreaks(const model::Model& model, double dt_element) {
  stable_step_ = std::numeric_limits<double>::infinity();
  for (const auto& itf : model.interfaces) {
    if (!itf.tiebreak) continue;
    pairs_.push_back(make_interface_pairs(model, itf));
    ids_.push_back(itf.id);
    stable_step_ = std::min(stable_step_, pairs_.back().stable_step());
  }
  if (stable_step_ < dt_element) {
    std::ostringstream w;
    w << "interface stiffness controls the step: the stiffest tiebreak pair alone allows " << stable_step_
      << " s against the elements' " << dt_element << " s (CN too high for the ply's mass; the step is "
      << solver::combined_step(dt_element, stable_step_) << " s before TSSFAC)";
    warnings_.push_back(w.str());
  }
}

void InterfaceTiebreaks::apply(const solver::ForceContext& c) {
  double dt = std::numeric_limits<double>::infinity();
  for (auto& p : pairs_) {
    p.apply(c.x, c.v, c.f, c.dt);
    dt = std::min(dt, p.stable_step());
  }
  stable_step_ = dt;
}

void InterfaceTiebreaks::energies(std::span<double> out) const {
  double elastic = 0, dissipated = 0;
  for (const auto& p : pairs_) {
    elastic += p.elastic_energy();
    dissipated += p.dissipated_energy();
  }
  out[0] = elastic;
  out[1] = dissipated;
}

double InterfaceTiebreaks::delaminated_area() const {
  double a = 0;
  for (const auto& p : pairs_) a += p.separated_area();
  return a;
}

std::vector<std::string> InterfaceTiebreaks::history_columns() const {
  std::vector<std::string> cols{"delaminated_area"};
  for (int id : ids_) cols.push_back("delaminated_area_" + std::to_string(id));
  return cols;
}

void InterfaceTiebreaks::history_values(std::vector<double>& row) const {
  row.push_back(delaminated_area());
  for (const auto& p : pairs_) row.push_back(p.separated_area());
}

void InterfaceTiebreaks::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "interfaces");
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    StateGroup one(visitor, "interface " + std::to_string(ids_[i]));
    pairs_[i].visit_state(visitor);
  }
}

}  // namespace plyimpact::interface
