// dcb-reduce: argument parsing, the reduction, and its three output files. See dcb_reduce_command.hpp.
#include "app/dcb_reduce_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "core/error.hpp"
#include "core/units.hpp"
#include "fracture/dcb_record.hpp"
#include "fracture/dcb_reduction.hpp"
#include "output/csv_plot.hpp"
#include "output/history_table.hpp"
#include "output/json.hpp"

namespace plyimpact::app {

const char* const kDcbReduceUsage =
    "  dcb-reduce DATA.csv --width B --thickness H [-o DIR]\n"
    "                            ASTM D5528 mode I reduction of a DCB record (test machine export or a\n"
    "                            simulated DCB's history.csv): G_Ic R-curve by MBT, CC and MCC.\n"
    "                            B, H: specimen width and total thickness, '25 mm' or a number in the\n"
    "                            length unit. Options: --length-unit U (opening and crack length\n"
    "                            columns, default m), --force-unit U (load column, default N),\n"
    "                            --load/--opening/--crack NAME (columns; default load, opening,\n"
    "                            crack_length), --all-rows (every row is a propagation point; default:\n"
    "                            the rows where the crack length grows), --smooth N (load and opening\n"
    "                            averaged over the 2N + 1 rows around each row first, as a load cell's\n"
    "                            filter: for simulated records, whose rows carry the arms' vibration;\n"
    "                            default 0). Writes to DIR (default\n"
    "                            results/<data>_dcb): dcb_reduction.csv (SI: a m, P N, delta m, C m/N,\n"
    "                            G J/m^2), dcb_fits.json, dcb_r_curve.png\n";

namespace {
namespace fs = std::filesystem;
namespace u = units;

struct DcbOptions {
  std::string data, width, thickness, length_unit = "m", force_unit = "N";
  fracture::DcbColumns columns;
  fracture::PropagationRule rule = fracture::PropagationRule::crack_growth;
  std::string smooth = "0";
  std::string out_dir;
};

// Fills `o` from args; returns false (after printing why) on a usage error.
bool parse_options(const std::vector<std::string>& args, DcbOptions& o, std::ostream& err) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    auto value = [&](std::string& target) {
      if (!has_value) return false;
      target = args[++i];
      return true;
    };
    bool ok = true;
    if (a == "--width") ok = value(o.width);
    else if (a == "--thickness") ok = value(o.thickness);
    else if (a == "--length-unit") ok = value(o.length_unit);
    else if (a == "--force-unit") ok = value(o.force_unit);
    else if (a == "--load") ok = value(o.columns.load);
    else if (a == "--opening") ok = value(o.columns.opening);
    else if (a == "--crack") ok = value(o.columns.crack);
    else if (a == "-o" || a == "--output") ok = value(o.out_dir);
    else if (a == "--smooth") ok = value(o.smooth);
    else if (a == "--all-rows") o.rule = fracture::PropagationRule::all_rows;
    else if (o.data.empty() && !a.starts_with("-")) o.data = a;
    else {
      err << "plyimpact dcb-reduce: unexpected argument '" << a << "'\n";
      return false;
    }
    if (!ok) {
      err << "plyimpact dcb-reduce: " << a << " needs a value\n";
      return false;
    }
  }
  if (o.data.empty() || o.width.empty() || o.thickness.empty()) {
    err << "plyimpact dcb-reduce: needs DATA.csv, --width and --thickness\n";
    return false;
  }
  return true;
}

// --smooth N: rows on each side of the moving average (fracture::smoothed_record).
int smooth_rows(const std::string& text) {
  std::size_t used = 0;
  int n = -1;
  try {
    n = std::stoi(text, &used);
  } catch (const std::exception&) {
  }
  if (used != text.size() || n < 0 || n > 1000)
    throw InputError(msg() << "--smooth " << text << ": not a row count; allowed an integer from 0 to 1000");
  return n;
}

double unit_factor(const std::string& option, const std::string& text, u::Dimension d) {
  u::Unit unit;
  try {
    unit = u::parse_unit(text);
  } catch (const u::UnitError& e) {
    throw InputError(msg() << option << " " << text << ": " << e.problem() << "; allowed " << u::describe(d));
  }
  if (!(unit.dim == d))
    throw InputError(msg() << option << " " << text << ": not a unit of " << u::name_of(d) << "; allowed "
                           << u::describe(d));
  return unit.factor;
}

double positive_length(const std::string& option, const std::string& text, double length_unit) {
  const u::UnitSystem system{"the length unit", length_unit, 1, 1};
  double v = 0;
  try {
    v = u::quantity_to_si(text, u::length, system);
  } catch (const u::UnitError& e) {
    throw InputError(msg() << option << " " << text << ": " << e.problem() << "; allowed " << e.allowed());
  }
  if (!(v > 0)) throw InputError(msg() << option << " " << text << ": must be > 0; allowed a positive length");
  return v;
}

output::Json fit_json(const fracture::LineFit& f, const char* x, const char* y) {
  output::Json j = output::Json::object();
  j["x"] = x;
  j["y"] = y;
  j["slope"] = f.slope;
  j["intercept"] = f.intercept;
  j["r2"] = f.r2;
  return j;
}

output::Json stats_json(const std::vector<double>& g) {
  output::Json j = output::Json::object();
  double sum = 0;
  for (double v : g) sum += v;
  j["mean"] = sum / double(g.size());
  j["min"] = *std::min_element(g.begin(), g.end());
  j["max"] = *std::max_element(g.begin(), g.end());
  return j;
}

void write_outputs(const fracture::DcbReduction& r, const std::vector<fracture::DcbRow>& rows,
                   const fracture::DcbSpecimen& spec, const DcbOptions& o, const fs::path& dir, std::ostream& out,
                   std::ostream& err) {
  fs::create_directories(dir);
  output::HistoryTable table({"a", "P", "delta", "C", "G_MBT", "G_CC", "G_MCC", "source_line"});
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const auto& p = r.points[i];
    const double row[] = {p.a, p.P, p.delta, r.compliance[i], r.G_mbt[i], r.G_cc[i], r.G_mcc[i], double(rows[i].line)};
    table.add_row(row);
  }
  const fs::path csv = dir / "dcb_reduction.csv", json = dir / "dcb_fits.json", png = dir / "dcb_r_curve.png";
  table.write_csv(csv);

  output::Json j = output::Json::object();
  j["data"] = o.data;
  j["units"] = "SI: a, delta, Delta in m; P in N; C in m/N; G in J/m^2; A1 in N^(1/3)/m^(1/3)";
  j["width"] = spec.width;
  j["thickness"] = spec.thickness;
  j["propagation_rule"] = o.rule == fracture::PropagationRule::all_rows ? "all rows" : "rows where the crack length grows";
  j["propagation_points"] = r.points.size();
  j["smooth_rows"] = smooth_rows(o.smooth);
  output::Json& mbt = j["MBT"] = output::Json::object();
  mbt["fit"] = fit_json(r.mbt_fit, "a", "C^(1/3)");
  mbt["x_intercept"] = r.delta_x_intercept;
  mbt["Delta"] = r.Delta;
  mbt["G"] = stats_json(r.G_mbt);
  output::Json& cc = j["CC"] = output::Json::object();
  cc["fit"] = fit_json(r.cc_fit, "ln a", "ln C");
  cc["n"] = r.n;
  cc["G"] = stats_json(r.G_cc);
  output::Json& mcc = j["MCC"] = output::Json::object();
  mcc["fit"] = fit_json(r.mcc_fit, "C^(1/3)", "a/h");
  mcc["A1"] = r.A1;
  mcc["G"] = stats_json(r.G_mcc);
  output::write_json_atomically(json, j);

  char buf[256];
  out << "plyimpact dcb-reduce: " << o.data << ": " << r.points.size() << " propagation points, a from "
      << r.points.front().a * 1e3 << " to " << r.points.back().a * 1e3 << " mm\n";
  std::snprintf(buf, sizeof buf, "  MBT: C^(1/3) = %.6g a %+.6g (R^2 %.6f), Delta = %.4g mm\n", r.mbt_fit.slope,
                r.mbt_fit.intercept, r.mbt_fit.r2, r.Delta * 1e3);
  out << buf;
  std::snprintf(buf, sizeof buf, "  CC:  ln C = %.6g ln a %+.6g (R^2 %.6f), n = %.5g\n", r.cc_fit.slope,
                r.cc_fit.intercept, r.cc_fit.r2, r.n);
  out << buf;
  std::snprintf(buf, sizeof buf, "  MCC: a/h = %.6g C^(1/3) %+.6g (R^2 %.6f), A1 = %.6g\n", r.mcc_fit.slope,
                r.mcc_fit.intercept, r.mcc_fit.r2, r.A1);
  out << buf;
  const auto mean = [](const std::vector<double>& g) {
    double s = 0;
    for (double v : g) s += v;
    return s / double(g.size());
  };
  std::snprintf(buf, sizeof buf, "  mean G_Ic: MBT %.5g, CC %.5g, MCC %.5g J/m^2\n", mean(r.G_mbt), mean(r.G_cc),
                mean(r.G_mcc));
  out << buf;
  out << "wrote " << csv.string() << "\nwrote " << json.string() << "\n";

  output::CsvPlot plot;
  plot.csv = csv;
  plot.x_column = "a";
  plot.x_scale = 1e3;
  plot.series = {{"G_MBT", "MBT"}, {"G_CC", "CC"}, {"G_MCC", "MCC"}};
  plot.title = "ASTM D5528 R-curve: " + fs::path(o.data).filename().string();
  plot.x_label = "crack length a (mm)";
  plot.y_label = "G_Ic (J/m^2)";
  plot.with_points = r.points.size() <= 60;
  if (!output::find_gnuplot()) {
    err << "warning: no PNG plot: gnuplot is not on PATH (Debian package gnuplot-nox; tools/install-deps.sh)\n";
    return;
  }
  output::plot_csv_png(plot, png);
  out << "wrote " << png.string() << "\n";
}

}  // namespace

int dcb_reduce_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  DcbOptions o;
  if (!parse_options(args, o, err)) {
    err << "usage:\n" << kDcbReduceUsage;
    return 64;
  }
  fracture::DcbUnits units;
  units.length = unit_factor("--length-unit", o.length_unit, u::length);
  units.force = unit_factor("--force-unit", o.force_unit, u::force);
  fracture::DcbSpecimen spec;
  spec.width = positive_length("--width", o.width, units.length);
  spec.thickness = positive_length("--thickness", o.thickness, units.length);
  const fracture::DcbRecord record = fracture::read_dcb_record(o.data, o.columns, units);
  const std::vector<fracture::DcbRow> rows =
      fracture::propagation_points(fracture::smoothed_record(record, smooth_rows(o.smooth)), o.rule);
  std::vector<fracture::DcbPoint> points;
  for (const auto& row : rows) points.push_back(row.point);
  const fracture::DcbReduction r = fracture::reduce_dcb(points, spec);
  const fs::path dir = o.out_dir.empty() ? fs::path("results") / (fs::path(o.data).stem().string() + "_dcb")
                                         : fs::path(o.out_dir);
  write_outputs(r, rows, spec, o, dir, out, err);
  return 0;
}

}  // namespace plyimpact::app
