// A study file: a base scene, the scene values to vary (any scalar key path, as for `--set`), how
// to combine them, fixed changes for every case, the quantities to extract, and optionally a
// mesh-convergence analysis and a Lambert-Jonas fit. Example (paths relative to the study file):
//
//   scene: ../low_velocity_impact.yaml
//   set: {output.interval: 1e-4}                 # every case
//   parameters:                                  # in file order; combined as a grid by default
//     impactor.velocity: [2, 3.12, 4]            # a list (YAML text, scene units or '<n> <unit>')
//     control.tssfac: {start: 0.5, stop: 0.9, step: 0.2}            # a linear range
//     contacts[0].PENALTY_SCALE: {start: 0.1, stop: 10, count: 3, spacing: log}
//   combine: grid                                # grid (cartesian product) or zip (lists in step)
//   quantities: [peak_contact_force, absorbed_energy, wall_time]
//   threads: 1                                   # per case (default: cores / jobs)
//   output: results/studies/energy               # default results/studies/<study file stem>
//   convergence: {parameter: laminate.refinement_level, h: refinement_level,
//                 reference: {peak_contact_force: 1.2e4}, order_band: [0.5, 4]}
//   lambert_jonas: {velocity: impactor.velocity}
//   ballistic_limit: {parameter: impactor.velocity, bracket: [100, 300], unit: m/s, tolerance: 5}
//   case_plots: true                             # force-time and energy-time PNG per case
//
// Every problem is an InputError naming study-file:line:col and the key (config/yaml_reader.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "config/overrides.hpp"

namespace plyimpact::study {

struct ParameterValue {
  std::string text;    // YAML text handed to --set ("5 m/s", "0.9", "2")
  std::string origin;  // "study.yaml:7:22" where the value is written (for error messages)
};

struct Parameter {
  std::string key;  // scene key path
  std::vector<ParameterValue> values;
};

enum class Combine { grid, zip };

// How the mesh size h of a case follows from the refinement parameter's value.
enum class HFrom {
  refinement_level,  // h = 2^-level (nested meshes)
  value,             // h = the value itself (an element size)
  list,              // h given per value, in the order of the parameter's values
};

struct ConvergenceSpec {
  std::string parameter;
  HFrom h_from = HFrom::refinement_level;
  std::vector<double> h;                                // HFrom::list
  std::vector<std::pair<std::string, double>> reference;  // quantity -> reference value (SI)
  double order_lo = 0.5, order_hi = 4.0;                // plausible band of the observed order
};

struct LambertJonasSpec {
  std::string velocity_parameter;  // the swept impact velocity
};

// Ballistic limit by bracketing (ballistic_limit.hpp); bracket and tolerance in `unit`. The
// parameter is the study's only one (its listed values, if any, are a sweep whose finished cases
// narrow the bracket) and `parameters:` may be left out.
struct BallisticLimitSpec {
  std::string parameter;
  double lo = 0, hi = 0, tolerance = 0;
  std::string unit;    // "" or a unit the scene accepts for the parameter ("m/s")
  std::string origin;  // "study.yaml:12:18: ballistic_limit" for messages
};

struct StudySpec {
  std::filesystem::path file;   // the study file
  std::string name;             // its stem
  std::filesystem::path scene;  // base scene (resolved against the study file's folder)
  std::filesystem::path output_dir;
  std::vector<config::SceneOverride> fixed;  // `set:`
  std::vector<Parameter> parameters;
  Combine combine = Combine::grid;
  std::vector<std::string> quantities;
  int threads = 0;  // per case; 0 = from the core count and the number of jobs
  bool case_plots = false;
  std::optional<ConvergenceSpec> convergence;
  std::optional<LambertJonasSpec> lambert_jonas;
  std::optional<BallisticLimitSpec> ballistic_limit;
};

/// Reads and validates a study file. @throws InputError (file:line:col: key: what; found; allowed)
StudySpec read_study(const std::filesystem::path& path);

/// Same from text; `path` labels messages and anchors relative paths.
StudySpec read_study_from_string(const std::string& text, const std::filesystem::path& path);

/// The numeric part of a value's text ("5 m/s" -> 5), NaN when it has none.
double leading_number(const std::string& text);

}  // namespace plyimpact::study
