// Mesh-convergence tables. See convergence.hpp.
#include "study/convergence.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace plyimpact::study {
namespace {

bool is_cost(const std::string& q) {
  return q == "wall_time" || q == "ns_per_element_cycle" || q == "elements" || q == "cycles";
}

struct Mesh {
  double h = 0;
  std::vector<std::size_t> rows;  // its replicates
};

bool same_size(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

struct Stats {
  double mean = std::nan(""), range = 0;
};

// Mean and range of quantity q over the mesh's replicates that have it.
Stats replicate_stats(const StudyTable& table, const Mesh& m, const std::string& q) {
  double sum = 0, lo = INFINITY, hi = -INFINITY;
  int count = 0;
  for (std::size_t r : m.rows) {
    const double v = table.rows[r].quantity(q);
    if (std::isnan(v)) continue;
    sum += v;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    ++count;
  }
  if (count == 0) return {};
  return {sum / count, hi - lo};
}

double relative_error(double q, double ref) {
  if (std::isnan(q) || std::isnan(ref)) return std::nan("");
  const double e = ref != 0 ? std::abs(q - ref) / std::abs(ref) : std::abs(q - ref);
  return e > 0 ? e : std::nan("");  // 0 has no place on a log axis
}

}  // namespace

double mesh_size(const ConvergenceSpec& c, const std::string& value_text, std::size_t index) {
  switch (c.h_from) {
    case HFrom::refinement_level: return std::pow(2.0, -leading_number(value_text));
    case HFrom::value: return leading_number(value_text);
    case HFrom::list: return c.h.at(index);
  }
  return std::nan("");
}

ConvergenceReport analyse_convergence(const StudySpec& spec, const StudyTable& table) {
  const ConvergenceSpec& c = *spec.convergence;
  ConvergenceReport rep;
  rep.parameter = c.parameter;
  std::size_t p = 0;
  while (spec.parameters[p].key != c.parameter) ++p;
  const auto& values = spec.parameters[p].values;
  // Finished rows grouped by their h (replicates share one), coarse (large h) first.
  std::vector<Mesh> meshes;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const CaseRow& row = table.rows[r];
    if (row.status != "completed" && row.status != "stopped" && row.status != "finished") continue;
    std::size_t v = 0;
    while (v < values.size() && values[v].text != row.values[p]) ++v;
    const double h = mesh_size(c, row.values[p], v);
    auto same = std::find_if(meshes.begin(), meshes.end(), [&](const Mesh& m) { return same_size(m.h, h); });
    if (same == meshes.end()) same = meshes.insert(meshes.end(), Mesh{h, {}});
    same->rows.push_back(r);
  }
  std::sort(meshes.begin(), meshes.end(), [](const Mesh& a, const Mesh& b) { return a.h > b.h; });
  for (const Mesh& m : meshes) {
    std::vector<std::string> names;
    for (std::size_t r : m.rows) names.push_back(table.rows[r].name);
    std::string joined;
    for (const auto& name : names) joined += (joined.empty() ? "" : "+") + name;
    rep.cases.push_back(joined);
    rep.case_names.push_back(names);
    rep.h.push_back(m.h);
    rep.wall_time.push_back(replicate_stats(table, m, "wall_time").mean);
  }
  const std::size_t n = meshes.size();
  for (const auto& q : table.quantity_columns) {
    if (is_cost(q) || n < 2) continue;
    QuantityConvergence qc;
    qc.quantity = q;
    for (const Mesh& m : meshes) {
      const Stats st = replicate_stats(table, m, q);
      qc.values.push_back(st.mean);
      qc.spread.push_back(st.range);
    }
    const double step = std::abs(qc.values[n - 1] - qc.values[n - 2]);
    const double scatter = std::max(qc.spread[n - 1], qc.spread[n - 2]);
    if (scatter > 0 && step <= scatter)
      qc.flags.push_back(msg() << "the two finest meshes differ by " << step << ", less than their replicates' spread "
                               << scatter << ": the mesh's effect is not resolved");
    for (const auto& [name, value] : c.reference)
      if (name == q) qc.reference = value;
    const double finest = qc.values.back();
    double extrapolated = std::nan("");
    if (n >= 3) {
      const double hs[3] = {rep.h[n - 3], rep.h[n - 2], rep.h[n - 1]};
      const double qs[3] = {qc.values[n - 3], qc.values[n - 2], qc.values[n - 1]};
      qc.richardson = richardson(hs, qs, c.order_lo, c.order_hi);
      if (qc.richardson->extrapolated) extrapolated = qc.richardson->value;
    }
    for (double v : qc.values) {
      qc.error_finest.push_back(relative_error(v, finest));
      qc.error_extrapolated.push_back(relative_error(v, extrapolated));
      qc.error_reference.push_back(relative_error(v, qc.reference ? *qc.reference : std::nan("")));
    }
    rep.quantities.push_back(std::move(qc));
  }
  return rep;
}

std::string convergence_csv(const ConvergenceReport& rep) {
  std::string out = "case,h,wall_time,replicates";
  for (const auto& q : rep.quantities)
    for (const char* suffix : {"", "_spread", "_error_finest", "_error_richardson", "_error_reference"}) {
      out += ',';
      out += q.quantity;
      out += suffix;
    }
  out += "\n";
  for (std::size_t i = 0; i < rep.cases.size(); ++i) {
    out += rep.cases[i];
    for (double v : {rep.h[i], rep.wall_time[i], double(rep.case_names[i].size())}) {
      out += ',';
      out += csv_number(v);
    }
    for (const auto& q : rep.quantities)
      for (double v : {q.values[i], q.spread[i], q.error_finest[i], q.error_extrapolated[i], q.error_reference[i]}) {
        out += ',';
        out += csv_number(v);
      }
    out += "\n";
  }
  return out;
}

output::Json convergence_json(const ConvergenceReport& rep) {
  output::Json j = output::Json::object();
  j["parameter"] = rep.parameter;
  output::Json cases = output::Json::array();
  for (std::size_t i = 0; i < rep.cases.size(); ++i) {
    output::Json c = output::Json::object();
    c["case"] = rep.case_names[i].front();
    output::Json names = output::Json::array();
    for (const auto& name : rep.case_names[i]) names.push_back(name);
    c["cases"] = names;
    c["h"] = rep.h[i];
    c["wall_time"] = rep.wall_time[i];
    cases.push_back(c);
  }
  j["meshes"] = cases;
  output::Json qs = output::Json::object();
  for (const auto& q : rep.quantities) {
    output::Json e = output::Json::object();
    if (q.richardson) {
      const RichardsonResult& r = *q.richardson;
      e["observed_order"] = r.order;
      e["extrapolated"] = r.value;
      e["refinement_ratios"] = output::Json(output::Json::Array{r.ratio_coarse, r.ratio_fine});
      e["asymptotic"] = r.asymptotic;
      output::Json flags = output::Json::array();
      for (const auto& f : r.flags) flags.push_back(f);
      e["flags"] = flags;
    } else {
      e["flags"] = output::Json(output::Json::Array{"fewer than three meshes: no extrapolation"});
    }
    for (const auto& f : q.flags) e["flags"].push_back(f);
    output::Json means = output::Json::array(), spreads = output::Json::array();
    for (std::size_t i = 0; i < q.values.size(); ++i) {
      means.push_back(q.values[i]);
      spreads.push_back(q.spread[i]);
    }
    e["values"] = means;
    e["spread"] = spreads;
    if (q.reference) e["reference"] = *q.reference;
    qs[q.quantity] = e;
  }
  j["quantities"] = qs;
  return j;
}

}  // namespace plyimpact::study
