#include "run/history_writer.hpp"

namespace plyimpact::run {

namespace {

std::vector<std::string> history_columns(const model::Model& model) {
  std::vector<std::string> cols = {"time",         "dt",    "kinetic_energy", "internal_energy",
                                   "hourglass_energy", "bulk_viscous_energy", "external_work",
                                   "total_energy", "energy_ratio", "dt_element"};
  for (int set : model.constrained_sets)
    for (const char* c : {"_fx", "_fy", "_fz"}) cols.push_back("reaction_" + model.node_sets[set].name + c);
  // Contact, rigid-wall and rigid-body columns only when the scene has them.
  if (!model.contacts.empty()) {
    cols.push_back("contact_energy");
    cols.push_back("friction_energy");
    for (const auto& c : model.contacts)
      for (const char* q : {"_fx", "_fy", "_fz", "_normal", "_tangential"})
        cols.push_back("contact_" + c.spec.name + q);
  }
  if (!model.rigid_walls.empty()) {
    cols.push_back("rigidwall_energy");
    for (const auto& w : model.rigid_walls)
      for (const char* q : {"_normal", "_tangential"}) cols.push_back("wall_" + w.name + q);
  }
  for (const auto& b : model.rigid_bodies)
    for (const char* q : {"_x", "_y", "_z", "_vx", "_vy", "_vz", "_ax", "_ay", "_az", "_contact_fx", "_contact_fy",
                          "_contact_fz"})
      cols.push_back("rigid_" + b.name + q);
  if (can_erode(model)) {
    cols.push_back("eroded_elements");
    cols.push_back("eroded_energy");
  }
  return cols;
}

}  // namespace

bool can_erode(const model::Model& model) {
  if (model.control.erode_tsmin > 0) return true;
  for (const auto& m : model.materials)
    if (m.kind == model::MaterialKind::CompositeDamage ||
        (m.kind == model::MaterialKind::Plastic && m.plastic.failure_strain > 0))
      return true;
  return false;
}

HistoryWriter::HistoryWriter(const model::Model& model, std::filesystem::path file, double interval,
                             double flush_interval)
    : file_(std::move(file)),
      t_end_(model.control.termination_time),
      table_(history_columns(model)),
      rows_(interval),
      flushes_(flush_interval) {}

void HistoryWriter::add_row(const solver::Solver& solver) {
  const solver::State& s = solver.state();
  const solver::Energies& e = solver.balance();
  std::vector<double> row = {e.time,     s.dt_prev_half, e.kinetic,       e.internal,           e.hourglass,
                             e.bulk_viscous, e.external_work, e.total(), solver.energy_ratio(), double(s.dt_element)};
  row.insert(row.end(), s.reaction.begin(), s.reaction.end());
  if (!solver.contacts().empty()) {
    row.push_back(e.contact);
    row.push_back(e.friction);
    for (const auto& c : solver.contacts()) {
      const auto& f = c.forces();
      row.insert(row.end(), {f.resultant[0], f.resultant[1], f.resultant[2], f.normal, f.tangential});
    }
  }
  if (!solver.rigid_walls().empty()) {
    row.push_back(e.rigid_wall);
    for (const auto& w : solver.rigid_walls()) row.insert(row.end(), {w.normal_force(), w.tangential_force()});
  }
  for (const auto& b : solver.rigid_bodies())
    row.insert(row.end(), {b.x[0], b.x[1], b.x[2], b.v[0], b.v[1], b.v[2], b.a[0], b.a[1], b.a[2], b.contact_force[0],
                           b.contact_force[1], b.contact_force[2]});
  if (can_erode(solver.model())) row.insert(row.end(), {double(s.eroded_elements), s.eroded_energy});
  table_.add_row(row);
}

void HistoryWriter::start(const solver::Solver& solver) {
  add_row(solver);
  table_.write_csv(file_);
}

void HistoryWriter::after_cycle(const solver::Solver& solver) {
  const double t = solver.state().time;
  if (rows_.due(t) && solver.balance().time > 0) {
    add_row(solver);
    rows_.advance(t);
  }
  if (flushes_.due(t) || t >= t_end_ * (1 - 1e-12)) {
    table_.write_csv(file_);
    if (flushes_.due(t)) flushes_.advance(t);
  }
}

void HistoryWriter::stop(const solver::Solver* solver, RunReport& report) {
  (void)solver;
  table_.write_csv(file_);
  report.history = file_;
}

}  // namespace plyimpact::run
