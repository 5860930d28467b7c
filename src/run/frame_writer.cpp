#include "run/frame_writer.hpp"

#include <cstdio>

#include "output/vtu_writer.hpp"
#include "run/frame_builder.hpp"

namespace plyimpact::run {

FrameWriter::FrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval)
    : dir_(dir), name_(model.name), t_end_(model.control.termination_time), pvd_(dir, model.name), frames_(interval) {}

void FrameWriter::write(const solver::Solver& solver) {
  char file[64];
  std::snprintf(file, sizeof file, "_%04zu.vtu", pvd_.size());
  const std::string vtu = name_ + file;
  output::write_vtu(make_frame(solver), dir_ / vtu);
  pvd_.add(solver.state().time, vtu);
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
  (void)solver;
  report.pvd = dir_ / (name_ + ".pvd");
}

}  // namespace plyimpact::run
