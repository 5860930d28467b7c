// Rigid bodies, rigid walls, contacts and gravity: the part of build_model that turns the scene's
// rigid_bodies / rigid_walls / contacts sections and MAT_020 parts into model data. Mass
// properties of an element-based rigid body follow docs/theory.md section 9: M = sum m_k,
// x_cm = sum m_k x_k / M, I = sum m_k (|r_k|^2 1 - r_k (x) r_k) over its lumped nodal masses.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "model/model.hpp"

namespace plyimpact::model {

namespace {

int part_index(const Model& model, const std::string& name) {
  for (int i = 0; i < int(model.parts.size()); ++i)
    if (model.parts[i].name == name) return i;
  return -1;
}

std::vector<Index> nodes_of_block(const ElementBlock& b) {
  std::vector<Index> nodes(b.conn.begin(), b.conn.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// Initial rigid motion from the nodal initial velocities: v_cm = sum m v / M, H = sum m r x v,
// omega = I^-1 H (pseudo-inverse for a degenerate inertia).
void initial_motion(const Model& model, RigidBody& body) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), h = Eigen::Vector3d::Zero();
  double m_sum = 0;
  for (Index n : body.nodes) {
    const double m = model.mass[n];
    const Eigen::Vector3d v(&model.v0[3 * std::size_t(n)]);
    const Eigen::Vector3d r = Eigen::Vector3d(&model.X[3 * std::size_t(n)]) - Eigen::Vector3d(body.centre.data());
    p += m * v;
    h += m * r.cross(v);
    m_sum += m;
  }
  const Eigen::Vector3d v = m_sum > 0 ? Eigen::Vector3d(p / m_sum) : Eigen::Vector3d::Zero();
  const Eigen::Matrix3d inertia = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(body.inertia.data());
  // h about the centre of mass: sum m r x (v - v_cm) = sum m r x v (sum m r = 0).
  // A degenerate inertia (all nodes on a line) leaves the rotation about that line undefined: zero.
  const double scale = inertia.trace();
  const Eigen::Vector3d w = std::abs(inertia.determinant()) > 1e-12 * scale * scale * scale
                                ? Eigen::Vector3d(inertia.inverse() * h) : Eigen::Vector3d::Zero();
  for (int d = 0; d < 3; ++d) {
    body.velocity[d] = v[d];
    body.angular_velocity[d] = w[d];
  }
}

void apply_card_constraints(const config::MatRigid& card, RigidBody& body) {
  if (card.CMO != 1) return;
  // LS-DYNA codes: 1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all.
  static const std::array<std::array<bool, 3>, 8> codes = {{{false, false, false}, {true, false, false},
                                                            {false, true, false}, {false, false, true},
                                                            {true, true, false}, {false, true, true},
                                                            {true, false, true}, {true, true, true}}};
  for (int d = 0; d < 3; ++d) {
    body.fixed[d] = body.fixed[d] || codes[card.CON1][d];
    body.fixed[3 + d] = body.fixed[3 + d] || codes[card.CON2][d];
  }
}

bool impactor_used(const config::Scene& scene) {
  if (!scene.impactor || !scene.impactor->rigid) return false;
  for (const auto& c : scene.contacts)
    for (const auto* side : {&c.surface_a, &c.surface_b})
      if (std::find(side->begin(), side->end(), "impactor") != side->end()) return true;
  for (const auto& rb : scene.rigid_bodies)
    if (rb.part == "impactor") return true;
  return false;
}

}  // namespace

void add_rigid_bodies_and_contacts(const config::Scene& scene, Model& model) {
  model.gravity = scene.gravity;
  std::vector<int> node_body(model.num_nodes(), -1);

  // Element-based rigid bodies: one per MAT_020 part.
  for (int p = 0; p < int(model.parts.size()); ++p) {
    const ElementBlock& block = model.blocks[model.parts[p].block];
    if (!block.rigid) continue;
    RigidBody body;
    body.name = model.parts[p].name;
    body.part = p;
    body.nodes = nodes_of_block(block);
    if (body.nodes.empty()) continue;
    for (Index n : body.nodes) {
      if (node_body[n] >= 0)
        throw InputError(at(scene.parts[p].where)
                         << "rigid part '" << body.name << "' shares node " << n + 1 << " with rigid part '"
                         << model.rigid_bodies[node_body[n]].name
                         << "'; found two rigid parts joined by a node; allowed: separate rigid parts (merging "
                            "rigid bodies is not supported; use one MAT_020 part)");
      node_body[n] = int(model.rigid_bodies.size());
    }
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (Index n : body.nodes) {
      body.mass += model.mass[n];
      c += model.mass[n] * Eigen::Vector3d(&model.X[3 * std::size_t(n)]);
    }
    c /= body.mass;
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (Index n : body.nodes) {
      const Eigen::Vector3d r = Eigen::Vector3d(&model.X[3 * std::size_t(n)]) - c;
      inertia += model.mass[n] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    for (int i = 0; i < 3; ++i) {
      body.centre[i] = c[i];
      for (int j = 0; j < 3; ++j) body.inertia[3 * i + j] = inertia(i, j);
    }
    apply_card_constraints(std::get<config::MatRigid>(scene.materials[model.parts[p].material].params), body);
    model.rigid_bodies.push_back(std::move(body));
  }

  // Nodal boundary conditions cannot act on slaved nodes.
  for (const auto& con : model.constraints)
    if (node_body[con.dof / 3] >= 0)
      throw InputError(msg() << scene.file << ": boundary_conditions: node " << con.dof / 3 + 1
                             << " belongs to rigid part '" << model.rigid_bodies[node_body[con.dof / 3]].name
                             << "'; found a nodal condition on a rigid body; allowed: rigid_bodies: [{part, fix: "
                                "[...], velocity: {...}}] or CMO/CON1/CON2 on the MAT_020 card");

  // The meshed rigid impactor (surface + stated mass properties), when something uses it.
  if (impactor_used(scene)) {
    const auto& imp = *model.impactor;
    const Index offset = Index(model.num_nodes());
    const std::size_t ns = imp.surface_coords.size() / 3;
    RigidBody body;
    body.name = "impactor";
    body.mass = imp.mass;
    body.centre = imp.centre_of_mass;
    body.inertia = imp.inertia;
    body.velocity = imp.velocity;
    for (std::size_t i = 0; i < ns; ++i) {
      model.X.insert(model.X.end(), &imp.surface_coords[3 * i], &imp.surface_coords[3 * i] + 3);
      model.v0.insert(model.v0.end(), imp.velocity.begin(), imp.velocity.end());
      model.mass.push_back(imp.mass / double(ns));
      body.nodes.push_back(offset + Index(i));
      node_body.push_back(int(model.rigid_bodies.size()));
    }
    for (Index q : imp.surface_quads) model.impactor_quads.push_back(offset + q);
    if (!scene.impactor->material.empty())
      for (const auto& m : model.materials)
        if (m.name == scene.impactor->material) model.impactor_bulk_modulus = m.bulk_modulus;
    model.rigid_bodies.push_back(std::move(body));
  }

  for (auto& body : model.rigid_bodies)
    if (body.part >= 0) initial_motion(model, body);

  // Extra conditions from the rigid_bodies section.
  for (const auto& spec : scene.rigid_bodies) {
    auto it = std::find_if(model.rigid_bodies.begin(), model.rigid_bodies.end(),
                           [&](const RigidBody& b) { return b.name == spec.part; });
    if (it == model.rigid_bodies.end())
      throw InputError(at(spec.where) << "part '" << spec.part << "' has no element, so no rigid body");
    int curve = -1;
    for (int d = 0; d < 6; ++d) {
      it->fixed[d] = it->fixed[d] || spec.fix[d];
      if (spec.prescribed[d]) {
        if (it->fixed[d])
          throw InputError(at(spec.where) << "dof " << d << " of rigid body '" << spec.part
                                          << "' is fixed on the MAT_020 card (CON1/CON2) and prescribed here; "
                                             "allowed: each dof fixed or prescribed");
        if (curve < 0) {
          curve = int(model.curves.size());
          model.curves.push_back(Curve{spec.curve.t, spec.curve.y});
        }
        it->curve[d] = curve;
      }
    }
  }
  // The nodes start with the rigid motion (consistent with the constraints at t = 0).
  for (auto& body : model.rigid_bodies) {
    for (int d = 0; d < 3; ++d) {
      if (body.fixed[d]) body.velocity[d] = 0;
      if (body.curve[d] >= 0) body.velocity[d] = model.curves[body.curve[d]](0.0);
      if (body.fixed[3 + d]) body.angular_velocity[d] = 0;
      if (body.curve[3 + d] >= 0) body.angular_velocity[d] = model.curves[body.curve[3 + d]](0.0);
    }
    const Eigen::Vector3d v(body.velocity.data()), w(body.angular_velocity.data()), c(body.centre.data());
    for (Index n : body.nodes) {
      const Eigen::Vector3d vn = v + w.cross(Eigen::Vector3d(&model.X[3 * std::size_t(n)]) - c);
      for (int d = 0; d < 3; ++d) model.v0[3 * std::size_t(n) + d] = vn[d];
    }
  }

  // Rigid walls.
  for (const auto& spec : scene.rigid_walls) {
    RigidWall w;
    w.name = spec.name;
    w.point = spec.point;
    w.normal = spec.normal;
    w.velocity = spec.velocity;
    w.friction = spec.friction;
    w.length_u = spec.length_u;
    w.length_v = spec.length_v;
    w.u = spec.u;
    const Eigen::Vector3d v = Eigen::Vector3d(spec.normal.data()).cross(Eigen::Vector3d(spec.u.data()));
    w.v = {v[0], v[1], v[2]};
    std::vector<char> mark(model.num_nodes(), 0);
    if (spec.parts.empty()) {
      for (const auto& b : model.blocks)
        if (!b.rigid)
          for (Index n : b.conn) mark[n] = 1;
    } else {
      for (const auto& name : spec.parts)
        for (Index n : model.blocks[model.parts[part_index(model, name)].block].conn) mark[n] = 1;
    }
    for (std::size_t n = 0; n < mark.size(); ++n)
      if (mark[n] && node_body[n] < 0 && model.mass[n] > 0) w.nodes.push_back(Index(n));
    model.rigid_walls.push_back(std::move(w));
  }

  // Contacts.
  for (const auto& spec : scene.contacts) {
    Contact c;
    c.spec = spec;
    auto side = [&](const std::vector<std::string>& names) {
      ContactSide s;
      for (const auto& name : names) {
        s.label += (s.label.empty() ? "" : "+") + name;
        const int p = part_index(model, name);
        if (p < 0) {
          s.impactor = true;  // the loader allows only parts and the rigid impactor
          continue;
        }
        s.blocks.push_back(model.parts[p].block);
      }
      return s;
    };
    c.a = side(spec.surface_a);
    if (spec.type == config::ContactSpec::Type::SurfaceToSurface) c.b = side(spec.surface_b);
    (spec.tiebreak ? model.tiebreak_contacts : model.contacts).push_back(std::move(c));
  }
}

}  // namespace plyimpact::model
