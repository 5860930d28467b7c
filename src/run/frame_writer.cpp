#include "run/frame_writer.hpp"

#include <algorithm>
#include <cstdio>

#include "run/frame_builder.hpp"

namespace plyimpact::run {

namespace {

output::Compression compression_of(config::OutputSpec::Compression c) {
  switch (c) {
    case config::OutputSpec::Compression::None: return output::Compression::none;
    case config::OutputSpec::Compression::LZ4: return output::Compression::lz4;
    case config::OutputSpec::Compression::ZLib: break;
  }
  return output::Compression::zlib;
}

// <name><part>_NNNN.vtu; part "" for the bodies, "_rigid" for the rigid bodies.
std::string frame_file(const std::string& name, const char* part, std::size_t index) {
  char number[32];
  std::snprintf(number, sizeof number, "_%04zu.vtu", index);
  return name + part + number;
}

bool has_rigid_geometry(const model::Model& model) {
  return !model.impactor_quads.empty() ||
         std::any_of(model.blocks.begin(), model.blocks.end(), [](const auto& b) { return b.rigid && b.size() > 0; });
}

}  // namespace

FrameWriter::FrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval)
    : dir_(dir),
      name_(model.name),
      t_end_(model.control.termination_time),
      pvd_(dir, model.name),
      frames_(interval),
      rigid_(has_rigid_geometry(model)) {
  options_.compression = compression_of(model.output.compression);
}

void FrameWriter::add_to_series(double time, std::size_t index) {
  if (!rigid_) {
    pvd_.add(time, frame_file(name_, "", index));
    return;
  }
  pvd_.add(time, frame_file(name_, "", index), 0, "bodies");
  pvd_.add(time, frame_file(name_, "_rigid", index), 1, "rigid");
}

void FrameWriter::write(const solver::Solver& solver) {
  const std::size_t index = times_.size();
  const double t = solver.state().time;
  output::write_vtu(make_frame(solver), dir_ / frame_file(name_, "", index), options_);
  if (rigid_) output::write_vtu(make_rigid_frame(solver), dir_ / frame_file(name_, "_rigid", index), options_);
  add_to_series(t, index);
  times_.push_back(t);
  pvd_.write();
}

void FrameWriter::resume(const solver::Solver& solver) {
  (void)solver;
  pvd_ = output::PvdSeries(dir_, name_);
  for (std::size_t i = 0; i < times_.size(); ++i) add_to_series(times_[i], i);
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
