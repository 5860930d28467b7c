#include "run/frame_builder.hpp"

#include "run/frame_material_fields.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "element/hex8.hpp"

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

}  // namespace

output::Frame make_frame(const Solver& solver) {
  const model::Model& model = solver.model();
  const State& state = solver.state();
  output::Frame frame;
  frame.time = state.time;
  frame.cycle = state.cycle;
  frame.points = state.x;
  const std::size_t n = model.num_nodes();

  output::Field displacement{"displacement", 3, {}, {}}, velocity{"velocity", 3, state.v, {}};
  displacement.values.resize(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i) displacement.values[i] = state.x[i] - model.X[i];
  output::Field acceleration{"acceleration", 3, solver.acceleration(), {}};
  frame.point_fields = {std::move(displacement), std::move(velocity), std::move(acceleration)};
  // Contact force of the last cycle per node (N, sum over the contacts, friction included): the
  // contacts keep it for their force-carrying nodes, so this costs one pass over those nodes.
  if (!solver.contacts().empty()) {
    output::Field contact_force{"contact_force", 3, std::vector<double>(3 * n, 0.0), {}};
    for (const auto& c : solver.contacts()) {
      const auto& nodes = c.force_nodes();
      const auto& fc = c.node_forces();
      for (std::size_t u = 0; u < nodes.size(); ++u)
        for (int d = 0; d < 3; ++d) contact_force.values[3 * std::size_t(nodes[u]) + d] += fc[3 * u + d];
    }
    frame.point_fields.push_back(std::move(contact_force));
  }

  output::Field stress{"stress", 6, {}, kTensorComponents}, stress_m{"stress_material", 6, {}, kTensorComponents};
  output::Field strain{"strain", 6, {}, kTensorComponents}, strain_m{"strain_material", 6, {}, kTensorComponents};
  output::Field vm{"von_mises", 1, {}, {}}, ie{"internal_energy", 1, {}, {}}, hg{"hourglass_energy", 1, {}, {}};
  output::Field relvol{"relative_volume", 1, {}, {}}, axis_a{"material_a_axis", 3, {}, {}};
  output::IntField part_id{"part_id", {}}, element_id{"element_id", {}};
  const std::size_t ne = model.num_elements();
  frame.hex_connectivity.reserve(8 * ne);

  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    const auto& blk = model.blocks[b];
    const auto& st = state.blocks[b];
    const auto kind = model.materials[blk.material].kind;
    for (std::size_t e = 0; e < blk.size(); ++e) {
      const Index* conn = &blk.conn[8 * e];
      frame.hex_connectivity.insert(frame.hex_connectivity.end(), conn, conn + 8);
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
      part_id.values.push_back(model.parts[blk.part].id);
      element_id.values.push_back(blk.element_id[e]);
    }
  }
  frame.cell_fields = {std::move(stress), std::move(stress_m), std::move(strain), std::move(strain_m), std::move(vm),
                       std::move(ie),     std::move(hg),       std::move(relvol), std::move(axis_a)};
  frame.cell_int_fields = {std::move(part_id), std::move(element_id)};
  add_material_fields(solver, frame);  // alive flag, plastic strain, MAT_054 damage fields
  return frame;
}

}  // namespace plyimpact::run
