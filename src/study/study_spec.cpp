// Study file reader. See study_spec.hpp.
#include "study/study_spec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "config/yaml_reader.hpp"
#include "core/error.hpp"
#include "study/quantities.hpp"

namespace plyimpact::study {
namespace {

using config::detail::Context;
using config::detail::Limits;
using config::detail::Reader;
namespace fs = std::filesystem;

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string origin_of(const Reader& r, const Context& ctx) { return config::detail::location(ctx.file, r.mark()); }

std::vector<ParameterValue> read_list(const Reader& r, const Context& ctx) {
  r.require_list("a list of values (numbers, '<number> <unit>', names or flow lists)", true);
  std::vector<ParameterValue> values;
  for (const Reader& item : r.items()) {
    if (item.node().IsScalar()) {
      values.push_back({item.node().Scalar(), origin_of(item, ctx)});
      continue;
    }
    // A list or mapping value (an element count [50, 1, 1]) is handed on as flow YAML.
    if (!item.node().IsSequence() && !item.node().IsMap())
      item.fail("a value is needed", item.found_text(), "a scalar, a [list] or a {mapping}");
    YAML::Emitter e;
    e << YAML::Flow << item.node();
    values.push_back({e.c_str(), origin_of(item, ctx)});
  }
  return values;
}

// {start, stop, step | count, spacing: linear | log, unit}
std::vector<ParameterValue> read_range(const Reader& r, const Context& ctx) {
  r.allow_keys({"start", "stop", "step", "count", "spacing", "unit"});
  const double start = r.at("start", "the first value").as_quantity(units::dimensionless);
  const double stop = r.at("stop", "the last value").as_quantity(units::dimensionless);
  const std::string spacing = r.has("spacing") ? r.at("spacing", "").as_choice({"linear", "log"}) : "linear";
  const std::string unit = r.has("unit") ? r.at("unit", "a unit such as m/s").as_name() : "";
  const std::string how = r.exactly_one({"step", "count"});
  std::vector<double> v;
  if (spacing == "log" && (start <= 0 || stop <= 0))
    r.fail("a log range needs start > 0 and stop > 0", msg() << "start " << start << ", stop " << stop,
           "positive start and stop, or spacing: linear");
  if (how == "count") {
    const long n = r.at("count", "").as_integer(Limits::at_least(2, "count"));
    for (long i = 0; i < n; ++i) {
      const double s = double(i) / double(n - 1);
      v.push_back(spacing == "log" ? start * std::pow(stop / start, s) : start + s * (stop - start));
    }
  } else {
    if (spacing == "log") r.at("step", "").fail("a log range is given by count", "step", "count: <number of values>");
    const Reader step_r = r.at("step", "");
    const double step = step_r.as_quantity(units::dimensionless);
    if (step == 0 || (stop - start) / step < 0)
      step_r.fail("the step does not lead from start to stop", format_number(step),
                  "a step with the sign of stop - start");
    const double n = std::floor((stop - start) / step * (1 + 1e-12) + 1e-9);
    if (n > 10000) step_r.fail("the range has more than 10000 values", format_number(n + 1), "a coarser step");
    for (long i = 0; i <= long(n); ++i) v.push_back(start + double(i) * step);
  }
  std::vector<ParameterValue> values;
  const std::string origin = origin_of(r, ctx);
  for (double x : v) values.push_back({unit.empty() ? format_number(x) : format_number(x) + " " + unit, origin});
  return values;
}

std::vector<Parameter> read_parameters(const Reader& r, const Context& ctx) {
  r.require_map("a mapping of scene key paths to lists or ranges of values");
  std::vector<Parameter> params;
  for (const auto& [key, value] : r.entries()) {
    Parameter p{key, {}};
    if (value.node().IsSequence()) p.values = read_list(value, ctx);
    else if (value.node().IsMap()) p.values = read_range(value, ctx);
    else value.fail("a parameter needs several values", value.found_text(),
                    "a list [a, b, c] or a range {start, stop, step | count}");
    params.push_back(std::move(p));
  }
  if (params.empty()) r.fail("no parameters", "an empty mapping", "at least one scene key path to vary");
  return params;
}

std::vector<config::SceneOverride> read_fixed(const Reader& r, const Context& ctx) {
  r.require_map("a mapping of scene key paths to values");
  std::vector<config::SceneOverride> out;
  for (const auto& [key, value] : r.entries()) {
    value.require_scalar("a scalar value");
    out.push_back({key, value.node().Scalar(), origin_of(value, ctx) + ": set " + key + "=" + value.node().Scalar()});
  }
  return out;
}

std::vector<std::string> read_quantities(const Reader& r) {
  r.require_list("a list of quantity names", true);
  std::vector<std::string> names;
  for (const Reader& item : r.items()) {
    const std::string name = item.as_name();
    if (!find_quantity(name)) {
      const std::string hint = config::detail::did_you_mean(name, quantity_names());
      item.fail("unknown quantity '" + name + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"),
                config::detail::join(quantity_names()));
    }
    names.push_back(name);
  }
  return names;
}

const Parameter* find_parameter(const std::vector<Parameter>& ps, const std::string& key) {
  for (const auto& p : ps)
    if (p.key == key) return &p;
  return nullptr;
}

std::vector<std::string> keys_of(const std::vector<Parameter>& ps) {
  std::vector<std::string> k;
  for (const auto& p : ps) k.push_back(p.key);
  return k;
}

ConvergenceSpec read_convergence(const Reader& r, const std::vector<Parameter>& params) {
  r.allow_keys({"parameter", "h", "reference", "order_band"});
  ConvergenceSpec c;
  const Reader pr = r.at("parameter", "the refinement parameter (one of the study's parameters)");
  c.parameter = pr.as_name();
  const Parameter* p = find_parameter(params, c.parameter);
  if (!p) pr.fail("not one of the study's parameters", c.parameter, config::detail::join(keys_of(params)));
  if (p->values.size() < 2) pr.fail("a convergence study needs at least two meshes", "1 value", "2 or more values");
  if (const auto h = r.find("h")) {
    if (h->node().IsSequence()) {
      c.h_from = HFrom::list;
      for (const Reader& item : h->items()) c.h.push_back(item.as_quantity(units::dimensionless, Limits::positive("h")));
      if (c.h.size() != p->values.size())
        h->fail("one h per value of the refinement parameter", msg() << c.h.size() << " values",
                msg() << p->values.size() << " values");
    } else {
      c.h_from = h->as_choice({"refinement_level", "value"}) == "value" ? HFrom::value : HFrom::refinement_level;
    }
  }
  if (const auto ref = r.find("reference")) {
    ref->require_map("a mapping of quantity names to reference values (SI)");
    for (const auto& [name, value] : ref->entries()) {
      if (!find_quantity(name) && name.find("delaminated_area") != 0 && name.find("eroded_elements") != 0)
        value.fail("unknown quantity '" + name + "'", config::detail::join(quantity_names()));
      c.reference.push_back({name, value.as_quantity(units::dimensionless)});
    }
  }
  if (const auto band = r.find("order_band")) {
    band->require_list("[low, high]", true);
    const auto items = band->items();
    if (items.size() != 2) band->fail("two numbers", band->found_text(), "[low, high] with 0 < low < high");
    c.order_lo = items[0].as_quantity(units::dimensionless, Limits::positive("low"));
    c.order_hi = items[1].as_quantity(units::dimensionless, Limits::positive("high"));
    if (c.order_hi <= c.order_lo) band->fail("low must be below high", band->found_text(), "[low, high], low < high");
  }
  return c;
}

void add_quantity(StudySpec& s, const std::string& name) {
  if (std::find(s.quantities.begin(), s.quantities.end(), name) == s.quantities.end()) s.quantities.push_back(name);
}

// ballistic_limit: {parameter, bracket: [lo, hi], unit, tolerance}; the parameter becomes the
// study's only parameter (with no values when the study does not sweep it).
BallisticLimitSpec read_ballistic_limit(const Reader& r, const Context& ctx, std::vector<Parameter>& params) {
  r.allow_keys({"parameter", "bracket", "unit", "tolerance"});
  BallisticLimitSpec b;
  b.origin = origin_of(r, ctx) + ": ballistic_limit";
  const Reader pr = r.at("parameter", "the swept impact velocity key path (impactor.velocity)");
  b.parameter = pr.as_name();
  if (params.empty()) params.push_back({b.parameter, {}});
  if (params.size() != 1 || params.front().key != b.parameter)
    pr.fail("the ballistic limit is searched with everything else fixed", config::detail::join(keys_of(params)),
            "parameters: only " + b.parameter + " (a sweep of it), other changes under set:");
  const Reader br = r.at("bracket", "[lo, hi]: lo stops the impactor, hi perforates");
  br.require_list("[lo, hi]", true);
  const auto items = br.items();
  if (items.size() != 2) br.fail("two values", br.found_text(), "[lo, hi] with 0 <= lo < hi");
  b.lo = items[0].as_quantity(units::dimensionless, Limits::non_negative("lo"));
  b.hi = items[1].as_quantity(units::dimensionless, Limits::positive("hi"));
  if (b.hi <= b.lo) br.fail("lo must be below hi", br.found_text(), "[lo, hi] with lo < hi");
  if (r.has("unit")) b.unit = r.at("unit", "a unit such as m/s").as_name();
  const Reader tr = r.at("tolerance", "the bracket width to stop at (same unit)");
  b.tolerance = tr.as_quantity(units::dimensionless, Limits::positive("tolerance"));
  if (b.tolerance >= b.hi - b.lo)
    tr.fail("the tolerance is not below the bracket's width", format_number(b.tolerance),
            "a tolerance below hi - lo = " + format_number(b.hi - b.lo));
  return b;
}

StudySpec read_root(const Reader& root, const Context& ctx, const fs::path& path) {
  root.require_map("a study: a mapping with scene, parameters, quantities ...");
  root.allow_keys({"scene", "set", "parameters", "combine", "quantities", "threads", "output", "convergence",
                   "lambert_jonas", "case_plots", "ballistic_limit"});
  StudySpec s;
  s.file = path;
  s.name = path.stem().string();
  const Reader scene = root.at("scene", "the base scene file (relative to the study file)");
  s.scene = path.parent_path() / scene.as_name();
  if (!fs::exists(s.scene)) scene.fail("the scene file does not exist", s.scene.string(), "a path to a scene YAML file");
  s.output_dir = root.has("output") ? fs::path(root.at("output", "").as_name()) : fs::path("results/studies") / s.name;
  if (const auto f = root.find("set")) s.fixed = read_fixed(*f, ctx);
  if (!root.has("parameters") && root.has("ballistic_limit")) {
    // The search's own cases only.
  } else {
    s.parameters = read_parameters(root.at("parameters", "the scene values to vary"), ctx);
  }
  if (root.has("combine")) {
    const Reader c = root.at("combine", "");
    s.combine = c.as_choice({"grid", "zip"}) == "zip" ? Combine::zip : Combine::grid;
    if (s.combine == Combine::zip)
      for (const auto& p : s.parameters)
        if (p.values.size() != s.parameters.front().values.size())
          c.fail("zip needs lists of equal length", msg() << p.key << " has " << p.values.size() << " values",
                 msg() << s.parameters.front().values.size() << " values, as " << s.parameters.front().key);
  }
  s.quantities = read_quantities(root.at("quantities", "the quantities to extract"));
  if (const auto bl = root.find("ballistic_limit")) {
    s.ballistic_limit = read_ballistic_limit(*bl, ctx, s.parameters);
    add_quantity(s, "residual_velocity");
    add_quantity(s, "perforated");
  }
  s.threads = int(root.integer_or("threads", 0, Limits::non_negative("threads")));
  if (const auto cp = root.find("case_plots")) s.case_plots = cp->as_choice({"true", "false"}) == "true";
  if (const auto c = root.find("convergence")) {
    s.convergence = read_convergence(*c, s.parameters);
    if (s.parameters.size() != 1)
      c->fail("a convergence study varies the mesh only", msg() << s.parameters.size() << " parameters",
              "one parameter, the refinement (fixed changes go under set:)");
    // Error against cost needs the cost.
    if (std::find(s.quantities.begin(), s.quantities.end(), "wall_time") == s.quantities.end())
      s.quantities.push_back("wall_time");
  }
  if (const auto lj = root.find("lambert_jonas")) {
    lj->allow_keys({"velocity"});
    const Reader v = lj->at("velocity", "the swept impact velocity parameter");
    if (!find_parameter(s.parameters, v.as_name()))
      v.fail("not one of the study's parameters", v.as_name(), config::detail::join(keys_of(s.parameters)));
    s.lambert_jonas = LambertJonasSpec{v.as_name()};
    bool has_residual = false;
    for (const auto& q : s.quantities) has_residual |= q == "residual_velocity";
    if (!has_residual) lj->fail("the fit needs the residual velocity", "quantities without residual_velocity",
                                "residual_velocity in quantities");
    add_quantity(s, "perforated");  // the fit counts a stopped impactor as 0 and leaves undecided runs out
  }
  return s;
}

}  // namespace

double leading_number(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  return end == begin ? std::nan("") : v;
}

StudySpec read_study_from_string(const std::string& text, const fs::path& path) {
  Context ctx{path.string(), {}};
  try {
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::Exception& e) {
      throw InputError(msg() << config::detail::location(ctx.file, e.mark) << ": YAML syntax error: " << e.msg
                             << "; found text that is not valid YAML here (or on the line before)"
                             << "; allowed a YAML mapping");
    }
    YAML::Mark start;
    return read_root(Reader(root, "", &ctx, start), ctx, path);
  } catch (const YAML::Exception& e) {
    throw InputError(msg() << config::detail::location(ctx.file, e.mark) << ": internal YAML error: " << e.msg);
  }
}

StudySpec read_study(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(msg() << path.string() << ": cannot open the study file; allowed a path to a readable file");
  std::ostringstream s;
  s << in.rdbuf();
  return read_study_from_string(s.str(), path);
}

}  // namespace plyimpact::study
