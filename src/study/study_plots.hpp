// The study's PNG plots, through output/csv_plot.hpp (gnuplot, headless): every quantity against
// every numeric parameter, error against wall time (log-log) per quantity of a convergence study,
// the residual-velocity curve with its Lambert-Jonas fit, and per case (case_plots: true) the
// contact force and the energy balance against time. A plot that cannot be made (gnuplot missing,
// no finite value) is reported as a warning: the tables are the study's result, plots a view.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "study/ballistic_limit.hpp"
#include "study/convergence.hpp"
#include "study/lambert_jonas.hpp"
#include "study/study_table.hpp"

namespace plyimpact::study {

struct PlotLog {
  std::vector<std::filesystem::path> written;
  std::vector<std::string> warnings;
};

/// <dir>/plots/<quantity>_vs_<parameter>.png from <dir>/study.csv.
void plot_quantities(const StudyTable& table, const std::filesystem::path& dir, PlotLog& log);

/// <dir>/plots/convergence_<quantity>.png from <dir>/convergence.csv.
void plot_convergence(const ConvergenceReport& report, const std::filesystem::path& dir, PlotLog& log);

/// <dir>/plots/residual_velocity_lambert_jonas.png: the computed residual velocities of study.csv,
/// with the Lambert-Jonas fit when there is one (<dir>/lambert_jonas_curve.csv, drawn from 0 to
/// 1.05 v_max) and the ballistic-limit bracket when a search found one (<dir>/ballistic_limit_bracket.csv:
/// the bracket as a segment at zero residual velocity, its mid-point marked). The velocity column of
/// study.csv must then be in m/s, as the fit is.
void plot_residual_velocity(const std::optional<LambertJonasFit>& fit, const std::optional<BallisticLimit>& limit,
                            const std::string& velocity_key, double v_max, const std::filesystem::path& dir,
                            PlotLog& log);

/// <case_dir>/force_time.png and <case_dir>/energy_time.png from its history.csv; with a rigid
/// impactor also impactor_force.csv and .png (its axial force, raw and CFC-filtered).
void plot_case(const std::filesystem::path& case_dir, PlotLog& log);

}  // namespace plyimpact::study
