// Frames: <scene>_NNNN.vtu at t = 0, every frame interval and at the end, listed in <scene>.pvd
// (rewritten with every frame, so ParaView can open a run in progress or one that stopped).
#pragma once

#include <filesystem>
#include <string>

#include "output/pvd_series.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

class FrameWriter : public RunObserver {
 public:
  FrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval);

  void start(const solver::Solver& solver) override { write(solver); }
  void after_cycle(const solver::Solver& solver) override;
  void stop(const solver::Solver* solver, RunReport& report) override;

 private:
  void write(const solver::Solver& solver);

  std::filesystem::path dir_;
  std::string name_;
  double t_end_;
  output::PvdSeries pvd_;
  Sampler frames_;
};

}  // namespace plyimpact::run
