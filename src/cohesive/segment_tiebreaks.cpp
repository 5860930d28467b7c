#include "cohesive/segment_tiebreaks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/geometry.hpp"
#include "core/error.hpp"

namespace plyimpact::cohesive {
namespace {

constexpr std::size_t kChunk = 1024;  // ties per chunk of the energy sums (fixed: thread-count independent)

using contact::cross3;
using contact::dot3;

}  // namespace

SegmentTiebreaks::SegmentTiebreaks(const TractionLawParams& params, std::vector<SegmentTie> ties, const double* x_ref,
                                   const double* nodal_mass)
    : law_(make_traction_law(params)), ties_(std::move(ties)) {
  const std::size_t n = ties_.size();
  weights_.resize(4 * n);
  offset_.resize(3 * n);
  for (std::size_t k = 0; k < n; ++k) {
    const SegmentTie& t = ties_[k];
    if (!(t.area > 0)) throw InputError(msg() << "segment tiebreak: tie " << k << " (slave node " << t.slave << ") has no area");
    if (!(std::abs(t.xi) <= 1 && std::abs(t.eta) <= 1))
      throw InputError(msg() << "segment tiebreak: tie " << k << " lies outside its segment (xi " << t.xi << ", eta " << t.eta << ")");
    for (Index m : t.master)
      if (m == t.slave) throw InputError(msg() << "segment tiebreak: slave node " << t.slave << " is a node of its own master segment");
    contact::quad_shape(t.xi, t.eta, &weights_[4 * k]);
  }
  // The reference opening, with offset_ still zero: the gap the tie accepted, held in the local frame.
  for (std::size_t k = 0; k < n; ++k) {
    Frame fr;
    double u[3];
    opening(x_ref, k, fr, u);
    for (int i = 0; i < 3; ++i) offset_[3 * k + i] = u[i];
  }
  history_.assign(n);
  released_.assign(n, 0);
  held_.assign(n, 0.0);
  force_.assign(3 * n, 0.0);
  sums_.assign((n + kChunk - 1) / kChunk);
  set_nodal_mass(nodal_mass);
}

SegmentTiebreaks::Frame SegmentTiebreaks::frame(const double* x, std::size_t k, double xm[3]) const {
  const SegmentTie& t = ties_[k];
  double xq[12];
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) xq[3 * a + i] = x[3 * std::size_t(t.master[a]) + i];
  double t_xi[3], t_eta[3], twist[3];
  contact::quad_point(xq, t.xi, t.eta, xm, t_xi, t_eta, twist);
  Frame fr;
  cross3(t_xi, t_eta, fr.n);
  const double inv_n = 1 / std::sqrt(dot3(fr.n, fr.n));
  for (int i = 0; i < 3; ++i) fr.n[i] *= inv_n;
  const double tn = dot3(t_xi, fr.n);
  for (int i = 0; i < 3; ++i) fr.t1[i] = t_xi[i] - tn * fr.n[i];
  const double inv_t = 1 / std::sqrt(dot3(fr.t1, fr.t1));
  for (int i = 0; i < 3; ++i) fr.t1[i] *= inv_t;
  cross3(fr.n, fr.t1, fr.t2);
  return fr;
}

void SegmentTiebreaks::opening(const double* x, std::size_t k, Frame& fr, double u[3]) const {
  double xm[3];
  fr = frame(x, k, xm);
  const double* xs = &x[3 * std::size_t(ties_[k].slave)];
  const double d[3] = {xs[0] - xm[0], xs[1] - xm[1], xs[2] - xm[2]};
  const double* u0 = &offset_[3 * k];
  u[0] = dot3(d, fr.n) - u0[0];
  u[1] = dot3(d, fr.t1) - u0[1];
  u[2] = dot3(d, fr.t2) - u0[2];
}

void SegmentTiebreaks::apply(const double* x, double* f) {
  const std::size_t n = ties_.size(), chunks = sums_.size();
#pragma omp parallel for schedule(static) if (n >= 2 * kChunk)
  for (std::size_t ch = 0; ch < chunks; ++ch) {
    double elastic = 0, dissipated = 0, separated = 0;
    const std::size_t end = std::min(n, (ch + 1) * kChunk);
    for (std::size_t k = ch * kChunk; k < end; ++k) {
      double* F = &force_[3 * k];
      if (released_[k]) {
        F[0] = F[1] = F[2] = 0;
        separated += ties_[k].area;
        continue;
      }
      Frame fr;
      double u[3];
      opening(x, k, fr, u);
      PointHistory h = history_.load(k);
      PointResponse r;
      traction_update(law_, u, h, r);
      history_.store(k, h);
      const double A = ties_[k].area;
      const double* t = r.traction;
      for (int i = 0; i < 3; ++i) F[i] = A * (t[0] * fr.n[i] + t[1] * fr.t1[i] + t[2] * fr.t2[i]);
      held_[k] = A * r.elastic_energy;
      elastic += held_[k];
      dissipated += A * r.dissipated_increment;
      if (h.damage >= 1) separated += A;
    }
    sums_.set(ch, elastic, dissipated, separated);
  }
  // Scatter in tie order: neighbouring ties share master nodes.
  for (std::size_t k = 0; k < n; ++k) {
    const double* F = &force_[3 * k];
    const SegmentTie& t = ties_[k];
    const double* N = &weights_[4 * k];
    for (int i = 0; i < 3; ++i) {
      f[3 * std::size_t(t.slave) + i] -= F[i];
      for (int a = 0; a < 4; ++a) f[3 * std::size_t(t.master[a]) + i] += N[a] * F[i];
    }
  }
  const ChunkSums::Totals total = sums_.total();
  elastic_energy_ = total.elastic;
  dissipated_energy_ += total.dissipated;
  separated_area_ = total.separated;
}

void SegmentTiebreaks::release(std::size_t k) {
  if (released_[k]) return;
  released_[k] = 1;
  // What the tie's springs held at the last pass leaves the model with it: the balance keeps it as
  // dissipated.
  dissipated_energy_ += held_[k];
  elastic_energy_ -= held_[k];
  held_[k] = 0;
  history_.release(k);
}

void SegmentTiebreaks::set_nodal_mass(const double* nodal_mass) {
  stable_step_ = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < ties_.size(); ++k) {
    const SegmentTie& t = ties_[k];
    const double* N = &weights_[4 * k];
    double inv_m = 1 / nodal_mass[t.slave];
    for (int a = 0; a < 4; ++a) inv_m += N[a] * N[a] / nodal_mass[t.master[a]];
    const double dt = 2 / std::sqrt(law_.k_max * t.area * inv_m);
    stable_step_ = std::min(stable_step_, dt);
  }
}

void SegmentTiebreaks::sample(const double* x, PairSample* out) const {
  for (std::size_t k = 0; k < ties_.size(); ++k) {
    Frame fr;
    PairSample& s = out[k];
    opening(x, k, fr, s.opening);
    if (released_[k]) {  // carries nothing: its master is gone
      s.damage = 1;
      s.mixity = 0;
      for (double& c : s.traction) c = 0;
      continue;
    }
    sample_point(law_, history_.load(k), s);
  }
}

void SegmentTiebreaks::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "segment tiebreaks");
  history_.visit_state(visitor);
  visitor.array("released", released_);
  visitor.array("held_energy", held_);
  visitor.array("force", force_);
  visitor.scalar("dissipated_energy", dissipated_energy_);
}

}  // namespace plyimpact::cohesive
