#include "model/subsystems.hpp"

#include <algorithm>
#include <set>
#include <sstream>

namespace plyimpact::model {

namespace {

// Which elements erode at scaled strains (erosion_reference_length) and by how much, or average
// their strains over a neighbourhood (erosion_nonlocal).
Subsystem erosion_length_scaling(const Model& model) {
  std::size_t scaled = 0, elements = 0, averaged = 0;
  double largest = 1, neighbours = 0;
  std::set<std::string> names;
  for (const auto& b : model.blocks) {
    const auto& n = b.erosion_neighbours;
    if (b.erosion_scale.empty() && n.empty()) continue;
    elements += b.size();
    names.insert(model.materials[b.material].name);
    for (double k : b.erosion_scale)
      if (k > 1) ++scaled, largest = std::max(largest, k);
    const std::size_t with = n.elements_with_neighbours();
    averaged += with;
    neighbours += n.mean_count() * double(with);
  }
  if (elements == 0) return {"erosion_length_scaling", false, "left out: no *MAT_054 with erosion_reference_length"};
  std::ostringstream s;
  if (scaled == 0 && averaged == 0)
    s << "all " << elements << " elements at least their reference length: the card's DFAIL*/EFS (";
  else if (averaged == 0)
    s << scaled << " of " << elements << " elements shorter than their reference length erode at up to " << largest
      << " x the card's DFAIL*/EFS (";
  else
    s << averaged << " of " << elements << " elements shorter than their reference length erode when the mean strain "
      << "over their reference length reaches the card's DFAIL*/EFS, or their own up to " << largest
      << " x them (erosion_nonlocal; " << std::size_t(neighbours / double(averaged) + 0.5)
      << " neighbours each on average) (";
  for (auto it = names.begin(); it != names.end(); ++it) s << (it == names.begin() ? "" : ", ") << *it;
  s << ")";
  return {"erosion_length_scaling", true, s.str()};
}

}  // namespace

std::vector<Subsystem> subsystems(const Model& model) {
  std::vector<Subsystem> list;
  list.push_back({"explicit_dynamics", true, "central difference, lumped mass, Courant step x TSSFAC"});

  std::set<int> ihq;
  bool elform2 = false, ans = false, viscosity = false;
  std::size_t one_point = 0, full = 0;  // elements of each family (a scene may mix them: an impact zone)
  std::set<std::string> cards;
  for (const auto& b : model.blocks) {
    if (b.size() == 0) continue;
    if (b.elform == 1) ihq.insert(b.ihq), one_point += b.size(); else elform2 = true, full += b.size();
    if (b.elform == -2) ans = true;
    viscosity = viscosity || b.q1 > 0 || b.q2 > 0;
    cards.insert(model.materials[b.material].card);
  }
  std::ostringstream hg;
  for (int i : ihq) hg << (hg.tellp() > 0 ? ", " : "IHQ ") << i;
  if (!ihq.empty()) hg << " (" << one_point << " one-point elements)";
  list.push_back({"hourglass_control", !ihq.empty(), ihq.empty() ? "no one-point (ELFORM 1) element" : hg.str()});
  const std::string counted = std::to_string(full) + " elements, ";
  list.push_back({"fully_integrated_elements", elform2,
                  !elform2 ? "no ELFORM 2 part"
                  : ans    ? counted + "ELFORM 2 / -2, selectively reduced; -2 with assumed natural transverse shear (thin elements)"
                           : counted + "ELFORM 2, selectively reduced"});
  list.push_back({"bulk_viscosity", viscosity, viscosity ? "compression only, Q1/Q2 per section" : "Q1 = Q2 = 0"});
  std::ostringstream mats;
  for (const auto& c : cards) mats << (mats.tellp() > 0 ? ", " : "") << c;
  list.push_back({"materials", true, mats.str()});
  list.push_back({"material_axes", !model.orientations.empty(),
                  model.orientations.empty() ? "no orthotropic material"
                                             : std::to_string(model.orientations.size()) + " orientation(s)"});
  std::size_t fixed = 0, prescribed = 0;
  for (const auto& c : model.constraints) (c.curve < 0 ? fixed : prescribed)++;
  list.push_back({"boundary_conditions", !model.constraints.empty(),
                  std::to_string(fixed) + " fixed dof, " + std::to_string(prescribed) + " prescribed-velocity dof"});
  // delamination: described by the interface contributor (interface/interface_tiebreaks.hpp).
  std::string eroding;
  for (const auto& m : model.materials)
    if (m.can_fail())
      eroding += (eroding.empty() ? "" : ", ") + m.name + " (" + m.card + ")";
  if (model.control.erode_tsmin > 0) eroding += std::string(eroding.empty() ? "" : ", ") + "time step below erode_tsmin";
  list.push_back({"erosion", !eroding.empty(),
                  eroding.empty() ? "left out: no material with a failure criterion"
                                  : "elements can erode: " + eroding +
                                        "; nodes left with nothing acting on them leave the calculation with "
                                        "their kinetic energy (eroded_kinetic_energy)"});
  list.push_back(erosion_length_scaling(model));
  const auto& end = model.control.termination_contact;
  list.push_back({"termination_contact", end.has_value(),
                  end ? "the run ends once " + describe_termination_contact(*end) + ", or at termination_time"
                      : "left out: the run goes to termination_time"});
  return list;
}

std::string describe_termination_contact(const config::TerminationContactSpec& spec) {
  const char* what[] = {"resultant force", "|x component|", "|y component|", "|z component|"};
  std::ostringstream s;
  s << "contact '" << spec.contact << "' has its " << what[spec.DOF] << " at or below " << spec.THRES << " N for "
    << spec.DUR << " s (timed from ACTIM " << spec.ACTIM << " s)";
  return s.str();
}

}  // namespace plyimpact::model
