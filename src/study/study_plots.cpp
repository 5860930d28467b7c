// Study plots. See study_plots.hpp.
#include "study/study_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_plot.hpp"
#include "study/channel_filter.hpp"
#include "study/quantities.hpp"

namespace plyimpact::study {
namespace {

namespace fs = std::filesystem;

// "contacts[0].SOFT" -> "contacts_0_.SOFT" is ugly; keep letters, digits, '.', '_' and '-'.
std::string file_part(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
  return out;
}

void try_plot(const output::CsvPlot& plot, const fs::path& png, PlotLog& log) {
  try {
    fs::create_directories(png.parent_path());
    output::plot_csv_png(plot, png);
    log.written.push_back(png);
  } catch (const std::exception& e) {
    log.warnings.push_back(msg() << "plot " << png.filename().string() << " not made: " << e.what());
  }
}

bool any_finite(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// <case_dir>/impactor_force.csv and .png: the rigid impactor's interval-mean axial force and the same
// filtered at CFC 600 and 1000, the curves the peak_impactor_force_* quantities take their peak from.
// A scene without a rigid impactor has none (no warning: nothing is missing).
void plot_impactor_force(const fs::path& case_dir, PlotLog& log) {
  ImpactorForce f;
  try {
    f = impactor_force(read_run_record(case_dir.string()));
  } catch (const NotAvailable&) {
    return;
  } catch (const std::exception& e) {
    log.warnings.push_back(e.what());
    return;
  }
  const auto cfc600 = cfc_filter(f.force, f.interval, 600), cfc1000 = cfc_filter(f.force, f.interval, 1000);
  std::string text = "time,impactor_force,impactor_force_cfc600,impactor_force_cfc1000\n";
  char line[128];
  for (std::size_t i = 0; i < f.time.size(); ++i) {
    std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,%.10g\n", f.time[i], f.force[i], cfc600[i], cfc1000[i]);
    text += line;
  }
  const fs::path csv = case_dir / "impactor_force.csv";
  output::write_text_atomically(csv, text);
  output::CsvPlot plot;
  plot.csv = csv;
  plot.x_column = "time";
  plot.series = {{"impactor_force", "mean over each history interval"},
                 {"impactor_force_cfc600", "CFC 600 (SAE J211)"},
                 {"impactor_force_cfc1000", "CFC 1000"}};
  plot.title = case_dir.filename().string() + ": axial force on the impactor";
  plot.x_label = "time (ms)";
  plot.x_scale = 1e3;
  plot.y_label = "force (kN)";
  plot.y_scale = 1e-3;
  try_plot(plot, case_dir / "impactor_force.png", log);
}

}  // namespace

void plot_quantities(const StudyTable& table, const fs::path& dir, PlotLog& log) {
  for (std::size_t p = 0; p < table.parameter_keys.size(); ++p) {
    std::vector<double> xs;
    for (const auto& r : table.rows) xs.push_back(leading_number(r.values[p]));
    if (!any_finite(xs)) continue;  // a parameter of names, not numbers
    for (const auto& q : table.quantity_columns) {
      std::vector<double> ys;
      for (const auto& r : table.rows) ys.push_back(r.quantity(q));
      if (!any_finite(ys)) continue;
      output::CsvPlot plot;
      plot.csv = dir / "study.csv";
      plot.x_column = table.parameter_keys[p];
      plot.series.push_back({q, q, {}, table.parameter_keys.size() > 1});
      plot.title = q + " against " + table.parameter_keys[p];
      plot.with_points = true;
      try_plot(plot, dir / "plots" / (file_part(q) + "_vs_" + file_part(table.parameter_keys[p]) + ".png"), log);
    }
  }
}

void plot_convergence(const ConvergenceReport& rep, const fs::path& dir, PlotLog& log) {
  for (const auto& q : rep.quantities) {
    output::CsvPlot plot;
    plot.csv = dir / "convergence.csv";
    plot.x_column = "wall_time";
    if (any_finite(q.error_finest)) plot.series.push_back({q.quantity + "_error_finest", "against the finest mesh"});
    if (any_finite(q.error_extrapolated))
      plot.series.push_back({q.quantity + "_error_richardson", "against the Richardson extrapolation"});
    if (any_finite(q.error_reference)) plot.series.push_back({q.quantity + "_error_reference", "against the reference"});
    if (plot.series.empty() || !any_finite(rep.wall_time)) continue;
    plot.title = q.quantity + ": relative error against run time";
    plot.x_label = "wall time (s)";
    plot.y_label = "relative error of " + q.quantity;
    plot.log_x = plot.log_y = true;
    plot.with_points = true;
    try_plot(plot, dir / "plots" / ("convergence_" + file_part(q.quantity) + ".png"), log);
  }
}

void plot_residual_velocity(const std::optional<LambertJonasFit>& fit, const std::optional<BallisticLimit>& limit,
                            const std::string& velocity_key, double v_max, const fs::path& dir, PlotLog& log) {
  output::CsvPlot plot;
  plot.csv = dir / "study.csv";
  plot.x_column = velocity_key;
  plot.series.push_back({"residual_velocity", "computed", {}, true});
  if (fit) {
    const double v_hi = 1.05 * v_max;
    std::string csv = velocity_key + ",residual_velocity_fit\n";
    for (int i = 0; i <= 200; ++i) {
      const double v = v_hi * i / 200.0;
      char line[64];
      std::snprintf(line, sizeof line, "%.10g,%.10g\n", v, lambert_jonas(*fit, v));
      csv += line;
    }
    const fs::path curve = dir / "lambert_jonas_curve.csv";
    output::write_text_atomically(curve, csv);
    char title[160];
    std::snprintf(title, sizeof title, "Lambert-Jonas fit: a = %.3g, p = %.3g, ballistic limit %.4g m/s", fit->a,
                  fit->p, fit->v_bl);
    plot.series.push_back({"residual_velocity_fit", title, curve, false});
  }
  if (limit) {
    char csv[256];
    std::snprintf(csv, sizeof csv, "%s,bracket,limit\n%.10g,0,\n%.10g,0,0\n%.10g,0,\n", velocity_key.c_str(),
                  limit->lo, limit->limit, limit->hi);
    const fs::path marks = dir / "ballistic_limit_bracket.csv";
    output::write_text_atomically(marks, csv);
    char title[160];
    std::snprintf(title, sizeof title, "ballistic limit by bracketing: %.4g +- %.2g (bracket [%.4g, %.4g])",
                  limit->limit, 0.5 * (limit->hi - limit->lo), limit->lo, limit->hi);
    plot.series.push_back({"bracket", title, marks, false});
    plot.series.push_back({"limit", "ballistic limit (mid-point of the bracket)", marks, true});
  }
  plot.title = "residual velocity against impact velocity";
  plot.x_label = velocity_key + " (m/s)";
  plot.y_label = "residual velocity (m/s)";
  try_plot(plot, dir / "plots" / "residual_velocity_lambert_jonas.png", log);
}

void plot_case(const fs::path& case_dir, PlotLog& log) {
  const fs::path csv = case_dir / "history.csv";
  std::vector<std::string> columns;
  try {
    columns = output::csv_columns(csv);
  } catch (const std::exception& e) {
    log.warnings.push_back(e.what());
    return;
  }
  output::CsvPlot force;
  force.csv = csv;
  force.x_column = "time";
  // The contact's resultant on its first surface, component by component (peak_contact_force is its
  // magnitude), not its `_normal` column: that sums the magnitudes of every spring's normal force,
  // both ways, which is no force on either body.
  for (const auto& c : columns)
    if ((c.starts_with("contact_") && (c.ends_with("_fx") || c.ends_with("_fy") || c.ends_with("_fz"))) ||
        (c.starts_with("wall_") && c.ends_with("_normal")))
      force.series.push_back({c, ""});
  if (!force.series.empty()) {
    force.title = case_dir.filename().string() + ": contact force";
    force.y_label = "force (N)";
    try_plot(force, case_dir / "force_time.png", log);
  }
  plot_impactor_force(case_dir, log);
  output::CsvPlot energy;
  energy.csv = csv;
  energy.x_column = "time";
  for (const char* c : {"kinetic_energy", "internal_energy", "hourglass_energy", "contact_energy", "eroded_energy",
                        "external_work", "total_energy"})
    if (std::find(columns.begin(), columns.end(), c) != columns.end()) energy.series.push_back({c, ""});
  energy.title = case_dir.filename().string() + ": energy balance";
  energy.y_label = "energy (J)";
  try_plot(energy, case_dir / "energy_time.png", log);
}

}  // namespace plyimpact::study
