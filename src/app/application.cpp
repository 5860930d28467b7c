#include "app/application.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/convert_command.hpp"
#include "app/dcb_reduce_command.hpp"
#include "app/mesh_export.hpp"
#include "app/plot_command.hpp"
#include "app/study_command.hpp"
#include "config/scene_digest.hpp"
#include "config/scene_loader.hpp"
#include "contact/contact_compliance.hpp"
#include "core/error.hpp"
#include "core/state_io.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "run/cycle_budget.hpp"
#include "run/run.hpp"
#include "solver/contributors.hpp"
#include "solver/mass_scaling.hpp"
#include "solver/solver.hpp"

namespace plyimpact::app {

namespace {

constexpr const char* kUsageHead =
    "usage: plyimpact <command> [options]\n"
    "\n"
    "commands:\n"
    "  run SCENE.yaml [-o DIR] [--restart DUMP] [--replace]\n"
    "                            run the scene; results go to DIR (default results/<scene>):\n"
    "                            <scene>.pvd + VTU frames (open the .pvd in ParaView), history.csv,\n"
    "                            summary.json, restart.dump. Ctrl-C or SIGTERM stops cleanly (exit 2);\n"
    "                            --restart DUMP continues a stopped or finished run (extend it with\n"
    "                            --set control.termination_time=...); --replace removes another\n"
    "                            run's results from DIR (refused otherwise)\n"
    "  check SCENE.yaml          validate the scene and print the model summary, active subsystems,\n"
    "                            stable time step and cost estimate; writes nothing\n"
    "  mesh SCENE.yaml [-o DIR]  mesh the scene and write it for inspection (default results/<scene>):\n"
    "                            <scene>_mesh.vtu (parts, plies, ply angles, material axes,\n"
    "                            interfaces) and <scene>.msh (gmsh)\n"
    "  convert DECK.k --units U [-o SCENE.yaml] [--coverage]   LS-DYNA keyword deck -> scene + .msh\n"
    "  run DECK.k --units U [-o DIR]   convert the deck into DIR and run it\n"
    "  run, check and mesh also take  --set key.path=value [...]  (change a scene value before it is\n"
    "                            read: units and validation as in the file, e.g. --set control.tssfac=0.8\n"
    "                            --set impactor.velocity='5 m/s' --set contacts[0].SOFT=2) and\n"
    "                            --threads N (same as --set control.threads=N)\n";
constexpr const char* kUsageTail =
    "  --help                    this text\n"
    "  --version                 program version\n"
    "\n"
    "exit codes: 0 success, 1 invalid input (scene, override, data file), 2 run stopped early (see\n"
    "summary.json) or an output could not be written, 64 bad usage\n";

std::string usage() { return std::string(kUsageHead) + kDcbReduceUsage + kPlotUsage + kStudyUsage + kUsageTail; }

struct Loaded {
  config::Scene scene;
  mesh::Mesh mesh;
  model::Model model;
};

using Overrides = std::vector<config::SceneOverride>;

// Boxes, or the gmsh laminate mesher and the impactor when the scene has a laminate. A scene to be
// run (or checked for a run) must also finish in a stated number of cycles.
Loaded load(const std::string& path, const Overrides& overrides, bool for_a_run = true) {
  Loaded l;
  l.scene = config::load_scene(path, overrides);
  l.mesh = mesh::mesh_scene(l.scene);
  l.model = model::build_model(l.scene, l.mesh);
  solver::apply_mass_scaling(l.model);  // control.dt2ms: before the cycle estimate, which uses the step
  if (for_a_run) run::require_cycle_budget(l.scene, l.model, run::estimate_cycles(l.model));
  return l;
}

// The meshed interfaces (delaminating or merged) and an impactor that no contact uses.
void print_mesher_extras(const model::Model& m, std::ostream& out) {
  for (const auto& i : m.interfaces)
    out << "  interface " << i.id << " (plies " << i.lower_ply + 1 << "/" << i.upper_ply + 1 << ", z = " << i.z
        << " m): " << i.lower_nodes.size() << " coincident node pairs, " << i.lower_segments.size() / 4
        << " segment pairs; "
        << (!i.tiebreak ? "merged (model: merged): the plies are bonded here"
            : i.tiebreak->model == config::InterfaceLawSpec::Model::Cohesive
                ? "delaminating (*MAT_138 cohesive elements, see the delamination subsystem)"
                : "delaminating (tiebreak law, see the delamination subsystem)")
        << "\n";
  if (m.impactor && m.impactor_quads.empty()) {
    const auto& imp = *m.impactor;
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "  impactor: %s, %zu surface quads, mass %.6g kg, centre of mass (%.6g, %.6g, %.6g) m, "
                  "velocity (%.6g, %.6g, %.6g) m/s; it acts on the plate through the contacts that name it\n",
                  imp.rigid ? "rigid" : "deformable", imp.surface_quads.size() / 4, imp.mass, imp.centre_of_mass[0],
                  imp.centre_of_mass[1], imp.centre_of_mass[2], imp.velocity[0], imp.velocity[1], imp.velocity[2]);
    out << buf;
  }
}

// `--set key.path=value [key.path=value ...]` and `--threads N` at args[i]: appends to `overrides`,
// advances i past what it used and returns true; false when args[i] is neither.
bool parse_override_option(const std::vector<std::string>& args, std::size_t& i, Overrides& overrides) {
  if (args[i] == "--set" && i + 1 < args.size()) {
    overrides.push_back(config::parse_set_argument(args[++i]));
    while (i + 1 < args.size() && !args[i + 1].starts_with("-") && args[i + 1].find('=') != std::string::npos)
      overrides.push_back(config::parse_set_argument(args[++i]));
    return true;
  }
  if (args[i] == "--threads" && i + 1 < args.size()) {
    overrides.push_back(config::threads_override(args[++i]));
    return true;
  }
  return false;
}

void print_overrides(const Overrides& overrides, std::ostream& out) {
  if (overrides.empty()) return;
  out << "  overrides:";
  for (const auto& o : overrides) out << " " << o.origin << ";";
  out << "\n";
}

int mesh_command(const std::string& path, const std::string& out_dir, const Overrides& overrides, std::ostream& out) {
  const Loaded l = load(path, overrides, /*for_a_run=*/false);
  const auto dir = out_dir.empty() ? std::filesystem::path("results") / l.scene.name : std::filesystem::path(out_dir);
  out << "plyimpact mesh: " << path << ": " << l.model.num_nodes() << " nodes, " << l.model.num_elements()
      << " elements, " << l.model.parts.size() << " parts\n";
  print_mesher_extras(l.model, out);
  for (const auto& p : export_mesh(l.scene, l.mesh, l.model, dir)) out << "wrote " << p.string() << "\n";
  return 0;
}

// The model's arrays and the solver's run state (all its blocks: nodal vectors, stresses, material
// histories per integration point, hourglass forces), which dominate; search and output buffers
// are left out.
std::size_t memory_estimate(const model::Model& m, solver::Solver& solver) {
  std::size_t bytes = (m.X.size() + m.mass.size() + m.v0.size()) * sizeof(double);
  for (const auto& b : m.blocks) bytes += b.conn.size() * sizeof(Index) + b.size() * (sizeof(Index) + sizeof(int) + sizeof(double));
  StateSize state;
  solver.visit_state(state);
  return bytes + state.bytes();
}

int check(const std::string& path, const Overrides& overrides, std::ostream& out) {
  const Loaded l = load(path, overrides);
  const model::Model& m = l.model;
  solver::Solver solver(m);  // evaluates the initial stable step
  char buf[256];
  out << "plyimpact check: " << path << ": scene is valid\n";
  print_overrides(overrides, out);
  out << "  units: " << l.scene.unit_system << " (internally SI)\n";
  out << "  nodes: " << m.num_nodes() << ", elements: " << m.num_elements() << "\n";
  out << "  parts:\n";
  for (const auto& p : m.parts) {
    const auto& b = m.blocks[p.block];
    out << "    " << p.id << " " << p.name << ": " << b.size() << " elements, " << m.materials[p.material].card << " '"
        << m.materials[p.material].name << "', section '" << p.section << "' ELFORM " << b.elform;
    if (b.elform == 1) out << " IHQ " << b.ihq << " QM " << b.qm;
    out << ", Q1 " << b.q1 << " Q2 " << b.q2 << "\n";
  }
  out << "  materials:\n";
  for (const auto& mat : m.materials) {
    std::snprintf(buf, sizeof buf, "    %s (%s): density %.6g kg/m^3, max wave speed %.6g m/s\n", mat.name.c_str(),
                  mat.card.c_str(), mat.density, mat.wave_speed);
    out << buf;
  }
  print_mesher_extras(m, out);
  out << "  subsystems:\n";
  for (const auto& s : plyimpact::solver::subsystems(m)) out << "    [" << (s.active ? "on " : "off") << "] " << s.name << ": " << s.detail << "\n";
  const auto& st = solver.state();
  for (std::size_t i = 0; i < solver.contacts().size(); ++i) {
    const auto& c = solver.contacts()[i];
    const auto& ip = solver.initial_penetrations()[i];
    std::snprintf(buf, sizeof buf,
                  "  contact %s: SOFT %d, %zu segments, %zu slave nodes, penalty stiffness %.4g to %.4g N/m, "
                  "contact stable step %.4g s\n",
                  c.name().c_str(), c.soft(), c.num_segments(), c.num_slave_nodes(), c.stiffness_min(),
                  c.stiffness_max(), c.stable_step());
    out << buf << contact::compliance_lines(m, c, l.scene);
    if (ip.count == 0) {
      out << "    initial penetrations: none\n";
    } else {
      std::snprintf(buf, sizeof buf, "    initial penetrations: %zu nodes, deepest %.4g m, %s\n", ip.count, ip.max_depth,
                    ip.moved ? "removed by moving the nodes onto the surface" : "kept as a zero-force offset");
      out << buf;
    }
  }
  for (const auto& line : solver::mass_scaling_lines(solver)) out << "  " << line << "\n";
  for (const auto& w : solver.warnings()) out << "  warning: " << w << "\n";
  if (st.dt_contact_controls)
    std::snprintf(buf, sizeof buf,
                  "  stable time step: %.6g s (TSSFAC %.3g applied), controlled by contact or interface stiffness\n",
                  st.dt_next_half, m.control.tssfac);
  else
    std::snprintf(buf, sizeof buf,
                  "  stable time step: %.6g s (TSSFAC %.3g applied), controlling element %d (part '%s')\n",
                  st.dt_next_half, m.control.tssfac, int(st.dt_element), solver.part_of_element(st.dt_element).c_str());
  out << buf;
  const double cycles = std::ceil(m.control.termination_time / st.dt_next_half);
  std::snprintf(buf, sizeof buf, "  termination time %.6g s: about %.0f cycles, %.3g element-cycles\n",
                m.control.termination_time, cycles, cycles * double(m.num_elements()));
  out << buf;
  std::snprintf(buf, sizeof buf, "  memory estimate: %.1f MiB\n", memory_estimate(m, solver) / 1048576.0);
  out << buf;
  return 0;
}

// What `run` takes besides the scene and its overrides.
struct RunFlags {
  std::string restart;  // dump to continue from
  bool replace = false;
};

int run(const std::string& path, const std::string& out_dir, const Overrides& overrides, std::ostream& out,
        const RunFlags& flags = {}) {
  const Loaded l = load(path, overrides);
  run::RunOptions options;
  options.output_dir = out_dir.empty() ? std::filesystem::path("results") / l.scene.name : std::filesystem::path(out_dir);
  options.progress = &out;
  options.progress_in_place = (&out == &std::cout) && isatty(STDOUT_FILENO);
  options.restart = flags.restart;
  options.replace = flags.replace;
  options.scene_digest = config::scene_digest(path, overrides);
  options.stop_on_signals = true;
  out << "plyimpact " << PLYIMPACT_VERSION << ": " << (flags.restart.empty() ? "running " : "continuing ") << path
      << " (" << l.model.num_nodes() << " nodes, " << l.model.num_elements() << " elements)";
  if (!flags.restart.empty()) out << " from " << flags.restart;
  out << "\n";
  print_overrides(overrides, out);
  const run::RunReport r = run::run_model(l.model, options);
  for (const auto& w : r.warnings) out << "warning: " << w << "\n";
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s at t = %.6g s after %ld cycles, %.2f s wall, %.1f ns per element-cycle, energy ratio %.4f\n",
                r.completed ? "completed" : r.interrupted ? "INTERRUPTED" : "STOPPED", r.end_time, r.cycles, r.wall_seconds, r.ns_per_element_cycle,
                r.energy_ratio);
  out << buf;
  if (!r.termination.empty()) out << "ended by " << r.termination << "\n";
  out << "where the wall time went (summary.json: timing):\n" << run::timing_table(r.timing);
  out << "results: " << r.pvd.string() << " (open in ParaView), " << r.history.string() << ", " << r.summary.string() << "\n";
  if (!r.dump.empty())
    out << "restart dump: " << r.dump.string() << " (continue or extend: plyimpact run " << path << " -o "
        << options.output_dir.string() << " --restart " << r.dump.string() << " [--set control.termination_time=...])\n";
  if (!r.completed) {
    out << "stopped: " << r.stop_reason << "\n";
    return 2;
  }
  return 0;
}

}  // namespace

int run_application(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      (args.empty() ? err : out) << usage();
      return args.empty() ? 64 : 0;
    }
    if (args[0] == "--version") {
      out << "plyimpact " << PLYIMPACT_VERSION << "\n";
      return 0;
    }
    if (args[0] == "dcb-reduce") return dcb_reduce_command({args.begin() + 1, args.end()}, out, err);
    if (args[0] == "plot") return plot_command({args.begin() + 1, args.end()}, out, err);
    if (args[0] == "study") return study_command({args.begin() + 1, args.end()}, out, err);
    if (is_keyword_command(args))
      return keyword_command(args, out, err, [](const std::string& scene, const std::string& dir, std::ostream& o) {
        return run(scene, dir, Overrides{}, o);
      });
    if ((args[0] == "run" || args[0] == "check" || args[0] == "mesh") && args.size() >= 2) {
      std::string out_dir;
      Overrides overrides;
      RunFlags flags;
      for (std::size_t i = 2; i < args.size(); ++i) {
        if (parse_override_option(args, i, overrides)) continue;
        if ((args[i] == "-o" || args[i] == "--output") && i + 1 < args.size() && (args[0] == "run" || args[0] == "mesh")) {
          out_dir = args[++i];
        } else if (args[i] == "--restart" && i + 1 < args.size() && args[0] == "run") {
          flags.restart = args[++i];
        } else if (args[i] == "--replace" && args[0] == "run") {
          flags.replace = true;
        } else {
          err << "plyimpact: unexpected argument '" << args[i] << "'\n" << usage();
          return 64;
        }
      }
      if (args[0] == "mesh") return mesh_command(args[1], out_dir, overrides, out);
      return args[0] == "run" ? run(args[1], out_dir, overrides, out, flags) : check(args[1], overrides, out);
    }
    err << "plyimpact: unknown command or missing scene file\n" << usage();
    return 64;
  } catch (const InputError& e) {
    err << "error: " << e.what() << "\n";
    return 1;
  } catch (const RunError& e) {
    err << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "error: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace plyimpact::app
