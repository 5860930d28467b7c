// Test support for the Taylor bar tests: an O-grid mesh of a quarter cylinder and the exact volume
// of a hexahedral mesh. Only geometry; each test states its problem and tolerances itself.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "mesh/mesh.hpp"

namespace plyimpact::test {

// Quarter-cylinder O-grid of radius kR0 and length kL0 (x >= 0, y >= 0), axis z from 0 (impact face)
// to kL0: an n x n core, two n x k ring blocks, nz layers along the axis. Element part 0.
inline mesh::Mesh quarter_cylinder(double kR0, double kL0, int n, int k, int nz) {
  constexpr double kPi = 3.14159265358979323846;
  mesh::Mesh m;
  std::map<std::tuple<long, long>, Index> index;  // merge coincident in-plane nodes
  std::vector<std::array<double, 2>> pts;
  auto node = [&](double x, double y) {
    const auto key = std::make_tuple(std::lround(x / kR0 * 1e9), std::lround(y / kR0 * 1e9));
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    pts.push_back({x, y});
    return index[key] = Index(pts.size() - 1);
  };
  const double c = 0.45 * kR0;  // core half-width: the core corner sits at 0.64 r0
  std::vector<std::array<Index, 4>> quads;
  auto quad = [&](Index a, Index b, Index cc, Index d) {
    const auto &pa = pts[a], &pb = pts[b], &pc = pts[cc], &pd = pts[d];
    const double area2 = (pc[0] - pa[0]) * (pd[1] - pb[1]) - (pc[1] - pa[1]) * (pd[0] - pb[0]);
    if (area2 > 0) quads.push_back({a, b, cc, d});
    else quads.push_back({a, d, cc, b});
  };
  std::vector<Index> grid((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) grid[j * (n + 1) + i] = node(c * i / n, c * j / n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      quad(grid[j * (n + 1) + i], grid[j * (n + 1) + i + 1], grid[(j + 1) * (n + 1) + i + 1], grid[(j + 1) * (n + 1) + i]);
  for (int side = 0; side < 2; ++side) {  // ring block on the x = c edge, then its mirror on y = c
    std::vector<Index> ring((n + 1) * (k + 1));
    for (int j = 0; j <= n; ++j) {
      const double th = 0.25 * kPi * j / n;
      const double in[2] = {c, c * j / double(n)}, out[2] = {kR0 * std::cos(th), kR0 * std::sin(th)};
      for (int r = 0; r <= k; ++r) {
        const double s = double(r) / k, x = in[0] + s * (out[0] - in[0]), y = in[1] + s * (out[1] - in[1]);
        ring[j * (k + 1) + r] = side == 0 ? node(x, y) : node(y, x);
      }
    }
    for (int j = 0; j < n; ++j)
      for (int r = 0; r < k; ++r)
        quad(ring[j * (k + 1) + r], ring[j * (k + 1) + r + 1], ring[(j + 1) * (k + 1) + r + 1], ring[(j + 1) * (k + 1) + r]);
  }
  const Index np = Index(pts.size());
  for (int l = 0; l <= nz; ++l)
    for (const auto& p : pts) m.coords.insert(m.coords.end(), {p[0], p[1], kL0 * l / nz});
  for (int l = 0; l < nz; ++l)
    for (const auto& q : quads) {
      for (int a = 0; a < 4; ++a) m.hex.push_back(q[a] + l * np);
      for (int a = 0; a < 4; ++a) m.hex.push_back(q[a] + (l + 1) * np);
      m.element_part.push_back(0);
    }
  return m;
}

// Exact volume of the trilinear hexahedra of `conn` at coordinates x: det J is at most quadratic in
// each reference coordinate, so 2 x 2 x 2 Gauss points integrate it exactly.
inline double hex_volume(const std::vector<double>& x, const std::vector<Index>& conn) {
  static constexpr double xi[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, eta[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                          zeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  const double g = 1 / std::sqrt(3.0);
  double volume = 0;
  for (std::size_t e = 0; e < conn.size() / 8; ++e)
    for (int p = 0; p < 8; ++p) {
      const double a = g * xi[p], b = g * eta[p], c = g * zeta[p];
      double J[3][3] = {};
      for (int k = 0; k < 8; ++k) {
        const double dN[3] = {xi[k] * (1 + eta[k] * b) * (1 + zeta[k] * c) / 8,
                              eta[k] * (1 + xi[k] * a) * (1 + zeta[k] * c) / 8,
                              zeta[k] * (1 + xi[k] * a) * (1 + eta[k] * b) / 8};
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) J[i][j] += x[3 * std::size_t(conn[8 * e + k]) + i] * dN[j];
      }
      volume += J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    }
  return volume;
}

}  // namespace plyimpact::test
