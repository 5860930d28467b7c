#include "contact/contact_compliance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "contact/geometry.hpp"

namespace plyimpact::contact {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double median(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// (1 - nu^2) / E of a material for a Hertz contact; 0 for a rigid one. Isotropic kinds from their
// Lame constants; an orthotropic one as the isotropic solid with its (Reuss) bulk modulus and
// its through-thickness (material c) P-wave modulus, M = K + 4/3 G.
double hertz_compliance(const model::Material& m) {
  double K = 0, G = 0;
  if (m.kind == model::MaterialKind::Rigid) return 0.0;
  if (m.has_axes()) {
    K = m.bulk_modulus;
    G = 0.75 * (m.c_material[14] - K);
    if (!(G > 0)) G = 0.5 * K;  // a P-wave modulus below K: no useful bound, a Poisson's ratio of 0.2
  } else {
    K = m.iso.bulk;
    G = m.iso.mu;
  }
  if (!(K > 0) || !(G > 0)) return 0.0;
  const double E = 9 * K * G / (3 * K + G), nu = (3 * K - 2 * G) / (2 * (3 * K + G));
  return (1 - nu * nu) / E;
}

}  // namespace

double peak_force_error(double eps) { return std::pow(1 + eps, -0.6) - 1; }
double indentation_error(double eps) { return std::pow(1 + eps, 0.6) - 1; }
double eps_warning_limit() { return std::pow(0.90, -1 / 0.6) - 1; }

PenaltyCompliance penalty_compliance(const model::Model& model, const PenaltyContact& contact) {
  const SegmentSet& set = contact.segments();
  const PenaltyLaw& law = contact.law();
  const SegmentSetSpec spec = segment_set_spec(contact.definition());
  const auto& X = model.X;
  PenaltyCompliance out;
  // Hertz modulus: the most compliant material of each side (rigid sides and the rigid impactor
  // add nothing).
  double hertz = 0;
  for (int side = 0; side < (spec.single ? 1 : 2); ++side) {
    double worst = 0;
    for (int b : spec.blocks[side]) worst = std::max(worst, hertz_compliance(model.materials[model.blocks[b].material]));
    hertz += spec.single ? 2 * worst : worst;  // one body against itself: both sides of the contact
  }
  out.e_star = hertz > 0 ? 1 / hertz : 0.0;

  // Bounding box of each side's contact nodes.
  std::array<std::array<double, 6>, 2> box;
  for (auto& b : box) b = {kInf, kInf, kInf, -kInf, -kInf, -kInf};
  const std::size_t nn = set.num_nodes();
  for (std::size_t i = 0; i < nn; ++i) {
    auto& b = box[std::size_t(set.node_side(i))];
    const double* p = &X[3 * std::size_t(set.node_id(i))];
    for (int d = 0; d < 3; ++d) b[d] = std::min(b[d], p[d]), b[3 + d] = std::max(b[3 + d], p[d]);
  }
  // Tributary area of each contact node (a quarter of each of its own segments).
  std::vector<double> area(nn, 0.0);
  for (std::size_t i = 0; i < nn; ++i)
    for (const Index* s = set.own_begin(i); s != set.own_end(i); ++s) {
      double xq[12];
      const Index* q = set.segment_nodes(std::size_t(*s));
      for (int k = 0; k < 4; ++k)
        for (int d = 0; d < 3; ++d) xq[3 * k + d] = X[3 * std::size_t(q[k]) + d];
      area[i] += 0.25 * quad_area(xq);
    }
  // The contact zone: nodes within one element (sqrt of their area) of the nearest approach of
  // their side to the other side's box.
  std::vector<double> dist(nn, kInf);
  double nearest[2] = {kInf, kInf};
  for (std::size_t i = 0; i < nn; ++i) {
    const int other = set.other_side(i);
    const auto& b = box[std::size_t(other)];
    const double* p = &X[3 * std::size_t(set.node_id(i))];
    double d2 = 0;
    for (int d = 0; d < 3; ++d) {
      const double e = std::max({b[d] - p[d], 0.0, p[d] - b[3 + d]});
      d2 += e * e;
    }
    dist[i] = std::sqrt(d2);
    nearest[set.node_side(i)] = std::min(nearest[set.node_side(i)], dist[i]);
  }
  auto in_zone = [&](std::size_t i) { return area[i] > 0 && dist[i] <= nearest[set.node_side(i)] + std::sqrt(area[i]); };
  // A representative segment of each side's zone: the median stiffness among those whose nodes
  // are all in the zone (the springs a node of the other side meets there).
  std::vector<char> zone_node(model.num_nodes(), 0);
  for (std::size_t i = 0; i < nn; ++i)
    if (in_zone(i)) zone_node[std::size_t(set.node_id(i))] |= char(1 << set.node_side(i));
  long rep[2] = {-1, -1};
  for (int side = 0; side < 2; ++side) {
    std::vector<std::pair<double, long>> ks;
    for (std::size_t s = 0; s < set.num_segments(); ++s) {
      if (set.segment_side(s) != side) continue;
      const Index* q = set.segment_nodes(s);
      bool all = true;
      for (int k = 0; k < 4; ++k) all = all && (zone_node[std::size_t(q[k])] & (1 << side));
      if (all) ks.push_back({set.segment_stiffness(s), long(s)});
    }
    if (ks.empty()) continue;
    std::nth_element(ks.begin(), ks.begin() + std::ptrdiff_t(ks.size() / 2), ks.end());
    rep[side] = ks[ks.size() / 2].second;
  }
  // Per side, the median spring stiffness per unit area k / A of its zone nodes against the other
  // side's representative segment; the sides' springs act in parallel.
  double per_area = 0;
  for (int side = 0; side < 2; ++side) {
    std::vector<double> ka;
    for (std::size_t i = 0; i < nn; ++i) {
      if (set.node_side(i) != side || !in_zone(i)) continue;
      const long s = rep[set.other_side(i)];
      if (s < 0) continue;
      const double k = law.stiffness(set, i, std::size_t(s));
      if (k > 0 && std::isfinite(k)) ka.push_back(k / area[i]);
    }
    per_area += median(ka);
  }
  out.layer = per_area > 0 ? 1 / per_area : 0.0;
  return out;
}

double hertz_impact_radius(double e_star, double R, double m, double v) {
  if (!(e_star > 0) || !(R > 0) || !(m > 0) || !(v > 0)) return 0.0;
  const double d_max = std::pow(15 * m * v * v / (16 * e_star * std::sqrt(R)), 0.4);
  return std::sqrt(R * d_max);
}

}  // namespace plyimpact::contact

namespace plyimpact::contact {

std::string compliance_lines(const model::Model& model, const PenaltyContact& contact, const config::Scene& scene) {
  const PenaltyCompliance c = penalty_compliance(model, contact);
  char buf[512];
  if (!(c.layer > 0) || !(c.e_star > 0)) return "    penalty compliance: not estimated (no deformable side or no spring)\n";
  const double limit = eps_warning_limit();
  double a = 0;
  if (const auto& imp = scene.impactor; imp && model.impactor &&
                                        (imp->shape == config::ImpactorSpec::Shape::Sphere ||
                                         imp->shape == config::ImpactorSpec::Shape::HemisphericalCylinder)) {
    const auto& v = model.impactor->velocity;
    a = hertz_impact_radius(c.e_star, 0.5 * imp->diameter, model.impactor->mass,
                            std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  }
  std::string out;
  if (a > 0) {
    const double eps = c.eps(a);
    std::snprintf(buf, sizeof buf,
                  "    penalty compliance: %.3g m/Pa against E* %.4g Pa; the impactor's Hertz contact (radius %.3g "
                  "m) %+.1f %% in peak force, %+.1f %% in indentation (upper bounds)\n",
                  c.layer, c.e_star, a, 100 * peak_force_error(eps), 100 * indentation_error(eps));
    out = buf;
    if (eps > limit) {
      // For SOFT 0 the springs scale with SLSFAC, so eps does inversely.
      char advice[96];
      if (contact.soft() == 0)
        std::snprintf(advice, sizeof advice, "SLSFAC %.2g keeps the bound within 10 %%", contact.law().SLSFAC * eps / limit);
      else
        std::snprintf(advice, sizeof advice, "stiffer springs (SLSFAC, SOFSCL) lower it");
      std::snprintf(buf, sizeof buf,
                    "    warning: contact '%s': the penalty springs are soft against the bodies (peak force up to "
                    "%.1f %% low); %s\n",
                    contact.name().c_str(), -100 * peak_force_error(eps), advice);
      out += buf;
    }
  } else {
    std::snprintf(buf, sizeof buf,
                  "    penalty compliance: %.3g m/Pa against E* %.4g Pa: a contact narrower than %.3g m (radius) "
                  "may lose more than 10 %% of its peak force\n",
                  c.layer, c.e_star, c.radius_at(limit));
    out = buf;
  }
  return out;
}

}  // namespace plyimpact::contact
