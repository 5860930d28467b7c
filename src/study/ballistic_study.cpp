// Ballistic-limit search on study cases. See ballistic_study.hpp.
#include "study/ballistic_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "core/units.hpp"
#include "study/study_table.hpp"

namespace plyimpact::study {
namespace {

namespace fs = std::filesystem;

// The shot of a finished case; throws NotAvailable when its record cannot tell.
Shot shot_of(const Case& c, double velocity, const fs::path& dir) {
  RunRecord r = read_run_record((dir / c.name).string());
  r.pass_distance = c.pass_distance;
  return {velocity, impactor_track(r).velocity.back(), classify(r, c.pass_distance), c.name};
}

// The study's finished sweep cases whose value is written as the search writes its own.
std::vector<Shot> known_shots(const BallisticLimitSpec& bl, const std::vector<Case>& cases, const fs::path& dir) {
  std::vector<Shot> known;
  for (const Case& c : cases) {
    const double v = leading_number(c.values.front());
    if (c.values.front() != velocity_text(bl, v) || !case_finished(c, dir / c.name)) continue;
    try {
      known.push_back(shot_of(c, v, dir));
    } catch (const std::exception&) {
      // A case that cannot be classified narrows nothing.
    }
  }
  return known;
}

class Shooter {
 public:
  Shooter(const StudySpec& spec, const std::string& scene_text, const CaseBatch& batch, std::vector<Case>& cases,
          std::vector<std::string>& failures, BallisticStudy& b, std::ostream& out)
      : spec_(spec), scene_text_(scene_text), batch_(batch), cases_(cases), failures_(failures), b_(b), out_(out) {}

  std::vector<Shot> operator()(const std::vector<double>& velocities) {
    std::vector<Case> round, pending;
    for (double v : velocities) {
      Case c = make_case(spec_, scene_text_, {{velocity_text(*spec_.ballistic_limit, v), spec_.ballistic_limit->origin}});
      c.pass_distance = plate_pass_distance(config::load_scene(spec_.scene.string(), c.overrides));
      if (!case_finished(c, batch_.dir / c.name)) pending.push_back(c);
      round.push_back(std::move(c));
    }
    std::vector<std::string> why;
    if (!pending.empty()) {
      out_ << "ballistic limit: running " << pending.size() << " case(s)\n";
      why = run_case_batch(batch_, pending, out_);
      b_.ran += pending.size();
    }
    std::vector<Shot> shots;
    for (const Case& c : round) {
      std::string failure;
      for (std::size_t k = 0; k < pending.size(); ++k)
        if (pending[k].name == c.name) failure = why[k];
      remember(c, failure);
      if (!failure.empty()) {
        ++b_.failed;
        throw InputError(msg() << spec_.ballistic_limit->origin << ": the case " << c.name << " failed (" << failure
                               << "; see " << (batch_.dir / c.name / "run.log").string() << ")");
      }
      try {
        shots.push_back(shot_of(c, leading_number(c.values.front()), batch_.dir));
      } catch (const NotAvailable& e) {
        throw InputError(msg() << spec_.ballistic_limit->origin << ": the case " << c.name
                               << " cannot be classified: " << e.what());
      }
      const Shot& s = shots.back();
      char line[160];
      std::snprintf(line, sizeof line, "ballistic limit: %s %s (residual velocity %.4g m/s)\n",
                    c.values.front().c_str(), perforation_name(s.state), s.residual);
      out_ << line;
    }
    return shots;
  }

 private:
  void remember(const Case& c, const std::string& failure) {
    for (std::size_t i = 0; i < cases_.size(); ++i)
      if (cases_[i].name == c.name) {
        if (!failure.empty()) failures_[i] = failure;
        return;
      }
    cases_.push_back(c);
    failures_.push_back(failure);
  }

  const StudySpec& spec_;
  const std::string& scene_text_;
  const CaseBatch& batch_;
  std::vector<Case>& cases_;
  std::vector<std::string>& failures_;
  BallisticStudy& b_;
  std::ostream& out_;
};

output::Json number_pair(double a, double b) {
  output::Json j = output::Json::array();
  j.push_back(a);
  j.push_back(b);
  return j;
}

}  // namespace

double plate_pass_distance(const config::Scene& scene) {
  if (!scene.laminate || !scene.impactor) return std::nan("");
  double thickness = 0;
  for (const auto& ply : scene.laminate->plies) thickness += ply.thickness;
  return scene.impactor->gap + thickness;
}

std::string velocity_text(const BallisticLimitSpec& spec, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return spec.unit.empty() ? std::string(buf) : std::string(buf) + " " + spec.unit;
}

BallisticStudy run_ballistic_search(const StudySpec& spec, const std::string& scene_text, const CaseBatch& batch,
                                    std::vector<Case>& cases, std::vector<std::string>& failures, std::ostream& out) {
  const BallisticLimitSpec& bl = *spec.ballistic_limit;
  BallisticStudy b;
  BracketSearch q{bl.lo, bl.hi, bl.tolerance, batch.jobs, bl.origin};
  out << "ballistic limit of " << bl.parameter << " in [" << velocity_text(bl, bl.lo) << ", " << velocity_text(bl, bl.hi)
      << "] to " << velocity_text(bl, bl.tolerance) << ", " << q.points << " case(s) per round\n";
  try {
    b.result = search_ballistic_limit(q, Shooter(spec, scene_text, batch, cases, failures, b, out),
                                      known_shots(bl, cases, batch.dir));
    char line[200];
    std::snprintf(line, sizeof line, "ballistic limit: %.6g +- %.3g %s (bracket [%.6g, %.6g], %d round(s))\n",
                  b.result->limit, 0.5 * (b.result->hi - b.result->lo), bl.unit.c_str(), b.result->lo, b.result->hi,
                  b.result->rounds);
    out << line;
    for (const auto& n : b.result->notes) out << "note: " << n << "\n";
  } catch (const InputError& e) {
    b.error = e.what();
    out << "error: " << b.error << "\n";
  }
  return b;
}

output::Json ballistic_json(const BallisticLimitSpec& spec, const BallisticStudy& b, const std::string& unit_system) {
  output::Json j = output::Json::object();
  j["parameter"] = spec.parameter;
  j["unit"] = spec.unit;
  j["criterion"] = std::string(kPerforationCriterion);
  j["bracket_given"] = number_pair(spec.lo, spec.hi);
  j["tolerance"] = spec.tolerance;
  if (!b.error.empty()) j["error"] = b.error;
  if (!b.result) return j;
  const BallisticLimit& r = *b.result;
  j["ballistic_limit"] = r.limit;
  j["bracket"] = number_pair(r.lo, r.hi);
  j["half_width"] = 0.5 * (r.hi - r.lo);
  if (!spec.unit.empty()) {
    const units::UnitSystem us = units::parse_unit_system(unit_system);
    j["ballistic_limit_si"] = units::quantity_to_si(velocity_text(spec, r.limit), units::velocity, us);
  }
  j["rounds"] = r.rounds;
  output::Json shots = output::Json::array();
  for (const Shot& s : r.shots) {
    output::Json e = output::Json::object();
    e["velocity"] = s.velocity;
    e["residual_velocity"] = s.residual;
    e["outcome"] = std::string(perforation_name(s.state));
    e["case"] = s.case_name;
    shots.push_back(e);
  }
  j["shots"] = shots;
  output::Json notes = output::Json::array();
  for (const auto& n : r.notes) notes.push_back(n);
  j["notes"] = notes;
  return j;
}

std::string ballistic_csv(const BallisticLimitSpec& spec, const BallisticLimit& b) {
  std::string out = spec.parameter + ",residual_velocity,perforated,case\n";
  for (const Shot& s : b.shots)
    out += csv_number(s.velocity) + "," + csv_number(s.residual) + "," +
           (s.state == Perforation::perforated ? "1" : "0") + "," + s.case_name + "\n";
  return out;
}

}  // namespace plyimpact::study
