#include "cohesive/cohesive_elements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "core/error.hpp"

namespace plyimpact::cohesive {
namespace {

// Elements per chunk of the energy sums: fixed, so the sums do not depend on the thread count.
constexpr std::size_t kChunk = 256;

}  // namespace

// Bilinear quad: corner a at (xi_a, eta_a); point g at r (xi_g, eta_g), r = 1/sqrt(3) (Gauss) or 1
// (Newton-Cotes: the corners, where N_a(g) = 1 for a = g and 0 otherwise).
struct CohesiveElements::QuadTables {
  double N[4][4], dxi[4][4], deta[4][4];  // [point][corner]
  explicit QuadTables(double r) {
    const double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
    for (int g = 0; g < 4; ++g)
      for (int a = 0; a < 4; ++a) {
        const double x = r * xi[g], y = r * eta[g];
        N[g][a] = 0.25 * (1 + xi[a] * x) * (1 + eta[a] * y);
        dxi[g][a] = 0.25 * xi[a] * (1 + eta[a] * y);
        deta[g][a] = 0.25 * eta[a] * (1 + xi[a] * x);
      }
  }
};

namespace {

using Quad = CohesiveElements::QuadTables;
const Quad kGauss(1 / std::sqrt(3.0));
const Quad kNewtonCotes(1.0);

inline void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
inline double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Corner coordinates of one element: lower face xl, upper face xu.
struct ElementCoords {
  double xl[4][3], xu[4][3];
};

inline void gather(const double* x, const Index* nodes, ElementCoords& c) {
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) {
      c.xl[a][i] = x[3 * std::size_t(nodes[a]) + i];
      c.xu[a][i] = x[3 * std::size_t(nodes[4 + a]) + i];
    }
}

// Mid-surface tangents at point g and their cross product (the vector area density).
inline void tangents(const Quad& q, const ElementCoords& c, int g, double a1[3], double a2[3], double an[3]) {
  for (int i = 0; i < 3; ++i) {
    a1[i] = a2[i] = 0;
    for (int a = 0; a < 4; ++a) {
      const double m = 0.5 * (c.xl[a][i] + c.xu[a][i]);
      a1[i] += q.dxi[g][a] * m;
      a2[i] += q.deta[g][a] * m;
    }
  }
  cross(a1, a2, an);
}

struct PointFrame {
  double n[3], e1[3], e2[3];
};

// Frame and local opening (normal, shear 1, shear 2) at point g.
[[gnu::always_inline]] inline void point_kinematics(const Quad& q, const ElementCoords& c, int g, PointFrame& fr,
                                                    double u[3]) {
  double a1[3], a2[3], an[3];
  tangents(q, c, g, a1, a2, an);
  const double inv_n = 1 / std::sqrt(dot(an, an)), inv_1 = 1 / std::sqrt(dot(a1, a1));
  for (int i = 0; i < 3; ++i) {
    fr.n[i] = an[i] * inv_n;
    fr.e1[i] = a1[i] * inv_1;
  }
  cross(fr.n, fr.e1, fr.e2);
  double d[3] = {0, 0, 0};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) d[i] += q.N[g][a] * (c.xu[a][i] - c.xl[a][i]);
  u[0] = dot(d, fr.n);
  u[1] = dot(d, fr.e1);
  u[2] = dot(d, fr.e2);
}

}  // namespace

CohesiveElements::CohesiveElements(const TractionLawParams& params, CohesiveElementsSpec spec, const double* x_ref,
                                   const double* nodal_mass)
    : laws_(params, spec.nodes.size() / 8, spec.nfls, spec.sfls),
      quad_(spec.integration == CohesiveIntegration::Gauss ? &kGauss : &kNewtonCotes),
      nodes_(std::move(spec.nodes)) {
  if (nodes_.size() % 8) throw InputError("cohesive elements: the node list is not a multiple of 8");
  num_elements_ = nodes_.size() / 8;
  const std::size_t ne = num_elements_, np = kPoints * ne;
  for (Index node : nodes_)
    if (node < 0) throw InputError(msg() << "cohesive elements: node index " << node);
  point_area_.assign(np, 0.0);
  corner_area_.assign(np, 0.0);
  for (std::size_t e = 0; e < ne; ++e) {
    ElementCoords c;
    gather(x_ref, &nodes_[8 * e], c);
    double size_sq = 0, gap_sq = 0;
    for (int a = 0; a < 4; ++a) {
      const int b = (a + 1) % 4;
      double edge = 0, gap = 0;
      for (int i = 0; i < 3; ++i) {
        edge += (c.xl[b][i] - c.xl[a][i]) * (c.xl[b][i] - c.xl[a][i]);
        gap += (c.xu[a][i] - c.xl[a][i]) * (c.xu[a][i] - c.xl[a][i]);
      }
      size_sq = std::max(size_sq, edge);
      gap_sq = std::max(gap_sq, gap);
    }
    // Zero thickness: the upper nodes coincide with the lower ones (the mesher's duplicates).
    if (gap_sq > 1e-18 * size_sq)
      throw InputError(msg() << "cohesive elements: element " << e << " has thickness " << std::sqrt(gap_sq)
                             << " m (edge " << std::sqrt(size_sq)
                             << " m); only zero-thickness elements (coincident lower and upper nodes) are supported");
    for (int g = 0; g < kPoints; ++g) {
      double a1[3], a2[3], an[3];
      tangents(*quad_, c, g, a1, a2, an);
      const double area = std::sqrt(dot(an, an));
      if (!(area > 0)) throw InputError(msg() << "cohesive elements: element " << e << " has no area at point " << g);
      point_area_[kPoints * e + g] = area;
    }
  }
  // Gather lists: slots sorted by node, then by slot, so each node sums in a fixed order.
  std::vector<std::pair<Index, Index>> entries(nodes_.size());
  for (std::size_t s = 0; s < nodes_.size(); ++s) entries[s] = {nodes_[s], Index(s)};
  std::sort(entries.begin(), entries.end());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (k == 0 || entries[k].first != entries[k - 1].first) {
      gather_node_.push_back(entries[k].first);
      gather_offset_.push_back(Index(k));
    }
    gather_slot_.push_back(entries[k].second);
  }
  gather_offset_.push_back(Index(entries.size()));
  // Tributary area of each node (sum over its slots of sum_g A_g N_a(g)), then per lower corner.
  std::vector<double> slot_area(nodes_.size(), 0.0), node_area(gather_node_.size(), 0.0);
  for (std::size_t e = 0; e < ne; ++e)
    for (int a = 0; a < 8; ++a)
      for (int g = 0; g < kPoints; ++g) slot_area[8 * e + a] += point_area_[kPoints * e + g] * quad_->N[g][a % 4];
  std::vector<double> area_of_slot(nodes_.size(), 0.0);
  for (std::size_t k = 0; k < gather_node_.size(); ++k) {
    for (Index s = gather_offset_[k]; s < gather_offset_[k + 1]; ++s) node_area[k] += slot_area[gather_slot_[s]];
    for (Index s = gather_offset_[k]; s < gather_offset_[k + 1]; ++s) area_of_slot[gather_slot_[s]] = node_area[k];
  }
  for (std::size_t e = 0; e < ne; ++e)
    for (int a = 0; a < 4; ++a) corner_area_[kPoints * e + a] = area_of_slot[8 * e + a];

  element_force_.assign(24 * ne, 0.0);
  history_.assign(np);
  sums_.assign((ne + kChunk - 1) / kChunk);
  set_nodal_mass(nodal_mass);
}

double CohesiveElements::element_area(std::size_t e) const {
  double a = 0;
  for (int g = 0; g < kPoints; ++g) a += point_area_[kPoints * e + g];
  return a;
}

void CohesiveElements::point_positions(const double* x, double* out) const {
  for (std::size_t e = 0; e < num_elements_; ++e) {
    ElementCoords c;
    gather(x, &nodes_[8 * e], c);
    for (int g = 0; g < kPoints; ++g) {
      double* o = &out[3 * (kPoints * e + g)];
      for (int i = 0; i < 3; ++i) {
        o[i] = 0;
        for (int a = 0; a < 4; ++a) o[i] += quad_->N[g][a] * 0.5 * (c.xl[a][i] + c.xu[a][i]);
      }
    }
  }
}

// Forces of element e into fe ((8, 3)), its history updated; adds its energies and separated area.
[[gnu::always_inline]] inline void CohesiveElements::element_forces(const double* x, std::size_t e, double* fe,
                                                                    double& elastic, double& dissipated,
                                                                    double& separated) {
  ElementCoords c;
  gather(x, &nodes_[8 * e], c);
  for (int k = 0; k < 24; ++k) fe[k] = 0;
  for (int g = 0; g < kPoints; ++g) {
    const std::size_t p = kPoints * e + g;
    PointFrame fr;
    double u[3];
    point_kinematics(*quad_, c, g, fr, u);
    PointHistory h = history_.load(p);
    PointResponse r;
    traction_update(laws_.of(e), u, h, r);
    history_.store(p, h);
    const double area = point_area_[p];
    const double* t = r.traction;
    double traction[3];
    for (int i = 0; i < 3; ++i) traction[i] = area * (t[0] * fr.n[i] + t[1] * fr.e1[i] + t[2] * fr.e2[i]);
    for (int a = 0; a < 4; ++a) {
      const double w = quad_->N[g][a];
      for (int i = 0; i < 3; ++i) {
        fe[3 * a + i] += w * traction[i];
        fe[3 * (4 + a) + i] -= w * traction[i];
      }
    }
    elastic += area * r.elastic_energy;
    dissipated += area * r.dissipated_increment;
    if (h.damage >= 1) separated += area;
  }
}

void CohesiveElements::apply(const double* x, const double* /*v*/, double* f, double /*dt*/) {
  const std::size_t ne = num_elements_, chunks = sums_.size(), nn = gather_node_.size();
#pragma omp parallel if (ne >= 2 * kChunk)
  {
#pragma omp for schedule(static)
    for (std::size_t ch = 0; ch < chunks; ++ch) {
      double elastic = 0, dissipated = 0, separated = 0;
      const std::size_t end = std::min(ne, (ch + 1) * kChunk);
      for (std::size_t e = ch * kChunk; e < end; ++e)
        element_forces(x, e, &element_force_[24 * e], elastic, dissipated, separated);
      sums_.set(ch, elastic, dissipated, separated);
    }
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < nn; ++k) {
      double sum[3] = {0, 0, 0};
      for (Index s = gather_offset_[k]; s < gather_offset_[k + 1]; ++s)
        for (int i = 0; i < 3; ++i) sum[i] += element_force_[3 * std::size_t(gather_slot_[s]) + i];
      for (int i = 0; i < 3; ++i) f[3 * std::size_t(gather_node_[k]) + i] += sum[i];
    }
  }
  const ChunkSums::Totals total = sums_.total();
  elastic_energy_ = total.elastic;
  dissipated_energy_ += total.dissipated;
  separated_area_ = total.separated;
}

void CohesiveElements::set_nodal_mass(const double* nodal_mass) {
  stable_step_ = std::numeric_limits<double>::infinity();
  stable_step_element_ = -1;
  for (std::size_t e = 0; e < num_elements_; ++e)
    for (int a = 0; a < 4; ++a) {
      const double k = laws_.card().k_max * corner_area_[kPoints * e + a];
      const double omega_sq = k * (1 / nodal_mass[nodes_[8 * e + a]] + 1 / nodal_mass[nodes_[8 * e + 4 + a]]);
      const double dt = 2 / std::sqrt(omega_sq);
      if (dt < stable_step_) {
        stable_step_ = dt;
        stable_step_element_ = Index(e);
      }
    }
}

void CohesiveElements::sample(const double* x, PairSample* out) const {
  for (std::size_t e = 0; e < num_elements_; ++e) {
    ElementCoords c;
    gather(x, &nodes_[8 * e], c);
    for (int g = 0; g < kPoints; ++g) {
      const std::size_t p = kPoints * e + g;
      PointFrame fr;
      PairSample& s = out[p];
      point_kinematics(*quad_, c, g, fr, s.opening);
      sample_point(laws_.of(e), history_.load(p), s);
    }
  }
}

void CohesiveElements::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "cohesive elements");
  history_.visit_state(visitor);
  visitor.scalar("dissipated_energy", dissipated_energy_);
}

}  // namespace plyimpact::cohesive
