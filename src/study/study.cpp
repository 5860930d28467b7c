// Study orchestration. See study.hpp.
#include "study/study.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>
#include <thread>

#include "config/scene_digest.hpp"
#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "output/atomic_file.hpp"
#include "output/json.hpp"
#include "study/ballistic_study.hpp"
#include "study/case_batch.hpp"
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
                                                     const std::string& unit_system, output::Json& j, PlotLog& plots) {
  std::size_t p = 0;
  while (spec.parameters[p].key != spec.lambert_jonas->velocity_parameter) ++p;
  const units::UnitSystem us = units::parse_unit_system(unit_system);
  std::vector<double> v, vr;
  for (const auto& r : t.rows) {
    const double res = r.quantity("residual_velocity");
    if (std::isnan(res)) continue;
    const bool undecided = std::any_of(r.notes.begin(), r.notes.end(),
                                       [](const std::string& n) { return n.starts_with("perforated: undecided"); });
    if (undecided) continue;  // still moving in contact: neither a residual velocity nor an arrest
    v.push_back(units::quantity_to_si(r.values[p], units::velocity, us));
    vr.push_back(r.quantity("perforated") == 0 ? 0.0 : res);  // stopped: no residual velocity
  }
  try {
    const LambertJonasFit fit = fit_lambert_jonas(v, vr);
    j["a"] = fit.a;
    j["p"] = fit.p;
    j["ballistic_limit"] = fit.v_bl;
    j["rms_residual"] = fit.rms;
    if (std::none_of(vr.begin(), vr.end(), [](double x) { return x <= 0; }))
      j["note"] = "every case perforated: the ballistic limit is an extrapolation below the swept velocities";
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
      if (rep.case_names[i].size() > 1) {
        std::snprintf(buf, sizeof buf, " [%zu runs, spread %.3g]", rep.case_names[i].size(), q.spread[i]);
        out << buf;
      }
    }
    if (q.richardson && q.richardson->extrapolated) {
      std::snprintf(buf, sizeof buf, "; observed order %.3g, extrapolated %.6g", q.richardson->order, q.richardson->value);
      out << buf;
    }
    if (q.richardson)
      for (const auto& f : q.richardson->flags) out << "; FLAG: " << f;
    for (const auto& f : q.flags) out << "; FLAG: " << f;
    out << "\n";
  }
}

}  // namespace

StudyOutcome run_study(const StudySpec& spec, const StudyOptions& o, std::ostream& out) {
  StudyOutcome res;
  res.dir = o.output_dir.empty() ? spec.output_dir : o.output_dir;
  // The scene's values, not its text: a comment or layout edit keeps the finished cases.
  const std::string scene_text = config::canonical_scene_text(slurp(spec.scene), spec.scene.string());
  std::vector<Case> cases = expand_cases(spec, scene_text);
  res.cases = cases.size();
  // Every case's effective scene must load: refuse the whole study before running anything.
  std::string unit_system = config::load_scene(spec.scene.string(), spec.fixed).unit_system;
  for (Case& c : cases) {
    const config::Scene scene = config::load_scene(spec.scene.string(), c.overrides);
    unit_system = scene.unit_system;
    c.pass_distance = plate_pass_distance(scene);
  }
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
    if (spec.ballistic_limit) {
      const auto& bl = *spec.ballistic_limit;
      out << "  then a ballistic-limit search of " << bl.parameter << " in [" << velocity_text(bl, bl.lo) << ", "
          << velocity_text(bl, bl.hi) << "] to " << velocity_text(bl, bl.tolerance) << ": the two ends, then at most "
          << int(std::ceil(std::log((bl.hi - bl.lo) / bl.tolerance) / std::log(jobs + 1.0))) << " round(s) of " << jobs
          << " case(s)\n";
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
    if (spec.ballistic_limit)
      out << "note: the ballistic-limit search chooses each round from the last, so it is not emitted; run the study "
             "without --emit for it\n";
    res.pending = pending.size();
    return res;
  }
  const CaseBatch batch{&spec, res.dir, program, jobs, threads};
  if (!o.collect && !pending.empty()) {
    out << "running " << pending.size() << " cases, " << jobs << " at a time, " << threads << " threads each\n";
    std::vector<Case> list;
    for (std::size_t i : pending) list.push_back(cases[i]);
    const auto why = run_case_batch(batch, list, out);
    for (std::size_t k = 0; k < pending.size(); ++k) {
      ++res.ran;
      failures[pending[k]] = why[k];
      res.failed += !why[k].empty();
    }
  }
  std::optional<BallisticStudy> search;
  if (spec.ballistic_limit && !o.collect) {
    // One case per core-share: a round of `jobs` velocities cuts the bracket into jobs + 1 parts.
    const auto [bjobs, bthreads] = share_cores(spec, o, std::size_t(std::max(1, o.jobs)), out);
    search = run_ballistic_search(spec, scene_text, CaseBatch{&spec, res.dir, program, bjobs, bthreads}, cases,
                                  failures, out);
    res.ran += search->ran;
    res.failed += search->failed;
    if (!search->error.empty()) res.errors.push_back(search->error);
  }
  StudyTable table = gather_table(spec, cases, res.dir, failures);
  if (spec.ballistic_limit)  // the search's cases come in search order: list them by velocity
    std::stable_sort(table.rows.begin(), table.rows.end(), [](const CaseRow& a, const CaseRow& b) {
      return leading_number(a.values.front()) < leading_number(b.values.front());
    });
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
  std::optional<LambertJonasFit> fit;
  if (spec.lambert_jonas) {
    output::Json lj = output::Json::object();
    fit = fit_residual_velocity(spec, table, unit_system, lj, plots);
    if (fit) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "Lambert-Jonas fit: ballistic limit %.4g m/s, a %.3g, p %.3g (rms %.3g m/s)\n",
                    fit->v_bl, fit->a, fit->p, fit->rms);
      out << buf;
    }
    j["lambert_jonas"] = lj;
  }
  std::optional<BallisticLimit> limit;
  if (spec.ballistic_limit && search) {
    j["ballistic_limit"] = ballistic_json(*spec.ballistic_limit, *search, unit_system);
    if (search->result) {
      limit = search->result;
      output::write_text_atomically(res.dir / "ballistic_limit.csv", ballistic_csv(*spec.ballistic_limit, *limit));
    }
  }
  if (fit || limit) {
    const std::string key = spec.lambert_jonas ? spec.lambert_jonas->velocity_parameter : spec.ballistic_limit->parameter;
    const auto p = std::size_t(std::find(table.parameter_keys.begin(), table.parameter_keys.end(), key) -
                               table.parameter_keys.begin());
    double v_max = limit ? limit->hi : 0;
    for (const auto& r : table.rows)
      if (!std::isnan(r.quantity("residual_velocity"))) v_max = std::max(v_max, leading_number(r.values[p]));
    plot_residual_velocity(fit, limit, key, v_max, res.dir, plots);
  }
  output::write_json_atomically(res.dir / "study.json", j);
  plot_quantities(table, res.dir, plots);
  if (spec.case_plots)
    for (const auto& r : table.rows)
      if (r.status == "completed" || r.status == "stopped") plot_case(res.dir / r.name, plots);
  for (const auto& w : plots.warnings) out << "warning: " << w << "\n";
  res.warnings = plots.warnings;
  for (const auto& e : res.errors) out << "error: " << e << "\n";
  out << "wrote " << (res.dir / "study.csv").string() << ", " << (res.dir / "study.json").string() << " and "
      << plots.written.size() << " plots; " << res.ran << " cases run (" << res.failed << " failed), "
      << res.already_finished << " reused, " << res.pending << " pending\n";
  return res;
}

}  // namespace plyimpact::study
