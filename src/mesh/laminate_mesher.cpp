#include "mesh/laminate_mesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>

#include "mesh/axis_grid.hpp"
#include "mesh/gmsh_session.hpp"

namespace plyimpact::mesh {
namespace {

struct Grid {
  std::vector<Band> bx, by;
  std::vector<double> x, y, z;   // exact node coordinates along each axis
  std::vector<int> ply_layer0;   // first z level of each ply; the ply's top is ply_layer0[p + 1]
};

}  // namespace

AxisSpec laminate_axis(const config::LaminateSpec& lam, int axis) {
  const bool x = axis == 0;
  const double side = x ? lam.length : lam.width, impact = x ? lam.impact_x : lam.impact_y;
  AxisSpec a;
  a.hi = lam.symmetry[x ? 0 : 1] ? side / 2 : side;
  for (const auto& s : lam.supports)
    if (s.kind == config::SupportSpec::Kind::Window) {
      const double w = x ? s.window_x : s.window_y;
      a.breaks.insert(a.breaks.end(), {impact - w / 2, impact + w / 2});
    }
  if (lam.zone_element_size > 0) {
    const double zone = x ? lam.zone_x : lam.zone_y;
    a.zone_lo = impact - zone / 2;
    a.zone_hi = impact + zone / 2;
  }
  a.size = lam.element_size;
  a.zone_size = lam.zone_element_size;
  a.level = lam.refinement_level;
  return a;
}

namespace {

Grid make_grid(const config::LaminateSpec& lam) {
  Grid g;
  g.bx = axis_bands(laminate_axis(lam, 0));
  g.by = axis_bands(laminate_axis(lam, 1));
  g.x = band_nodes(g.bx);
  g.y = band_nodes(g.by);
  double z0 = 0;
  g.z.push_back(0);
  for (const auto& ply : lam.plies) {
    g.ply_layer0.push_back(int(g.z.size()) - 1);
    const int n = lam.elements_per_ply;
    for (int k = 1; k < n; ++k) g.z.push_back(z0 + ply.thickness * k / n);
    z0 += ply.thickness;
    g.z.push_back(z0);
  }
  g.ply_layer0.push_back(int(g.z.size()) - 1);
  return g;
}

// Builds the gmsh geometry and mesh. The whole stack is one layered extrusion of the base patches
// (a layer per element through each ply): extruding ply by ply costs gmsh's built-in kernel time
// growing faster than quadratically with the number of plies (3.9 s for 16 plies of 25 patches,
// against 0.03 s for the single extrusion), and the plies are told apart by z afterwards anyway.
void build_gmsh(const Grid& g) {
  namespace geo = gmsh::model::geo;
  const std::size_t nx = g.bx.size(), ny = g.by.size();
  std::vector<double> xb{g.bx[0].x0}, yb{g.by[0].x0};
  for (const auto& b : g.bx) xb.push_back(b.x1);
  for (const auto& b : g.by) yb.push_back(b.x1);
  auto pt = [&](std::size_t i, std::size_t j) { return int(j * (nx + 1) + i + 1); };
  for (std::size_t j = 0; j <= ny; ++j)
    for (std::size_t i = 0; i <= nx; ++i) geo::addPoint(xb[i], yb[j], 0, 0, pt(i, j));
  // Lines along x (i, j) then along y (i, j), all oriented towards +x / +y so that a band's
  // progression ratio applies as is.
  auto hline = [&](std::size_t i, std::size_t j) { return int(j * nx + i + 1); };
  auto vline = [&](std::size_t i, std::size_t j) { return int((ny + 1) * nx + j * (nx + 1) + i + 1); };
  for (std::size_t j = 0; j <= ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      geo::addLine(pt(i, j), pt(i + 1, j), hline(i, j));
      geo::mesh::setTransfiniteCurve(hline(i, j), g.bx[i].elements + 1, "Progression", g.bx[i].ratio);
    }
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i <= nx; ++i) {
      geo::addLine(pt(i, j), pt(i, j + 1), vline(i, j));
      geo::mesh::setTransfiniteCurve(vline(i, j), g.by[j].elements + 1, "Progression", g.by[j].ratio);
    }
  gmsh::vectorpair base;
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      // Counter-clockwise seen from +z: normal +z, so the extruded hexahedra are positive.
      const int loop = geo::addCurveLoop({hline(i, j), vline(i + 1, j), -hline(i, j + 1), -vline(i, j)});
      const int s = geo::addPlaneSurface({loop});
      geo::mesh::setTransfiniteSurface(s);
      geo::mesh::setRecombine(2, s);
      base.emplace_back(2, s);
    }
  // One layer per z interval of the grid; heights are cumulative fractions of the total thickness
  // (gmsh's z values are snapped back onto g.z when read).
  const double total = g.z.back();
  std::vector<int> layers(g.z.size() - 1, 1);
  std::vector<double> heights;
  for (std::size_t k = 1; k < g.z.size(); ++k) heights.push_back(k + 1 == g.z.size() ? 1.0 : g.z[k] / total);
  gmsh::vectorpair out;
  geo::extrude(base, 0, 0, total, out, layers, heights, true);
  geo::synchronize();
  gmsh::model::mesh::generate(3);
}

// Index of the value of `axis` nearest to v; throws if v is not within `tol` of it.
int snap(const std::vector<double>& axis, double v, double tol, const char* name) {
  const auto it = std::lower_bound(axis.begin(), axis.end(), v);
  std::size_t i = std::size_t(it - axis.begin());
  if (i == axis.size() || (i > 0 && v - axis[i - 1] < *it - v)) --i;
  if (!(std::abs(axis[i] - v) <= tol))
    throw InputError(msg() << "meshing failed: gmsh placed a node at " << name << " = " << v
                           << " m, off the structured grid (nearest line " << axis[i] << " m)");
  return int(i);
}

double min_spacing(const std::vector<double>& a) {
  double h = 1e300;
  for (std::size_t i = 1; i < a.size(); ++i) h = std::min(h, a[i] - a[i - 1]);
  return h;
}

// Whether the element (its corner nodes c) has its centre in the impact zone, if there is one.
bool in_impact_zone(const config::LaminateSpec& lam, const std::vector<double>& coords, const Index* c) {
  if (lam.impact_zone_section.empty()) return false;
  double centre[2] = {0, 0};
  for (int k = 0; k < 8; ++k)
    for (int d = 0; d < 2; ++d) centre[d] += coords[3 * std::size_t(c[k]) + d] / 8;
  // Centres lie half an element from any grid line, so a zone edge on a grid line decides clearly.
  return std::abs(centre[0] - lam.impact_x) < lam.impact_zone_x / 2 &&
         std::abs(centre[1] - lam.impact_y) < lam.impact_zone_y / 2;
}

// A zone narrower than the elements at the impact point holds no element centre: refused, since its
// parts would be empty and the scene would silently keep the outer section everywhere.
void require_impact_zone_elements(const config::LaminateSpec& lam, const Mesh& m) {
  if (lam.impact_zone_section.empty()) return;
  for (std::size_t e = 0; e < m.num_elements(); ++e)
    if (m.element_part[e] == lam.plies[std::size_t(m.element_ply[e])].zone_part) return;
  throw InputError(config::at(lam.impact_zone_where) << "no element centre lies in the " << lam.impact_zone_x * 1e3
                         << " x " << lam.impact_zone_y * 1e3
                         << " mm impact zone; allowed: a zone at least one element wide around the impact point");
}

}  // namespace

Mesh mesh_laminate(const config::Scene& scene) {
  const config::LaminateSpec& lam = *scene.laminate;
  const Grid g = make_grid(lam);
  GmshModel model("laminate");
  gmsh_call("meshing the laminate", [&] { build_gmsh(g); });

  Mesh m;
  std::vector<int> level;  // (num_nodes, 3) grid indices of each node
  gmsh_call("reading the laminate mesh", [&] {
    std::vector<std::size_t> tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
    std::size_t max_tag = 0;
    for (auto t : tags) max_tag = std::max(max_tag, t);
    std::vector<Index> node_of_tag(max_tag + 1, -1);
    m.coords.resize(3 * tags.size());
    level.resize(3 * tags.size());
    const double tx = 1e-3 * min_spacing(g.x), ty = 1e-3 * min_spacing(g.y), tz = 1e-3 * min_spacing(g.z);
    for (std::size_t a = 0; a < tags.size(); ++a) {
      node_of_tag[tags[a]] = Index(a);
      const int i = snap(g.x, xyz[3 * a], tx, "x"), j = snap(g.y, xyz[3 * a + 1], ty, "y"),
                k = snap(g.z, xyz[3 * a + 2], tz, "z");
      m.coords[3 * a] = g.x[i];
      m.coords[3 * a + 1] = g.y[j];
      m.coords[3 * a + 2] = g.z[k];
      level[3 * a] = i;
      level[3 * a + 1] = j;
      level[3 * a + 2] = k;
    }
    // Ply of each z interval (element layer).
    std::vector<int> ply_of_layer(g.z.size() - 1);
    for (std::size_t p = 0; p + 1 < g.ply_layer0.size(); ++p)
      for (int k = g.ply_layer0[p]; k < g.ply_layer0[p + 1]; ++k) ply_of_layer[std::size_t(k)] = int(p);
    // Elements are bucketed by ply so that they stay numbered ply by ply, bottom ply first.
    std::vector<std::vector<Index>> ply_hex(lam.plies.size());
    std::vector<std::size_t> etags, enodes;
    gmsh::model::mesh::getElementsByType(5, etags, enodes, -1);  // 5 = 8-node hexahedron
    for (std::size_t e = 0; e < etags.size(); ++e) {
      Index c[8];
      int lowest = int(g.z.size());
      for (int k = 0; k < 8; ++k) {
        c[k] = node_of_tag[enodes[8 * e + k]];
        lowest = std::min(lowest, level[3 * std::size_t(c[k]) + 2]);
      }
      // gmsh keeps the bottom quad's order; the elements are boxes, so the sign of the
      // triple product at corner 0 decides: (x1 - x0) x (x3 - x0) . (x4 - x0) > 0, else mirror.
      double edge[3][3];
      for (int d = 0; d < 3; ++d) {
        const double x0 = m.coords[3 * std::size_t(c[0]) + d];
        edge[0][d] = m.coords[3 * std::size_t(c[1]) + d] - x0;
        edge[1][d] = m.coords[3 * std::size_t(c[3]) + d] - x0;
        edge[2][d] = m.coords[3 * std::size_t(c[4]) + d] - x0;
      }
      const auto& d = edge;
      const double triple = (d[0][1] * d[1][2] - d[0][2] * d[1][1]) * d[2][0] +
                            (d[0][2] * d[1][0] - d[0][0] * d[1][2]) * d[2][1] +
                            (d[0][0] * d[1][1] - d[0][1] * d[1][0]) * d[2][2];
      if (!(triple > 0)) {
        std::swap(c[1], c[3]);
        std::swap(c[5], c[7]);
      }
      auto& bucket = ply_hex[std::size_t(ply_of_layer[std::size_t(lowest)])];
      bucket.insert(bucket.end(), c, c + 8);
    }
    for (std::size_t p = 0; p < ply_hex.size(); ++p) {
      m.hex.insert(m.hex.end(), ply_hex[p].begin(), ply_hex[p].end());
      for (std::size_t e = 0; e < ply_hex[p].size(); e += 8)
        m.element_part.push_back(in_impact_zone(lam, m.coords, &ply_hex[p][e]) ? lam.plies[p].zone_part : lam.plies[p].part);
      m.element_ply.insert(m.element_ply.end(), ply_hex[p].size() / 8, int(p));
    }
  });
  require_impact_zone_elements(lam, m);
  const std::size_t expected = (g.x.size() - 1) * (g.y.size() - 1) * (g.z.size() - 1);
  if (m.num_elements() != expected || m.num_nodes() != g.x.size() * g.y.size() * g.z.size())
    throw InputError(msg() << "meshing failed: gmsh made " << m.num_elements() << " elements and " << m.num_nodes()
                           << " nodes; the structured grid has " << expected << " and "
                           << g.x.size() * g.y.size() * g.z.size());

  // Delaminating interfaces: the upper ply gets its own copy of every node on the interface.
  for (std::size_t i = 0; i + 1 < lam.plies.size(); ++i) {
    if (!lam.delaminating[i]) continue;
    const int iz = g.ply_layer0[i + 1];
    Interface itf;
    itf.id = int(i) + 1;
    itf.lower_ply = int(i);
    itf.upper_ply = int(i) + 1;
    itf.z = g.z[std::size_t(iz)];
    std::vector<Index> partner(m.num_nodes(), -1);
    for (std::size_t e = 0; e < m.num_elements(); ++e) {
      if (m.element_ply[e] != int(i) + 1) continue;
      for (int k = 0; k < 4; ++k) {
        Index& node = m.hex[8 * e + k];
        if (level[3 * std::size_t(node) + 2] != iz) break;  // not the ply's bottom layer
        if (partner[node] < 0) {
          partner[node] = Index(m.num_nodes());
          for (int d = 0; d < 3; ++d) m.coords.push_back(m.coords[3 * std::size_t(node) + d]);
          for (int d = 0; d < 3; ++d) level.push_back(level[3 * std::size_t(node) + d]);
          itf.lower_nodes.push_back(node);
          itf.upper_nodes.push_back(partner[node]);
        }
        node = partner[node];
      }
    }
    for (std::size_t e = 0; e < m.num_elements(); ++e) {
      if (m.element_ply[e] != int(i)) continue;
      const Index* c = &m.hex[8 * e];
      if (level[3 * c[4] + 2] != iz) continue;  // not the ply's top layer
      const Index lower[4] = {c[4], c[5], c[6], c[7]};
      const Index upper[4] = {partner[c[4]], partner[c[7]], partner[c[6]], partner[c[5]]};
      itf.lower_segments.insert(itf.lower_segments.end(), lower, lower + 4);
      itf.upper_segments.insert(itf.upper_segments.end(), upper, upper + 4);
    }
    m.interfaces.push_back(std::move(itf));
  }

  // Generated node sets on exact grid lines.
  const double xhi = g.x.back(), yhi = g.y.back();
  const double tol = 1e-9 * std::max(xhi, yhi);
  auto select = [&](const std::string& name, auto&& pred) {
    NodeList set{name, {}};
    for (std::size_t a = 0; a < m.num_nodes(); ++a)
      if (pred(&m.coords[3 * a], level[3 * a + 2])) set.nodes.push_back(Index(a));
    m.node_sets.push_back(std::move(set));
  };
  auto near = [&](double a, double b) { return std::abs(a - b) <= tol; };
  for (const auto& s : lam.supports) {
    if (s.kind == config::SupportSpec::Kind::Window) {
      const double x0 = lam.impact_x - s.window_x / 2, x1 = lam.impact_x + s.window_x / 2;
      const double y0 = lam.impact_y - s.window_y / 2, y1 = lam.impact_y + s.window_y / 2;
      select(s.name, [&](const double* p, int iz) {
        const bool in_x = p[0] >= x0 - tol && p[0] <= x1 + tol, in_y = p[1] >= y0 - tol && p[1] <= y1 + tol;
        return iz == 0 && ((in_y && (near(p[0], x0) || near(p[0], x1))) || (in_x && (near(p[1], y0) || near(p[1], y1))));
      });
    } else {
      select(s.name, [&](const double* p, int) {
        return (s.edges[0] && near(p[0], 0)) || (s.edges[1] && near(p[0], xhi)) || (s.edges[2] && near(p[1], 0)) ||
               (s.edges[3] && near(p[1], yhi));
      });
    }
  }
  if (lam.symmetry[0]) select("symmetry_x", [&](const double* p, int) { return near(p[0], xhi); });
  if (lam.symmetry[1]) select("symmetry_y", [&](const double* p, int) { return near(p[1], yhi); });
  return m;
}

}  // namespace plyimpact::mesh
