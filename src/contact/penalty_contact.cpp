#include "contact/penalty_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>

#include "element/hex8.hpp"

namespace plyimpact::contact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

PenaltyContact::PenaltyContact(const model::Model& model, const model::Contact& def, const std::vector<double>& x,
                               double dt_initial)
    : model_(model), def_(def) {
  single_ = def.spec.type == config::ContactSpec::Type::SingleSurface;
  dt_c_ = def.spec.DTSTIF > 0 ? def.spec.DTSTIF : dt_initial;
  builder_a_ = SurfaceBuilder(model, def.a.blocks);
  if (!single_) builder_b_ = SurfaceBuilder(model, def.b.blocks);
  node_rigid_.assign(model.num_nodes(), 0);
  for (const auto& body : model.rigid_bodies)
    for (Index n : body.nodes) node_rigid_[n] = 1;
  local_of_.assign(model.num_nodes(), -1);
  build(x, nullptr);
}

void PenaltyContact::build(const std::vector<double>& x, const AliveMask* alive) {
  const auto& spec = def_.spec;
  // Keep per-node history across a rebuild (eroding contact): forces, friction, offsets, whether
  // the node was in contact (its spring is not a new one) and that spring's gap, stiffness and
  // normal force (its potential is carried to whatever segment it finds next: apply). history key:
  // 2 * node + side.
  std::vector<std::pair<Index, std::array<double, 12>>> history;
  for (std::size_t i = 0; i < sn_node_.size(); ++i)
    history.push_back({2 * sn_node_[i] + sn_side_[i],
                       {sn_ft_[3 * i], sn_ft_[3 * i + 1], sn_ft_[3 * i + 2], sn_offset_[i], sn_k_[i],
                        sn_engaged_[i] ? 1.0 : 0.0, sn_gap_[i], sn_k_last_[i], sn_fn_[3 * i], sn_fn_[3 * i + 1],
                        sn_fn_[3 * i + 2], sn_exp_offset_[i]}});
  // The segment each node was in contact with, by its sorted nodes and side (indices change), and
  // every segment (to tell the faces a rebuild exposes).
  std::vector<std::array<Index, 5>> old_keys;
  for (std::size_t s = 0; s < seg_side_.size(); ++s) old_keys.push_back(segment_key(long(s)));
  std::vector<std::array<Index, 5>> history_segment, history_exposure;
  for (std::size_t i = 0; i < sn_node_.size(); ++i) {
    history_segment.push_back(segment_key(sn_segment_[i]));
    history_exposure.push_back(segment_key(sn_exp_seg_[i]));
  }
  std::vector<std::pair<Index, std::array<double, 3>>> old_forces;
  for (std::size_t u = 0; u < union_nodes_.size(); ++u)
    old_forces.push_back({union_nodes_[u], {fc_prev_[3 * u], fc_prev_[3 * u + 1], fc_prev_[3 * u + 2]}});

  seg_nodes_.clear();
  seg_owner_.clear();
  seg_side_.clear();
  seg_k_.clear();
  seg_mass_.clear();
  seg_node_mass_.clear();
  seg_depth_.clear();
  auto add_segment = [&](const Index* q, const Index* owner, int side, double K, double volume, double elem_mass) {
    double xq[12];
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) xq[3 * k + d] = x[3 * std::size_t(q[k]) + d];
    const double area = quad_area(xq);
    const double sf = spec.SLSFAC * (side == 0 ? spec.SFS : spec.SFM);
    seg_nodes_.insert(seg_nodes_.end(), q, q + 4);
    for (int k = 0; k < 8; ++k) seg_owner_.push_back(owner ? owner[k] : -1);
    seg_side_.push_back(char(side));
    seg_k_.push_back(K > 0 && volume > 0 ? sf * K * area * area / volume : kInf);
    seg_mass_.push_back(elem_mass > 0 ? 0.5 * elem_mass : 0.0);
    double m = 0;
    for (int k = 0; k < 4; ++k) m += 0.25 * model_.mass[q[k]];
    seg_node_mass_.push_back(m);
    const double thickness = volume > 0 ? volume / area : 0.0;
    seg_depth_.push_back(spec.PENMAX > 0 ? spec.PENMAX : 0.4 * std::max(thickness, std::sqrt(area)));
  };
  auto add_side = [&](const model::ContactSide& side, const SurfaceBuilder& builder, int id) {
    for (const auto& f : builder.exterior(alive)) {
      const auto& blk = model_.blocks[f.block];
      const auto& mat = model_.materials[blk.material];
      const Index* conn = &blk.conn[8 * std::size_t(f.element)];
      Index q[4];
      for (int k = 0; k < 4; ++k) q[k] = conn[kHexFaces[f.face][k]];
      const double volume = blk.volume0[f.element];
      add_segment(q, conn, id, mat.bulk_modulus, volume, mat.density * volume);
    }
    if (side.impactor) {
      const std::size_t nq = model_.impactor_quads.size() / 4;
      const double m = model_.impactor ? model_.impactor->mass / double(std::max<std::size_t>(nq, 1)) : 0.0;
      for (std::size_t s = 0; s < nq; ++s) add_segment(&model_.impactor_quads[4 * s], nullptr, id, 0.0, 0.0, 2 * m);
    }
  };
  add_side(def_.a, builder_a_, 0);
  if (!single_) add_side(def_.b, builder_b_, 1);
  const std::size_t S = seg_side_.size();
  seg_geo_.assign(kGeo * S, 0.0);  // stamps 0: stale (cycle_ starts at 1)
  for (std::size_t s = 0; s < S; ++s) seg_geo_[kGeo * s + 7] = seg_depth_[s];  // constant; the rest per pass
  for (auto& ids : side_segs_) ids.clear();
  for (std::size_t s = 0; s < S; ++s) side_segs_[single_ ? 0 : seg_side_[s]].push_back(Index(s));

  // Slave nodes: the segment nodes of each side (ENMASS 1 keeps eroded nodes as mass points).
  std::vector<double> k_sum(model_.num_nodes() * 2, 0.0), segm_sum(model_.num_nodes() * 2, 0.0);
  std::vector<int> k_count(model_.num_nodes() * 2, 0);
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k) {
      const std::size_t key = 2 * std::size_t(seg_nodes_[4 * s + k]) + seg_side_[s];
      k_sum[key] += seg_k_[s];
      segm_sum[key] += seg_mass_[s];
      ++k_count[key];
    }
  sn_node_.clear();
  sn_side_.clear();
  sn_k_.clear();
  sn_mass_.clear();
  sn_seg_mass_.clear();
  for (std::size_t n = 0; n < model_.num_nodes(); ++n)
    for (int side = 0; side < 2; ++side) {
      const std::size_t key = 2 * n + side;
      if (k_count[key] == 0) continue;
      sn_node_.push_back(Index(n));
      sn_side_.push_back(char(side));
      sn_k_.push_back(k_sum[key] / k_count[key]);
      sn_mass_.push_back(model_.mass[n]);
      sn_seg_mass_.push_back(segm_sum[key] / k_count[key]);
    }
  if (spec.ENMASS == 1)
    for (std::size_t i = 0; i < history.size(); ++i) {
      const Index n = history[i].first / 2;
      if (k_count[2 * std::size_t(n)] == 0 && k_count[2 * std::size_t(n) + 1] == 0 && model_.mass[n] > 0) {
        // Orphan node kept as a contact mass point, on the side it belonged to.
        sn_node_.push_back(n);
        sn_side_.push_back(char(single_ ? 0 : history[i].first % 2));
        sn_k_.push_back(history[i].second[4]);
        sn_mass_.push_back(model_.mass[n]);
        sn_seg_mass_.push_back(model_.mass[n]);
      }
    }
  const std::size_t N = sn_node_.size();
  {
    std::vector<Index> slave_index(2 * model_.num_nodes(), -1);
    for (std::size_t i = 0; i < N; ++i) slave_index[2 * std::size_t(sn_node_[i]) + sn_side_[i]] = Index(i);
    std::vector<Index> seg_slave(4 * S);  // slave index of each segment node on the segment's side
    for (std::size_t s = 0; s < S; ++s)
      for (int k = 0; k < 4; ++k) seg_slave[4 * s + k] = slave_index[2 * std::size_t(seg_nodes_[4 * s + k]) + seg_side_[s]];
    // Own-side segments of each slave node (CSR, ascending segment order).
    own_start_.assign(N + 1, 0);
    for (Index i : seg_slave)
      if (i >= 0) ++own_start_[std::size_t(i) + 1];
    for (std::size_t i = 0; i < N; ++i) own_start_[i + 1] += own_start_[i];
    own_segs_.resize(std::size_t(own_start_[N]));
    std::vector<Index> fill(own_start_.begin(), own_start_.end() - 1);
    for (std::size_t s = 0; s < S; ++s)
      for (int k = 0; k < 4; ++k)
        if (const Index i = seg_slave[4 * s + k]; i >= 0) own_segs_[std::size_t(fill[std::size_t(i)]++)] = Index(s);
  }
  sn_normal_.assign(3 * N, 0.0);
  sn_offset_.assign(N, 0.0);
  sn_ft_.assign(3 * N, 0.0);
  sn_segment_.assign(N, -1);
  sn_engaged_.assign(N, 0);
  sn_gap_.assign(N, 0.0);
  sn_k_last_.assign(N, 0.0);
  sn_fn_.assign(3 * N, 0.0);
  sn_exp_offset_.assign(N, 0.0);
  sn_exp_seg_.assign(N, -1);
  sn_new_.assign(N, 0);
  seg_new_.assign(S, 0);
  exposed_pass_ = alive != nullptr;
  if (!history.empty()) {  // restore the per-node history (once per rebuild)
    std::vector<Index> slave_of(2 * model_.num_nodes(), -1);
    for (std::size_t i = 0; i < N; ++i) slave_of[2 * std::size_t(sn_node_[i]) + sn_side_[i]] = Index(i);
    for (const auto& [key, h] : history) {
      Index i = slave_of[std::size_t(key)];
      if (i < 0) continue;
      for (int d = 0; d < 3; ++d) sn_ft_[3 * std::size_t(i) + d] = h[d];
      sn_offset_[i] = h[3];
      sn_engaged_[i] = h[5] > 0;
      sn_gap_[i] = h[6];
      sn_k_last_[i] = h[7];
      for (int d = 0; d < 3; ++d) sn_fn_[3 * std::size_t(i) + d] = h[8 + std::size_t(d)];
      sn_exp_offset_[i] = h[11];
    }
    // What the rebuild added: nodes new to the surface and faces erosion exposed (see apply).
    std::vector<char> known(N, 0);
    for (const auto& entry : history)
      if (const Index i = slave_of[std::size_t(entry.first)]; i >= 0) known[std::size_t(i)] = 1;
    for (std::size_t i = 0; i < N; ++i) sn_new_[i] = !known[i];
    // The segment of the last pass, where it survived: its neighbours keep the full release depth
    // (find_segment), so a node pressed into the surface is not released by an erosion elsewhere.
    std::map<std::array<Index, 5>, long> segment_of;
    for (std::size_t s = 0; s < S; ++s) segment_of.emplace(segment_key(long(s)), long(s));
    for (std::size_t h = 0; h < history.size(); ++h) {
      const Index i = slave_of[std::size_t(history[h].first)];
      if (i < 0 || history_segment[h][0] < 0) continue;
      if (auto it = segment_of.find(history_segment[h]); it != segment_of.end()) sn_segment_[std::size_t(i)] = it->second;
    }
    for (std::size_t h = 0; h < history.size(); ++h) {  // exposure offsets on surviving segments
      const Index i = slave_of[std::size_t(history[h].first)];
      if (i < 0) continue;
      const auto it = history_exposure[h][0] < 0 ? segment_of.end() : segment_of.find(history_exposure[h]);
      if (it != segment_of.end()) sn_exp_seg_[std::size_t(i)] = it->second;
      else sn_exp_offset_[std::size_t(i)] = 0;
    }
    std::vector<char> old_segment(S, 0);
    for (const auto& key : old_keys)
      if (auto it = segment_of.find(key); it != segment_of.end()) old_segment[std::size_t(it->second)] = 1;
    for (std::size_t s = 0; s < S; ++s) seg_new_[s] = !old_segment[s];
  }

  // Union of all force-carrying nodes.
  for (Index n : union_nodes_) local_of_[n] = -1;
  union_nodes_.clear();
  union_side_a_.clear();
  auto add_union = [&](Index n, bool side_a) {
    if (local_of_[n] < 0) {
      local_of_[n] = Index(union_nodes_.size());
      union_nodes_.push_back(n);
      union_side_a_.push_back(0);
    }
    if (side_a) union_side_a_[local_of_[n]] = 1;
  };
  for (std::size_t i = 0; i < N; ++i) add_union(sn_node_[i], sn_side_[i] == 0 && !single_);
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k) add_union(seg_nodes_[4 * s + k], seg_side_[s] == 0 && !single_);
  sn_local_.resize(N);
  for (std::size_t i = 0; i < N; ++i) sn_local_[i] = local_of_[sn_node_[i]];
  seg_local_.resize(4 * S);
  for (std::size_t k = 0; k < 4 * S; ++k) seg_local_[k] = local_of_[seg_nodes_[k]];
  const std::size_t U = union_nodes_.size();
  fc_.assign(3 * U, 0.0);
  fc_prev_.assign(3 * U, 0.0);
  union_row_.assign(U, 0.0);
  union_inv_mass_.resize(U);
  for (std::size_t u = 0; u < U; ++u) {
    const Index n = union_nodes_[u];
    union_inv_mass_[u] = !node_rigid_[n] && model_.mass[n] > 0 ? 1 / model_.mass[n] : 0.0;
  }
  x_sort_.assign(3 * U, 0.0);
  for (const auto& [node, f] : old_forces)
    if (local_of_[node] >= 0)
      for (int d = 0; d < 3; ++d) fc_prev_[3 * std::size_t(local_of_[node]) + d] = f[d];

  // Search parameters. Each segment's box is expanded by its own margin: release depth (the
  // deepest accepted penetration), 5 % of its extent (MAXPAR) and the motion allowance. Allowance
  // and bucket edge follow the median segment extent, not the largest, so a graded mesh (a fine
  // impact zone in a coarse plate) does not put the whole fine zone into one bucket; a large
  // segment is simply listed in every bucket its box overlaps.
  std::vector<double> extent(S, 0.0);
  for (std::size_t s = 0; s < S; ++s)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        double d2 = 0;
        for (int d = 0; d < 3; ++d) {
          const double e = x[3 * std::size_t(seg_nodes_[4 * s + a]) + d] - x[3 * std::size_t(seg_nodes_[4 * s + b]) + d];
          d2 += e * e;
        }
        extent[s] = std::max(extent[s], std::sqrt(d2));
      }
  cell_ = 0;
  if (S > 0) {
    std::vector<double> sorted = extent;
    std::nth_element(sorted.begin(), sorted.begin() + S / 2, sorted.end());
    cell_ = sorted[S / 2];
  }
  allowance_ = 0.25 * cell_;
  seg_margin_.resize(S);
  for (std::size_t s = 0; s < S; ++s) seg_margin_[s] = seg_depth_[s] + 0.05 * extent[s] + allowance_;
  // Bucket edge = median extent: a segment's expanded box then spans a few buckets, and a node's
  // bucket holds few segments (measured: 10-15 % faster than an edge of extent + 2 margins).
  search_cell_ = cell_;
  estimate_stiffness_range();
  build_neighbours();
  sort(x.data(), 0.0);
}

std::array<Index, 5> PenaltyContact::segment_key(long s) const {
  std::array<Index, 5> key{-1, -1, -1, -1, -1};
  if (s < 0) return key;
  key[0] = Index(seg_side_[std::size_t(s)]);
  for (int k = 0; k < 4; ++k) key[std::size_t(k) + 1] = seg_nodes_[4 * std::size_t(s) + std::size_t(k)];
  std::sort(key.begin() + 1, key.end());
  return key;
}

void PenaltyContact::estimate_stiffness_range() {
  // Stiffness bounds (for `check`) and the stable step of the stiffest node-segment spring.
  const std::size_t S = seg_side_.size(), N = sn_node_.size();
  double seg_k_max[2] = {0, 0}, seg_mass_max[2] = {0, 0};
  double k_fin_min = kInf;
  bool seg_k_inf[2] = {false, false};  // a segment without an element (impactor surface) on that side
  for (std::size_t s = 0; s < S; ++s) {
    const int side = seg_side_[s];
    if (!std::isfinite(seg_k_[s])) seg_k_inf[side] = true;
    if (std::isfinite(seg_k_[s])) {
      seg_k_max[side] = std::max(seg_k_max[side], seg_k_[s]);
      k_fin_min = std::min(k_fin_min, seg_k_[s]);
    }
    seg_mass_max[side] = std::max(seg_mass_max[side], seg_mass_[s]);
  }
  k_min_ = kInf;
  k_max_ = 0;
  dt_stable_ = kInf;
  const auto& spec = def_.spec;
  for (std::size_t i = 0; i < N; ++i) {
    const int other = single_ ? 0 : 1 - sn_side_[i];
    double k_lo = 0, k_hi = 0;
    // PENOPT 1: k0 = min(k_node, k_segment) <= min(k_node, stiffest segment of the other side); a
    // stiff node against a soft surface gets the surface's stiffness, not its own.
    const double k_seg_hi = seg_k_inf[other] ? kInf : seg_k_max[other];
    double k0_hi = std::min(sn_k_[i], k_seg_hi);
    if (!std::isfinite(k0_hi)) k0_hi = std::isfinite(sn_k_[i]) ? sn_k_[i] : seg_k_max[other];
    const double k0_lo = std::isfinite(sn_k_[i]) ? std::min(sn_k_[i], k_fin_min) : k_fin_min;
    if (spec.SOFT == 0) {
      k_lo = k0_lo;
      k_hi = k0_hi;
    } else if (spec.SOFT == 1) {
      const double soft = spec.SOFSCL * 0.5 * sn_mass_[i] / (dt_c_ * dt_c_);
      k_lo = std::max(k0_lo, 0.0);
      k_hi = std::max(k0_hi, soft);
      k_lo = std::max(k_lo == kInf ? 0.0 : k_lo, std::min(soft, k_hi));
    } else {
      const double sf = spec.SLSFAC * (sn_side_[i] == 0 ? spec.SFS : spec.SFM);
      const double m1 = sn_seg_mass_[i], m2 = seg_mass_max[other];
      k_hi = m1 + m2 > 0 ? 0.5 * sf * m1 * m2 / (m1 + m2) / (dt_c_ * dt_c_) : 0.0;
      k_lo = k_hi;
    }
    if (!(k_hi > 0) || !std::isfinite(k_hi)) continue;
    k_min_ = std::min(k_min_, k_lo > 0 && std::isfinite(k_lo) ? k_lo : k_hi);
    k_max_ = std::max(k_max_, k_hi);
  }
  if (!std::isfinite(k_min_)) k_min_ = 0;

  // Stable step of the stiffest pair. A spring k between node i (mass m_i) and a point of segment
  // s (weights N_a, sum 1, on nodes of mass m_a) has omega^2 <= k (1/m_i + sum N_a^2 / m_a)
  // <= k / m_i + k / m_s, m_s the lightest deformable node of s; rigid nodes count as infinitely
  // heavy. So omega^2 <= max_i A_i + max_s B_s with k bounded once by node-only and once by
  // segment-only quantities (A_i: k <= its bound from the node's side, B_s: from the segment's):
  //   SOFT 0: k = min(k_i, k_s) <= min(k_i, max k_s) and <= min(k_s, max k_i)
  //   SOFT 1: k = max(that, SOFSCL 0.5 min(m_i, m_seg) / dt_c^2), m_seg <= its own value
  //   SOFT 2: k = 0.5 sf m1 m2 / (m1 + m2) / dt_c^2 <= 0.5 sf min(m1, m2) / dt_c^2
  // This pairs the stiffness and mass of the same node or segment, instead of the stiffest spring
  // anywhere with the lightest node anywhere (far too small a step on a graded mesh).
  const double dt2 = dt_c_ * dt_c_;
  double sn_k_max[2] = {0, 0}, sn_segm_max[2] = {0, 0}, sf_max[2] = {0, 0};
  bool sn_k_inf[2] = {false, false};
  for (std::size_t i = 0; i < N; ++i) {
    const int side = sn_side_[i];
    if (std::isfinite(sn_k_[i])) sn_k_max[side] = std::max(sn_k_max[side], sn_k_[i]);
    else sn_k_inf[side] = true;
    sn_segm_max[side] = std::max(sn_segm_max[side], sn_seg_mass_[i]);
    sf_max[side] = std::max(sf_max[side], spec.SLSFAC * (side == 0 ? spec.SFS : spec.SFM));
  }
  auto finite_or_zero = [](double k) { return std::isfinite(k) ? k : 0.0; };
  double A[2] = {0, 0}, B[2] = {0, 0};  // A[side]: slave nodes of that side; B[side]: its segments
  for (std::size_t i = 0; i < N; ++i) {
    if (node_rigid_[sn_node_[i]] || !(sn_mass_[i] > 0)) continue;
    const int side = sn_side_[i], other = single_ ? 0 : 1 - side;
    double k;
    if (spec.SOFT == 2) {
      k = 0.5 * spec.SLSFAC * (side == 0 ? spec.SFS : spec.SFM) * std::min(sn_seg_mass_[i], seg_mass_max[other]) / dt2;
    } else {
      k = finite_or_zero(std::min(sn_k_[i], seg_k_inf[other] ? kInf : seg_k_max[other]));
      if (spec.SOFT == 1) k = std::max(k, spec.SOFSCL * 0.5 * sn_mass_[i] / dt2);
    }
    A[side] = std::max(A[side], k / sn_mass_[i]);
  }
  for (std::size_t s = 0; s < S; ++s) {
    double m_s = kInf;
    for (int a = 0; a < 4; ++a) {
      const Index n = seg_nodes_[4 * s + a];
      if (!node_rigid_[n] && model_.mass[n] > 0) m_s = std::min(m_s, model_.mass[n]);
    }
    if (!std::isfinite(m_s)) continue;
    const int side = seg_side_[s], slaves = single_ ? 0 : 1 - side;
    double k;
    if (spec.SOFT == 2) {
      k = 0.5 * sf_max[slaves] * std::min(seg_mass_[s], sn_segm_max[slaves]) / dt2;
    } else {
      k = finite_or_zero(std::min(seg_k_[s], sn_k_inf[slaves] ? kInf : sn_k_max[slaves]));
      if (spec.SOFT == 1) k = std::max(k, spec.SOFSCL * 0.5 * seg_node_mass_[s] / dt2);
    }
    B[side] = std::max(B[side], k / m_s);
  }
  double omega2 = 0;
  for (int side = 0; side < (single_ ? 1 : 2); ++side) {
    const int other = single_ ? 0 : 1 - side;
    omega2 = std::max(omega2, A[side] + B[other]);
  }
  if (omega2 > 0) dt_stable_ = 2.0 / std::sqrt(omega2);
}

void PenaltyContact::sort(const double* x, double step_depth) {
  // One grid per side (two-way contact): a slave node only walks the other side's segments.
  for (int side = 0; side < (single_ ? 1 : 2); ++side) {
    const auto& ids = side_segs_[side];
    auto& boxes = boxes_[side];
    boxes.resize(6 * ids.size());
    for (std::size_t j = 0; j < ids.size(); ++j) {
      const std::size_t s = std::size_t(ids[j]);
      double* b = &boxes[6 * j];
      for (int d = 0; d < 3; ++d) {
        b[d] = 1e300;
        b[3 + d] = -1e300;
      }
      for (int k = 0; k < 4; ++k)
        for (int d = 0; d < 3; ++d) {
          const double c = x[3 * std::size_t(seg_nodes_[4 * s + k]) + d];
          b[d] = std::min(b[d], c - seg_margin_[s]);
          b[3 + d] = std::max(b[3 + d], c + seg_margin_[s]);
        }
    }
    grid_[side].build(boxes, search_cell_);
  }
  for (std::size_t u = 0; u < union_nodes_.size(); ++u)
    for (int d = 0; d < 3; ++d) x_sort_[3 * u + d] = x[3 * std::size_t(union_nodes_[u]) + d];
  cycles_since_sort_ = 0;
  ++sorts_;
  // The lists are built for the motion expected before the next sort, not for the whole bucket
  // allowance: a node moving at the present largest speed covers BSORT dt v_max = BSORT
  // step_depth / 4 until the next sort, an eighth of this list allowance (a re-sort comes first if
  // it moves a quarter: apply), at least a fifth of the bucket allowance (fewer sorts by motion).
  // They hold the segments a node can newly catch within the new-contact depth (find_segment),
  // whose bound until the next sort is twice the present one (a re-sort comes first if the
  // motion per step grows beyond it), at least an eighth of the list allowance.
  list_allowance_ = std::min(allowance_, std::max(0.2 * allowance_, 2.0 * double(def_.spec.BSORT) * step_depth));
  new_depth_cap_ = std::max(2 * step_depth, 0.125 * list_allowance_);
  refresh_all(x);
  build_candidates(x, exposed_pass_);  // the pass after a rebuild looks at any depth (apply)
}

void PenaltyContact::build_neighbours() {
  // Segments of the same side sharing a node with s (CSR, ascending, s itself left out).
  const std::size_t S = seg_side_.size();
  std::vector<std::vector<Index>> of_node(model_.num_nodes());
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k) of_node[std::size_t(seg_nodes_[4 * s + std::size_t(k)])].push_back(Index(s));
  nbr_start_.assign(S + 1, 0);
  nbr_.clear();
  std::vector<Index> near;
  for (std::size_t s = 0; s < S; ++s) {
    near.clear();
    for (int k = 0; k < 4; ++k)
      for (Index t : of_node[std::size_t(seg_nodes_[4 * s + std::size_t(k)])])
        if (t != Index(s) && seg_side_[std::size_t(t)] == seg_side_[s]) near.push_back(t);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    nbr_.insert(nbr_.end(), near.begin(), near.end());
    nbr_start_[s + 1] = Index(nbr_.size());
  }
}

void PenaltyContact::build_candidates(const double* x, bool full_depth) {
  // Until the next sort every contact node moves less than a / 4 from where it is now (the re-sort
  // test), a = the list allowance (sort): a node-to-centre distance changes by at most a / 2 and a bounding
  // radius grows by at most a / 2. The search's sphere test (find_segment) accepts at most
  // |p - c| <= r_factor r + D, D the depth accepted for a new contact (at most
  // min(depth, cap + 2 % depth) until the next sort; the full depth when `full_depth`), so a
  // segment with
  //   |p - c| > r_factor (r + a / 2) + D + a / 2   now
  // cannot pass it before the next sort and is left out of the node's list. The full release
  // depth of a node already in contact is searched on its segment's neighbours (find_segment), not
  // here: a list sized for it would hold every segment within ~0.4 element of the node, and make
  // nodes a plate's thickness away from the other surface search and refresh every cycle.
  // What remains is the node's bucket filtered to its neighbourhood, in bucket order.
  const std::size_t N = sn_node_.size();
  const double r_factor = 1 + 2 * std::max(def_.spec.MAXPAR - 1, 0.0), half_a = 0.5 * list_allowance_;
  cand_start_.resize(N + 1);
  cand_.clear();
  for (std::size_t i = 0; i < N; ++i) {
    cand_start_[i] = Index(cand_.size());
    const double* p = &x[3 * std::size_t(sn_node_[i])];
    const int gs = single_ ? 0 : 1 - sn_side_[i];
    const std::vector<Index>& ids = side_segs_[gs];
    for (Index k : grid_[gs].candidates(p)) {
      const std::size_t s = std::size_t(ids[std::size_t(k)]);
      const double* g = &seg_geo_[kGeo * s];
      const double depth = full_depth ? g[7] : std::min(g[7], new_depth_cap_ + 0.02 * g[7]);
      const double dx = p[0] - g[0], dy = p[1] - g[1], dz = p[2] - g[2];
      const double reach = r_factor * (double(segment_radius(g)) + half_a) + depth + half_a;
      if (dx * dx + dy * dy + dz * dz > reach * reach) continue;
      cand_.push_back(Index(s));
    }
  }
  cand_start_[N] = Index(cand_.size());
}

double PenaltyContact::stiffness(std::size_t i, std::size_t s) const {
  const auto& spec = def_.spec;
  if (spec.SOFT == 2) {
    const double sf = spec.SLSFAC * (sn_side_[i] == 0 ? spec.SFS : spec.SFM);
    const double m1 = sn_seg_mass_[i], m2 = seg_mass_[s];
    return m1 + m2 > 0 ? 0.5 * sf * m1 * m2 / (m1 + m2) / (dt_c_ * dt_c_) : 0.0;
  }
  double k0 = std::min(sn_k_[i], seg_k_[s]);  // PENOPT 1
  if (!std::isfinite(k0)) k0 = 0;
  if (spec.SOFT == 0) return k0;
  const double m = std::min(sn_mass_[i], seg_node_mass_[s]);
  return std::max(k0, spec.SOFSCL * 0.5 * m / (dt_c_ * dt_c_));
}

long PenaltyContact::find_segment(std::size_t i, const double* x, Projection& best, double new_contact_depth,
                                  const double* v, double dt) {
  const Index c_begin = cand_start_[i], c_end = cand_start_[i + 1];
  const long last = sn_segment_[i];
  if (c_begin == c_end && last < 0) return -1;  // nothing within reach until the next sort
  const Index node = sn_node_[i];
  const double* p = &x[3 * std::size_t(node)];
  const double v_node = v != nullptr ? std::sqrt(dot3(&v[3 * std::size_t(node)], &v[3 * std::size_t(node)])) : 0.0;
  // The node's normal, from its own segments, once a candidate passes the sphere test.
  const double* nn = &sn_normal_[3 * i];
  double nn_len = -1;
  // The in-plane pre-check assumes |gap| <= release depth, i.e. no initial-penetration offset.
  const bool plain = sn_offset_[i] == 0 && sn_exp_seg_[i] < 0;
  // Distance from the closest point to the node beyond |g|: the tangential overshoot of a
  // projection clamped to the edge, at most (MAXPAR - 1) x the longest edge <= 2 r (MAXPAR - 1).
  const double r_factor = 1 + 2 * std::max(def_.spec.MAXPAR - 1, 0.0);
  long best_s = -1;
  double best_g = 0;
  // Nodes of the segment of the last pass (-1: none). A node in contact slides from its segment to
  // a neighbour (one sharing a node with it) at the depth it has: the neighbour accepts the node's
  // depth at the last pass plus the one-step catch depth. With the catch depth alone a node pressed
  // deeper was released at every segment boundary it slid across (Hertz: the contact area grows
  // under the sphere); with the full release depth a node lifting off a top face beside an eroded
  // hole was caught by the hole's side face (which shares the edge) at its distance from the edge,
  // a spring from nothing that pushed the bodies apart (energy created).
  Index ln[4] = {-1, -1, -1, -1};
  const double last_depth = last >= 0 ? std::max(-sn_gap_[i], 0.0) : 0.0;
  if (last >= 0)
    for (int k = 0; k < 4; ++k) ln[k] = seg_nodes_[4 * std::size_t(last) + std::size_t(k)];
  auto shares_node_with_last = [&](const Index* q) {
    bool near = false;
    for (int a = 0; a < 4; ++a) near = near || q[a] == ln[0] || q[a] == ln[1] || q[a] == ln[2] || q[a] == ln[3];
    return near;
  };
  auto consider = [&](Index s) __attribute__((always_inline)) {  // inlined: a few candidates per node
    double* sg = &seg_geo_[kGeo * std::size_t(s)];
    if (segment_stamp(sg) != cycle_) refresh_segment(std::size_t(s), x);  // first look this cycle
    // Bounding sphere: an accepted node lies within r + |g| (+ overshoot) of the centre, |g| below
    // the accepted depth, and it can only beat the best so far if it is less penetrated,
    // |g| < |g_best|. Full release depth on the segment the node was in contact with, its depth at
    // the last pass plus the new-contact depth on the neighbours, the new-contact depth elsewhere
    // (tested first: most candidates fail it).
    const double depth = sg[7];
    const double catch_depth = new_contact_depth + 0.02 * depth;
    const double dx = p[0] - sg[0], dy = p[1] - sg[1], dz = p[2] - sg[2];
    const double d2 = dx * dx + dy * dy + dz * dz, r = r_factor * double(segment_radius(sg));
    auto reach = [&](double accept) { return r + (best_s >= 0 ? std::min(accept, -best_g) : accept); };
    const Index* q = &seg_nodes_[4 * std::size_t(s)];
    double accept = std::min(depth, catch_depth);
    const double accept_catch = accept;  // what a new contact may be caught at (exposures aside)
    bool exposure = false, neighbour = false;
    if (last >= 0) {
      const double near_depth = s == last ? depth : std::min(depth, last_depth + catch_depth);
      if (const double rn = reach(accept); d2 > rn * rn) {
        const double rf = reach(near_depth);
        if (d2 > rf * rf || !shares_node_with_last(q)) return;
        accept = near_depth;
        neighbour = s != last;
      } else if (shares_node_with_last(q)) {
        accept = near_depth;
        neighbour = s != last;
      }
    } else {
      // First pass after a rebuild: a node new to the surface, or a face erosion exposed, may
      // already lie behind the other side by more than one step's motion (apply books it as an
      // offset, not a spring).
      exposure = exposed_pass_ && (sn_new_[i] || seg_new_[std::size_t(s)]);
      if (exposure) accept = depth;
      if (const double rn = reach(accept); d2 > rn * rn) return;
    }
    if (q[0] == node || q[1] == node || q[2] == node || q[3] == node) return;
    if (single_) {
      const Index* o = &seg_owner_[8 * std::size_t(s)];
      bool own = false;
      for (int k = 0; k < 8; ++k) own = own || o[k] == node;
      if (own) return;
    }
    if (nn_len < 0) {
      node_normal(i, x);
      nn_len = std::sqrt(dot3(nn, nn));
    }
    // Orientation pre-check with the segment's centre normal, made conservative by the bound of
    // the normal's deviation over the segment: it skips only what the exact check below would skip
    // (a node beside a side face it cannot push through), without the projection.
    double n0[3];
    cross3(sg + 4, sg + 8, n0);
    float normal_bound[2];  // deviation bound, 1 / |n0|
    std::memcpy(normal_bound, sg + 11, sizeof normal_bound);
    if (nn_len > 0 && dot3(nn, n0) * double(normal_bound[1]) > (-0.3 + double(normal_bound[0])) * nn_len) return;
    // Can it beat the best so far (g > g_best)? An accepted node has a negative gap, p - c =
    // xi a1 + eta a2 + xi eta a3 + gap n with |xi|, |eta| <= m, and 0 < n . n0/|n0| <= 1 (normal
    // deviation bound < 1), so gap <= gap (n . n0/|n0|) = (p - c) . n0/|n0| - xi eta a3 . n0/|n0|
    // <= (p - c) . n0/|n0| + m^2 |a3 . n0|/|n0|. A node on the shared corner of several segments of
    // a flat surface (matching meshes) then projects onto the first only: the others tie.
    if (best_s >= 0 && double(normal_bound[0]) < 1) {
      const double m = def_.spec.MAXPAR, inv = 1 / std::sqrt(dot3(n0, n0));
      const double upper = (dx * n0[0] + dy * n0[1] + dz * n0[2] + m * m * std::abs(dot3(n0, sg + 12))) * inv;
      if (upper - offset_of(i, s) <= best_g) return;
    }
    // In-plane pre-check (refresh_segment): a node the projection would accept has
    // |(p - c) . a1| <= bound_xi and |(p - c) . a2| <= bound_eta; two dot products instead of the
    // Newton projection of a neighbour the node lies beside (about half the projections).
    if (plain) {
      float bound[2];
      std::memcpy(bound, sg + 15, sizeof bound);
      if (std::abs(dx * sg[4] + dy * sg[5] + dz * sg[6]) > double(bound[0]) ||
          std::abs(dx * sg[8] + dy * sg[9] + dz * sg[10]) > double(bound[1]))
        return;
    }
    const Projection pr = project_to_bilinear(p, sg, def_.spec.MAXPAR);
    if (!pr.inside) return;
    // Orientation: the node's own surface must face the segment (normals at more than ~107 deg),
    // so a node at a corner is not pushed out through a side face it merely slid under.
    if (nn_len > 0 && dot3(nn, pr.normal) > -0.3 * nn_len) return;
    const double g = pr.gap - offset_of(i, s);
    // A node with an exposure offset stays on that segment while it is behind the face (the offset
    // relaxes as it backs out: apply), not only while it is deeper than the offset.
    const bool relaxing = s == sn_exp_seg_[i] && pr.gap - sn_offset_[i] < 0;
    if ((!(g < 0) && !relaxing) || g <= -accept) return;
    // Deeper than a step's motion behind an exposed face only if within the face proper: beside
    // its edge (inside only by the MAXPAR tolerance) it is a node next to a hole, not behind a face.
    if (exposure && g <= -accept_catch && (std::abs(pr.xi) > 1 || std::abs(pr.eta) > 1)) return;
    // The catch depth above bounds the relative motion by the fastest contact node anywhere (one
    // number for the sphere tests); a flying fragment then lets a slow node be caught tens of um
    // deep, a spring nobody compressed (0.06 J each in the default scene). The node can only have
    // crossed this segment by its own and the segment nodes' motion in the step.
    if (v != nullptr && s != last && !exposure) {  // a neighbour switch or a new contact
      double vq2 = 0;
      for (int a = 0; a < 4; ++a) vq2 = std::max(vq2, dot3(&v[3 * std::size_t(q[a])], &v[3 * std::size_t(q[a])]));
      const double crossed = 2 * dt * (v_node + std::sqrt(vq2)) + 0.02 * depth;
      if (g <= -std::min(depth, neighbour ? last_depth + crossed : crossed)) return;
    }
    // The nearest surface wins: the least penetrated segment (ties: the one met first, the
    // segment of the last pass).
    if (best_s < 0 || g > best_g) {
      best = pr;
      best_s = s;
      best_g = g;
    }
  };
  // The segment of the last pass first. Its neighbours take the full release depth; the node's
  // list covers them only within the new-contact depth: search them here unless the node was
  // caught at most that deep on its segment (then anything less penetrated is in the list).
  if (last >= 0) {
    consider(Index(last));
    if (best_s < 0 || -best_g > new_depth_cap_)
      for (Index k = nbr_start_[std::size_t(last)]; k < nbr_start_[std::size_t(last) + 1]; ++k) consider(nbr_[std::size_t(k)]);
  }
  for (Index k = c_begin; k < c_end; ++k) {
    const Index s = cand_[std::size_t(k)];
    if (s != last) consider(s);
  }
  return best_s;
}

void PenaltyContact::refresh_segment(std::size_t s, const double* x) {
  // Coefficient form, bounding sphere (centre c, largest corner distance) and the normal bound:
  // t_xi x t_eta = n0 + xi u + eta w with n0 = a1 x a2, u = a1 x a3, w = a3 x a2 (linear: the
  // xi eta term is a3 x a3 = 0), so over the segment |n - n0| <= |u| + |w| =: E and the unit
  // normal deviates from n0 / |n0| by at most 2 E / |n0| (|a/|a| - b/|b|| <= 2 |a - b| / |b|).
  double* g = &seg_geo_[kGeo * s];
  const Index* q = &seg_nodes_[4 * s];
  const double* p0 = &x[3 * std::size_t(q[0])];
  const double* p1 = &x[3 * std::size_t(q[1])];
  const double* p2 = &x[3 * std::size_t(q[2])];
  const double* p3 = &x[3 * std::size_t(q[3])];
  bilinear_coefficients(p0, p1, p2, p3, g);
  double r2 = 0;
  for (const double* pk : {p0, p1, p2, p3}) {
    const double dx = pk[0] - g[0], dy = pk[1] - g[1], dz = pk[2] - g[2];
    r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
  }
  // Radius as a float rounded up (the sphere tests stay conservative) beside this cycle's stamp.
  const float radius = std::nextafter(float(std::sqrt(r2)), std::numeric_limits<float>::infinity());
  std::memcpy(g + 3, &radius, sizeof radius);
  std::memcpy(reinterpret_cast<char*>(g + 3) + sizeof radius, &cycle_, sizeof cycle_);
  // In-plane bounds for the search's pre-check (find_segment). A node the projection accepts is
  // p = x(xi, eta) + gap n with |xi|, |eta| <= m = MAXPAR, |gap| <= release depth D, and n normal
  // to t_xi = a1 + eta a3 (so n . a1 = -eta n . a3). Hence
  //   |(p - c) . a1| = |xi a1.a1 + eta a1.a2 + xi eta a1.a3 + gap n.a1|
  //                  <= m (|a1|^2 + |a1.a2| + m |a1.a3|) + D m |a3|,
  // and likewise for a2. Stored as two floats in slot 15, rounded up.
  {
    const double m = def_.spec.MAXPAR, a12 = std::abs(dot3(g + 4, g + 8)), tw = g[7] * m * std::sqrt(dot3(g + 12, g + 12));
    const double b_xi = m * (dot3(g + 4, g + 4) + a12 + m * std::abs(dot3(g + 4, g + 12))) + tw;
    const double b_eta = m * (dot3(g + 8, g + 8) + a12 + m * std::abs(dot3(g + 8, g + 12))) + tw;
    const float bound[2] = {float(b_xi * (1 + 1e-6)), float(b_eta * (1 + 1e-6))};
    std::memcpy(g + 15, bound, sizeof bound);
  }
  double n0[3], u[3], w[3];
  cross3(g + 4, g + 8, n0);
  cross3(g + 4, g + 12, u);
  cross3(g + 12, g + 8, w);
  const double len = std::sqrt(dot3(n0, n0));
  // Stored as floats: the bound rounded up and widened by 1e-6, which also covers the relative
  // error of 1 / |n0| in float (the pre-check then still skips only what the exact check skips).
  float normal_bound[2] = {2.0f, 0.0f};  // degenerate: no orientation pre-check
  if (len > 0) {
    normal_bound[0] = float(std::min(2.0, 2 * (std::sqrt(dot3(u, u)) + std::sqrt(dot3(w, w))) / len) * (1 + 1e-6) + 1e-6);
    normal_bound[1] = float(1 / len);
  }
  std::memcpy(g + 11, normal_bound, sizeof normal_bound);
}

void PenaltyContact::refresh_all(const double* x) {
  const std::size_t S = seg_side_.size(), N = sn_node_.size();
  for (std::size_t s = 0; s < S; ++s) refresh_segment(s, x);
  for (std::size_t i = 0; i < N; ++i) node_normal(i, x);
}

void PenaltyContact::node_normal(std::size_t i, const double* x) {
  // Sum over the node's own segments of x_13 x x_24 = 8 a1 x a2 (twice the area times the mean
  // normal), in ascending segment order.
  double* nn = &sn_normal_[3 * i];
  nn[0] = nn[1] = nn[2] = 0;
  for (Index k = own_start_[i]; k < own_start_[i + 1]; ++k) {
    const std::size_t s = std::size_t(own_segs_[std::size_t(k)]);
    double* g = &seg_geo_[kGeo * s];
    if (segment_stamp(g) != cycle_) refresh_segment(s, x);
    double n[3];
    cross3(g + 4, g + 8, n);
    for (int d = 0; d < 3; ++d) nn[d] += 8 * n[d];
  }
}

InitialPenetrations PenaltyContact::resolve_initial_penetrations(std::vector<double>& x) {
  InitialPenetrations r;
  r.moved = def_.spec.initial_penetration == config::ContactSpec::InitialPenetration::Move;
  refresh_all(x.data());
  build_candidates(x.data(), true);  // any depth counts here, so lists sized for the full depth
  for (std::size_t i = 0; i < sn_node_.size(); ++i) {
    Projection pr;
    const long s = find_segment(i, x.data(), pr, std::numeric_limits<double>::infinity());
    if (s < 0) continue;
    const double g = pr.gap - sn_offset_[i];
    ++r.count;
    r.max_depth = std::max(r.max_depth, -g);
    const Index node = sn_node_[i];
    if (r.moved && !node_rigid_[node]) {
      for (int d = 0; d < 3; ++d) x[3 * std::size_t(node) + d] -= g * pr.normal[d];
    } else {
      sn_offset_[i] += g;
    }
  }
  build_candidates(x.data(), false);
  return r;
}

void PenaltyContact::apply(const double* x, const double* v, double* f, double dt) {
  const auto& spec = def_.spec;
  const std::size_t N = sn_node_.size(), U = union_nodes_.size();
  // One pass over the contact nodes: the fastest (it bounds the relative motion in one step) and
  // the re-sort test: at the interval, or when a node has moved a quarter of the list allowance since
  // the last sort (node and segment together then stay within the allowance).
  ++cycles_since_sort_;
  ++cycle_;  // every segment record and node normal is stale until first looked at (find_segment)
  const double lim2 = 0.25 * list_allowance_ * 0.25 * list_allowance_;
  double v_max2 = 0, moved2 = 0;
  for (std::size_t u = 0; u < U; ++u) {
    const std::size_t node = std::size_t(union_nodes_[u]);
    const double* p = &x[3 * node];
    const double* vu = &v[3 * node];
    const double dx = p[0] - x_sort_[3 * u], dy = p[1] - x_sort_[3 * u + 1], dz = p[2] - x_sort_[3 * u + 2];
    moved2 = std::max(moved2, dx * dx + dy * dy + dz * dz);
    v_max2 = std::max(v_max2, dot3(vu, vu));
  }
  // Largest new-contact depth of this pass (find_segment's new_contact_depth below).
  const double step_depth = 4 * dt * std::sqrt(v_max2);
  if (cycles_since_sort_ >= spec.BSORT || moved2 > lim2 || step_depth > new_depth_cap_) sort(x, step_depth);
  std::fill(fc_.begin(), fc_.end(), 0.0);
  forces_ = ContactForces{};
  const bool friction = spec.FS > 0 || spec.FD > 0;
  double friction_work = 0, spring_correction = 0;
  const double v_max = std::sqrt(v_max2);
  for (std::size_t i = 0; i < N; ++i) {
    Projection pr;
    const double* vi = &v[3 * std::size_t(sn_node_[i])];
    const long s = find_segment(i, x, pr, 2.0 * dt * (std::sqrt(dot3(vi, vi)) + v_max), v, dt);
    double* ft = &sn_ft_[3 * i];
    const bool entering = !sn_engaged_[i];
    const long last = sn_segment_[i];
    sn_segment_[i] = s;
    sn_engaged_[i] = s >= 0;
    if (s < 0) {  // released: a spring's remaining potential stays in the contact energy (lost)
      if (!entering) {  // (a node that was not in contact has all of this at zero already)
        sn_exp_seg_[i] = -1;  // an exposure offset ends with the contact
        sn_exp_offset_[i] = 0;
        ft[0] = ft[1] = ft[2] = 0;
        sn_gap_[i] = sn_k_last_[i] = 0;
        for (int d = 0; d < 3; ++d) sn_fn_[3 * i + d] = 0;
      }
      continue;
    }
    // Erosion exposed a face already behind this node, within the face proper (or made it a surface
    // node already behind a face): nothing crossed anything, so a spring of that depth would be energy from nowhere
    // (0.13 J in one step of the default scene). Kept as an offset instead, like an initial
    // penetration, but on that face only (a node beside a hole's edge "behind" the new side face is
    // not offset against the top face it then lands on): the force starts from zero and grows with
    // further penetration; the offset relaxes as the node backs out and ends when it leaves the face.
    if (exposed_pass_ && last < 0 && (sn_new_[i] || seg_new_[std::size_t(s)]) && std::abs(pr.xi) <= 1 &&
        std::abs(pr.eta) <= 1) {
      sn_exp_seg_[i] = s;
      sn_exp_offset_[i] = pr.gap - sn_offset_[i];
      ++exposures_;
    } else if (s != sn_exp_seg_[i]) {  // the offset belongs to the face it was found on
      sn_exp_seg_[i] = -1;
      sn_exp_offset_[i] = 0;
    }
    if (s == sn_exp_seg_[i]) sn_exp_offset_[i] = std::max(sn_exp_offset_[i], pr.gap - sn_offset_[i]);  // relaxes
    const Index node = sn_node_[i];
    const Index* q = &seg_nodes_[4 * std::size_t(s)];
    const double* n = pr.normal;
    const double g = pr.gap - offset_of(i, s);
    const double k = stiffness(i, std::size_t(s));
    double fn = -k * g;
    double vrel[3];
    for (int d = 0; d < 3; ++d) {
      vrel[d] = v[3 * std::size_t(node) + d];
      for (int a = 0; a < 4; ++a) vrel[d] -= pr.N[a] * v[3 * std::size_t(q[a]) + d];
    }
    const double vn = dot3(vrel, n);
    if (spec.VDC > 0) {
      const double ms = sn_mass_[i], mm = seg_node_mass_[s];
      if (ms > 0 && mm > 0) {
        const double omega = std::sqrt(k * (ms + mm) / (ms * mm));
        fn -= spec.VDC / 100.0 * 2.0 * std::min(ms, mm) * omega * vn;
      }
      fn = std::max(fn, 0.0);
    }
    double F[3] = {fn * n[0], fn * n[1], fn * n[2]};
    if (friction) {
      double vt[3] = {vrel[0] - vn * n[0], vrel[1] - vn * n[1], vrel[2] - vn * n[2]};
      const double speed = std::sqrt(dot3(vt, vt));
      const double mu = spec.FD + (spec.FS - spec.FD) * std::exp(-spec.DC * speed);
      const double ftn = dot3(ft, n);
      double trial[3];
      for (int d = 0; d < 3; ++d) trial[d] = ft[d] - ftn * n[d] - k * vt[d] * dt;
      const double mag = std::sqrt(dot3(trial, trial)), limit = mu * fn;
      const double scale = mag > limit && mag > 0 ? limit / mag : 1.0;
      for (int d = 0; d < 3; ++d) {
        ft[d] = scale * trial[d];
        F[d] += ft[d];
      }
      friction_work -= dot3(ft, vt) * dt;
      forces_.tangential += std::sqrt(dot3(ft, ft));
    }
    // Energy of a spring that is new in this step (the node engages, switches segment or the
    // stiffness changed). The trapezoid below books this node's old and new forces times the whole
    // step's relative motion, -0.5 (F_old . v_rel + fn vn) dt, which is right only for a spring
    // whose gap moved continuously from g_old to g. Otherwise:
    //  - engaging: the node crossed the surface part of the way; the spring holds 0.5 k g^2 (the
    //    difference grows as k (vn dt)^2 and with a stiff penalty exceeds the impact energy,
    //    ContactStep test);
    //  - switching: the new spring starts from g0 = g - vn dt (its gap before this step's motion),
    //    potential P0 = 0.5 k g0^2, where the old one had P_old. Its energy is booked as
    //    P - min(P0, P_old): a jump up (a node found deeper behind the new segment than the old
    //    one had it) is energy the discrete model creates, booked here so that the contact energy
    //    keeps its springs' potential and the jump shows in the energy ratio instead of as
    //    negative contact energy; a jump down keeps the lost part in the contact energy like a
    //    spring released while compressed.
    if (entering || s != last || k != sn_k_last_[i]) {
      const double g0 = g - vn * dt;
      const double p_new = 0.5 * k * g * g, p_start = g0 < 0 ? 0.5 * k * g0 * g0 : 0.0;
      const double p_old = entering ? 0.0 : 0.5 * sn_k_last_[i] * sn_gap_[i] * sn_gap_[i];
      const double booked = -0.5 * (dot3(&sn_fn_[3 * i], vrel) + fn * vn) * dt;
      spring_correction += booked - (p_new - std::min(p_start, p_old));
    }
    sn_gap_[i] = g;
    sn_k_last_[i] = k;
    for (int d = 0; d < 3; ++d) sn_fn_[3 * i + d] = fn * n[d];
    forces_.normal += fn;
    forces_.potential += 0.5 * k * g * g;
    ++forces_.active;
    const Index ui = sn_local_[i];
    double* fs = &fc_[3 * std::size_t(ui)];
    for (int d = 0; d < 3; ++d) fs[d] += F[d];
    const Index* ql = &seg_local_[4 * std::size_t(s)];
    for (int a = 0; a < 4; ++a) {
      double* fm = &fc_[3 * std::size_t(ql[a])];
      for (int d = 0; d < 3; ++d) fm[d] -= pr.N[a] * F[d];
    }
    // Stability: the spring is k b b^T (x) D, b = (1, -N_1..-N_4) over the node and the segment
    // nodes, D <= k I (normal spring; the friction return map never exceeds the same k
    // tangentially). Gershgorin on M^-1 K: row j gets k |b_j| sum_l |b_l| over deformable nodes
    // (rigid nodes move with their body, whose mass is far larger; their rows and columns drop out).
    double sum_b = union_inv_mass_[std::size_t(ui)] > 0 ? 1.0 : 0.0;
    for (int a = 0; a < 4; ++a)
      if (union_inv_mass_[std::size_t(ql[a])] > 0) sum_b += pr.N[a];
    union_row_[std::size_t(ui)] += k * sum_b;
    for (int a = 0; a < 4; ++a) union_row_[std::size_t(ql[a])] += k * pr.N[a] * sum_b;
  }
  // Scatter, energy (trapezoid: the step moved the nodes by dt v) and side-A resultant.
  double work = 0, omega2 = 0;
  for (std::size_t u = 0; u < U; ++u) {
    omega2 = std::max(omega2, union_row_[u] * union_inv_mass_[u]);
    union_row_[u] = 0;
    const std::size_t node = std::size_t(union_nodes_[u]);
    for (int d = 0; d < 3; ++d) {
      const double fu = fc_[3 * u + d];
      f[3 * node + d] += fu;
      work += 0.5 * (fc_prev_[3 * u + d] + fu) * v[3 * node + d] * dt;
      if (union_side_a_[u]) forces_.resultant[d] += fu;
    }
  }
  energy_ -= work + spring_correction;
  friction_energy_ += friction_work;
  dt_springs_ = omega2 > 0 ? 2 / std::sqrt(omega2) : kInf;
  exposed_pass_ = false;
  fc_prev_.swap(fc_);
  std::copy(fc_prev_.begin(), fc_prev_.end(), fc_.begin());  // fc_ keeps the last forces for output
}

void PenaltyContact::rebuild(const AliveMask& alive, const std::vector<double>& x) {
  build(x, &alive);
}

}  // namespace plyimpact::contact
