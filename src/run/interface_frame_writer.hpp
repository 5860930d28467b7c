// Delamination outputs, for every contributor that is an interface::InterfaceSampleSource (the
// laminate's tiebreak pairs and cohesive elements, the tiebreak contacts' ties):
//   interfaces.pvd            the series, at the ply frames' times (t = 0, every frame interval, the end)
//   interfaces/interfaces_NNNN.vtm        one block per interface, named "interface_3 (plies 3/4, 45/-45)"
//   interfaces/interfaces_NNNN_III.vtu    its display quads (interface_output.hpp) on the current
//                             mid-surface with point data damage, mode_mixity, opening_normal,
//                             opening_shear (m), traction_normal, traction_shear (Pa) and
//                             delaminated (0/1), each vertex showing its sample point
//   cscan.vtu, cscan.png      the projected delamination map (output/cscan.hpp) at the stop, also
//                             an early one
// and the delaminated areas (per interface, total, projected) in the report for summary.json.
// The surfaces' buffers are sized at the start and refilled in place; files are replaced atomically
// and the series rewritten after each frame, so a stopped run keeps a valid series.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "interface/interface_output.hpp"
#include "output/pvd_series.hpp"
#include "output/quad_surface.hpp"
#include "run/run_observer.hpp"

namespace plyimpact::run {

class InterfaceFrameWriter : public RunObserver {
 public:
  InterfaceFrameWriter(const model::Model& model, const std::filesystem::path& dir, double interval);

  void start(const solver::Solver& solver) override;
  void resume(const solver::Solver& solver) override;
  void after_cycle(const solver::Solver& solver) override;
  std::string_view timing_name() const override { return "interface frames (VTU)"; }
  void stop(const solver::Solver* solver, RunReport& report) override;
  // The frames written so far and the next frame time: a continued run keeps the series.
  void visit_state(StateVisitor& visitor) override;

 private:
  void find_blocks(const solver::Solver& solver);
  struct Block {
    const interface::InterfaceSampleSource* source = nullptr;
    std::size_t index = 0;
    output::QuadSurface surface;
    std::vector<cohesive::PairSample> samples;  // (num_points)
    std::vector<double> reference;              // (num_vertices, 3) m, vertex positions at the start
    const interface::InterfaceLayout& layout() const { return source->layout(index); }
  };

  void write_frame(const solver::Solver& solver);
  void fill(Block& block, const solver::Solver& solver);
  void write_cscan(const solver::Solver& solver, RunReport& report);

  std::filesystem::path dir_;
  double t_end_;
  output::PvdSeries pvd_;
  Sampler frames_;
  std::vector<double> times_;  // s, of the frames written (the series' list; run state)
  std::vector<Block> blocks_;
  std::vector<output::MultiBlockEntry> entries_;  // (blocks_) names fixed, file names per frame
};

}  // namespace plyimpact::run
