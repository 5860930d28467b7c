#include "run/frame_writer.hpp"

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

}  // namespace

FrameWriter::FrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval)
    : dir_(dir), name_(model.name), t_end_(model.control.termination_time), pvd_(dir, model.name), frames_(interval) {
  options_.compression = compression_of(model.output.compression);
}

void FrameWriter::write(const solver::Solver& solver) {
  char number[32];
  std::snprintf(number, sizeof number, "_%04zu.vtu", written_);
  const double t = solver.state().time;
  const std::string bodies = name_ + number;
  output::write_vtu(make_frame(solver), dir_ / bodies, options_);
  const output::Frame rigid = make_rigid_frame(solver);
  if (rigid.num_cells() == 0) {
    pvd_.add(t, bodies);
  } else {
    const std::string rigid_file = name_ + "_rigid" + number;
    output::write_vtu(rigid, dir_ / rigid_file, options_);
    pvd_.add(t, bodies, 0, "bodies");
    pvd_.add(t, rigid_file, 1, "rigid");
  }
  pvd_.write();
  ++written_;
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
