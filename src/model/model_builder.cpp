#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "element/hex8.hpp"
#include "element/hex8_ans.hpp"
#include "model/erosion_neighbours.hpp"
#include "model/erosion_scale.hpp"
#include "model/material_builder.hpp"
#include "model/mesh_conversion.hpp"
#include "model/model.hpp"

namespace plyimpact::model {

namespace {

std::vector<Index> select_nodes(const config::NodeSetSpec& spec, const Model& model, double tol) {
  std::vector<Index> nodes;
  const std::size_t n = model.num_nodes();
  if (spec.kind == config::NodeSetSpec::Kind::Part) {
    std::vector<char> mark(n, 0);
    for (const auto& part : model.parts)
      if (part.name == spec.part)
        for (Index node : model.blocks[part.block].conn) mark[node] = 1;
    for (std::size_t i = 0; i < n; ++i)
      if (mark[i]) nodes.push_back(Index(i));
    return nodes;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &model.X[3 * i];
    bool in = true;
    if (spec.kind == config::NodeSetSpec::Kind::Box) {
      for (int d = 0; d < 3; ++d) in = in && p[d] >= spec.box_min[d] - tol && p[d] <= spec.box_max[d] + tol;
    } else if (spec.kind == config::NodeSetSpec::Kind::Plane) {
      in = std::abs(p[spec.plane_axis] - spec.plane_value) <= tol;
    }
    if (in) nodes.push_back(Index(i));
  }
  return nodes;
}

// The natural direction whose centre base vector dX/dxi_c is the shortest: a ply element's thickness.
// Within 1 % of the shortest, zeta wins, then eta: zeta runs from the face of nodes 1-4 to that of
// 5-8, a thick shell's thickness direction, and a beam one element deep and wide (two equal short
// directions) then ties the shear of its zeta bending.
std::uint8_t thinnest_natural_direction(const double (&x)[3][8]) {
  double J[9];
  element::hex8_centroid_jacobian(x, J);
  double length[3] = {};
  for (int c = 0; c < 3; ++c) length[c] = std::sqrt(J[c] * J[c] + J[3 + c] * J[3 + c] + J[6 + c] * J[6 + c]);
  const double shortest = *std::min_element(length, length + 3);
  for (int c = 2; c >= 0; --c)
    if (length[c] <= 1.01 * shortest) return std::uint8_t(c);
  return 2;
}

template <class T>
int index_by_name(const std::vector<T>& items, const std::string& name) {
  for (int i = 0; i < int(items.size()); ++i)
    if (items[i].name == name) return i;
  return -1;
}

}  // namespace

double Curve::operator()(double time) const {
  if (t.size() == 1 || time <= t.front()) return y.front();
  if (time >= t.back()) return y.back();
  const auto it = std::upper_bound(t.begin(), t.end(), time);
  const std::size_t i = std::size_t(it - t.begin());
  const double w = (time - t[i - 1]) / (t[i] - t[i - 1]);
  return y[i - 1] + w * (y[i] - y[i - 1]);
}

std::size_t Model::num_elements() const {
  std::size_t n = 0;
  for (const auto& b : blocks) n += b.size();
  return n;
}

Model build_model(const config::Scene& scene, const mesh::Mesh& mesh) {
  Model model;
  model.name = scene.name;
  model.control = scene.control;
  model.coupon = scene.coupon;
  model.output = scene.output;
  model.X = mesh.coords;
  const std::size_t num_nodes = mesh.num_nodes();

  for (const auto& spec : scene.materials) model.materials.push_back(make_material(spec));

  // One block per part, elements in mesh order.
  for (const auto& ps : scene.parts) {
    Part part;
    part.id = ps.id;
    part.name = ps.name;
    part.section = ps.section;
    part.material = index_by_name(scene.materials, ps.material);
    const int section = index_by_name(scene.sections, ps.section);
    if (part.material < 0 || section < 0)
      throw InputError(at(ps.where) << "unknown material '" << ps.material << "' or section '" << ps.section << "'");
    const auto& sec = scene.sections[section];
    ElementBlock block;
    block.part = int(model.parts.size());
    block.material = part.material;
    block.elform = sec.ELFORM;
    block.ihq = sec.IHQ;
    block.qm = sec.QM;
    block.q1 = sec.Q1;
    block.q2 = sec.Q2;
    block.rigid = std::holds_alternative<config::MatRigid>(scene.materials[part.material].params);
    part.block = int(model.blocks.size());
    model.blocks.push_back(std::move(block));
    model.parts.push_back(part);
  }
  for (std::size_t e = 0; e < mesh.num_elements(); ++e) {
    ElementBlock& block = model.blocks[model.parts[mesh.element_part[e]].block];
    block.conn.insert(block.conn.end(), &mesh.hex[8 * e], &mesh.hex[8 * e] + 8);
    block.element_id.push_back(Index(e + 1));
  }
  // Tagged interfaces have duplicated (coincident) nodes. An interface with a law (tiebreak pairs or
  // *MAT_138 cohesive elements) keeps them apart: each ply's elements use their own nodes (so each node's lumped mass comes from its
  // own ply) and the interface contributor holds the pairs together. An interface without a law
  // (`model: merged`) is bonded: the upper ply's elements use the lower partner nodes, so the
  // laminate is one body; the upper duplicates remain as unused, massless nodes.
  const auto law_of = [&](const mesh::Interface& itf) -> std::optional<config::InterfaceLawSpec> {
    if (!scene.laminate) return std::nullopt;
    const auto& laws = scene.laminate->interface_law;
    const std::size_t k = std::size_t(itf.id - 1);
    return k < laws.size() ? laws[k] : std::nullopt;
  };
  if (!mesh.interfaces.empty()) {
    std::vector<Index> partner(mesh.num_nodes());
    for (std::size_t i = 0; i < partner.size(); ++i) partner[i] = Index(i);
    for (const auto& itf : mesh.interfaces) {
      if (law_of(itf)) continue;
      for (std::size_t k = 0; k < itf.upper_nodes.size(); ++k) partner[itf.upper_nodes[k]] = itf.lower_nodes[k];
      model.interfaces_bonded = true;
    }
    if (model.interfaces_bonded)
      for (auto& block : model.blocks)
        for (Index& node : block.conn) node = partner[node];
  }

  // Geometry checks, reference volumes, lumped masses and material orientations.
  model.mass.assign(num_nodes, 0.0);
  std::map<std::pair<int, std::array<double, 9>>, int> orientation_index;
  for (auto& block : model.blocks) {
    const Part& part = model.parts[block.part];
    const Material& mat = model.materials[block.material];
    const auto& part_spec = scene.parts[block.part];
    block.volume0.resize(block.size());
    if (mat.has_axes()) block.orientation.resize(block.size());
    for (std::size_t e = 0; e < block.size(); ++e) {
      double x[3][8];
      gather_reference(model.X, &block.conn[8 * e], x);
      double detj[8];
      element::hex8_corner_jacobians(x, detj);
      const double volume = element::hex8_volume(x);
      for (int k = 0; k < 8; ++k)
        if (!(detj[k] > 0.0) || !(volume > 0.0))
          throw InputError(at(part_spec.where)
                           << "element " << block.element_id[e] << " of part '" << part.name
                           << "' has a zero or negative Jacobian at its corner node " << block.conn[8 * e + k] + 1
                           << " (volume " << volume << " m^3); allowed: valid hexahedra with positive volume "
                           << "(check node order and degenerate elements)");
      block.volume0[e] = volume;
      if (block.elform == -2) {
        const int thin = thinnest_natural_direction(x);
        block.thin_axis.push_back(std::uint8_t(thin));
        double layer_volume[2] = {};
        for (int g = 0; g < 8; ++g) {
          double J[9];
          element::hex8_gauss_jacobian(x, g, J);
          layer_volume[element::ans_layer(g, thin)] += element::det3(J);
        }
        block.layer_volume0.insert(block.layer_volume0.end(), layer_volume, layer_volume + 2);
      }
      if (mat.kind == MaterialKind::OrthotropicElastic && block.elform == 1) {
        double J[9], Jinv[9];
        element::hex8_centroid_jacobian(x, J);
        element::inverse3(J, Jinv);
        block.reference_jacobian_inverse.insert(block.reference_jacobian_inverse.end(), Jinv, Jinv + 9);
      }
      for (int k = 0; k < 8; ++k) model.mass[block.conn[8 * e + k]] += mat.density * volume / 8.0;
      if (mat.has_axes()) {
        const double beta = part_spec.beta + (mat.axes.AOPT == 3 ? mat.axes.BETA : 0.0);
        const Mat3 axes = material::material_axes(mat.axes, beta, x);
        const auto key = std::make_pair(block.material, axes);
        auto it = orientation_index.find(key);
        if (it == orientation_index.end()) {
          Orientation o;
          o.axes = axes;
          o.c_global = material::rotate_to_global(mat.c_material, axes);
          for (double v : o.c_global)
            if (!std::isfinite(v))
              throw InputError(at(scene.materials[block.material].where)
                               << "material axes are undefined for element " << block.element_id[e]
                               << " (AOPT " << mat.axes.AOPT << ": vector parallel to the normal?)");
          it = orientation_index.emplace(key, int(model.orientations.size())).first;
          model.orientations.push_back(o);
        }
        block.orientation[e] = it->second;
        const double reference = mat.kind == MaterialKind::CompositeDamage ? mat.composite.erosion_reference_length : 0;
        if (reference > 0) {
          block.erosion_scale.resize(block.size(), 1.0);
          block.erosion_scale[e] = erosion_strain_scale(reference, ply_plane_length(x, volume, axes));
        }
      }
    }
    if (mat.kind == MaterialKind::CompositeDamage && mat.composite.erosion_nonlocal && !block.erosion_scale.empty()) {
      // The elements the scaling applies to also erode where their neighbourhood's mean strain
      // reaches the card's limits.
      std::vector<bool> needs(block.size());
      for (std::size_t e = 0; e < block.size(); ++e) needs[e] = block.erosion_scale[e] > 1;
      block.erosion_neighbours =
          build_erosion_neighbours(block, model.X, mat.composite.erosion_reference_length, needs);
    }
  }

  // Node sets.
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < num_nodes; ++i)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], model.X[3 * i + d]);
      hi[d] = std::max(hi[d], model.X[3 * i + d]);
    }
  const double size = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  for (const auto& spec : scene.node_sets) {
    const double tol = spec.tolerance > 0 ? spec.tolerance : 1e-6 * size;
    NodeSet set{spec.name, {}};
    if (spec.kind == config::NodeSetSpec::Kind::Generated) {
      const auto it = std::find_if(mesh.node_sets.begin(), mesh.node_sets.end(),
                                   [&](const mesh::NodeList& l) { return l.name == spec.name; });
      if (it == mesh.node_sets.end())
        throw InputError(at(spec.where) << "node set '" << spec.name << "' should come from the mesh generator, "
                                        << "which did not make it");
      set.nodes = it->nodes;
    } else {
      set.nodes = select_nodes(spec, model, tol);
    }
    if (set.nodes.empty())
      throw InputError(at(spec.where) << "node set '" << spec.name << "' selects no node; the model spans x ["
                                      << lo[0] << ", " << hi[0] << "] y [" << lo[1] << ", " << hi[1] << "] z ["
                                      << lo[2] << ", " << hi[2] << "] m");
    model.node_sets.push_back(std::move(set));
  }

  // Boundary conditions: one entry per constrained dof; the same dof constrained twice differently
  // is an error rather than a silent override.
  std::vector<int> dof_curve(3 * num_nodes, -2);  // -2 free, -1 fixed, >= 0 curve
  for (const auto& bc : scene.boundary_conditions) {
    const int set = index_by_name(model.node_sets, bc.node_set);
    if (set < 0) throw InputError(at(bc.where) << "unknown node set '" << bc.node_set << "'");
    if (std::find(model.constrained_sets.begin(), model.constrained_sets.end(), set) == model.constrained_sets.end())
      model.constrained_sets.push_back(set);
    int curve = -1;
    if (bc.kind == config::BoundaryConditionSpec::Kind::Velocity) {
      curve = int(model.curves.size());
      model.curves.push_back(Curve{bc.curve.t, bc.curve.y});
    }
    for (Index node : model.node_sets[set].nodes)
      for (int d = 0; d < 3; ++d) {
        if (!bc.dofs[d]) continue;
        int& slot = dof_curve[3 * std::size_t(node) + d];
        if (slot != -2 && !(slot == -1 && curve == -1))
          throw InputError(at(bc.where) << "node " << node + 1 << " dof " << "xyz"[d]
                                        << " already has another boundary condition; allowed: one condition per dof");
        slot = curve;
      }
  }
  for (std::size_t i = 0; i < dof_curve.size(); ++i)
    if (dof_curve[i] != -2) model.constraints.push_back({Index(i), dof_curve[i]});

  // Initial velocities.
  model.v0.assign(3 * num_nodes, 0.0);
  for (const auto& iv : scene.initial_velocities) {
    std::vector<Index> nodes;
    if (!iv.part.empty()) {
      const int p = index_by_name(model.parts, iv.part);
      if (p < 0) throw InputError(at(iv.where) << "unknown part '" << iv.part << "'");
      config::NodeSetSpec spec;
      spec.kind = config::NodeSetSpec::Kind::Part;
      spec.part = iv.part;
      nodes = select_nodes(spec, model, 0);
    } else {
      const int s = index_by_name(model.node_sets, iv.node_set);
      if (s < 0) throw InputError(at(iv.where) << "unknown node set '" << iv.node_set << "'");
      nodes = model.node_sets[s].nodes;
    }
    for (Index node : nodes)
      for (int d = 0; d < 3; ++d) model.v0[3 * std::size_t(node) + d] = iv.velocity[d];
  }

  model.element_ply = mesh.element_ply;
  for (const auto& itf : mesh.interfaces) {
    model.interfaces.push_back(make_interface(itf, model.X));
    model.interfaces.back().tiebreak = law_of(itf);
    if (scene.laminate) {
      const auto& plies = scene.laminate->plies;
      Interface& added = model.interfaces.back();
      added.lower_angle = plies[std::size_t(itf.lower_ply)].angle;
      added.upper_angle = plies[std::size_t(itf.upper_ply)].angle;
      for (std::size_t p = std::size_t(itf.upper_ply); p < plies.size(); ++p) added.depth += plies[p].thickness;
      const auto modulus_c = [&](int ply) {
        return model.materials[std::size_t(index_by_name(model.materials, plies[std::size_t(ply)].material))].modulus_c;
      };
      added.transverse_modulus = std::min(modulus_c(itf.lower_ply), modulus_c(itf.upper_ply));
    }
  }
  // *MAT_138 elements with RO (mass per unit mid-surface area, the card's ROFLG = 1) add RO A to the
  // interface: half to each face, each node its tributary share A_p of the mid-surface.
  for (const auto& itf : model.interfaces) {
    if (!itf.tiebreak || itf.tiebreak->model != config::InterfaceLawSpec::Model::Cohesive) continue;
    const double ro = itf.tiebreak->mat138.RO;
    for (std::size_t p = 0; p < itf.num_pairs() && ro > 0; ++p) {
      model.mass[std::size_t(itf.lower_nodes[p])] += 0.5 * ro * itf.area[p];
      model.mass[std::size_t(itf.upper_nodes[p])] += 0.5 * ro * itf.area[p];
    }
  }
  if (mesh.impactor) model.impactor = make_impactor(*mesh.impactor);
  add_rigid_bodies_and_contacts(scene, model);
  model.schedule = make_schedule(model.blocks, num_nodes);
  return model;
}

}  // namespace plyimpact::model
