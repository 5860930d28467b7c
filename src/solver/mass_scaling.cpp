#include "solver/mass_scaling.hpp"

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "solver/element_update.hpp"
#include "solver/solver.hpp"

namespace plyimpact::solver {

namespace {

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g %%", 100.0 * fraction);
  return buf;
}

// A spring's bound against the target, and the step the two give together (Solver::combined_step).
std::string spring_line(const std::string& name, double dt_spring, const model::Model& model) {
  const double target = model.mass_scaling.target;
  char buf[320];
  std::snprintf(buf, sizeof buf, "  %s: spring bound %.4g s, %s; with the scaled elements the step is %.4g s", name.c_str(),
                dt_spring, dt_spring < target ? "below the target: it still controls the step" : "above the target",
                model.control.tssfac * combined_step(target, dt_spring));
  return buf;
}

}  // namespace

void apply_mass_scaling(model::Model& model) {
  model::MassScalingReport& report = model.mass_scaling;
  if (report.applied) return;
  report.applied = true;
  if (!(model.control.dt2ms < 0)) return;
  const double target = -model.control.dt2ms;
  report.target = target;
  std::vector<char> rigid_node(model.num_nodes(), 0);
  for (const auto& body : model.rigid_bodies)
    for (Index n : body.nodes) rigid_node[std::size_t(n)] = 1;
  for (double m : model.mass) report.total_mass += m;
  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    model::ElementBlock& blk = model.blocks[b];
    if (blk.rigid || blk.size() == 0) continue;
    const double rho = model.materials[blk.material].density;
    model::PartAddedMass part{blk.part, 0.0, 0.0, 0};
    const std::vector<double> dt = initial_element_steps(model, b);
    std::vector<double> scale(blk.size(), 1.0);
    for (std::size_t e = 0; e < blk.size(); ++e) {
      const double m_e = rho * blk.volume0[e];
      part.mass += m_e;
      if (!(dt[e] < target)) continue;
      const double ratio = target / dt[e];
      scale[e] = ratio;
      const double dm_node = m_e * (ratio * ratio - 1.0) / 8.0;  // lumped as rho V0 / 8 per node
      for (int k = 0; k < 8; ++k) {
        const std::size_t n = std::size_t(blk.conn[8 * e + k]);
        if (rigid_node[n]) continue;
        model.mass[n] += dm_node;
        part.added += dm_node;
      }
      ++part.scaled_elements;
    }
    if (part.scaled_elements > 0) blk.step_scale = std::move(scale);
    report.total_added += part.added;
    report.parts.push_back(part);
  }
  std::string over;  // the parts above the warning fraction, one warning for all
  for (const auto& p : report.parts)
    if (p.fraction() > kAddedMassWarnFraction)
      over += (over.empty() ? "" : ", ") + model.parts[p.part].name + " +" + percent(p.fraction());
  if (!over.empty())
    report.warnings.push_back(msg() << "mass scaling (dt2ms " << model.control.dt2ms << " s) adds more than "
                                    << percent(kAddedMassWarnFraction)
                                    << " of a part's mass, the usual limit for dynamic runs: " << over
                                    << "; their inertia, wave speeds and kinetic energy change accordingly "
                                       "(lower |dt2ms|)");
  const double endmas = model.control.endmas;
  if (endmas > 0 && 100.0 * report.total_fraction() > endmas)
    throw InputError(msg() << "mass scaling (dt2ms " << model.control.dt2ms << " s) would add " << report.total_added
                           << " kg, " << percent(report.total_fraction()) << " of the model's " << report.total_mass
                           << " kg, above control.endmas " << endmas
                           << " %; allowed: a smaller |dt2ms| or a larger endmas (*CONTROL_TERMINATION ENDMAS)");
}

std::vector<std::string> mass_scaling_lines(const Solver& solver) {
  const model::Model& model = solver.model();
  const model::MassScalingReport& r = model.mass_scaling;
  std::vector<std::string> lines;
  if (!(r.target > 0)) return lines;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "mass scaling (DT2MS %.4g s): target element step %.4g s (step %.4g s with TSSFAC), added "
                "%.6g kg once at the start = %s of the deformable parts' %.6g kg, %s of the model's %.6g kg",
                model.control.dt2ms, r.target, model.control.tssfac * r.target, r.total_added,
                percent(r.total_added / r.deformable_mass()).c_str(), r.deformable_mass(),
                percent(r.total_fraction()).c_str(), r.total_mass);
  lines.push_back(buf);
  for (const auto& p : r.parts) {
    std::snprintf(buf, sizeof buf, "  part %s: %lld of %zu elements scaled, added %.6g kg = %s of its %.6g kg",
                  model.parts[p.part].name.c_str(), static_cast<long long>(p.scaled_elements),
                  model.blocks[model.parts[p.part].block].size(), p.added, percent(p.fraction()).c_str(), p.mass);
    lines.push_back(buf);
  }
  // Springs are not scaled: their bound 2/omega rises only where their nodes gained mass.
  bool any = false;
  for (const auto& c : solver.contacts()) {
    any = true;
    lines.push_back(spring_line("contact " + c.name() + " (a priori, while it acts)", c.stable_step(), model));
  }
  for (const auto& c : solver.contributors()) {
    const double dt = c->stable_step();
    if (dynamic_cast<const PenaltyContacts*>(c.get()) || !std::isfinite(dt) || !(dt > 0)) continue;
    any = true;
    lines.push_back(spring_line(c->name(), dt, model));
  }
  if (!any) lines.push_back("  no contact or interface springs bound the step");
  return lines;
}

}  // namespace plyimpact::solver
