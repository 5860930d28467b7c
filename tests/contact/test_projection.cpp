// Node-to-segment projection (contact/geometry.hpp), the cases of NimbleSM's
// projection_node_to_face tests: a node above the inside of a flat segment, above an edge, above a
// corner, outside, and above a warped segment. References: for a flat square the closest point and
// gap are known in closed form; for the warped segment the Newton result is compared with a brute
// force minimisation of |p - x(xi, eta)| on a 2001 x 2001 grid followed by the same accuracy check
// (grid spacing 1e-3 in xi gives a distance error below 1e-6 relative; the Newton answer must be
// at least as close).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/geometry.hpp"

namespace plyimpact::contact {
namespace {

// Unit square [0, 2] x [0, 2] at z = 0, counter-clockwise seen from +z: normal +z.
const double kSquare[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0};
constexpr double kTol = 1e-12;  // round-off of a converged Newton solve on O(1) coordinates

TEST(Projection, InsideFlatSegment) {
  const double p[3] = {0.5, 1.5, -0.1};
  const Projection r = project_to_quad(p, kSquare);
  EXPECT_TRUE(r.inside);
  EXPECT_NEAR(r.xi, -0.5, kTol);
  EXPECT_NEAR(r.eta, 0.5, kTol);
  EXPECT_NEAR(r.gap, -0.1, kTol);
  EXPECT_NEAR(r.normal[2], 1.0, kTol);
  double sum = 0;
  for (double n : r.N) sum += n;
  EXPECT_NEAR(sum, 1.0, kTol);  // partition of unity: the master forces sum to the slave force
  EXPECT_NEAR(r.N[3], 0.25 * 1.5 * 1.5, kTol);
}

TEST(Projection, OnEdge) {
  const double p[3] = {2.0, 1.0, 0.3};
  const Projection r = project_to_quad(p, kSquare);
  EXPECT_TRUE(r.inside);
  EXPECT_NEAR(r.xi, 1.0, kTol);
  EXPECT_NEAR(r.eta, 0.0, kTol);
  EXPECT_NEAR(r.gap, 0.3, kTol);
  EXPECT_NEAR(r.N[1] + r.N[2], 1.0, kTol);  // only the edge nodes carry force
}

TEST(Projection, AtCorner) {
  const double p[3] = {2.0, 2.0, -0.05};
  const Projection r = project_to_quad(p, kSquare);
  EXPECT_TRUE(r.inside);
  EXPECT_NEAR(r.N[2], 1.0, kTol);
  EXPECT_NEAR(r.gap, -0.05, kTol);
}

TEST(Projection, JustOutsideWithinMaxparAndFarOutside) {
  // xi = 1.02 is within MAXPAR = 1.025: accepted, pushed along the edge's normal.
  const double near[3] = {2.02, 1.0, -0.01};
  const Projection a = project_to_quad(near, kSquare);
  EXPECT_TRUE(a.inside);
  EXPECT_NEAR(a.xi, 1.02, 1e-10);
  EXPECT_NEAR(a.gap, -0.01, kTol);
  const double far[3] = {2.2, 1.0, -0.01};
  EXPECT_FALSE(project_to_quad(far, kSquare).inside);
  const double very_far[3] = {40.0, -30.0, 5.0};
  const Projection c = project_to_quad(very_far, kSquare);
  EXPECT_FALSE(c.inside);
  EXPECT_TRUE(std::isfinite(c.gap));
}

TEST(Projection, WarpedSegmentMatchesBruteForce) {
  // Corner 2 lifted by 0.4: a hyperbolic paraboloid z = 0.1 (1 + xi)(1 + eta).
  const double warped[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0.4, 0, 2, 0};
  const double p[3] = {1.3, 1.1, 0.05};
  const Projection r = project_to_quad(p, warped);
  ASSERT_TRUE(r.inside);
  auto dist = [&](double xi, double eta) {
    double x[3], a[3], b[3], w[3];
    quad_point(warped, xi, eta, x, a, b, w);
    return std::hypot(p[0] - x[0], p[1] - x[1], p[2] - x[2]);
  };
  double best = 1e300;
  for (int i = 0; i <= 2000; ++i)
    for (int j = 0; j <= 2000; ++j) best = std::min(best, dist(-1 + i * 1e-3, -1 + j * 1e-3));
  const double d_newton = dist(r.xi, r.eta);
  EXPECT_LE(d_newton, best + 1e-12);
  EXPECT_NEAR(d_newton, best, 1e-6);
  // The normal is the surface normal at the contact point: p - x_c is parallel to it.
  EXPECT_NEAR(std::abs(r.gap), d_newton, 1e-10);
}

TEST(Projection, AreaOfFlatAndWarpedSegments) {
  EXPECT_NEAR(quad_area(kSquare), 4.0, kTol);
  // z = 0.1 (1 + xi)(1 + eta) over x, y in [0, 2]: z = 0.1 x y; area = int int sqrt(1 + 0.01 (x^2 + y^2)),
  // 2x2 Gauss is exact to ~1e-5 for this smooth integrand (value by 200x200 midpoint rule below).
  const double warped[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0.4, 0, 2, 0};
  double ref = 0;
  const int n = 200;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) * 2.0 / n, y = (j + 0.5) * 2.0 / n;
      ref += std::sqrt(1 + 0.01 * (x * x + y * y)) * (2.0 / n) * (2.0 / n);
    }
  EXPECT_NEAR(quad_area(warped), ref, 1e-4);
}

}  // namespace
}  // namespace plyimpact::contact
