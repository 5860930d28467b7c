#include "run/history_writer.hpp"

#include <span>

#include "core/error.hpp"

namespace plyimpact::run {

namespace {

// Columns: time and step, the integrator's energies, total and ratio, the controlling element, the
// reactions, then each force contributor's energies and own columns, then erosion. Energies come
// from the balance's named list (solver/energies.hpp), so a new energy is named in one place.
std::vector<std::string> history_columns(const model::Model& model, const solver::Solver* solver,
                                         const std::vector<const HistoryColumns*>& extra) {
  const solver::Energies own;
  std::vector<std::string> cols = {"time", "dt"};
  for (const auto& t : own.terms) cols.push_back(t.column);
  for (const char* c : {"total_energy", "energy_ratio", "dt_controlling_element"}) cols.push_back(c);
  for (int set : model.constrained_sets)
    for (const char* c : {"_fx", "_fy", "_fz"}) cols.push_back("reaction_" + model.node_sets[set].name + c);
  if (solver) {
    const auto& terms = solver->balance().terms;
    for (std::size_t c = 0; c < solver->contributors().size(); ++c) {
      for (const auto& t : terms)
        if (t.owner == int(c)) cols.push_back(t.column);
      for (auto& col : solver->contributors()[c]->history_columns()) cols.push_back(std::move(col));
    }
  }
  if (solver::can_erode(model))
    for (const char* c : {"eroded_elements", "eroded_energy", "eroded_hourglass_energy", "eroded_kinetic_energy"})
      cols.push_back(c);
  for (const HistoryColumns* x : extra)
    for (auto& col : x->columns()) cols.push_back(std::move(col));
  return cols;
}

}  // namespace

HistoryWriter::HistoryWriter(const model::Model& model, std::filesystem::path file, double interval,
                             std::vector<const HistoryColumns*> extra)
    : model_(model), file_(std::move(file)), extra_(std::move(extra)), rows_(interval) {}

void HistoryWriter::add_row(const solver::Solver& solver) {
  const solver::State& s = solver.state();
  const solver::Energies& e = solver.balance();
  row_.assign({e.time, s.dt_prev_half});
  for (const auto& t : e.terms)
    if (t.owner == solver::Energies::kIntegrator) row_.push_back(t.value);
  row_.insert(row_.end(), {e.total(), solver.energy_ratio(), double(s.dt_element)});
  row_.insert(row_.end(), s.reaction.begin(), s.reaction.end());
  for (std::size_t c = 0; c < solver.contributors().size(); ++c) {
    for (const auto& t : e.terms)
      if (t.owner == int(c)) row_.push_back(t.value);
    solver.contributors()[c]->history_values(row_);
  }
  if (solver::can_erode(solver.model()))
    row_.insert(row_.end(), {double(s.eroded_elements), s.eroded_energy, s.eroded_hourglass_energy, s.eroded_kinetic_energy});
  for (const HistoryColumns* x : extra_) x->values(solver, row_);
  table_->add_row(row_);
}

void HistoryWriter::rewrite(bool keep_appending) {
  appender_.close();
  table_->write_csv(file_);
  rows_on_disk_ = table_->rows();
  last_append_ = Clock::now();
  if (keep_appending) appender_.open(file_);
}

void HistoryWriter::append_pending() {
  appender_.append(table_->csv_text(rows_on_disk_, false));
  rows_on_disk_ = table_->rows();
  last_append_ = Clock::now();
}

void HistoryWriter::start(const solver::Solver& solver) {
  table_.emplace(history_columns(model_, &solver, extra_));
  add_row(solver);
  rewrite(true);
}

void HistoryWriter::resume(const solver::Solver& solver) {
  table_.emplace(history_columns(model_, &solver, extra_));
  const std::size_t ncol = table_->columns().size();
  if (stored_.size() % ncol != 0)
    throw InputError(msg() << "the restart dump's history has rows of another width than this scene's " << ncol
                           << " columns");
  for (std::size_t r = 0; r < stored_.size(); r += ncol) table_->add_row(std::span(stored_).subspan(r, ncol));
  stored_ = {};
  rewrite(true);
}

void HistoryWriter::after_cycle(const solver::Solver& solver) {
  const double t = solver.state().time;
  if (rows_.due(t) && solver.balance().time > 0) {
    add_row(solver);
    rows_.advance(t);
  }
  if (table_->rows() > rows_on_disk_ && Clock::now() - last_append_ >= kAppendDelay) append_pending();
}

void HistoryWriter::stop(const solver::Solver* solver, RunReport& report) {
  if (!table_) table_.emplace(history_columns(model_, solver, extra_));  // the solver could not be built
  rewrite(false);
  report.history = file_;
}

void HistoryWriter::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "history");
  // Written from the table; read into stored_ (the table is built by resume, from the solver).
  if (table_) stored_.assign(table_->values().begin(), table_->values().end());
  visitor.array("rows", stored_);
  if (table_) stored_ = {};
  rows_.visit_state(visitor, "next_row_time");
}

}  // namespace plyimpact::run
