#include "run/summary_writer.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdint>

#include "solver/contributors.hpp"
#include "output/json.hpp"
#include "run/history_writer.hpp"

namespace plyimpact::run {

namespace {

// Areas in m^2 and depths in m, as everywhere in the summary; the units member says so.
output::Json delamination_json(const DelaminationReport& d) {
  output::Json j = output::Json::object();
  output::Json units = output::Json::object();
  units["area"] = "m^2";
  units["depth"] = "m below the impacted face";
  units["cscan_pitch"] = "m";
  j["units"] = units;
  j["delaminated_area"] = d.total_area;
  j["projected_delaminated_area"] = d.projected_area;
  j["cscan_pitch"] = d.cscan_pitch;
  output::Json per = output::Json::array();
  for (const auto& i : d.interfaces) {
    output::Json e = output::Json::object();
    e["id"] = i.id;
    e["name"] = i.label;
    e["depth"] = i.depth;
    e["delaminated_area"] = i.area;
    per.push_back(e);
  }
  j["interfaces"] = per;
  return j;
}

// Mass scaling (control.dt2ms): added mass per part and in total, kg and as a fraction.
output::Json mass_scaling_json(const model::Model& model) {
  const model::MassScalingReport& r = model.mass_scaling;
  output::Json j = output::Json::object();
  j["dt2ms"] = model.control.dt2ms;
  j["target_element_step"] = r.target;
  j["total_mass"] = r.total_mass;
  j["deformable_mass"] = r.deformable_mass();
  j["added_mass"] = r.total_added;
  j["added_fraction"] = r.total_fraction();
  output::Json parts = output::Json::array();
  for (const auto& p : r.parts) {
    output::Json e = output::Json::object();
    e["part"] = model.parts[p.part].name;
    e["mass"] = p.mass;
    e["added_mass"] = p.added;
    e["added_fraction"] = p.fraction();
    e["scaled_elements"] = std::int64_t(p.scaled_elements);
    parts.push_back(e);
  }
  j["parts"] = parts;
  j["units"] = "s, kg; added_fraction: of the whole model's mass (rigid bodies included), per part: of the part's";
  return j;
}

// Where the wall time went (run_timing.hpp): rows in the order they were measured.
output::Json timing_json(const RunTiming& t) {
  output::Json j = output::Json::object();
  j["units"] = "s (wall); share: of span, the set-up and the cycles up to the stop";
  j["span"] = t.span;
  j["accounted"] = t.accounted();
  output::Json rows = output::Json::array();
  for (const TimingRow& r : t.rows()) {
    output::Json e = output::Json::object();
    e["name"] = r.name;
    e["seconds"] = r.seconds;
    e["share"] = t.span > 0 ? r.seconds / t.span : 0.0;
    rows.push_back(e);
  }
  j["rows"] = rows;
  return j;
}

// m^3: reference volume of the deleted elements. Unlike their count, which grows as the elements
// shrink, it compares between meshes (what a mesh study of a perforation should converge).
double eroded_volume(const model::Model& model, const solver::Solver& solver) {
  double v = 0;
  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    const auto& blk = model.blocks[b];
    if (blk.rigid) continue;
    for (std::size_t e = 0; e < blk.size(); ++e)
      if (!solver.element_alive(int(b), Index(e))) v += blk.volume0[e];
  }
  return v;
}

}  // namespace

void SummaryWriter::stop(const solver::Solver* solver, RunReport& report) {
  const model::Model& model = model_;
  report.summary = file_;
  output::Json j = output::Json::object();
  j["scene"] = model.name;
  j["version"] = PLYIMPACT_VERSION;
  j["status"] = report.completed ? "completed" : report.interrupted ? "interrupted" : "stopped";
  j["stop_reason"] = report.stop_reason;
  j["cycles"] = report.cycles;
  j["end_time"] = report.end_time;
  j["termination_time"] = model.control.termination_time;
  if (!report.termination.empty()) j["terminated_by"] = report.termination;
  j["wall_seconds"] = std::chrono::duration<double>(Clock::now() - t_start_).count();
  j["nodes"] = std::uint64_t(model.num_nodes());
  j["elements"] = std::uint64_t(model.num_elements());
  j["threads"] = solver ? solver->threads_used() : omp_get_max_threads();
  j["ns_per_element_cycle"] = report.ns_per_element_cycle;
  j["timing"] = timing_json(report.timing);
  output::Json subs = output::Json::object();
  for (const auto& s : solver::subsystems(model)) {
    output::Json entry = output::Json::object();
    entry["active"] = s.active;
    entry["detail"] = s.detail;
    subs[s.name] = entry;
  }
  j["subsystems"] = subs;
  if (solver) {
    const solver::Energies& e = solver->balance();
    output::Json en = output::Json::object();
    en["time"] = e.time;
    for (const auto& t : e.terms) en[t.key] = t.value;
    en["total"] = e.total();
    en["energy_ratio"] = solver->energy_ratio();
    j["final_energies"] = en;
    j["time_step"] = solver->state().dt_next_half;
    j["controlling_element"] = solver->state().dt_element;
  }
  if (solver && !solver->contacts().empty()) {  // nodes released behind a face (ContactPenetrationCheck)
    output::Json pen = output::Json::array();
    auto event = [](const contact::PenetrationEvent& e) {
      output::Json o = output::Json::object();
      o["node"] = std::int64_t(e.node) + 1;  // 1-based, the .msh tag
      o["time"] = e.time;
      o["depth"] = e.depth;
      return o;
    };
    for (const auto& c : solver->contacts()) {
      output::Json entry = output::Json::object();
      entry["contact"] = c.name();
      entry["count"] = std::int64_t(c.penetrations().count);
      if (c.penetrations().count > 0) {
        entry["first"] = event(c.penetrations().first);
        entry["deepest"] = event(c.penetrations().deepest);
        entry["released_potential"] = c.penetrations().released_potential;  // J
      }
      pen.push_back(entry);
    }
    j["contact_penetrations"] = pen;
  }
  output::Json warnings = output::Json::array();
  for (const auto& w : report.warnings) warnings.push_back(w);
  j["warnings"] = warnings;
  if (solver && solver::can_erode(model)) {
    output::Json erosion = output::Json::object();
    erosion["eroded_elements"] = solver->state().eroded_elements;
    erosion["eroded_energy"] = solver->state().eroded_energy;
    erosion["eroded_hourglass_energy"] = solver->state().eroded_hourglass_energy;
    erosion["eroded_volume"] = eroded_volume(model, *solver);
    erosion["removed_nodes"] = solver->state().removed_node_count();  // left with nothing acting on them
    erosion["eroded_kinetic_energy"] = solver->state().eroded_kinetic_energy;  // J, what they carried
    output::Json by_part = output::Json::array();
    for (const auto& c : solver->state().erosion) {
      output::Json entry = output::Json::object();
      entry["part"] = model.parts[c.part].name;
      entry["cause"] = solver::erosion_cause_name(c.cause);
      entry["count"] = c.count;
      entry["energy"] = c.energy;
      by_part.push_back(entry);
    }
    erosion["by_part_and_cause"] = by_part;
    j["erosion"] = erosion;
  }
  if (model.mass_scaling.target > 0) j["mass_scaling"] = mass_scaling_json(model);
  if (report.delamination) j["delamination"] = delamination_json(*report.delamination);
  if (report.hourglass) {
    const HourglassVerdict& h = *report.hourglass;
    output::Json hg = output::Json::object();
    hg["max_ratio"] = h.max_ratio;  // hourglass / max(internal, 1 % of the reference), over the run
    hg["time_of_max"] = h.time;
    hg["hourglass_energy_at_max"] = h.hourglass;
    hg["eroded_hourglass_energy_at_max"] = h.eroded_hourglass;  // part held by eroded elements
    output::Json by_part = output::Json::array();  // where it was: parts holding any, largest first
    std::vector<std::size_t> order;
    for (std::size_t p = 0; p < h.by_part.size() && p < model.parts.size(); ++p)
      if (h.by_part[p] > 0) order.push_back(p);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h.by_part[a] > h.by_part[b]; });
    for (std::size_t p : order) {
      output::Json entry = output::Json::object();
      entry["part"] = model.parts[p].name;
      entry["hourglass_energy"] = h.by_part[p];
      by_part.push_back(entry);
    }
    hg["by_part_at_max"] = by_part;
    hg["denominator_at_max"] = h.denominator;
    hg["floor_governs"] = h.floor_governs;
    hg["limit"] = h.limit;
    hg["passed"] = h.passed;
    j["hourglass_check"] = hg;
  }
  if (report.energy_balance) {
    const EnergyBalanceVerdict& b = *report.energy_balance;
    output::Json eb = output::Json::object();
    eb["ratio_min"] = b.ratio_min;  // energy ratio over the history samples (and the end)
    eb["time_of_min"] = b.time_of_min;
    eb["ratio_max"] = b.ratio_max;
    eb["time_of_max"] = b.time_of_max;
    eb["tolerance"] = b.tolerance;
    output::Json negative = output::Json::array();
    for (const NegativeEnergy& n : b.negative) {
      output::Json entry = output::Json::object();
      entry["energy"] = n.key;
      entry["value"] = n.value;
      entry["time"] = n.time;
      negative.push_back(entry);
    }
    eb["negative_energies"] = negative;  // contributor energies (contact, interfaces) that went below zero
    eb["passed"] = b.passed;
    j["energy_balance_check"] = eb;
  }
  j["files"] = output::Json::object();
  j["files"]["pvd"] = report.pvd.filename().string();
  j["files"]["history"] = report.history.filename().string();
  if (!report.dump.empty()) j["files"]["restart_dump"] = report.dump.filename().string();
  if (!report.interfaces_pvd.empty()) j["files"]["interfaces"] = report.interfaces_pvd.filename().string();
  if (!report.cscan_vtu.empty()) j["files"]["cscan_vtu"] = report.cscan_vtu.filename().string();
  if (!report.cscan_png.empty()) j["files"]["cscan_png"] = report.cscan_png.filename().string();
  output::write_json_atomically(file_, j);
}

}  // namespace plyimpact::run
