#include "run/frame_builder.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>

#include "element/hex8.hpp"
#include "run/frame_legends.hpp"
#include "run/frame_material_fields.hpp"

namespace plyimpact::run {

using namespace solver;  // the frame reads the solver's state types throughout

namespace {

const std::vector<std::string> kTensorComponents = {"xx", "yy", "zz", "xy", "yz", "zx"};

void put_tensor(const Eigen::Matrix3d& t, std::vector<double>& out) {
  out.insert(out.end(), {t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(2, 0)});
}

Eigen::Matrix3d voigt_to_matrix(const double* s) {
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  return m;
}

double von_mises(const Eigen::Matrix3d& s) {
  const Eigen::Matrix3d dev = s - s.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
}

// The model nodes a frame's cells use, in increasing node order, and each one's point index.
class PointSubset {
 public:
  explicit PointSubset(std::size_t num_nodes) : point_(num_nodes, -1) {}
  void use(const Index* nodes, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) point_[std::size_t(nodes[k])] = 0;
  }
  // Numbers the used nodes; call once, after every use().
  void number() {
    for (std::size_t n = 0; n < point_.size(); ++n)
      if (point_[n] >= 0) {
        point_[n] = std::int64_t(nodes_.size());
        nodes_.push_back(Index(n));
      }
  }
  std::int64_t point(Index node) const { return point_[std::size_t(node)]; }
  const std::vector<Index>& nodes() const { return nodes_; }

 private:
  std::vector<std::int64_t> point_;  // (num_nodes) point index, -1 unused
  std::vector<Index> nodes_;         // (num_points) model node of each point
};

void append_cells(const PointSubset& subset, const Index* conn, std::size_t count, std::vector<std::int64_t>& out) {
  for (std::size_t k = 0; k < count; ++k) out.push_back(subset.point(conn[k]));
}

// Coordinates and the point fields, gathered over the subset's nodes.
void add_points(const Solver& solver, const PointSubset& subset, output::Frame& frame) {
  const model::Model& model = solver.model();
  const State& state = solver.state();
  const std::vector<double> acceleration = solver.acceleration();
  output::Field displacement{"displacement", 3, {}, {}, "m"}, velocity{"velocity", 3, {}, {}, "m/s"};
  output::Field accel{"acceleration", 3, {}, {}, "m/s^2"};
  output::IntField node_id{"node_id", {}, "-"};
  const auto& nodes = subset.nodes();
  for (Index n : nodes)
    for (int d = 0; d < 3; ++d) {
      const std::size_t i = 3 * std::size_t(n) + std::size_t(d);
      frame.points.push_back(state.x[i]);
      displacement.values.push_back(state.x[i] - model.X[i]);
      velocity.values.push_back(state.v[i]);
      accel.values.push_back(acceleration[i]);
    }
  for (Index n : nodes) node_id.values.push_back(std::int32_t(n + 1));
  frame.point_fields = {std::move(displacement), std::move(velocity), std::move(accel)};
  // Contact force of the last cycle per node (N, sum over the contacts, friction included): the
  // contacts keep it for their force-carrying nodes, so this costs one pass over those nodes.
  if (!solver.contacts().empty()) {
    output::Field contact_force{"contact_force", 3, std::vector<double>(3 * nodes.size(), 0.0), {}, "N"};
    for (const auto& c : solver.contacts()) {
      const auto& force_nodes = c.force_nodes();
      const auto& fc = c.node_forces();
      for (std::size_t u = 0; u < force_nodes.size(); ++u) {
        const std::int64_t p = subset.point(force_nodes[u]);
        if (p < 0) continue;
        for (int d = 0; d < 3; ++d) contact_force.values[3 * std::size_t(p) + std::size_t(d)] += fc[3 * u + std::size_t(d)];
      }
    }
    frame.point_fields.push_back(std::move(contact_force));
  }
  frame.point_int_fields = {std::move(node_id)};
}

// Ply angle of an element in degrees: the direction of its reference fibre (a) axis in the x-y
// plane, measured from +x towards +y and folded into (-90, 90] (a fibre has no sense); NaN when
// the material has no axes or its a axis is (nearly) normal to the x-y plane.
double ply_angle_degrees(const model::Model& model, const model::ElementBlock& blk, std::size_t e) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (blk.orientation.empty()) return nan;
  const auto& a = model.orientations[std::size_t(blk.orientation[e])].axes;  // row 0: a axis
  if (std::hypot(a[0], a[1]) < 1e-6) return nan;
  double deg = std::atan2(a[1], a[0]) * 180.0 / std::numbers::pi;
  if (deg <= -90.0 + 1e-9) deg += 180.0;
  if (deg > 90.0 + 1e-9) deg -= 180.0;
  return deg;
}

// 1-based ply of the laminate (the mesher's numbering, bottom ply 1), 0 outside a laminate.
std::int32_t ply_index(const model::Model& model, Index element_id) {
  const auto i = std::size_t(element_id - 1);
  if (i >= model.element_ply.size() || model.element_ply[i] < 0) return 0;
  return std::int32_t(model.element_ply[i] + 1);
}

}  // namespace

output::Frame make_frame(const Solver& solver) {
  const model::Model& model = solver.model();
  const State& state = solver.state();
  output::Frame frame;
  frame.time = state.time;
  frame.cycle = state.cycle;

  PointSubset subset(model.num_nodes());
  for (const auto& blk : model.blocks)
    if (in_bodies_frame(blk)) subset.use(blk.conn.data(), blk.conn.size());
  subset.number();
  add_points(solver, subset, frame);

  output::Field stress{"stress", 6, {}, kTensorComponents, "Pa"}, stress_m{"stress_material", 6, {}, kTensorComponents, "Pa"};
  output::Field strain{"strain", 6, {}, kTensorComponents, "1"}, strain_m{"strain_material", 6, {}, kTensorComponents, "1"};
  output::Field vm{"von_mises", 1, {}, {}, "Pa"}, ie{"internal_energy", 1, {}, {}, "J"}, hg{"hourglass_energy", 1, {}, {}, "J"};
  output::Field relvol{"relative_volume", 1, {}, {}, "1"}, axis_a{"material_a_axis", 3, {}, {}, "1"};
  output::Field angle{"ply_angle", 1, {}, {}, "deg"};
  output::IntField part_id{"part_id", {}, "-"}, element_id{"element_id", {}, "-"}, ply{"ply_index", {}, "-"};

  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    const auto& blk = model.blocks[b];
    if (!in_bodies_frame(blk)) continue;
    const auto& st = state.blocks[b];
    const auto kind = model.materials[blk.material].kind;
    for (std::size_t e = 0; e < blk.size(); ++e) {
      const Index* conn = &blk.conn[8 * e];
      append_cells(subset, conn, 8, frame.hex_connectivity);
      double xe[3][8], Xe[3][8], bgrad[3][8];
      for (int k = 0; k < 8; ++k)
        for (int i = 0; i < 3; ++i) {
          xe[i][k] = state.x[3 * std::size_t(conn[k]) + i];
          Xe[i][k] = model.X[3 * std::size_t(conn[k]) + i];
        }
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      if (element::hex8_mean_gradient(xe, bgrad) > 0) {
        Eigen::Matrix3d Finv;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 8; ++k) s += Xe[i][k] * bgrad[j][k];
            Finv(i, j) = s;
          }
        F = Finv.inverse();
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> left(F * F.transpose());
      const Eigen::Vector3d lam = left.eigenvalues().cwiseMax(1e-300);
      const Eigen::Matrix3d Nv = left.eigenvectors();
      const Eigen::Matrix3d hencky = Nv * (0.5 * lam.array().log()).matrix().asDiagonal() * Nv.transpose();
      const Eigen::Matrix3d Vinv = Nv * lam.cwiseSqrt().cwiseInverse().asDiagonal() * Nv.transpose();
      const Eigen::Matrix3d R = Vinv * F;  // polar rotation

      Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
      const int points = blk.points();
      for (int g = 0; g < points; ++g) sigma += voigt_to_matrix(&st.stress[6 * (points * e + g)]);
      sigma /= points;

      Eigen::Matrix3d Q = Eigen::Matrix3d::Identity();  // rows: current material axes
      if (kind == model::MaterialKind::CompositeDamage) {
        // *MAT_054 keeps its own axes, rotated with the element's spin: report the ones its
        // stress and failure criteria are evaluated in.
        const double* ax = &st.axes[9 * e];
        Q << ax[0], ax[1], ax[2], ax[3], ax[4], ax[5], ax[6], ax[7], ax[8];
      } else if (kind == model::MaterialKind::OrthotropicElastic) {
        const auto& ax = model.orientations[blk.orientation[e]].axes;
        Eigen::Matrix3d Q0;
        Q0 << ax[0], ax[1], ax[2], ax[3], ax[4], ax[5], ax[6], ax[7], ax[8];
        Q = Q0 * R.transpose();  // row r becomes (R a0_r)^T
      }
      put_tensor(sigma, stress.values);
      put_tensor(Q * sigma * Q.transpose(), stress_m.values);
      put_tensor(hencky, strain.values);
      put_tensor(Q * hencky * Q.transpose(), strain_m.values);
      vm.values.push_back(von_mises(sigma));
      ie.values.push_back(st.internal_energy[e]);
      hg.values.push_back(st.hourglass_energy[e]);
      relvol.values.push_back(st.volume[e] / blk.volume0[e]);
      axis_a.values.insert(axis_a.values.end(), {Q(0, 0), Q(0, 1), Q(0, 2)});
      angle.values.push_back(ply_angle_degrees(model, blk, e));
      part_id.values.push_back(model.parts[blk.part].id);
      element_id.values.push_back(blk.element_id[e]);
      ply.values.push_back(ply_index(model, blk.element_id[e]));
    }
  }
  frame.cell_fields = {std::move(stress), std::move(stress_m), std::move(strain), std::move(strain_m), std::move(vm),
                       std::move(ie),     std::move(hg),       std::move(relvol), std::move(axis_a), std::move(angle)};
  frame.cell_int_fields = {std::move(part_id), std::move(element_id), std::move(ply)};
  add_material_fields(solver, frame);  // alive flag, plastic strain, MAT_054 damage fields
  add_frame_description(model, frame);
  return frame;
}

output::Frame make_rigid_frame(const Solver& solver) {
  const model::Model& model = solver.model();
  const State& state = solver.state();
  output::Frame frame;
  frame.time = state.time;
  frame.cycle = state.cycle;

  PointSubset subset(model.num_nodes());
  for (const auto& blk : model.blocks)
    if (!in_bodies_frame(blk)) subset.use(blk.conn.data(), blk.conn.size());
  subset.use(model.impactor_quads.data(), model.impactor_quads.size());
  subset.number();
  if (subset.nodes().empty()) return frame;
  add_points(solver, subset, frame);

  // The rigid body (1-based, as listed in legend_rigid_body) that carries each part.
  std::vector<std::int32_t> body_of_part(model.parts.size(), 0);
  std::int32_t impactor_body = 0;
  for (std::size_t r = 0; r < model.rigid_bodies.size(); ++r) {
    const int part = model.rigid_bodies[r].part;
    (part >= 0 ? body_of_part[std::size_t(part)] : impactor_body) = std::int32_t(r + 1);
  }
  output::IntField part_id{"part_id", {}, "-"}, element_id{"element_id", {}, "-"}, body{"rigid_body", {}, "-"};
  for (const auto& blk : model.blocks) {
    if (in_bodies_frame(blk)) continue;
    append_cells(subset, blk.conn.data(), blk.conn.size(), frame.hex_connectivity);
    for (std::size_t e = 0; e < blk.size(); ++e) {
      part_id.values.push_back(model.parts[blk.part].id);
      element_id.values.push_back(blk.element_id[e]);
      body.values.push_back(body_of_part[std::size_t(blk.part)]);
    }
  }
  append_cells(subset, model.impactor_quads.data(), model.impactor_quads.size(), frame.quad_connectivity);
  const std::size_t quads = model.impactor_quads.size() / 4;
  part_id.values.insert(part_id.values.end(), quads, 0);
  element_id.values.insert(element_id.values.end(), quads, 0);
  body.values.insert(body.values.end(), quads, impactor_body);
  frame.cell_int_fields = {std::move(part_id), std::move(element_id), std::move(body)};
  add_rigid_description(model, frame);
  return frame;
}

}  // namespace plyimpact::run
