// Study orchestration. See study.hpp.
#include "study/study.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>
#include <thread>

#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "output/atomic_file.hpp"
#include "output/json.hpp"
#include "study/case_runner.hpp"
#include "study/cases.hpp"
#include "study/convergence.hpp"
#include "study/lambert_jonas.hpp"
#include "study/quantities.hpp"
#include "study/scheduler_scripts.hpp"
#include "study/study_plots.hpp"
#include "study/study_table.hpp"

namespace plyimpact::study {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(msg() << p.string() << ": cannot read the base scene; allowed a readable scene file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Jobs and threads per case with jobs x threads <= cores.
std::pair<int, int> share_cores(const StudySpec& spec, const StudyOptions& o, std::size_t pending, std::ostream& out) {
  const int cores = o.cores > 0 ? o.cores : std::max(1, int(std::thread::hardware_concurrency()));
  int jobs = std::clamp(o.jobs, 1, std::max(1, int(pending)));
  int threads = o.threads > 0 ? o.threads : spec.threads;
  if (threads <= 0) threads = std::max(1, cores / jobs);
  if (jobs * threads > cores) {
    const int fit = std::max(1, cores / threads);
    out << "note: " << jobs << " jobs x " << threads << " threads exceed the " << cores << " cores; running " << fit
        << " at a time\n";
    jobs = fit;
  }
  return {jobs, threads};
}

output::Json case_json(const StudySpec& spec, const CaseRow& row) {
  output::Json j = output::Json::object();
  j["case"] = row.name;
  j["status"] = row.status;
  output::Json params = output::Json::object();
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) params[spec.parameters[p].key] = row.values[p];
  j["parameters"] = params;
  output::Json q = output::Json::object();
  for (const auto& v : row.quantities) q[v.name] = v.value;
  j["quantities"] = q;
  output::Json notes = output::Json::array();
  for (const auto& n : row.notes) notes.push_back(n);
  j["not_available"] = notes;
  return j;
}

output::Json quantity_units(const StudySpec& spec) {
  output::Json j = output::Json::object();
  for (const auto& name : spec.quantities) {
    const QuantityDefinition* d = find_quantity(name);
    output::Json e = output::Json::object();
    e["unit"] = std::string(d->unit);
    e["description"] = std::string(d->description);
    j[name] = e;
  }
  return j;
}

// The Lambert-Jonas fit over the finished cases (velocities converted to m/s with the scene's units).
std::optional<LambertJonasFit> fit_residual_velocity(const StudySpec& spec, const StudyTable& t,
                                                     const std::string& unit_system, output::Json& j, PlotLog& plots,
                                                     const fs::path& dir) {
  std::size_t p = 0;
  while (spec.parameters[p].key != spec.lambert_jonas->velocity_parameter) ++p;
  const units::UnitSystem us = units::parse_unit_system(unit_system);
  std::vector<double> v, vr;
  for (const auto& r : t.rows) {
    const double res = r.quantity("residual_velocity");
    if (std::isnan(res)) continue;
    v.push_back(units::quantity_to_si(r.values[p], units::velocity, us));
    vr.push_back(res);
  }
  try {
    const LambertJonasFit fit = fit_lambert_jonas(v, vr);
    j["a"] = fit.a;
    j["p"] = fit.p;
    j["ballistic_limit"] = fit.v_bl;
    j["rms_residual"] = fit.rms;
    if (std::none_of(vr.begin(), vr.end(), [](double x) { return x <= 0; }))
      j["note"] = "every case perforated: the ballistic limit is an extrapolation below the swept velocities";
    plot_lambert_jonas(fit, spec.lambert_jonas->velocity_parameter, *std::max_element(v.begin(), v.end()), dir, plots);
    return fit;
  } catch (const InputError& e) {
    j["not_fitted"] = e.what();
    plots.warnings.push_back(e.what());
    return std::nullopt;
  }
}

void print_convergence(const ConvergenceReport& rep, std::ostream& out) {
  char buf[256];
  out << "convergence in " << rep.parameter << " (" << rep.cases.size() << " meshes):\n";
  for (const auto& q : rep.quantities) {
    out << "  " << q.quantity << ":";
    for (std::size_t i = 0; i < q.values.size(); ++i) {
      std::snprintf(buf, sizeof buf, " h %.4g: %.6g (%.3gs)", rep.h[i], q.values[i], rep.wall_time[i]);
      out << buf;
    }
    if (q.richardson && q.richardson->extrapolated) {
      std::snprintf(buf, sizeof buf, "; observed order %.3g, extrapolated %.6g", q.richardson->order, q.richardson->value);
      out << buf;
    }
    if (q.richardson)
      for (const auto& f : q.richardson->flags) out << "; FLAG: " << f;
    out << "\n";
  }
}

}  // namespace

StudyOutcome run_study(const StudySpec& spec, const StudyOptions& o, std::ostream& out) {
  StudyOutcome res;
  res.dir = o.output_dir.empty() ? spec.output_dir : o.output_dir;
  const std::string scene_text = slurp(spec.scene);
  const std::vector<Case> cases = expand_cases(spec, scene_text);
  res.cases = cases.size();
  // Every case's effective scene must load: refuse the whole study before running anything.
  std::string unit_system;
  for (const Case& c : cases) unit_system = config::load_scene(spec.scene.string(), c.overrides).unit_system;
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (case_finished(cases[i], res.dir / cases[i].name)) ++res.already_finished;
    else pending.push_back(i);
  }
  out << "study " << spec.name << ": " << cases.size() << " cases, " << res.already_finished << " already finished, "
      << pending.size() << " to run; folder " << res.dir.string() << "\n";
  const auto [jobs, threads] = share_cores(spec, o, pending.size(), out);
  if (o.dry_run) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const bool todo = std::find(pending.begin(), pending.end(), i) != pending.end();
      out << "  " << (todo ? "pending  " : "finished ") << cases[i].name << ":";
      for (const auto& ov : cases[i].overrides) out << " " << ov.key_path << "=" << ov.value;
      out << "\n";
    }
    res.pending = pending.size();
    return res;
  }
  const fs::path program = o.program.empty() ? fs::read_symlink("/proc/self/exe") : o.program;
  std::vector<std::string> failures(cases.size());
  if (o.emit != Emit::none) {
    std::vector<PendingCase> list;
    for (std::size_t i : pending) {
      const fs::path dir = res.dir / cases[i].name;
      std::error_code ec;
      fs::remove(dir / "summary.json", ec);  // a stale result must not count as this case's
      write_case_record(spec, cases[i], dir, "emitted");
      list.push_back({cases[i].name, dir, case_arguments(spec, cases[i], dir, threads)});
    }
    const auto commands = case_command_lines(program, list);
    if (o.emit == Emit::slurm) {
      out << "wrote " << write_slurm_array(res.dir, spec.name, commands, threads).string() << " (" << commands.size()
          << " array tasks; submit with sbatch, then run with --collect)\n";
    } else {
      out << "wrote " << write_parallel_jobs(res.dir, commands).string() << " (run: parallel -j " << jobs << " < "
          << (res.dir / "parallel_jobs.txt").string() << ", then --collect)\n";
    }
    res.pending = pending.size();
    return res;
  }
  if (!o.collect && !pending.empty()) {
    out << "running " << pending.size() << " cases, " << jobs << " at a time, " << threads << " threads each\n";
    std::vector<CaseJob> list;
    for (std::size_t i : pending) {
      const fs::path dir = res.dir / cases[i].name;
      std::error_code ec;
      fs::remove(dir / "summary.json", ec);
      write_case_record(spec, cases[i], dir, "running");
      list.push_back({cases[i].name, dir, case_arguments(spec, cases[i], dir, threads)});
    }
    run_case_processes(program, list, jobs, out, [&](std::size_t k, const CaseOutcome& oc) {
      const std::size_t i = pending[k];
      const fs::path dir = res.dir / cases[i].name;
      ++res.ran;
      // Exit 0 completed, 2 stopped early with its summary written: both are results.
      if (oc.failure.empty() && (oc.exit_code == 0 || oc.exit_code == 2) && fs::exists(dir / "summary.json")) {
        write_case_record(spec, cases[i], dir, oc.exit_code == 0 ? "completed" : "stopped");
      } else {
        ++res.failed;
        failures[i] = oc.failure.empty() ? "exit code " + std::to_string(oc.exit_code) : oc.failure;
        write_case_record(spec, cases[i], dir, "failed: " + failures[i]);
      }
    });
  }
  const StudyTable table = gather_table(spec, cases, res.dir, failures);
  for (const auto& r : table.rows) res.pending += r.status == "pending";
  fs::create_directories(res.dir);
  output::write_text_atomically(res.dir / "study.csv", study_csv(table));
  PlotLog plots;
  output::Json j = output::Json::object();
  j["study"] = spec.file.string();
  j["scene"] = fs::absolute(spec.scene).string();
  j["version"] = PLYIMPACT_VERSION;
  j["quantities"] = quantity_units(spec);
  output::Json rows = output::Json::array();
  for (const auto& r : table.rows) rows.push_back(case_json(spec, r));
  j["cases"] = rows;
  if (spec.convergence) {
    const ConvergenceReport rep = analyse_convergence(spec, table);
    output::write_text_atomically(res.dir / "convergence.csv", convergence_csv(rep));
    j["convergence"] = convergence_json(rep);
    print_convergence(rep, out);
    plot_convergence(rep, res.dir, plots);
  }
  if (spec.lambert_jonas) {
    output::Json lj = output::Json::object();
    if (const auto fit = fit_residual_velocity(spec, table, unit_system, lj, plots, res.dir)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "Lambert-Jonas fit: ballistic limit %.4g m/s, a %.3g, p %.3g (rms %.3g m/s)\n",
                    fit->v_bl, fit->a, fit->p, fit->rms);
      out << buf;
    }
    j["lambert_jonas"] = lj;
  }
  output::write_json_atomically(res.dir / "study.json", j);
  plot_quantities(table, res.dir, plots);
  if (spec.case_plots)
    for (const auto& r : table.rows)
      if (r.status == "completed" || r.status == "stopped") plot_case(res.dir / r.name, plots);
  for (const auto& w : plots.warnings) out << "warning: " << w << "\n";
  res.warnings = plots.warnings;
  out << "wrote " << (res.dir / "study.csv").string() << ", " << (res.dir / "study.json").string() << " and "
      << plots.written.size() << " plots; " << res.ran << " cases run (" << res.failed << " failed), "
      << res.already_finished << " reused, " << res.pending << " pending\n";
  return res;
}

}  // namespace plyimpact::study
