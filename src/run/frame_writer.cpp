#include "run/frame_writer.hpp"

#include <cstdio>

#include "output/vtu_writer.hpp"
#include "run/frame_builder.hpp"

namespace plyimpact::run {

namespace {
std::string frame_file(const std::string& name, std::size_t index) {
  char file[64];
  std::snprintf(file, sizeof file, "_%04zu.vtu", index);
  return name + file;
}
}  // namespace

FrameWriter::FrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval)
    : dir_(dir), name_(model.name), t_end_(model.control.termination_time), pvd_(dir, model.name), frames_(interval) {}

void FrameWriter::write(const solver::Solver& solver) {
  const std::string vtu = frame_file(name_, pvd_.size());
  output::write_vtu(make_frame(solver), dir_ / vtu);
  pvd_.add(solver.state().time, vtu);
  times_.push_back(solver.state().time);
  pvd_.write();
}

void FrameWriter::resume(const solver::Solver& solver) {
  (void)solver;
  pvd_ = output::PvdSeries(dir_, name_);
  for (std::size_t i = 0; i < times_.size(); ++i) pvd_.add(times_[i], frame_file(name_, i));
  pvd_.write();
}

void FrameWriter::after_cycle(const solver::Solver& solver) {
  const double t = solver.state().time;
  const bool last = t >= t_end_ * (1 - 1e-12);
  if (frames_.due(t) || last) {
    write(solver);
    frames_.advance(t);
  }
}

void FrameWriter::stop(const solver::Solver* solver, RunReport& report) {
  report.pvd = dir_ / (name_ + ".pvd");
  // An early stop with a sound state shows where it stopped (a failed state is not worth a frame).
  if (solver && !report.completed && !report.failed && (times_.empty() || times_.back() != solver->state().time))
    write(*solver);
}

void FrameWriter::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "frames");
  visitor.array("times", times_);
  frames_.visit_state(visitor, "next_frame_time");
}

}  // namespace plyimpact::run
