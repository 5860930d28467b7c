// Contact geometry kernels: closest-point projection of a node onto a bilinear quadrilateral
// segment (LS-DYNA Theory Manual, "Sliding interfaces": Newton on the two tangency conditions
// t_xi . (p - x(xi, eta)) = 0, t_eta . (p - x(xi, eta)) = 0), the segment normal at that point and
// the segment area. Segment nodes in LS-DYNA/VTK quad order, natural coordinates in [-1, 1]^2;
// the normal t_xi x t_eta points outward for a face taken from a hexahedron (contact/surface.hpp).
// Free inline functions over plain arrays: no allocation, used in the contact loop.
#pragma once

#include <algorithm>
#include <cmath>

namespace plyimpact::contact {

struct Projection {
  double xi = 0, eta = 0;   // natural coordinates of the closest point (unclamped Newton result)
  double N[4] = {0, 0, 0, 0};  // shape functions at (xi, eta) after clamping to [-1, 1]
  double point[3] = {0, 0, 0};   // closest point x_c on the segment
  double normal[3] = {0, 0, 1};  // unit normal t_xi x t_eta at x_c
  double gap = 0;               // signed normal distance n . (p - x_c): < 0 behind the segment
  bool inside = false;          // |xi|, |eta| <= maxpar (node projects onto the segment)
};

inline void quad_shape(double xi, double eta, double N[4]) {
  N[0] = 0.25 * (1 - xi) * (1 - eta);
  N[1] = 0.25 * (1 + xi) * (1 - eta);
  N[2] = 0.25 * (1 + xi) * (1 + eta);
  N[3] = 0.25 * (1 - xi) * (1 + eta);
}

inline void cross3(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

inline double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// x(xi, eta), tangents t_xi = dx/dxi, t_eta = dx/deta and the twist x_xieta = d2x/dxi deta.
// xq: the four corner coordinates, (4, 3) node-major.
inline void quad_point(const double* xq, double xi, double eta, double x[3], double t_xi[3], double t_eta[3],
                       double twist[3]) {
  double N[4];
  quad_shape(xi, eta, N);
  const double dxi[4] = {-0.25 * (1 - eta), 0.25 * (1 - eta), 0.25 * (1 + eta), -0.25 * (1 + eta)};
  const double deta[4] = {-0.25 * (1 - xi), -0.25 * (1 + xi), 0.25 * (1 + xi), 0.25 * (1 - xi)};
  const double dxe[4] = {0.25, -0.25, 0.25, -0.25};
  for (int d = 0; d < 3; ++d) {
    x[d] = t_xi[d] = t_eta[d] = twist[d] = 0;
    for (int k = 0; k < 4; ++k) {
      const double c = xq[3 * k + d];
      x[d] += N[k] * c;
      t_xi[d] += dxi[k] * c;
      t_eta[d] += deta[k] * c;
      twist[d] += dxe[k] * c;
    }
  }
}

// A bilinear segment in coefficient form, x(xi, eta) = c + xi a1 + eta a2 + xi eta a3, so that
// t_xi = a1 + eta a3, t_eta = a2 + xi a3 and the twist is a3. From the corners (quad order, nodes
// at (xi, eta) = (-1,-1), (1,-1), (1,1), (-1,1)): c = (x0 + x1 + x2 + x3) / 4,
// a1 = (-x0 + x1 + x2 - x3) / 4, a2 = (-x0 - x1 + x2 + x3) / 4, a3 = (x0 - x1 + x2 - x3) / 4.
// Layout: c at [0..2], a1 at [4..6], a2 at [8..10], a3 at [12..14]; slots 3, 7, 11 and 15 are the
// caller's (the contact keeps its per-segment search data there, one 128-byte record per segment).
inline void bilinear_coefficients(const double* x0, const double* x1, const double* x2, const double* x3,
                                  double* g) {
  for (int d = 0; d < 3; ++d) {
    const double s02 = x0[d] + x2[d], s13 = x1[d] + x3[d], d20 = x2[d] - x0[d], d13 = x1[d] - x3[d];
    g[d] = 0.25 * (s02 + s13);
    g[4 + d] = 0.25 * (d20 + d13);
    g[8 + d] = 0.25 * (d20 - d13);
    g[12 + d] = 0.25 * (s02 - s13);
  }
}

// Closest point of p on the bilinear segment g (coefficient form above). Newton from the centre
// with the exact Hessian of 0.5 |p - x|^2 (x_xixi = x_etaeta = 0 on a bilinear patch), iterates
// kept in [-2, 2]^2 so a far-outside node cannot diverge; at most 12 iterations, stop at
// |d xi| < 1e-12. The contact point and normal use (xi, eta) clamped to the segment, so a node just
// outside an edge (|xi| <= maxpar) is pushed along the edge's normal, as LS-DYNA's MAXPAR
// tolerance intends.
inline Projection project_to_bilinear(const double p[3], const double* g, double maxpar = 1.025) {
  Projection r;
  const double* c = g;
  const double* a1 = g + 4;
  const double* a2 = g + 8;
  const double* w = g + 12;
  const double e[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};  // p - c
  double xi = 0, eta = 0;
  for (int it = 0; it < 12; ++it) {
    double a[3], b[3], d[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = a1[k] + eta * w[k];
      b[k] = a2[k] + xi * w[k];
      d[k] = e[k] - xi * a1[k] - eta * a2[k] - xi * eta * w[k];  // p - x(xi, eta)
    }
    const double g0 = -dot3(a, d), g1 = -dot3(b, d);  // gradient of 0.5 |p - x|^2
    const double h00 = dot3(a, a), h11 = dot3(b, b), ab = dot3(a, b);
    double h01 = ab - dot3(w, d);
    double det = h00 * h11 - h01 * h01;
    if (!(det > 1e-14 * h00 * h11)) {  // indefinite (strongly warped, far node): Gauss-Newton step
      h01 = ab;
      det = h00 * h11 - h01 * h01;
      if (!(det > 0)) break;
    }
    const double dxi = -(h11 * g0 - h01 * g1) / det, deta = -(h00 * g1 - h01 * g0) / det;
    xi = std::clamp(xi + dxi, -2.0, 2.0);
    eta = std::clamp(eta + deta, -2.0, 2.0);
    if (std::abs(dxi) + std::abs(deta) < 1e-12) break;
  }
  r.xi = xi;
  r.eta = eta;
  r.inside = std::abs(xi) <= maxpar && std::abs(eta) <= maxpar;
  const double xc = std::clamp(xi, -1.0, 1.0), ec = std::clamp(eta, -1.0, 1.0);
  quad_shape(xc, ec, r.N);
  double a[3], b[3];
  for (int k = 0; k < 3; ++k) {
    r.point[k] = c[k] + xc * a1[k] + ec * a2[k] + xc * ec * w[k];
    a[k] = a1[k] + ec * w[k];
    b[k] = a2[k] + xc * w[k];
  }
  cross3(a, b, r.normal);
  const double len = std::sqrt(dot3(r.normal, r.normal));
  for (double& v : r.normal) v /= len;
  const double d[3] = {p[0] - r.point[0], p[1] - r.point[1], p[2] - r.point[2]};
  r.gap = dot3(r.normal, d);
  return r;
}

// The same for a segment given by its corners xq (4, 3), node-major.
inline Projection project_to_quad(const double p[3], const double* xq, double maxpar = 1.025) {
  double g[16];
  bilinear_coefficients(xq, xq + 3, xq + 6, xq + 9, g);
  return project_to_bilinear(p, g, maxpar);
}

// Area of a (possibly warped) bilinear segment: 2x2 Gauss integral of |t_xi x t_eta|.
inline double quad_area(const double* xq) {
  const double g = 1.0 / std::sqrt(3.0);
  double area = 0, x[3], a[3], b[3], w[3], n[3];
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      quad_point(xq, xi, eta, x, a, b, w);
      cross3(a, b, n);
      area += std::sqrt(dot3(n, n));
    }
  return area;
}

}  // namespace plyimpact::contact
