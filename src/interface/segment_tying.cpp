#include "interface/segment_tying.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "contact/bucket_grid.hpp"
#include "contact/geometry.hpp"

namespace plyimpact::interface {
namespace {

// A projection this close outside [-1, 1] still lies within the segment (round-off of the Newton
// solution at a shared edge or corner); the tie then uses the clamped point.
constexpr double kInsideMargin = 1e-6;
constexpr double kOpposedCosine = -0.5;

void corners(const std::vector<Index>& faces, std::size_t f, const double* x, double xq[12]) {
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) xq[3 * a + i] = x[3 * std::size_t(faces[4 * f + a]) + i];
}

// Unit normal t_xi x t_eta at the centre of a quad.
void centre_normal(const double xq[12], double n[3]) {
  double g[16];
  contact::bilinear_coefficients(xq, xq + 3, xq + 6, xq + 9, g);
  contact::cross3(g + 4, g + 8, n);
  const double len = std::sqrt(contact::dot3(n, n));
  for (int i = 0; i < 3; ++i) n[i] = len > 0 ? n[i] / len : 0.0;
}

}  // namespace

TyingResult tie_slave_nodes(const TyingSurfaces& s, const double* x) {
  const std::size_t nsf = s.slave_faces.size() / 4, nmf = s.master_faces.size() / 4;
  TyingResult out;

  // Slave nodes (sorted, unique) and the faces around each (CSR), with the faces' normals.
  std::vector<Index> nodes(s.slave_faces.begin(), s.slave_faces.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto local = [&](Index node) { return std::size_t(std::lower_bound(nodes.begin(), nodes.end(), node) - nodes.begin()); };
  std::vector<std::size_t> offset(nodes.size() + 1, 0);
  for (Index node : s.slave_faces) ++offset[local(node) + 1];
  for (std::size_t k = 0; k < nodes.size(); ++k) offset[k + 1] += offset[k];
  std::vector<std::size_t> node_face(offset.back()), fill(offset.begin(), offset.end() - 1);
  std::vector<double> slave_normal(3 * nsf);
  double t_slave_max = 0;
  for (std::size_t f = 0; f < nsf; ++f) {
    double xq[12];
    corners(s.slave_faces, f, x, xq);
    centre_normal(xq, &slave_normal[3 * f]);
    for (int a = 0; a < 4; ++a) node_face[fill[local(s.slave_faces[4 * f + a])]++] = f;
    t_slave_max = std::max(t_slave_max, s.slave_thickness[f]);
  }

  // Master segments in coefficient form, in a bucket grid of their boxes grown by the tolerance.
  std::vector<double> coeff(16 * nmf), boxes(6 * nmf), master_normal(3 * nmf);
  std::vector<double> sizes;
  for (std::size_t m = 0; m < nmf; ++m) {
    double xq[12];
    corners(s.master_faces, m, x, xq);
    const double* c = xq;
    contact::bilinear_coefficients(c, c + 3, c + 6, c + 9, &coeff[16 * m]);
    centre_normal(xq, &master_normal[3 * m]);
    // Twice the tolerance: nodes that just miss a segment are found too, and reported.
    const double margin = 1.2 * (s.master_thickness[m] + t_slave_max);
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min({xq[i], xq[3 + i], xq[6 + i], xq[9 + i]});
      hi[i] = std::max({xq[i], xq[3 + i], xq[6 + i], xq[9 + i]});
      boxes[6 * m + i] = lo[i] - margin;
      boxes[6 * m + 3 + i] = hi[i] + margin;
    }
    sizes.push_back(std::sqrt(contact::quad_area(xq)));
  }
  if (nmf == 0 || nodes.empty()) return out;
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  // Buckets no smaller than the tolerance: a thick element behind small faces would otherwise list
  // every segment in a column of buckets through the tolerance band.
  double margin_max = 0;
  for (double t : s.master_thickness) margin_max = std::max(margin_max, 1.2 * (t + t_slave_max));
  contact::BucketGrid grid;
  grid.build(boxes, std::max(sizes[sizes.size() / 2], margin_max));

  struct Choice {
    Index face = -1;
    double xi = 0, eta = 0, distance = 0;
  };
  std::vector<Choice> chosen(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Index node = nodes[k];
    const double* p = &x[3 * std::size_t(node)];
    bool considered = false, projected = false;
    double nearest = std::numeric_limits<double>::infinity(), nearest_tol = 0;
    for (Index m : grid.candidates(p)) {
      const Index* q = &s.master_faces[4 * std::size_t(m)];
      if (std::find(q, q + 4, node) != q + 4) continue;  // the node is a corner: shared, already bonded
      double t_slave = std::numeric_limits<double>::infinity();
      for (std::size_t j = offset[k]; j < offset[k + 1]; ++j) {
        const std::size_t f = node_face[j];
        if (contact::dot3(&slave_normal[3 * f], &master_normal[3 * std::size_t(m)]) < kOpposedCosine)
          t_slave = std::min(t_slave, s.slave_thickness[f]);
      }
      if (!std::isfinite(t_slave)) continue;  // no slave face of this node faces the segment
      const contact::Projection r = contact::project_to_bilinear(p, &coeff[16 * std::size_t(m)], 1 + kInsideMargin);
      const double distance = std::abs(r.gap), tol = 0.6 * (s.master_thickness[std::size_t(m)] + t_slave);
      if (r.gap <= -tol) continue;  // behind the segment, beyond the tolerance: the far side of the master body
      considered = true;
      if (!r.inside) continue;
      projected = true;
      if (distance >= tol) {
        if (distance < nearest) {
          nearest = distance;
          nearest_tol = tol;
        }
        continue;
      }
      Choice& c = chosen[k];
      if (c.face < 0 || distance < c.distance || (distance == c.distance && m < c.face))
        c = {m, std::clamp(r.xi, -1.0, 1.0), std::clamp(r.eta, -1.0, 1.0), distance};
    }
    if (!considered) continue;
    ++out.slave_nodes;
    if (chosen[k].face >= 0) continue;
    if (!projected) out.untied.push_back({node, UntiedNode::Reason::OutsideProjection, 0, 0});
    else out.untied.push_back({node, UntiedNode::Reason::TooFar, nearest, nearest_tol});
  }

  // Tributary areas: a quarter of every slave face whose four corners are tied.
  std::vector<double> area(nodes.size(), 0.0);
  for (std::size_t f = 0; f < nsf; ++f) {
    const Index* q = &s.slave_faces[4 * f];
    bool all = true;
    for (int a = 0; a < 4; ++a) all = all && chosen[local(q[a])].face >= 0;
    if (!all) continue;
    double xq[12];
    corners(s.slave_faces, f, x, xq);
    const double quarter = 0.25 * contact::quad_area(xq);
    for (int a = 0; a < 4; ++a) area[local(q[a])] += quarter;
  }
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Choice& c = chosen[k];
    if (c.face < 0) continue;
    if (!(area[k] > 0)) {
      out.untied.push_back({nodes[k], UntiedNode::Reason::NoTiedFace, c.distance, 0});
      continue;
    }
    cohesive::SegmentTie t;
    t.slave = nodes[k];
    for (int a = 0; a < 4; ++a) t.master[a] = s.master_faces[4 * std::size_t(c.face) + a];
    t.xi = c.xi;
    t.eta = c.eta;
    t.area = area[k];
    out.ties.push_back(t);
    out.tie_master_face.push_back(c.face);
  }
  std::sort(out.untied.begin(), out.untied.end(), [](const UntiedNode& a, const UntiedNode& b) { return a.node < b.node; });
  return out;
}

std::string tying_summary(const TyingResult& r, const double* x) {
  std::size_t outside = 0, far = 0, no_face = 0;
  const UntiedNode* worst = nullptr;
  for (const auto& u : r.untied) {
    switch (u.reason) {
      case UntiedNode::Reason::OutsideProjection: ++outside; break;
      case UntiedNode::Reason::TooFar:
        ++far;
        if (!worst || u.distance > worst->distance) worst = &u;
        break;
      case UntiedNode::Reason::NoTiedFace: ++no_face; break;
    }
  }
  std::ostringstream s;
  s << r.ties.size() << " of " << r.slave_nodes << " slave nodes tied";
  if (r.untied.empty()) return s.str();
  s << "; untied:";
  if (outside) s << " " << outside << " outside every master segment's projection";
  if (far) {
    s << (outside ? "," : "") << " " << far << " farther than 0.6 (t_master + t_slave)";
    if (worst) {
      const double* p = &x[3 * std::size_t(worst->node)];
      s << " (node index " << worst->node << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ") m: " << worst->distance
        << " m against " << worst->tolerance << " m)";
    }
  }
  if (no_face) s << ((outside || far) ? "," : "") << " " << no_face << " tied but on no slave face whose corners are all tied (no area)";
  return s.str();
}

}  // namespace plyimpact::interface
