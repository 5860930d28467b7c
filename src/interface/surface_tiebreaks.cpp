#include "interface/surface_tiebreaks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "contact/geometry.hpp"
#include "contact/surface.hpp"
#include "interface/interface_tiebreaks.hpp"

namespace plyimpact::interface {

namespace {
// Below this fraction of the elements' step the interface's bound is worth a warning.
constexpr double kInterfaceStepWarnRatio = 0.5;
}  // namespace
namespace {

struct SideFaces {
  std::vector<Index> quads;          // (num, 4)
  std::vector<double> thickness;     // (num) m
  std::vector<int> block;            // (num)
  std::vector<Index> element;        // (num)
};

// The exterior faces of a side's blocks with the depth of the element behind each (volume / face
// area) or the card's contact thickness when given.
SideFaces side_faces(const model::Model& model, const model::ContactSide& side, double card_thickness) {
  SideFaces out;
  const contact::SurfaceBuilder builder(model, side.blocks);
  for (const auto& face : builder.exterior(nullptr)) {
    const auto& b = model.blocks[std::size_t(face.block)];
    double xq[12];
    for (int a = 0; a < 4; ++a) {
      const Index node = b.conn[8 * std::size_t(face.element) + std::size_t(contact::kHexFaces[face.face][a])];
      out.quads.push_back(node);
      for (int i = 0; i < 3; ++i) xq[3 * a + i] = model.X[3 * std::size_t(node) + i];
    }
    const double area = contact::quad_area(xq);
    out.thickness.push_back(card_thickness > 0 ? card_thickness : b.volume0[std::size_t(face.element)] / area);
    out.block.push_back(face.block);
    out.element.push_back(face.element);
  }
  return out;
}

}  // namespace

ContactTying tie_contact(const model::Model& model, const model::Contact& contact) {
  const SideFaces slave = side_faces(model, contact.a, contact.spec.SST);
  const SideFaces master = side_faces(model, contact.b, contact.spec.MST);
  TyingSurfaces s{slave.quads, slave.thickness, master.quads, master.thickness};
  ContactTying out;
  out.result = tie_slave_nodes(s, model.X.data());
  out.slave_faces = slave.quads;
  for (Index face : out.result.tie_master_face) {
    out.master_block.push_back(master.block[std::size_t(face)]);
    out.master_element.push_back(master.element[std::size_t(face)]);
  }
  return out;
}

model::Subsystem SurfaceTiebreaks::describe(const model::Model& model) {
  if (model.tiebreak_contacts.empty())
    return {"tiebreak_contacts", false, "left out: the scene defines no tiebreak contact between parts"};
  std::ostringstream d;
  for (const auto& c : model.tiebreak_contacts) {
    const ContactTying tying = tie_contact(model, c);
    d << (d.tellp() > 0 ? "; " : "") << c.spec.name << ": slave " << c.a.label << " tied to master " << c.b.label
      << ", " << tiebreak_law_text(*c.spec.tiebreak) << "; " << tying_summary(tying.result, model.X.data());
  }
  return {"tiebreak_contacts", true, d.str()};
}

SurfaceTiebreaks::SurfaceTiebreaks(const model::Model& model, double dt_element) {
  stable_step_ = std::numeric_limits<double>::infinity();
  int id = 0;  // outputs: numbered after the laminate's interfaces
  for (const auto& itf : model.interfaces) id = std::max(id, itf.id);
  for (const auto& c : model.tiebreak_contacts) {
    ContactTying tying = tie_contact(model, c);
    if (!tying.result.untied.empty() || tying.result.ties.empty())
      warnings_.push_back("tiebreak contact '" + c.spec.name + "': " + tying_summary(tying.result, model.X.data()));
    names_.push_back(c.spec.name);
    ties_.emplace_back(*c.spec.tiebreak, tying.result.ties, model.X.data(), model.mass.data());
    std::vector<int> blocks = c.a.blocks;
    blocks.insert(blocks.end(), c.b.blocks.begin(), c.b.blocks.end());
    layouts_.push_back(tie_layout(model, ++id, c.spec.name, ties_.back(), tying.slave_faces, blocks));
    tying_.push_back(std::move(tying));
    stable_step_ = std::min(stable_step_, ties_.back().stable_step());
  }
  // Sharing control of the step with the elements is normal for the seed's CN on thin plies (the
  // two bounds combine, solver::combined_step; `check` prints both): a warning only when the
  // interface more than halves the step, i.e. at least doubles the run's cost.
  if (stable_step_ < kInterfaceStepWarnRatio * dt_element) {
    std::ostringstream w;
    w << "tiebreak stiffness controls the step: the stiffest tie alone allows " << stable_step_ << " s against the elements' "
      << dt_element << " s, so the step is " << solver::combined_step(dt_element, stable_step_)
      << " s before TSSFAC (a CN lower by a factor k lengthens the interface's bound by sqrt(k))";
    warnings_.push_back(w.str());
  }
}

void SurfaceTiebreaks::apply(const solver::ForceContext& c) {
  for (auto& t : ties_) t.apply(c.x, c.f);
}

void SurfaceTiebreaks::energies(std::span<double> out) const {
  double elastic = 0, dissipated = 0;
  for (const auto& t : ties_) {
    elastic += t.elastic_energy();
    dissipated += t.dissipated_energy();
  }
  out[0] = elastic;
  out[1] = dissipated;
}

void SurfaceTiebreaks::on_erosion(const solver::AliveMask& alive, const std::vector<double>& /*x*/) {
  for (std::size_t c = 0; c < ties_.size(); ++c) {
    const ContactTying& t = tying_[c];
    for (std::size_t k = 0; k < t.master_block.size(); ++k) {
      const auto& mask = alive[std::size_t(t.master_block[k])];
      if (!mask.empty() && !mask[std::size_t(t.master_element[k])]) ties_[c].release(k);
    }
  }
}

void SurfaceTiebreaks::mark_held_nodes(std::vector<char>& held) const {
  for (const auto& t : ties_)
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t.released(k)) continue;
      const cohesive::SegmentTie& tie = t.tie(k);
      held[std::size_t(tie.slave)] = 1;
      for (Index m : tie.master) held[std::size_t(m)] = 1;
    }
}

std::vector<std::string> SurfaceTiebreaks::history_columns() const {
  std::vector<std::string> cols;
  for (const auto& n : names_) cols.push_back("delaminated_area_" + n);
  return cols;
}

void SurfaceTiebreaks::history_values(std::vector<double>& row) const {
  for (const auto& t : ties_) row.push_back(t.separated_area());
}

void SurfaceTiebreaks::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "tiebreak contacts");
  for (std::size_t c = 0; c < ties_.size(); ++c) {
    StateGroup one(visitor, "contact " + names_[c]);
    ties_[c].visit_state(visitor);
  }
}

}  // namespace plyimpact::interface
