#include "interface/interface_output.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "cohesive/tiebreak_pairs.hpp"
#include "contact/geometry.hpp"

namespace plyimpact::interface {

std::string InterfaceLayout::label() const {
  if (!contact.empty()) return "tiebreak contact " + contact;
  const auto degrees = [](double rad) { return long(std::lround(rad * 180 / std::numbers::pi)); };
  std::ostringstream s;
  s << "interface_" << id << " (plies " << lower_ply + 1 << "/" << upper_ply + 1 << ", " << degrees(lower_angle)
    << "/" << degrees(upper_angle) << ")";
  return s.str();
}

void InterfaceLayout::add_vertex(Index point, std::initializer_list<Index> nodes, std::initializer_list<double> weights) {
  vertex_point.push_back(point);
  vertex_node.insert(vertex_node.end(), nodes);
  vertex_weight.insert(vertex_weight.end(), weights);
  vertex_offset.push_back(Index(vertex_node.size()));
}

void InterfaceLayout::vertex_positions(const double* x, double* out) const {
  for (std::size_t v = 0; v < num_vertices(); ++v) {
    double p[3] = {0, 0, 0};
    for (Index k = vertex_offset[v]; k < vertex_offset[v + 1]; ++k)
      for (int i = 0; i < 3; ++i) p[i] += vertex_weight[std::size_t(k)] * x[3 * std::size_t(vertex_node[std::size_t(k)]) + i];
    for (int i = 0; i < 3; ++i) out[3 * v + i] = p[i];
  }
}

namespace {

void set_laminate_place(InterfaceLayout& l, const model::Interface& itf) {
  l.id = itf.id;
  l.lower_ply = itf.lower_ply;
  l.upper_ply = itf.upper_ply;
  l.lower_angle = itf.lower_angle;
  l.upper_angle = itf.upper_angle;
  l.depth = itf.depth;
}

}  // namespace

InterfaceLayout pair_layout(const model::Model& model, const model::Interface& itf) {
  InterfaceLayout l;
  set_laminate_place(l, itf);
  l.area = itf.area;
  for (std::size_t p = 0; p < itf.num_pairs(); ++p) {
    const Index lo = itf.lower_nodes[p], up = itf.upper_nodes[p];
    l.add_vertex(Index(p), {lo, up}, {0.5, 0.5});
    for (int i = 0; i < 3; ++i)
      l.reference.push_back(0.5 * (model.X[3 * std::size_t(lo) + i] + model.X[3 * std::size_t(up) + i]));
  }
  l.quads = cohesive::pair_faces_from_segments(itf.lower_nodes, itf.lower_segments);
  return l;
}

InterfaceLayout cohesive_layout(const model::Model& model, const model::Interface& itf,
                                const cohesive::CohesiveElements& elements) {
  InterfaceLayout l;
  set_laminate_place(l, itf);
  const std::size_t np = elements.num_points();
  l.area.resize(np);
  for (std::size_t p = 0; p < np; ++p) l.area[p] = elements.point_area(p);
  l.reference.resize(3 * np);
  elements.point_positions(model.X.data(), l.reference.data());
  const auto& nodes = elements.nodes();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const Index* n = &nodes[8 * e];  // lower 0-3 counter-clockwise, upper 4-7 over them
    for (int g = 0; g < cohesive::CohesiveElements::kPoints; ++g) {
      const Index point = Index(cohesive::CohesiveElements::kPoints * e + std::size_t(g));
      const int a = g, b = (g + 1) % 4, c = (g + 3) % 4;  // the corner and its two neighbours
      const Index first = Index(l.num_vertices());
      l.add_vertex(point, {n[a], n[4 + a]}, {0.5, 0.5});
      l.add_vertex(point, {n[a], n[4 + a], n[b], n[4 + b]}, {0.25, 0.25, 0.25, 0.25});
      l.add_vertex(point, {n[0], n[1], n[2], n[3], n[4], n[5], n[6], n[7]},
                   {0.125, 0.125, 0.125, 0.125, 0.125, 0.125, 0.125, 0.125});
      l.add_vertex(point, {n[c], n[4 + c], n[a], n[4 + a]}, {0.25, 0.25, 0.25, 0.25});
      for (Index k = 0; k < 4; ++k) l.quads.push_back(first + k);
    }
  }
  return l;
}

InterfaceLayout tie_layout(const model::Model& model, int id, const std::string& contact,
                           const cohesive::SegmentTiebreaks& ties, const std::vector<Index>& slave_faces,
                           const std::vector<int>& blocks) {
  InterfaceLayout l;
  l.id = id;
  l.contact = contact;
  const std::size_t n = ties.size();
  Index max_node = 0;
  for (Index node : slave_faces) max_node = std::max(max_node, node);
  std::vector<Index> tie_of(std::size_t(max_node) + 1, -1);
  double z_mean = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const cohesive::SegmentTie& t = ties.tie(k);
    double N[4];
    contact::quad_shape(t.xi, t.eta, N);
    l.area.push_back(t.area);
    l.add_vertex(Index(k), {t.slave, t.master[0], t.master[1], t.master[2], t.master[3]},
                 {0.5, 0.5 * N[0], 0.5 * N[1], 0.5 * N[2], 0.5 * N[3]});
    if (std::size_t(t.slave) < tie_of.size()) tie_of[std::size_t(t.slave)] = Index(k);
  }
  l.reference.resize(3 * n);
  l.vertex_positions(model.X.data(), l.reference.data());  // one vertex per tie, in tie order
  for (std::size_t k = 0; k < n; ++k) z_mean += l.reference[3 * k + 2] / double(n);
  for (std::size_t f = 0; f + 3 < slave_faces.size(); f += 4) {
    Index q[4];
    bool tied = true;
    for (int a = 0; a < 4; ++a) {
      q[a] = tie_of[std::size_t(slave_faces[f + std::size_t(a)])];
      tied = tied && q[a] >= 0;
    }
    if (tied) l.quads.insert(l.quads.end(), q, q + 4);
  }
  double top = -std::numeric_limits<double>::infinity();
  for (int b : blocks)
    for (Index node : model.blocks[std::size_t(b)].conn) top = std::max(top, model.X[3 * std::size_t(node) + 2]);
  l.depth = n ? top - z_mean : 0.0;
  return l;
}

}  // namespace plyimpact::interface
