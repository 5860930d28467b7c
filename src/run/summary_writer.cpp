#include "run/summary_writer.hpp"

#include <omp.h>

#include <cstdint>

#include "solver/contributors.hpp"
#include "output/json.hpp"
#include "run/history_writer.hpp"

namespace plyimpact::run {

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
  j["wall_seconds"] = std::chrono::duration<double>(Clock::now() - t_start_).count();
  j["nodes"] = std::uint64_t(model.num_nodes());
  j["elements"] = std::uint64_t(model.num_elements());
  j["threads"] = solver ? solver->threads_used() : omp_get_max_threads();
  j["ns_per_element_cycle"] = report.ns_per_element_cycle;
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
      entry["cause"] = solver::erosion_cause_name(c.cause);
      entry["count"] = c.count;
      by_part.push_back(entry);
    }
    erosion["by_part_and_cause"] = by_part;
    j["erosion"] = erosion;
  }
  j["files"] = output::Json::object();
  j["files"]["pvd"] = report.pvd.filename().string();
  j["files"]["history"] = report.history.filename().string();
  if (!report.dump.empty()) j["files"]["restart_dump"] = report.dump.filename().string();
  output::write_json_atomically(file_, j);
}

}  // namespace plyimpact::run
