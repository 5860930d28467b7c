// ASTM D5528 data reduction. See dcb_reduction.hpp.
#include "fracture/dcb_reduction.hpp"

#include <cmath>
#include <cstddef>

#include "core/error.hpp"

namespace plyimpact::fracture {

LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = x.size();
  if (n != y.size()) throw InputError(msg() << "fit_line: " << n << " x values but " << y.size() << " y values");
  // Centred sums (two passes) rather than the one-pass normal equations, which lose digits when
  // x is far from 0 relative to its spread (crack lengths 50..100 mm, log compliances).
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= double(n);
  my /= double(n);
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (n < 2 || !(sxx > 0))
    throw InputError(msg() << "a straight-line fit needs at least 2 points with different abscissae; found " << n
                           << " point(s)" << (n >= 2 ? " with equal abscissae" : ""));
  LineFit f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double ss_res = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - (f.slope * x[i] + f.intercept);
    ss_res += r * r;
  }
  f.r2 = syy > 0 ? 1.0 - ss_res / syy : 1.0;
  return f;
}

DcbReduction reduce_dcb(std::span<const DcbPoint> points, const DcbSpecimen& specimen) {
  const double b = specimen.width, h = specimen.thickness;
  if (!(b > 0) || !(h > 0))
    throw InputError(msg() << "DCB specimen width and thickness must be > 0; found width " << b << " m, thickness " << h
                           << " m");
  if (points.size() < 3)
    throw InputError(msg() << "the D5528 reduction needs at least 3 propagation points (three fits of a line); found "
                           << points.size());
  DcbReduction r;
  r.points.assign(points.begin(), points.end());
  const std::size_t m = points.size();
  std::vector<double> a(m), cbrt_c(m), ln_a(m), ln_c(m), a_over_h(m);
  r.compliance.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const DcbPoint& p = points[i];
    if (!(p.a > 0) || !(p.P > 0) || !(p.delta > 0))
      throw InputError(msg() << "propagation point " << i + 1 << ": a, P and delta must be > 0; found a = " << p.a
                             << " m, P = " << p.P << " N, delta = " << p.delta << " m");
    if (i > 0 && !(p.a > points[i - 1].a))
      throw InputError(msg() << "propagation point " << i + 1 << ": crack length must increase; found a = " << p.a
                             << " m after " << points[i - 1].a << " m");
    const double C = p.delta / p.P;
    r.compliance[i] = C;
    a[i] = p.a;
    cbrt_c[i] = std::cbrt(C);
    ln_a[i] = std::log(p.a);
    ln_c[i] = std::log(C);
    a_over_h[i] = p.a / h;
  }
  r.mbt_fit = fit_line(a, cbrt_c);       // C^(1/3) = s (a - x0): x0 = -intercept / slope
  r.cc_fit = fit_line(ln_a, ln_c);       // ln C = ln alpha + n ln a
  r.mcc_fit = fit_line(cbrt_c, a_over_h);  // a / h = A1 C^(1/3) + c
  if (!(r.mbt_fit.slope > 0))
    throw InputError(msg() << "compliance does not grow with crack length (slope of C^(1/3) against a = "
                           << r.mbt_fit.slope << "); the data are not a DCB propagation record");
  r.delta_x_intercept = -r.mbt_fit.intercept / r.mbt_fit.slope;
  r.Delta = std::abs(r.delta_x_intercept);
  r.n = r.cc_fit.slope;
  r.A1 = r.mcc_fit.slope;
  r.G_mbt.resize(m);
  r.G_cc.resize(m);
  r.G_mcc.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const DcbPoint& p = points[i];
    const double C = r.compliance[i];
    r.G_mbt[i] = 3.0 * p.P * p.delta / (2.0 * b * (p.a + r.Delta));
    r.G_cc[i] = r.n * p.P * p.delta / (2.0 * b * p.a);
    r.G_mcc[i] = 3.0 * p.P * p.P * std::cbrt(C * C) / (2.0 * r.A1 * b * h);
  }
  return r;
}

}  // namespace plyimpact::fracture
