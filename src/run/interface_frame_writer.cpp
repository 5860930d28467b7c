#include "run/interface_frame_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.hpp"
#include "output/cscan.hpp"

namespace plyimpact::run {
namespace fs = std::filesystem;

namespace {

const char* const kSubdir = "interfaces";

output::QuadSurface make_surface(const interface::InterfaceLayout& l) {
  output::QuadSurface s;
  const std::size_t n = l.num_vertices();
  s.points.assign(3 * n, 0.0);
  s.quads.assign(l.quads.begin(), l.quads.end());
  for (const char* name : {"damage", "mode_mixity", "opening_normal", "opening_shear", "traction_normal", "traction_shear"})
    s.point_fields.push_back({name, 1, std::vector<double>(n, 0.0), {}});
  // The mid-surface's displacement from its reference position: Warp By Vector with -1, or a
  // damage map drawn flat, undoes the motion (the pairs of eroded plies fly off with their nodes).
  s.point_fields.push_back({"displacement", 3, std::vector<double>(3 * n, 0.0), {}});
  s.point_int_fields.push_back({"delaminated", std::vector<std::int32_t>(n, 0)});
  s.units = {{"coordinates", "m (current mid-surface of the interface)"},
             {"damage", "- (0 intact .. 1 separated)"},
             {"mode_mixity", "- (G_II / G_T: 0 mode I, 1 shear)"},
             {"opening_normal", "m"},
             {"opening_shear", "m (magnitude)"},
             {"traction_normal", "Pa"},
             {"traction_shear", "Pa (magnitude)"},
             {"displacement", "m (of the mid-surface from its reference position)"},
             {"delaminated", "0/1 (damage 1)"}};
  return s;
}

std::string frame_stem(std::size_t index) {
  char stem[64];
  std::snprintf(stem, sizeof stem, "interfaces_%04zu", index);
  return stem;
}

}  // namespace

InterfaceFrameWriter::InterfaceFrameWriter(const model::Model& model, const fs::path& dir, double interval)
    : dir_(dir), t_end_(model.control.termination_time), pvd_(dir, kSubdir), frames_(interval) {}

void InterfaceFrameWriter::start(const solver::Solver& solver) {
  find_blocks(solver);
  if (blocks_.empty()) return;
  fs::create_directories(dir_ / kSubdir);
  write_frame(solver);
}

void InterfaceFrameWriter::resume(const solver::Solver& solver) {
  find_blocks(solver);
  if (blocks_.empty()) return;
  fs::create_directories(dir_ / kSubdir);
  pvd_ = output::PvdSeries(dir_, kSubdir);
  for (std::size_t i = 0; i < times_.size(); ++i) pvd_.add(times_[i], std::string(kSubdir) + "/" + frame_stem(i) + ".vtm");
  pvd_.write();
}

void InterfaceFrameWriter::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "interface frames");
  visitor.array("times", times_);
  frames_.visit_state(visitor, "next_frame_time");
}

void InterfaceFrameWriter::find_blocks(const solver::Solver& solver) {
  for (const auto& c : solver.contributors()) {
    const auto* source = dynamic_cast<const interface::InterfaceSampleSource*>(c.get());
    if (!source) continue;
    for (std::size_t i = 0; i < source->num_interfaces(); ++i) {
      const interface::InterfaceLayout& l = source->layout(i);
      Block b{source, i, make_surface(l), std::vector<cohesive::PairSample>(l.size()),
              std::vector<double>(3 * l.num_vertices())};
      l.vertex_positions(solver.model().X.data(), b.reference.data());
      entries_.push_back({b.layout().label(), {}});
      blocks_.push_back(std::move(b));
    }
  }
}

void InterfaceFrameWriter::after_cycle(const solver::Solver& solver) {
  if (blocks_.empty()) return;
  const double t = solver.state().time;
  if (frames_.due(t) || t >= t_end_ * (1 - 1e-12)) {
    write_frame(solver);
    frames_.advance(t);
  }
}

void InterfaceFrameWriter::fill(Block& b, const solver::Solver& solver) {
  const interface::InterfaceLayout& l = b.layout();
  const double* x = solver.state().x.data();
  b.source->sample(b.index, x, b.samples.data());
  output::QuadSurface& s = b.surface;
  s.time = solver.state().time;
  s.cycle = solver.state().cycle;
  auto& f = s.point_fields;
  auto& delaminated = s.point_int_fields[0].values;
  l.vertex_positions(x, s.points.data());
  std::vector<double>& u = f[6].values;
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = s.points[i] - b.reference[i];
  for (std::size_t v = 0; v < l.num_vertices(); ++v) {
    const cohesive::PairSample& q = b.samples[std::size_t(l.vertex_point[v])];
    f[0].values[v] = q.damage;
    f[1].values[v] = q.mixity;
    f[2].values[v] = q.opening[0];
    f[3].values[v] = std::hypot(q.opening[1], q.opening[2]);
    f[4].values[v] = q.traction[0];
    f[5].values[v] = std::hypot(q.traction[1], q.traction[2]);
    delaminated[v] = q.damage >= 1 ? 1 : 0;
  }
}

void InterfaceFrameWriter::write_frame(const solver::Solver& solver) {
  const std::string stem = frame_stem(pvd_.size());
  for (std::size_t k = 0; k < blocks_.size(); ++k) {
    fill(blocks_[k], solver);
    char file[96];
    std::snprintf(file, sizeof file, "%s_%03d.vtu", stem.c_str(), blocks_[k].layout().id);
    output::write_quad_vtu(blocks_[k].surface, dir_ / kSubdir / file);
    entries_[k].file = file;
  }
  const std::string vtm = std::string(stem) + ".vtm";
  output::write_vtm(dir_ / kSubdir / vtm, entries_);
  pvd_.add(solver.state().time, std::string(kSubdir) + "/" + vtm);
  pvd_.write();
  times_.push_back(solver.state().time);
}

void InterfaceFrameWriter::write_cscan(const solver::Solver& solver, RunReport& report) {
  std::vector<output::CscanLayer> layers;
  DelaminationReport d;
  double top = -INFINITY, deepest = 0;
  for (Block& b : blocks_) {
    fill(b, solver);
    const interface::InterfaceLayout& l = b.layout();
    const std::size_t nv = l.num_vertices();
    output::CscanLayer layer{l.id, l.depth, std::vector<double>(2 * nv), b.surface.quads, std::vector<char>(nv)};
    for (std::size_t v = 0; v < nv; ++v) {
      const double* X = &b.reference[3 * v];
      layer.xy[2 * v] = X[0];
      layer.xy[2 * v + 1] = X[1];
      layer.delaminated[v] = b.samples[std::size_t(l.vertex_point[v])].damage >= 1;
      top = std::max(top, X[2] + l.depth);
    }
    const double area = b.source->delaminated_area(b.index);  // as history.csv: the perforation left out
    deepest = std::max(deepest, l.depth);
    d.interfaces.push_back({l.id, l.label(), l.depth, area});
    d.total_area += area;
    layers.push_back(std::move(layer));
  }
  report.delamination = d;
  const double t = solver.state().time;
  try {
    d.cscan_pitch = output::cscan_pitch(layers);
    const output::CscanMap map = output::make_cscan(layers, d.cscan_pitch);
    d.projected_area = map.projected_area();
    report.delamination = d;
    output::write_cscan_vtu(map, top, t, dir_ / "cscan.vtu");
    report.cscan_vtu = dir_ / "cscan.vtu";
    std::ostringstream title;
    title.precision(4);
    title << "C-scan from the impacted face at t = " << t * 1e3 << " ms: projected delaminated area "
          << d.projected_area * 1e6 << " mm^2";
    output::write_cscan_png(map, deepest, title.str(), dir_ / "cscan.png");
    report.cscan_png = dir_ / "cscan.png";
  } catch (const RunError& e) {
    report.warnings.push_back(std::string("C-scan not written: ") + e.what());
  }
}

void InterfaceFrameWriter::stop(const solver::Solver* solver, RunReport& report) {
  if (blocks_.empty()) return;
  report.interfaces_pvd = pvd_.path();
  if (solver) write_cscan(*solver, report);
}

}  // namespace plyimpact::run
