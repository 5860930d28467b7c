#include "output/cscan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "output/csv_plot.hpp"
#include "output/quad_surface.hpp"

namespace plyimpact::output {
namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Point2 {
  double x, y;
};

Point2 corner(const CscanLayer& l, std::int64_t q, int c) {
  const std::size_t p = std::size_t(l.quads[4 * std::size_t(q) + c]);
  return {l.xy[2 * p], l.xy[2 * p + 1]};
}

// Parametric coordinates of (x, y) in the bilinear quad p[0..3] by Newton's method from the centre
// (one step for a parallelogram). False when the iteration fails (degenerate quad).
bool parametric(const Point2 p[4], double x, double y, double& xi, double& eta) {
  const double ax = 0.25 * (p[0].x + p[1].x + p[2].x + p[3].x), ay = 0.25 * (p[0].y + p[1].y + p[2].y + p[3].y);
  const double bx = 0.25 * (-p[0].x + p[1].x + p[2].x - p[3].x), by = 0.25 * (-p[0].y + p[1].y + p[2].y - p[3].y);
  const double cx = 0.25 * (-p[0].x - p[1].x + p[2].x + p[3].x), cy = 0.25 * (-p[0].y - p[1].y + p[2].y + p[3].y);
  const double dx = 0.25 * (p[0].x - p[1].x + p[2].x - p[3].x), dy = 0.25 * (p[0].y - p[1].y + p[2].y - p[3].y);
  xi = eta = 0;
  for (int it = 0; it < 20; ++it) {
    const double rx = ax + bx * xi + cx * eta + dx * xi * eta - x, ry = ay + by * xi + cy * eta + dy * xi * eta - y;
    const double j11 = bx + dx * eta, j12 = cx + dx * xi, j21 = by + dy * eta, j22 = cy + dy * xi;
    const double det = j11 * j22 - j12 * j21;
    if (det == 0) return false;
    const double dxi = (j22 * rx - j12 * ry) / det, deta = (j11 * ry - j21 * rx) / det;
    xi -= dxi;
    eta -= deta;
    if (std::abs(dxi) + std::abs(deta) < 1e-13) return true;
  }
  return false;
}

// Marks hit[cell] = 1 for the cells whose centre lies in the tributary area of a delaminated point.
void rasterise(const CscanLayer& l, const CscanMap& m, std::vector<char>& hit) {
  std::fill(hit.begin(), hit.end(), 0);
  const std::size_t nq = l.quads.size() / 4;
  constexpr double tol = 1e-9;
  for (std::size_t q = 0; q < nq; ++q) {
    bool any = false;
    for (int c = 0; c < 4; ++c) any = any || l.delaminated[std::size_t(l.quads[4 * q + c])];
    if (!any) continue;
    Point2 p[4];
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int c = 0; c < 4; ++c) {
      p[c] = corner(l, std::int64_t(q), c);
      xmin = std::min(xmin, p[c].x), xmax = std::max(xmax, p[c].x);
      ymin = std::min(ymin, p[c].y), ymax = std::max(ymax, p[c].y);
    }
    const int i0 = std::max(0, int(std::floor((xmin - m.x0) / m.pitch - 0.5)));
    const int i1 = std::min(m.nx - 1, int(std::ceil((xmax - m.x0) / m.pitch - 0.5)));
    const int j0 = std::max(0, int(std::floor((ymin - m.y0) / m.pitch - 0.5)));
    const int j1 = std::min(m.ny - 1, int(std::ceil((ymax - m.y0) / m.pitch - 0.5)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        double xi, eta;
        if (!parametric(p, m.x0 + (i + 0.5) * m.pitch, m.y0 + (j + 0.5) * m.pitch, xi, eta)) continue;
        if (std::abs(xi) > 1 + tol || std::abs(eta) > 1 + tol) continue;
        const int c = xi < 0 ? (eta < 0 ? 0 : 3) : (eta < 0 ? 1 : 2);  // the corner whose quarter holds it
        if (l.delaminated[std::size_t(l.quads[4 * q + c])]) hit[std::size_t(j) * std::size_t(m.nx) + std::size_t(i)] = 1;
      }
  }
}

}  // namespace

double CscanMap::projected_area() const {
  const auto cells = std::count_if(count.begin(), count.end(), [](int c) { return c > 0; });
  return double(cells) * pitch * pitch;
}

double cscan_pitch(const std::vector<CscanLayer>& layers, std::size_t max_cells) {
  double shortest = INFINITY, xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const auto& l : layers) {
    for (std::size_t q = 0; 4 * q < l.quads.size(); ++q)
      for (int c = 0; c < 4; ++c) {
        const Point2 a = corner(l, std::int64_t(q), c), b = corner(l, std::int64_t(q), (c + 1) % 4);
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        if (len > 0) shortest = std::min(shortest, len);
        xmin = std::min(xmin, a.x), xmax = std::max(xmax, a.x), ymin = std::min(ymin, a.y), ymax = std::max(ymax, a.y);
      }
  }
  if (!std::isfinite(shortest)) throw RunError("C-scan: no interface quad to project");
  const double floor_pitch = std::sqrt((xmax - xmin) * (ymax - ymin) / double(max_cells));
  return std::max(0.5 * shortest, floor_pitch);
}

CscanMap make_cscan(const std::vector<CscanLayer>& layers, double pitch) {
  CscanMap m;
  double xmax = -INFINITY, ymax = -INFINITY;
  m.x0 = m.y0 = INFINITY;
  for (const auto& l : layers)
    for (std::size_t p = 0; 2 * p < l.xy.size(); ++p) {
      m.x0 = std::min(m.x0, l.xy[2 * p]), xmax = std::max(xmax, l.xy[2 * p]);
      m.y0 = std::min(m.y0, l.xy[2 * p + 1]), ymax = std::max(ymax, l.xy[2 * p + 1]);
    }
  if (!(pitch > 0) || !std::isfinite(xmax)) throw RunError("C-scan: no interface point or a non-positive pitch");
  m.pitch = pitch;
  m.nx = std::max(1, int(std::ceil((xmax - m.x0) / pitch - 1e-9)));
  m.ny = std::max(1, int(std::ceil((ymax - m.y0) / pitch - 1e-9)));
  const std::size_t n = std::size_t(m.nx) * std::size_t(m.ny);
  m.shallowest.assign(n, kNaN);
  m.deepest.assign(n, kNaN);
  m.count.assign(n, 0);
  m.shallowest_id.assign(n, 0);
  std::vector<char> hit(n);
  for (const auto& l : layers) {
    rasterise(l, m, hit);
    for (std::size_t k = 0; k < n; ++k) {
      if (!hit[k]) continue;
      ++m.count[k];
      if (std::isnan(m.shallowest[k]) || l.depth < m.shallowest[k]) {
        m.shallowest[k] = l.depth;
        m.shallowest_id[k] = l.id;
      }
      if (std::isnan(m.deepest[k]) || l.depth > m.deepest[k]) m.deepest[k] = l.depth;
    }
  }
  return m;
}

void write_cscan_vtu(const CscanMap& m, double z, double time, const fs::path& path) {
  QuadSurface s;
  s.time = time;
  const std::size_t px = std::size_t(m.nx) + 1;
  s.points.reserve(3 * px * (std::size_t(m.ny) + 1));
  for (int j = 0; j <= m.ny; ++j)
    for (int i = 0; i <= m.nx; ++i) s.points.insert(s.points.end(), {m.x0 + i * m.pitch, m.y0 + j * m.pitch, z});
  s.quads.reserve(4 * m.count.size());
  for (std::size_t j = 0; j < std::size_t(m.ny); ++j)
    for (std::size_t i = 0; i < std::size_t(m.nx); ++i) {
      const auto a = std::int64_t(j * px + i);
      s.quads.insert(s.quads.end(), {a, a + 1, a + std::int64_t(px) + 1, a + std::int64_t(px)});
    }
  Field shallow{"depth_shallowest", 1, m.shallowest, {}}, deep{"depth_deepest", 1, m.deepest, {}};
  for (double& v : shallow.values) v *= 1e3;
  for (double& v : deep.values) v *= 1e3;
  s.cell_fields = {std::move(shallow), std::move(deep)};
  s.cell_int_fields = {{"interfaces_delaminated", m.count}, {"shallowest_interface", m.shallowest_id}};
  s.units = {{"coordinates", "m"},
             {"depth_shallowest", "mm below the impacted face (pulse-echo from the impacted side; NaN: none)"},
             {"depth_deepest", "mm below the impacted face (the first reflector seen from the back face; NaN: none)"},
             {"interfaces_delaminated", "count"},
             {"shallowest_interface", "interface number (0: none)"}};
  write_quad_vtu(s, path);
}

void write_cscan_png(const CscanMap& m, double max_depth, const std::string& title, const fs::path& path, int width,
                     int height) {
  const auto script = [&](const fs::path& tmp) {
    std::ostringstream s;
    s.precision(9);
    s << "set terminal pngcairo size " << width << "," << height << " enhanced font 'sans,11'\n"
      << "set output '" << tmp.string() << "'\n$map << EOD\n";
    for (int j = 0; j < m.ny; ++j) {
      for (int i = 0; i < m.nx; ++i) {
        const double v = m.shallowest[std::size_t(j) * std::size_t(m.nx) + std::size_t(i)];
        s << 1e3 * (m.x0 + (i + 0.5) * m.pitch) << ' ' << 1e3 * (m.y0 + (j + 0.5) * m.pitch) << ' ';
        if (std::isnan(v)) s << "NaN\n";
        else s << 1e3 * v << '\n';
      }
      s << '\n';
    }
    std::string quoted_title;
    for (char c : title) quoted_title += c == '\'' ? std::string("''") : std::string(1, c);
    s << "EOD\nset size ratio -1\nset tics out\n"
      << "set xrange [" << 1e3 * m.x0 << ":" << 1e3 * (m.x0 + m.nx * m.pitch) << "]\n"
      << "set yrange [" << 1e3 * m.y0 << ":" << 1e3 * (m.y0 + m.ny * m.pitch) << "]\n"
      << "set cbrange [0:" << 1e3 * std::max(max_depth, 1e-9) << "]\n"
      << "set palette defined (0 '#08306b', 0.25 '#2171b5', 0.5 '#41b6c4', 0.75 '#fec44f', 1 '#d7301f')\n"
      << "set title '" << quoted_title << "' noenhanced\n"
      << "set xlabel 'x (mm)'\nset ylabel 'y (mm)'\n"
      << "set cblabel 'depth of the shallowest delamination below the impacted face (mm)'\n"
      << "set object 1 rectangle from graph 0,0 to graph 1,1 fillcolor rgb 'white' behind\n"
      << "plot $map using 1:2:3 with image notitle\nunset output\n";
    return s.str();
  };
  gnuplot_png(script, path, "the C-scan map");
}

}  // namespace plyimpact::output
