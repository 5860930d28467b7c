// Mesh-convergence analysis of a study table: the cases ordered from the coarsest to the finest
// mesh (h from the refinement parameter, study_spec.hpp), and for every quantity its relative error
// against the finest mesh, against the Richardson extrapolation of the three finest meshes
// (richardson.hpp: observed order, asymptotic-range flags) and against the study's reference
// value, beside each case's wall time: what each digit of accuracy costs. Cost quantities (wall
// time, ns per element-cycle, element and cycle counts) are tabulated, not analysed.
// Replicates: when the study varies another parameter beside the mesh (a perturbation such as
// impactor.gap or control.tssfac, combined as a grid), the cases of one mesh are replicates of it.
// A mesh's value is then their mean, its spread the range (largest minus smallest), and its wall
// time the mean of one run. An event driven by thresholds (first erosion, onset of delamination)
// moves by a few per cent under any perturbation; a change between the two finest meshes smaller
// than their spread is flagged as not resolved by the study, whatever its size.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "output/json.hpp"
#include "study/richardson.hpp"
#include "study/study_spec.hpp"
#include "study/study_table.hpp"

namespace plyimpact::study {

struct QuantityConvergence {
  std::string quantity;
  std::vector<double> values;  // per mesh, coarse to fine (the replicates' mean)
  std::vector<double> spread;  // per mesh, largest minus smallest replicate (0 for one run)
  std::vector<std::string> flags;  // replicate flags (beside the Richardson ones)
  std::optional<RichardsonResult> richardson;  // with three or more meshes
  std::optional<double> reference;
  // Relative errors per mesh (|q - q_x| / |q_x|); NaN where undefined (the finest against itself).
  std::vector<double> error_finest, error_extrapolated, error_reference;
};

struct ConvergenceReport {
  std::string parameter;
  std::vector<std::string> cases;  // coarse to fine; replicates of one mesh joined with '+'
  std::vector<std::vector<std::string>> case_names;  // per mesh, every replicate's case
  std::vector<double> h, wall_time;                  // wall_time: mean of one run of the mesh
  std::vector<QuantityConvergence> quantities;
};

/// Analyses the finished rows of `table` (unfinished meshes are left out).
ConvergenceReport analyse_convergence(const StudySpec& spec, const StudyTable& table);

/// convergence.csv: case, h, wall_time, replicates, then per quantity <q>, <q>_spread,
/// <q>_error_finest, <q>_error_richardson, <q>_error_reference.
std::string convergence_csv(const ConvergenceReport& report);

output::Json convergence_json(const ConvergenceReport& report);

/// Mesh size of a refinement value (HFrom rules), for the value at `index` of the parameter.
double mesh_size(const ConvergenceSpec& c, const std::string& value_text, std::size_t index);

}  // namespace plyimpact::study
