// Frames: <scene>_NNNN.vtu at t = 0, every frame interval and at the end, listed in <scene>.pvd
// (rewritten with every frame, so ParaView can open a run in progress or one that stopped). A run
// that stops early (signal, max_cycles) also writes the state it stopped in; that frame is not part
// of the run state, so a run continued from the dump writes its next regular frame over it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "output/pvd_series.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

class FrameWriter : public RunObserver {
 public:
  FrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval);

  void start(const solver::Solver& solver) override { write(solver); }
  void resume(const solver::Solver& solver) override;
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;
  void visit_state(StateVisitor& visitor) override;

 private:
  void write(const solver::Solver& solver);

  std::filesystem::path dir_;
  std::string name_;
  double t_end_;
  output::PvdSeries pvd_;
  std::vector<double> times_;  // s, of the frames written (the .pvd's list; run state)
  Sampler frames_;
};

}  // namespace plyimpact::run
