#include "solver/run.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>

#include "core/error.hpp"
#include "model/subsystems.hpp"
#include "output/history_table.hpp"
#include "output/json.hpp"
#include "output/pvd_series.hpp"
#include "output/vtu_writer.hpp"
#include "solver/contact_energy_watch.hpp"
#include "solver/frame_builder.hpp"
#include "solver/solver.hpp"

namespace plyimpact::solver {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Erosion columns only when something can erode (a material with failure, or erode_tsmin).
bool can_erode(const model::Model& model) {
  if (model.control.erode_tsmin > 0) return true;
  for (const auto& m : model.materials)
    if (m.kind == model::MaterialKind::CompositeDamage ||
        (m.kind == model::MaterialKind::Plastic && m.plastic.failure_strain > 0))
      return true;
  return false;
}

std::vector<std::string> history_columns(const model::Model& model) {
  std::vector<std::string> cols = {"time",         "dt",    "kinetic_energy", "internal_energy",
                                   "hourglass_energy", "bulk_viscous_energy", "external_work",
                                   "total_energy", "energy_ratio", "dt_element"};
  for (int set : model.constrained_sets)
    for (const char* c : {"_fx", "_fy", "_fz"}) cols.push_back("reaction_" + model.node_sets[set].name + c);
  // Contact, rigid-wall and rigid-body columns only when the scene has them.
  if (!model.contacts.empty()) {
    cols.push_back("contact_energy");
    cols.push_back("friction_energy");
    for (const auto& c : model.contacts)
      for (const char* q : {"_fx", "_fy", "_fz", "_normal", "_tangential"})
        cols.push_back("contact_" + c.spec.name + q);
  }
  if (!model.rigid_walls.empty()) {
    cols.push_back("rigidwall_energy");
    for (const auto& w : model.rigid_walls)
      for (const char* q : {"_normal", "_tangential"}) cols.push_back("wall_" + w.name + q);
  }
  for (const auto& b : model.rigid_bodies)
    for (const char* q : {"_x", "_y", "_z", "_vx", "_vy", "_vz", "_ax", "_ay", "_az", "_contact_fx", "_contact_fy",
                          "_contact_fz"})
      cols.push_back("rigid_" + b.name + q);
  if (can_erode(model)) {
    cols.push_back("eroded_elements");
    cols.push_back("eroded_energy");
  }
  return cols;
}

void add_history_row(const Solver& solver, output::HistoryTable& table) {
  const State& s = solver.state();
  const Energies& e = solver.balance();
  std::vector<double> row = {e.time,     s.dt_prev_half, e.kinetic,       e.internal,           e.hourglass,
                             e.bulk_viscous, e.external_work, e.total(), solver.energy_ratio(), double(s.dt_element)};
  row.insert(row.end(), s.reaction.begin(), s.reaction.end());
  if (!solver.contacts().empty()) {
    row.push_back(e.contact);
    row.push_back(e.friction);
    for (const auto& c : solver.contacts()) {
      const auto& f = c.forces();
      row.insert(row.end(), {f.resultant[0], f.resultant[1], f.resultant[2], f.normal, f.tangential});
    }
  }
  if (!solver.rigid_walls().empty()) {
    row.push_back(e.rigid_wall);
    for (const auto& w : solver.rigid_walls()) row.insert(row.end(), {w.normal_force(), w.tangential_force()});
  }
  for (const auto& b : solver.rigid_bodies())
    row.insert(row.end(), {b.x[0], b.x[1], b.x[2], b.v[0], b.v[1], b.v[2], b.a[0], b.a[1], b.a[2], b.contact_force[0],
                           b.contact_force[1], b.contact_force[2]});
  if (can_erode(solver.model())) row.insert(row.end(), {double(s.eroded_elements), s.eroded_energy});
  table.add_row(row);
}

std::string format_seconds(double s) {
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1fs", s);
  else std::snprintf(buf, sizeof buf, "%dm%02ds", int(s / 60), int(s) % 60);
  return buf;
}

}  // namespace

RunReport run_model(const model::Model& model, const RunOptions& options) {
  const auto t_start = Clock::now();
  if (model.control.threads > 0) omp_set_num_threads(model.control.threads);
  std::filesystem::create_directories(options.output_dir);
  RunReport report;
  const std::string& name = model.name;
  report.pvd = options.output_dir / (name + ".pvd");
  report.history = options.output_dir / "history.csv";
  report.summary = options.output_dir / "summary.json";

  const double t_end = model.control.termination_time;
  const double frame_interval = model.output.interval > 0 ? model.output.interval : t_end / 20;
  const double history_interval = model.output.history_interval > 0 ? model.output.history_interval : t_end / 1000;
  output::PvdSeries pvd(options.output_dir, name);
  output::HistoryTable history(history_columns(model));
  double solver_seconds = 0;
  long solver_cycles = 0;
  // Hourglass check as in LS-DYNA practice: hourglass energy against the PEAK internal energy (a
  // running ratio is meaningless early on, when the internal energy is still tiny).
  double max_hourglass_ratio = 0, peak_internal = 0;

  auto write_frame = [&](const Solver& solver) {
    char file[64];
    std::snprintf(file, sizeof file, "_%04zu.vtu", pvd.size());
    const std::string vtu = name + file;
    output::write_vtu(make_frame(solver), options.output_dir / vtu);
    pvd.add(solver.state().time, vtu);
    pvd.write();
    history.write_csv(report.history);
  };

  auto write_summary = [&](const Solver* solver) {
    output::Json j = output::Json::object();
    j["scene"] = name;
    j["version"] = PLYIMPACT_VERSION;
    j["status"] = report.completed ? "completed" : "stopped";
    j["stop_reason"] = report.stop_reason;
    j["cycles"] = report.cycles;
    j["end_time"] = report.end_time;
    j["termination_time"] = t_end;
    j["wall_seconds"] = seconds_since(t_start);
    j["nodes"] = std::uint64_t(model.num_nodes());
    j["elements"] = std::uint64_t(model.num_elements());
    j["threads"] = solver ? solver->threads_used() : omp_get_max_threads();
    j["ns_per_element_cycle"] = report.ns_per_element_cycle;
    output::Json subs = output::Json::object();
    for (const auto& s : model::subsystems(model)) {
      output::Json entry = output::Json::object();
      entry["active"] = s.active;
      entry["detail"] = s.detail;
      subs[s.name] = entry;
    }
    j["subsystems"] = subs;
    if (solver) {
      const Energies& e = solver->balance();
      output::Json en = output::Json::object();
      en["time"] = e.time;
      en["kinetic"] = e.kinetic;
      en["internal"] = e.internal;
      en["hourglass"] = e.hourglass;
      en["bulk_viscous"] = e.bulk_viscous;
      en["external_work"] = e.external_work;
      if (!model.contacts.empty()) {
        en["contact"] = e.contact;
        en["friction"] = e.friction;
      }
      if (!model.rigid_walls.empty()) en["rigid_wall"] = e.rigid_wall;
      en["total"] = e.total();
      en["energy_ratio"] = solver->energy_ratio();
      j["final_energies"] = en;
      j["time_step"] = solver->state().dt_next_half;
      j["controlling_element"] = solver->state().dt_element;
    }
    output::Json warnings = output::Json::array();
    for (const auto& w : report.warnings) warnings.push_back(w);
    j["warnings"] = warnings;
    if (solver && can_erode(model)) {
      output::Json erosion = output::Json::object();
      erosion["eroded_elements"] = solver->state().eroded_elements;
      erosion["eroded_energy"] = solver->state().eroded_energy;
      output::Json by_part = output::Json::array();
      for (const auto& c : solver->state().erosion) {
        output::Json entry = output::Json::object();
        entry["part"] = model.parts[c.part].name;
        entry["cause"] = erosion_cause_name(c.cause);
        entry["count"] = c.count;
        by_part.push_back(entry);
      }
      erosion["by_part_and_cause"] = by_part;
      j["erosion"] = erosion;
    }
    j["files"] = output::Json::object();
    j["files"]["pvd"] = report.pvd.filename().string();
    j["files"]["history"] = report.history.filename().string();
    output::write_json_atomically(report.summary, j);
  };

  std::unique_ptr<Solver> solver;
  std::vector<std::string> contact_names;
  for (const auto& c : model.contacts) contact_names.push_back(c.spec.name);
  ContactEnergyWatch contact_watch(contact_names);
  std::vector<double> contact_energies(model.contacts.size(), 0.0);
  try {
    solver = std::make_unique<Solver>(model);
    for (const auto& w : solver->warnings()) report.warnings.push_back(w);
    add_history_row(*solver, history);
    write_frame(*solver);
    double next_frame = frame_interval, next_history = history_interval, next_progress = 0;
    const long max_cycles = model.control.max_cycles;
    while (solver->state().time < t_end * (1 - 1e-12) && (max_cycles <= 0 || solver->state().cycle < max_cycles)) {
      State& s = solver->state();
      if (s.time + s.dt_next_half > t_end) s.dt_next_half = t_end - s.time;  // land on the end time
      const auto t0 = Clock::now();
      solver->step();
      solver_seconds += seconds_since(t0);
      ++solver_cycles;
      const double t = s.time;
      if (!contact_energies.empty()) {
        for (std::size_t c = 0; c < contact_energies.size(); ++c) contact_energies[c] = solver->contacts()[c].energy();
        contact_watch.observe(contact_energies, t, s.initial_total_energy + solver->balance().external_work);
      }
      if (t >= next_history * (1 - 1e-12) && solver->balance().time > 0) {
        add_history_row(*solver, history);
        next_history += history_interval * std::max(1.0, std::floor((t - next_history) / history_interval) + 1);
        const Energies& e = solver->balance();
        peak_internal = std::max(peak_internal, e.internal);
        if (peak_internal > 0) max_hourglass_ratio = std::max(max_hourglass_ratio, e.hourglass / peak_internal);
      }
      const bool last = t >= t_end * (1 - 1e-12);
      if (t >= next_frame * (1 - 1e-12) || last) {
        write_frame(*solver);
        next_frame += frame_interval * std::max(1.0, std::floor((t - next_frame) / frame_interval) + 1);
      }
      const double wall = seconds_since(t_start);
      if (options.progress && (wall >= next_progress || last)) {
        const double pct = 100.0 * t / t_end;
        const double eta = pct > 0 ? wall * (100.0 - pct) / pct : 0.0;
        char line[200];
        std::snprintf(line, sizeof line, "t %.4e s (%5.1f%%)  cycle %ld  dt %.3e s  wall %s  ETA %s  energy ratio %.4f",
                      t, pct, s.cycle, s.dt_prev_half, format_seconds(wall).c_str(), format_seconds(eta).c_str(),
                      solver->energy_ratio());
        if (options.progress_in_place) {
          *options.progress << '\r' << line << "\033[K" << std::flush;
          next_progress = wall + 0.2;
        } else {
          *options.progress << line << '\n' << std::flush;
          next_progress = wall + 10.0;
        }
      }
    }
    if (options.progress && options.progress_in_place) *options.progress << '\n';
    report.completed = solver->state().time >= t_end * (1 - 1e-12);
    if (!report.completed) report.stop_reason = "max_cycles reached before the termination time";
  } catch (const RunError& e) {
    report.completed = false;
    report.stop_reason = e.what();
    if (options.progress && options.progress_in_place) *options.progress << '\n';
  }
  if (solver) {
    report.cycles = solver->state().cycle;
    report.end_time = solver->state().time;
    report.energy_ratio = solver->energy_ratio();
  }
  const double element_cycles = double(model.num_elements()) * double(solver_cycles);
  report.ns_per_element_cycle = element_cycles > 0 ? 1e9 * solver_seconds / element_cycles : 0.0;
  if (max_hourglass_ratio > model.control.hourglass_warn_ratio) {
    char w[200];
    std::snprintf(w, sizeof w, "hourglass energy reached %.1f%% of the peak internal energy (limit %.1f%%): refine the mesh "
                  "(more elements through the thickness) or use ELFORM 2", 100 * max_hourglass_ratio,
                  100 * model.control.hourglass_warn_ratio);
    report.warnings.push_back(w);
  }
  for (const auto& w : contact_watch.warnings()) report.warnings.push_back(w);
  if (solver && std::abs(report.energy_ratio - 1.0) > 0.05)
    report.warnings.push_back("energy ratio " + std::to_string(report.energy_ratio) + " differs from 1 by more than 5%");
  history.write_csv(report.history);
  report.wall_seconds = seconds_since(t_start);
  write_summary(solver.get());
  return report;
}

}  // namespace plyimpact::solver
