// The quantity table. See quantities.hpp.
#include "study/quantities.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/error.hpp"
#include "output/json_reader.hpp"
#include "study/ballistic_limit.hpp"
#include "study/channel_filter.hpp"

namespace plyimpact::study {
namespace {

using Values = std::vector<QuantityValue>;

std::size_t rows(const RunRecord& r) { return r.history.rows(); }

// Index of a required history column; NotAvailable naming it otherwise.
std::size_t column(const RunRecord& r, const std::string& name, std::string_view why) {
  const int c = r.history.column_index(name);
  if (c < 0) throw NotAvailable("not available in this scene: history.csv has no column '" + name + "' (" + std::string(why) + ")");
  return std::size_t(c);
}

std::vector<std::size_t> columns_starting_with(const RunRecord& r, std::string_view prefix, std::string_view suffix = "") {
  std::vector<std::size_t> out;
  const auto& names = r.history.columns();
  for (std::size_t c = 0; c < names.size(); ++c)
    if (names[c].starts_with(prefix) && names[c].ends_with(suffix)) out.push_back(c);
  return out;
}

void require_rows(const RunRecord& r) {
  if (rows(r) == 0) throw NotAvailable("history.csv has no rows");
}

// The impactor as a rigid body: columns rigid_<name>_{x,y,z,vx,...,contact_fz}.
struct RigidColumns {
  std::array<std::size_t, 3> x, v, a, f;
};

bool has_deformable_impactor(const RunRecord& r) {
  const auto& names = r.history.columns();
  return std::find(names.begin(), names.end(), "impactor_vx") != names.end();
}

RigidColumns rigid_impactor(const RunRecord& r) {
  const auto vx = columns_starting_with(r, "rigid_", "_vx");
  if (vx.empty())
    throw NotAvailable("not available in this scene: no rigid impactor (history.csv has no rigid_<name>_vx column)");
  const std::string& col = r.history.columns()[vx.front()];
  const std::string base = col.substr(0, col.size() - 2);  // "rigid_<name>_"
  RigidColumns rc;
  const char* axes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    rc.x[k] = column(r, base + axes[k], "rigid body position");
    rc.v[k] = column(r, base + "v" + axes[k], "rigid body velocity");
    rc.a[k] = column(r, base + "a" + axes[k], "rigid body acceleration");
    rc.f[k] = column(r, base + "contact_f" + axes[k], "rigid body contact force");
  }
  return rc;
}

// Position and velocity columns of the impactor: a rigid impactor's rigid_<name>_*, else a deformable
// impactor's centre of mass impactor_* (solver/impactor_motion.hpp).
struct MotionColumns {
  std::array<std::size_t, 3> x, v;
};

MotionColumns impactor_motion(const RunRecord& r) {
  if (columns_starting_with(r, "rigid_", "_vx").empty() && has_deformable_impactor(r)) {
    MotionColumns m;
    const char* axes[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      m.x[k] = column(r, std::string("impactor_") + axes[k], "impactor centre of mass");
      m.v[k] = column(r, std::string("impactor_v") + axes[k], "impactor velocity");
    }
    return m;
  }
  const RigidColumns rc = rigid_impactor(r);
  return {rc.x, rc.v};
}

std::array<double, 3> row_vec(const RunRecord& r, std::size_t row, const std::array<std::size_t, 3>& c) {
  return {r.history.at(row, c[0]), r.history.at(row, c[1]), r.history.at(row, c[2])};
}
double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Unit vector of the initial impactor velocity (the impact direction).
std::array<double, 3> impact_direction(const RunRecord& r, const MotionColumns& rc) {
  auto v0 = row_vec(r, 0, rc.v);
  const double n = std::sqrt(dot(v0, v0));
  if (n == 0) throw NotAvailable("the impactor starts at rest: no impact direction");
  for (double& c : v0) c /= n;
  return v0;
}

// The rigid impactor's mass from Newton's law on the recorded samples, m = sum(F.a) / sum(a.a):
// the contact force is the only force on a free rigid impactor, so every sample gives F = m a.
double rigid_mass(const RunRecord& r, const RigidColumns& rc) {
  double fa = 0, aa = 0;
  for (std::size_t i = 0; i < rows(r); ++i) {
    const auto f = row_vec(r, i, rc.f), a = row_vec(r, i, rc.a);
    fa += dot(f, a);
    aa += dot(a, a);
  }
  if (aa == 0 || fa <= 0) throw NotAvailable("the rigid impactor never accelerates: no contact, mass unknown");
  return fa / aa;
}

// Magnitude of the total contact force per row: the resultant of all contacts, else the rigid walls'
// normal forces.
std::vector<double> contact_force(const RunRecord& r) {
  require_rows(r);
  const auto fx = columns_starting_with(r, "contact_", "_fx");
  std::vector<double> f(rows(r), 0.0);
  if (!fx.empty()) {
    for (std::size_t i = 0; i < rows(r); ++i) {
      std::array<double, 3> sum{0, 0, 0};
      for (std::size_t c : fx)
        for (int k = 0; k < 3; ++k) sum[k] += r.history.at(i, c + k);  // _fx, _fy, _fz are adjacent
      f[i] = std::sqrt(dot(sum, sum));
    }
    return f;
  }
  const auto walls = columns_starting_with(r, "wall_", "_normal");
  if (walls.empty()) throw NotAvailable("not available in this scene: no contact_* or wall_* force columns");
  for (std::size_t i = 0; i < rows(r); ++i)
    for (std::size_t c : walls) f[i] += std::abs(r.history.at(i, c));
  return f;
}

Values peak_contact_force(const RunRecord& r) {
  const auto f = contact_force(r);
  const auto it = std::max_element(f.begin(), f.end());
  return {{"peak_contact_force", *it}};
}

Values peak_contact_force_time(const RunRecord& r) {
  const auto f = contact_force(r);
  const auto i = std::size_t(std::max_element(f.begin(), f.end()) - f.begin());
  return {{"peak_contact_force_time", r.history.at(i, column(r, "time", "time"))}};
}

// Largest value of the impactor force filtered at channel frequency class cfc, and its time.
struct FilteredPeak {
  double force, time;
};

FilteredPeak filtered_impactor_peak(const RunRecord& r, double cfc) {
  const ImpactorForce f = impactor_force(r);
  const auto filtered = cfc_filter(f.force, f.interval, cfc);
  const auto peak = std::size_t(std::max_element(filtered.begin(), filtered.end()) - filtered.begin());
  return {filtered[peak], f.time[peak]};
}

Values peak_impactor_force_cfc600(const RunRecord& r) {
  return {{"peak_impactor_force_cfc600", filtered_impactor_peak(r, 600).force}};
}
Values peak_impactor_force_cfc600_time(const RunRecord& r) {
  return {{"peak_impactor_force_cfc600_time", filtered_impactor_peak(r, 600).time}};
}
Values peak_impactor_force_cfc1000(const RunRecord& r) {
  return {{"peak_impactor_force_cfc1000", filtered_impactor_peak(r, 1000).force}};
}

Values absorbed_energy(const RunRecord& r) {
  require_rows(r);
  if (!columns_starting_with(r, "rigid_", "_vx").empty()) {
    const auto rc = rigid_impactor(r);
    const double m = rigid_mass(r, rc);
    const auto v0 = row_vec(r, 0, rc.v), v1 = row_vec(r, rows(r) - 1, rc.v);
    return {{"absorbed_energy", 0.5 * m * (dot(v0, v0) - dot(v1, v1))}};
  }
  if (has_deformable_impactor(r)) {
    const std::size_t k = column(r, "impactor_kinetic_energy", "impactor kinetic energy");
    return {{"absorbed_energy", r.history.at(0, k) - r.history.at(rows(r) - 1, k)}};
  }
  const std::size_t k = column(r, "kinetic_energy", "kinetic energy");
  return {{"absorbed_energy", r.history.at(0, k) - r.history.at(rows(r) - 1, k)}};
}

Values residual_velocity(const RunRecord& r) { return {{"residual_velocity", impactor_track(r).velocity.back()}}; }

// 1 perforated, 0 stopped; an undecided run has no value (the reason says why).
Values perforated(const RunRecord& r) {
  const Perforation p = classify(r, r.pass_distance);
  if (p == Perforation::undecided)
    throw NotAvailable("undecided: the impactor still moves forward in contact with the plate at the end of the run "
                       "(a longer control.termination_time decides it)");
  return {{"perforated", p == Perforation::perforated ? 1.0 : 0.0}};
}

std::vector<double> impactor_travel(const RunRecord& r) { return impactor_track(r).travel; }

Values max_impactor_displacement(const RunRecord& r) {
  const auto s = impactor_travel(r);
  return {{"max_impactor_displacement", *std::max_element(s.begin(), s.end())}};
}

// The impactor's final travel once it has rebounded (moving back, out of contact): the dent it
// leaves, measured at the impactor. The gap at the start of the run is not subtracted (the scenes
// start the impactor a stated `gap` away; the table reports travel, the user subtracts the gap).
Values permanent_indentation(const RunRecord& r) {
  const ImpactorTrack t = impactor_track(r);
  const auto& s = t.travel;
  if (t.velocity.back() >= 0)
    throw NotAvailable("not available in this run: the impactor has not rebounded by the termination time");
  return {{"permanent_indentation", s.back()}};
}

const output::Json* erosion(const RunRecord& r) {
  const output::Json* e = r.summary.find("erosion");
  if (!e) throw NotAvailable("not available in this scene: nothing can erode (summary.json has no 'erosion')");
  return e;
}

Values eroded_elements(const RunRecord& r) {
  const output::Json* e = erosion(r);
  Values out{{"eroded_elements", e->find("eroded_elements") ? e->find("eroded_elements")->as_number() : 0.0}};
  std::map<std::string, double> by_cause;
  if (const auto* list = e->find("by_part_and_cause"))
    for (const auto& entry : list->as_array()) by_cause[entry.find("cause")->as_string()] += entry.find("count")->as_number();
  for (const auto& [cause, count] : by_cause) out.push_back({"eroded_elements_" + cause, count});
  return out;
}

// A number the summary's erosion block carries (0 when a run eroded nothing and omits it).
double erosion_number(const RunRecord& r, const char* key) {
  const output::Json* e = erosion(r);
  return e->find(key) ? e->find(key)->as_number() : 0.0;
}

Values eroded_volume(const RunRecord& r) {
  const output::Json* e = erosion(r);
  if (!e->find("eroded_volume"))
    throw NotAvailable("not in this run's summary.json (written by an older plyimpact: run the case again)");
  return {{"eroded_volume", erosion_number(r, "eroded_volume")}};
}

Values eroded_energy(const RunRecord& r) { return {{"eroded_energy", erosion_number(r, "eroded_energy")}}; }

// Largest value reached by each delaminated_area* column (total and per interface).
Values delaminated_area(const RunRecord& r) {
  require_rows(r);
  const auto cols = columns_starting_with(r, "delaminated_area");
  if (cols.empty())
    throw NotAvailable("not available in this scene: history.csv has no delaminated_area columns (no delamination "
                       "interfaces modelled)");
  Values out;
  for (std::size_t c : cols) {
    double peak = 0;
    for (std::size_t i = 0; i < rows(r); ++i) peak = std::max(peak, r.history.at(i, c));
    out.push_back({r.history.columns()[c], peak});
  }
  return out;
}

// Earliest sample with an eroded element or a delaminated area.
Values first_damage_time(const RunRecord& r) {
  require_rows(r);
  auto cols = columns_starting_with(r, "delaminated_area");
  if (const int e = r.history.column_index("eroded_elements"); e >= 0) cols.push_back(std::size_t(e));
  if (cols.empty())
    throw NotAvailable("not available in this scene: neither erosion nor delamination is modelled (no eroded_elements "
                       "or delaminated_area columns)");
  const std::size_t t = column(r, "time", "time");
  for (std::size_t i = 0; i < rows(r); ++i)
    for (std::size_t c : cols)
      if (r.history.at(i, c) > 0) return {{"first_damage_time", r.history.at(i, t)}};
  throw NotAvailable("no damage in this run (no element eroded, no area delaminated)");
}

Values energy_ratio_deviation(const RunRecord& r) {
  require_rows(r);
  const std::size_t c = column(r, "energy_ratio", "energy balance");
  double worst = 0;
  for (std::size_t i = 0; i < rows(r); ++i) worst = std::max(worst, std::abs(r.history.at(i, c) - 1.0));
  return {{"energy_ratio_deviation", worst}};
}

// The run's own hourglass check (summary.json hourglass_check.max_ratio: hourglass energy over the
// internal energy of the same sample, floored at 1 % of the initial energy + external work, so the
// first contact, when the internal energy is round-off, does not read as a huge ratio). A run
// without it (its summary lost): the same rule on history.csv, without the floor when the energy
// columns are missing.
Values hourglass_ratio(const RunRecord& r) {
  if (const output::Json* check = r.summary.find("hourglass_check"))
    if (const output::Json* v = check->find("max_ratio"); v && v->kind() == output::Json::Kind::number)
      return {{"hourglass_ratio", v->as_number()}};
  require_rows(r);
  const std::size_t h = column(r, "hourglass_energy", "hourglass energy"), e = column(r, "internal_energy", "internal energy");
  const int total = r.history.column_index("total_energy"), external = r.history.column_index("external_work");
  double worst = 0;
  for (std::size_t i = 0; i < rows(r); ++i) {
    double floor = 0;
    if (total >= 0)
      floor = 0.01 * (r.history.at(0, std::size_t(total)) + (external >= 0 ? r.history.at(i, std::size_t(external)) : 0.0));
    const double denominator = std::max(r.history.at(i, e), floor);
    if (denominator > 0) worst = std::max(worst, r.history.at(i, h) / denominator);
  }
  return {{"hourglass_ratio", worst}};
}

Values summary_number(const RunRecord& r, const char* key, const char* name) {
  const output::Json* v = r.summary.find(key);
  if (!v || (v->kind() != output::Json::Kind::number && v->kind() != output::Json::Kind::integer))
    throw NotAvailable(std::string("summary.json has no number '") + key + "'");
  return {{name, v->as_number()}};
}

Values wall_time(const RunRecord& r) { return summary_number(r, "wall_seconds", "wall_time"); }
Values ns_per_element_cycle(const RunRecord& r) { return summary_number(r, "ns_per_element_cycle", "ns_per_element_cycle"); }
Values element_count(const RunRecord& r) { return summary_number(r, "elements", "elements"); }
Values cycle_count(const RunRecord& r) { return summary_number(r, "cycles", "cycles"); }

constexpr QuantityDefinition kQuantities[] = {
    {"peak_contact_force", "N", "largest magnitude of the total contact force", peak_contact_force},
    {"peak_contact_force_time", "s", "time of the peak contact force", peak_contact_force_time},
    {"peak_impactor_force_cfc600", "N",
     "largest axial force on the rigid impactor, its momentum change per history interval filtered at CFC 600 (SAE J211)",
     peak_impactor_force_cfc600},
    {"peak_impactor_force_cfc600_time", "s", "time of peak_impactor_force_cfc600", peak_impactor_force_cfc600_time},
    {"peak_impactor_force_cfc1000", "N", "as peak_impactor_force_cfc600, filtered at CFC 1000",
     peak_impactor_force_cfc1000},
    {"absorbed_energy", "J",
     "impactor kinetic energy lost (rigid impactor); else the total kinetic energy lost", absorbed_energy},
    {"residual_velocity", "m/s", "final impactor velocity (a deformable one's centre of mass) along the impact direction (< 0: rebound)",
     residual_velocity},
    {"perforated", "1",
     "1 when the impactor perforated (moving on, free, nose past the plate's rear face), 0 when it was arrested",
     perforated},
    {"max_impactor_displacement", "m", "largest rigid-impactor travel along the impact direction",
     max_impactor_displacement},
    {"permanent_indentation", "m", "final rigid-impactor travel after rebound", permanent_indentation},
    {"eroded_elements", "1", "eroded elements at the end, total and eroded_elements_<cause>", eroded_elements},
    {"eroded_volume", "m^3",
     "reference volume of the eroded elements at the end (compares between meshes, unlike their count)",
     eroded_volume},
    {"eroded_energy", "J", "internal and hourglass energy the eroded elements held when deleted", eroded_energy},
    {"delaminated_area", "m^2", "largest delaminated area, total and per interface (delaminated_area* columns)",
     delaminated_area},
    {"first_damage_time", "s", "first sample with an eroded element or a delaminated area", first_damage_time},
    {"energy_ratio_deviation", "1", "largest |energy ratio - 1| over the history", energy_ratio_deviation},
    {"hourglass_ratio", "1", "the run's hourglass check: largest hourglass / max(internal energy, 1 % of the run's energy)", hourglass_ratio},
    {"wall_time", "s", "wall-clock time of the run (summary.json wall_seconds)", wall_time},
    {"ns_per_element_cycle", "ns", "solver cost per element and cycle", ns_per_element_cycle},
    {"elements", "1", "element count", element_count},
    {"cycles", "1", "time steps taken", cycle_count},
};

}  // namespace

ImpactorForce impactor_force(const RunRecord& r) {
  require_rows(r);
  if (rows(r) < 4) throw NotAvailable("history.csv has fewer than 4 rows: no force record to filter");
  const auto rc = rigid_impactor(r);
  const double m = rigid_mass(r, rc);
  const auto d = impact_direction(r, MotionColumns{rc.x, rc.v});
  const std::size_t tc = column(r, "time", "time");
  std::vector<double> t_mid, force, steps;
  for (std::size_t i = 1; i < rows(r); ++i) {
    const double dt = r.history.at(i, tc) - r.history.at(i - 1, tc);
    if (!(dt > 0)) continue;
    const double dv = dot(row_vec(r, i, rc.v), d) - dot(row_vec(r, i - 1, rc.v), d);
    t_mid.push_back(r.history.at(i - 1, tc) + 0.5 * dt);
    force.push_back(-m * dv / dt);
    steps.push_back(dt);
  }
  if (t_mid.size() < 3) throw NotAvailable("history.csv has fewer than 4 distinct times: no force record");
  std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(steps.size() / 2), steps.end());
  ImpactorForce out;
  out.interval = steps[steps.size() / 2];
  for (std::size_t k = 0, j = 0;; ++k) {
    const double t = t_mid.front() + double(k) * out.interval;
    if (t > t_mid.back()) break;
    while (j + 2 < t_mid.size() && t_mid[j + 1] < t) ++j;
    const double w = std::clamp((t - t_mid[j]) / (t_mid[j + 1] - t_mid[j]), 0.0, 1.0);
    out.time.push_back(t);
    out.force.push_back(force[j] + w * (force[j + 1] - force[j]));
  }
  return out;
}

ImpactorTrack impactor_track(const RunRecord& r) {
  require_rows(r);
  const auto rc = impactor_motion(r);
  const auto d = impact_direction(r, rc);
  const auto x0 = row_vec(r, 0, rc.x);
  const std::size_t time = column(r, "time", "time");
  ImpactorTrack t;
  for (std::size_t i = 0; i < rows(r); ++i) {
    auto x = row_vec(r, i, rc.x);
    for (int k = 0; k < 3; ++k) x[k] -= x0[k];
    t.time.push_back(r.history.at(i, time));
    t.travel.push_back(dot(x, d));
    t.velocity.push_back(dot(row_vec(r, i, rc.v), d));
  }
  return t;
}

std::span<const QuantityDefinition> quantity_table() { return kQuantities; }

const QuantityDefinition* find_quantity(std::string_view name) {
  for (const auto& q : kQuantities)
    if (q.name == name) return &q;
  return nullptr;
}

std::vector<std::string> quantity_names() {
  std::vector<std::string> names;
  for (const auto& q : kQuantities) names.emplace_back(q.name);
  return names;
}

RunRecord read_run_record(const std::string& case_dir) {
  const std::filesystem::path dir(case_dir);
  RunRecord r;
  r.history = output::read_history_csv(dir / "history.csv");
  r.summary = output::read_json_file(dir / "summary.json");
  return r;
}

}  // namespace plyimpact::study
