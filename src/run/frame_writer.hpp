// Frames: at t = 0, every frame interval and at the end, listed in <scene>.pvd (rewritten with
// every frame, so ParaView can open a run in progress or one that stopped). Each time has the
// deformable bodies in <scene>_NNNN.vtu and, when the model has rigid bodies with geometry (the
// meshed rigid impactor, *MAT_020 parts), those in <scene>_rigid_NNNN.vtu: the .pvd lists both as
// parts named "bodies" and "rigid", which ParaView's PVD reader turns into the two blocks of one
// multiblock source, so the impactor moves with the plate through time without a second source.
// Compressed as the scene's output.compression says (zlib by default). A run that stops early
// (signal, max_cycles) also writes the state it stopped in; that frame is not part of the run
// state, so a run continued from the dump writes its next regular frame over it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "output/pvd_series.hpp"
#include "output/vtu_writer.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

class FrameWriter : public RunObserver {
 public:
  FrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval);

  void start(const solver::Solver& solver) override { write(solver); }
  void resume(const solver::Solver& solver) override;
  void after_cycle(const solver::Solver& solver) override;
  std::string_view timing_name() const override { return "frames (VTU)"; }
  void stop(const solver::Solver* solver, RunReport& report) override;
  void visit_state(StateVisitor& visitor) override;

 private:
  void write(const solver::Solver& solver);
  void add_to_series(double time, std::size_t index);  // frame `index`'s parts, to pvd_

  std::filesystem::path dir_;
  std::string name_;
  double t_end_;
  output::WriteOptions options_;
  output::PvdSeries pvd_;
  std::vector<double> times_;  // s, of the frames written (the .pvd's list; run state)
  Sampler frames_;
  bool rigid_ = false;  // the model has rigid bodies with geometry: each time has a "rigid" part
};

}  // namespace plyimpact::run
