#include "contact/segment_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/geometry.hpp"
#include "contact/parallel_items.hpp"

namespace plyimpact::contact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

double default_release_depth(double volume, double area) {
  // LS-DYNA's 0.4 x the segment thickness [KW *CONTACT, PENMAX]: for a solid the element's depth
  // behind the face, V/A, so a node is caught only by the element it is inside of (a face of a
  // 0.25 mm ply reaches 0.1 mm, not into the plies below it). A face without volume (a rigid
  // surface-only body) has no thickness: 0.4 x its edge, sqrt(A).
  return 0.4 * (volume > 0 ? volume / area : std::sqrt(area));
}
}  // namespace

SegmentSetSpec segment_set_spec(const model::Contact& def) {
  const auto& spec = def.spec;
  SegmentSetSpec s;
  s.single = spec.type == config::ContactSpec::Type::SingleSurface;
  s.blocks[0] = def.a.blocks;
  s.impactor[0] = def.a.impactor;
  if (!s.single) {
    s.blocks[1] = def.b.blocks;
    s.impactor[1] = def.b.impactor;
  }
  s.stiffness_scale[0] = spec.SLSFAC * spec.SFS;
  s.stiffness_scale[1] = spec.SLSFAC * spec.SFM;
  s.PENMAX = spec.PENMAX;
  s.keep_orphans = spec.ENMASS == 1;
  return s;
}

SegmentSet::SegmentSet(const model::Model& model, SegmentSetSpec spec, const std::vector<double>& x)
    : model_(&model), spec_(std::move(spec)) {
  builder_[0] = SurfaceBuilder(model, spec_.blocks[0]);
  if (!spec_.single) builder_[1] = SurfaceBuilder(model, spec_.blocks[1]);
  node_rigid_.assign(model.num_nodes(), 0);
  for (const auto& body : model.rigid_bodies)
    for (Index n : body.nodes) node_rigid_[n] = 1;
  force_of_model_.assign(model.num_nodes(), -1);
  assemble(x, nullptr, nullptr);
  build_neighbours();
}

namespace {
// Identity of segment s of a set (its nodes (S, 4) and sides): side and sorted nodes.
std::array<Index, 5> key_of(const std::vector<Index>& seg_nodes, const std::vector<char>& seg_side, std::size_t s) {
  std::array<Index, 5> key{Index(seg_side[s]), seg_nodes[4 * s], seg_nodes[4 * s + 1], seg_nodes[4 * s + 2],
                           seg_nodes[4 * s + 3]};
  std::sort(key.begin() + 1, key.end());
  return key;
}
}  // namespace

std::array<Index, 5> SegmentSet::segment_key(long s) const {
  if (s < 0) return {-1, -1, -1, -1, -1};
  return key_of(seg_nodes_, seg_side_, std::size_t(s));
}

SegmentSetRemap SegmentSet::rebuild(const AliveMask& alive, const std::vector<double>& x) {
  // The old identities: contact nodes by model node and side, segments by key, force nodes by node.
  Identities& old = previous_;
  old.node_id.swap(node_id_);
  old.node_side.swap(node_side_);
  old.node_k.swap(node_k_);
  old.seg_nodes.swap(seg_nodes_);
  old.seg_side.swap(seg_side_);
  old.force_nodes.assign(force_nodes_.begin(), force_nodes_.end());  // build_force_nodes clears their map
  old.nbr_start.swap(nbr_start_);
  old.nbr.swap(nbr_);
  const std::size_t old_nodes = old.node_id.size(), old_segments = old.seg_side.size();
  assemble(x, &alive, &old);
  SegmentSetRemap r;
  const std::size_t N = num_nodes(), S = num_segments(), n_model = model_->num_nodes();
  std::vector<Index> node_of(2 * n_model, -1);
  for (std::size_t i = 0; i < N; ++i) node_of[2 * std::size_t(node_id_[i]) + node_side_[i]] = Index(i);
  r.node.resize(old_nodes);
  for (std::size_t i = 0; i < old_nodes; ++i) r.node[i] = node_of[2 * std::size_t(old.node_id[i]) + old.node_side[i]];
  // Each old segment's new index: the first new segment with its key. The new segments are listed
  // by their smallest node (CSR, ascending), so a lookup compares a few keys. Neither a map nor a
  // sort: a rebuild runs at every cycle that erodes an element, over all ~19,000 segments of the
  // default scene.
  std::vector<std::array<Index, 5>> key(S);
  const bool parallel = parallel_items(std::max(S, old_segments));
#pragma omp parallel for schedule(static) if (parallel)
  for (long s = 0; s < long(S); ++s) key[std::size_t(s)] = segment_key(s);
  std::vector<Index> start(n_model + 1, 0);
  for (std::size_t s = 0; s < S; ++s) ++start[std::size_t(key[s][1]) + 1];
  for (std::size_t n = 0; n < n_model; ++n) start[n + 1] += start[n];
  std::vector<Index> by_node(S), fill(start.begin(), start.end() - 1);
  for (std::size_t s = 0; s < S; ++s) by_node[std::size_t(fill[std::size_t(key[s][1])]++)] = Index(s);
  r.segment.resize(old_segments);
#pragma omp parallel for schedule(static) if (parallel)
  for (long i = 0; i < long(old_segments); ++i) {
    const std::size_t s = std::size_t(i);
    const std::array<Index, 5> k = key_of(old.seg_nodes, old.seg_side, s);
    r.segment[s] = -1;
    for (Index j = start[std::size_t(k[1])]; j < start[std::size_t(k[1]) + 1]; ++j)
      if (key[std::size_t(by_node[std::size_t(j)])] == k) {
        r.segment[s] = by_node[std::size_t(j)];
        break;
      }
  }
  r.force_node.resize(old.force_nodes.size());
  for (std::size_t u = 0; u < old.force_nodes.size(); ++u) r.force_node[u] = force_of_model_[old.force_nodes[u]];
  // What the rebuild added (nothing when there was no surface before).
  r.new_node.assign(N, 0);
  r.new_segment.assign(S, 0);
  if (old_nodes > 0) {
    std::vector<char> known(N, 0), kept(S, 0);
    for (Index i : r.node)
      if (i >= 0) known[std::size_t(i)] = 1;
    for (long s : r.segment)
      if (s >= 0) kept[std::size_t(s)] = 1;
    for (std::size_t i = 0; i < N; ++i) r.new_node[i] = !known[i];
    for (std::size_t s = 0; s < S; ++s) r.new_segment[s] = !kept[s];
  }
  build_neighbours(&old, &r);
  return r;
}

void SegmentSet::assemble(const std::vector<double>& x, const AliveMask* alive, const Identities* old) {
  seg_nodes_.clear();
  seg_owner_.clear();
  seg_side_.clear();
  seg_k_.clear();
  seg_mass_.clear();
  seg_node_mass_.clear();
  seg_depth_.clear();
  add_side(0, builder_[0], alive, x);
  if (!spec_.single) add_side(1, builder_[1], alive, x);
  collect_nodes(old);
  build_own_segments();
  build_force_nodes();
}

void SegmentSet::set_segment(std::size_t s, const Index* q, const Index* owner, int side, double K, double volume,
                             double elem_mass, const std::vector<double>& x) {
  double xq[12];
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) xq[3 * k + d] = x[3 * std::size_t(q[k]) + d];
  const double area = quad_area(xq);
  const double sf = spec_.stiffness_scale[side];
  std::copy_n(q, 4, &seg_nodes_[4 * s]);
  for (int k = 0; k < 8; ++k) seg_owner_[8 * s + std::size_t(k)] = owner ? owner[k] : -1;
  seg_side_[s] = char(side);
  seg_k_[s] = K > 0 && volume > 0 ? sf * K * area * area / volume : kInf;  // PENOPT 1
  seg_mass_[s] = elem_mass > 0 ? 0.5 * elem_mass : 0.0;
  double m = 0;
  for (int k = 0; k < 4; ++k) m += 0.25 * model_->mass[q[k]];
  seg_node_mass_[s] = m;
  seg_depth_[s] = spec_.PENMAX > 0 ? spec_.PENMAX : default_release_depth(volume, area);
}

void SegmentSet::resize_segments(std::size_t S) {
  seg_nodes_.resize(4 * S);
  seg_owner_.resize(8 * S);
  seg_side_.resize(S);
  seg_k_.resize(S);
  seg_mass_.resize(S);
  seg_node_mass_.resize(S);
  seg_depth_.resize(S);
}

void SegmentSet::add_side(int side, const SurfaceBuilder& builder, const AliveMask* alive,
                          const std::vector<double>& x) {
  const model::Model& model = *model_;
  const std::vector<SurfaceBuilder::Face> faces = builder.exterior(alive);
  const std::size_t base = num_segments(), nf = faces.size();
  const std::size_t nq = spec_.impactor[side] ? model.impactor_quads.size() / 4 : 0;
  resize_segments(base + nf + nq);
  // Each segment's data depend on its face alone: filled in parallel, the same for any thread count.
  // A rebuild (every eroding cycle) recomputes them all, as the areas are those at x.
  const long n = long(nf);
#pragma omp parallel for schedule(static) if (parallel_items(nf))
  for (long i = 0; i < n; ++i) {
    const auto& f = faces[std::size_t(i)];
    const auto& blk = model.blocks[f.block];
    const auto& mat = model.materials[blk.material];
    const Index* conn = &blk.conn[8 * std::size_t(f.element)];
    Index q[4];
    for (int k = 0; k < 4; ++k) q[k] = conn[kHexFaces[f.face][k]];
    const double volume = blk.volume0[f.element];
    set_segment(base + std::size_t(i), q, conn, side, mat.bulk_modulus, volume, mat.density * volume, x);
  }
  // No element behind the impactor's surface: infinite PENOPT 1 stiffness (the node's decides), an
  // equal share of the impactor's mass.
  const double m = model.impactor ? model.impactor->mass / double(std::max<std::size_t>(nq, 1)) : 0.0;
  for (std::size_t s = 0; s < nq; ++s)
    set_segment(base + nf + s, &model.impactor_quads[4 * s], nullptr, side, 0.0, 0.0, 2 * m, x);
}

void SegmentSet::collect_nodes(const Identities* old) {
  // The segment nodes of each side, by model node then side; node stiffness and segment mass are
  // the means over the node's segments of that side.
  const model::Model& model = *model_;
  const std::size_t S = num_segments(), n_model = model.num_nodes();
  std::vector<double> k_sum(n_model * 2, 0.0), segm_sum(n_model * 2, 0.0);
  std::vector<int> k_count(n_model * 2, 0);
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k) {
      const std::size_t key = 2 * std::size_t(seg_nodes_[4 * s + k]) + seg_side_[s];
      k_sum[key] += seg_k_[s];
      segm_sum[key] += seg_mass_[s];
      ++k_count[key];
    }
  node_id_.clear();
  node_side_.clear();
  node_k_.clear();
  node_mass_.clear();
  node_seg_mass_.clear();
  for (std::size_t n = 0; n < n_model; ++n)
    for (int side = 0; side < 2; ++side) {
      const std::size_t key = 2 * n + side;
      if (k_count[key] == 0) continue;
      node_id_.push_back(Index(n));
      node_side_.push_back(char(side));
      node_k_.push_back(k_sum[key] / k_count[key]);
      node_mass_.push_back(model.mass[n]);
      node_seg_mass_.push_back(segm_sum[key] / k_count[key]);
    }
  if (spec_.keep_orphans && old)
    for (std::size_t i = 0; i < old->node_id.size(); ++i) {
      const Index n = old->node_id[i];
      if (k_count[2 * std::size_t(n)] == 0 && k_count[2 * std::size_t(n) + 1] == 0 && model.mass[n] > 0) {
        // Orphan node kept as a contact mass point, on the side it belonged to.
        node_id_.push_back(n);
        node_side_.push_back(char(spec_.single ? 0 : old->node_side[i]));
        node_k_.push_back(old->node_k[i]);
        node_mass_.push_back(model.mass[n]);
        node_seg_mass_.push_back(model.mass[n]);
      }
    }
}

void SegmentSet::build_own_segments() {
  // Own-side segments of each contact node (CSR, ascending segment order).
  const std::size_t N = num_nodes(), S = num_segments();
  std::vector<Index> node_of(2 * model_->num_nodes(), -1);
  for (std::size_t i = 0; i < N; ++i) node_of[2 * std::size_t(node_id_[i]) + node_side_[i]] = Index(i);
  std::vector<Index> seg_node(4 * S);  // contact node of each segment node on the segment's side
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k) seg_node[4 * s + k] = node_of[2 * std::size_t(seg_nodes_[4 * s + k]) + seg_side_[s]];
  own_start_.assign(N + 1, 0);
  for (Index i : seg_node)
    if (i >= 0) ++own_start_[std::size_t(i) + 1];
  for (std::size_t i = 0; i < N; ++i) own_start_[i + 1] += own_start_[i];
  own_segs_.resize(std::size_t(own_start_[N]));
  std::vector<Index> fill(own_start_.begin(), own_start_.end() - 1);
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k)
      if (const Index i = seg_node[4 * s + k]; i >= 0) own_segs_[std::size_t(fill[std::size_t(i)]++)] = Index(s);
}

void SegmentSet::build_force_nodes() {
  // Union of the contact nodes and the segment nodes, in that order of first appearance.
  for (Index n : force_nodes_) force_of_model_[n] = -1;
  force_nodes_.clear();
  force_side_a_.clear();
  auto add = [&](Index n, bool side_a) {
    if (force_of_model_[n] < 0) {
      force_of_model_[n] = Index(force_nodes_.size());
      force_nodes_.push_back(n);
      force_side_a_.push_back(0);
    }
    if (side_a) force_side_a_[force_of_model_[n]] = 1;
  };
  const std::size_t N = num_nodes(), S = num_segments();
  for (std::size_t i = 0; i < N; ++i) add(node_id_[i], node_side_[i] == 0 && !spec_.single);
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k) add(seg_nodes_[4 * s + k], seg_side_[s] == 0 && !spec_.single);
  node_force_.resize(N);
  for (std::size_t i = 0; i < N; ++i) node_force_[i] = force_of_model_[node_id_[i]];
  seg_force_.resize(4 * S);
  for (std::size_t k = 0; k < 4 * S; ++k) seg_force_[k] = force_of_model_[seg_nodes_[k]];
  const std::size_t U = force_nodes_.size();
  force_inv_mass_.resize(U);
  for (std::size_t u = 0; u < U; ++u) {
    const Index n = force_nodes_[u];
    force_inv_mass_[u] = !node_rigid_[n] && model_->mass[n] > 0 ? 1 / model_->mass[n] : 0.0;
  }
}

void SegmentSet::build_neighbours(const Identities* old, const SegmentSetRemap* remap) {
  // Segments of the same side sharing a node with s (CSR, ascending, s itself left out).
  // The segments of each model node as CSR, ascending (one allocation, not one per node: this runs
  // at every rebuild).
  const std::size_t S = num_segments(), n_model = model_->num_nodes();
  std::vector<Index> start(n_model + 1, 0);
  for (std::size_t k = 0; k < 4 * S; ++k) ++start[std::size_t(seg_nodes_[k]) + 1];
  for (std::size_t n = 0; n < n_model; ++n) start[n + 1] += start[n];
  std::vector<Index> of_node(static_cast<std::size_t>(start[n_model]));
  std::vector<Index> fill(start.begin(), start.end() - 1);
  for (std::size_t s = 0; s < S; ++s)
    for (int k = 0; k < 4; ++k) of_node[std::size_t(fill[std::size_t(seg_nodes_[4 * s + std::size_t(k)])]++)] = Index(s);
  // After a rebuild, a segment none of whose nodes lost or gained a segment has the neighbours it
  // had, renumbered. The survivors keep their order (both sets list the exterior faces in the
  // builders' fixed face order), so the renumbered lists stay ascending. A search of every segment's
  // nodes would cost a third of a rebuild (BENCHMARKS.md), and one runs at every eroding cycle.
  std::vector<Index> old_of;
  std::vector<char> changed;
  if (old && remap) {
    old_of.assign(S, -1);
    changed.assign(n_model, 0);
    for (std::size_t o = 0; o < remap->segment.size(); ++o) {
      if (const long t = remap->segment[o]; t >= 0) {
        old_of[std::size_t(t)] = Index(o);
        continue;
      }
      for (int k = 0; k < 4; ++k) changed[std::size_t(old->seg_nodes[4 * o + std::size_t(k)])] = 1;
    }
    for (std::size_t s = 0; s < S; ++s)
      if (old_of[s] < 0)
        for (int k = 0; k < 4; ++k) changed[std::size_t(seg_nodes_[4 * s + std::size_t(k)])] = 1;
  }
  nbr_start_.assign(S + 1, 0);
  nbr_.clear();
  std::vector<Index> near;
  for (std::size_t s = 0; s < S; ++s) {
    const Index* q = &seg_nodes_[4 * s];
    const bool carried = !old_of.empty() && old_of[s] >= 0 && !changed[std::size_t(q[0])] &&
                         !changed[std::size_t(q[1])] && !changed[std::size_t(q[2])] && !changed[std::size_t(q[3])];
    if (carried) {
      const std::size_t o = std::size_t(old_of[s]);
      for (Index j = old->nbr_start[o]; j < old->nbr_start[o + 1]; ++j)
        nbr_.push_back(Index(remap->segment[std::size_t(old->nbr[std::size_t(j)])]));
    } else {
      near.clear();
      for (int k = 0; k < 4; ++k) {
        const std::size_t n = std::size_t(q[k]);
        for (Index j = start[n]; j < start[n + 1]; ++j)
          if (const Index t = of_node[std::size_t(j)]; t != Index(s) && seg_side_[std::size_t(t)] == seg_side_[s])
            near.push_back(t);
      }
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      nbr_.insert(nbr_.end(), near.begin(), near.end());
    }
    nbr_start_[s + 1] = Index(nbr_.size());
  }
}

void SegmentSet::visit_state(StateVisitor& v) {
  StateGroup group(v, "segment set");
  v.array("segment nodes", seg_nodes_);
  v.array("segment owners", seg_owner_);
  v.array("segment sides", seg_side_);
  v.array("segment stiffness", seg_k_);
  v.array("segment mass", seg_mass_);
  v.array("segment node mass", seg_node_mass_);
  v.array("release depth", seg_depth_);
  v.array("neighbour starts", nbr_start_);
  v.array("neighbours", nbr_);
  v.array("node ids", node_id_);
  v.array("node sides", node_side_);
  v.array("node stiffness", node_k_);
  v.array("node mass", node_mass_);
  v.array("node segment mass", node_seg_mass_);
  v.array("own segment starts", own_start_);
  v.array("own segments", own_segs_);
  v.array("force nodes", force_nodes_);
  v.array("force node of model node", force_of_model_);
  v.array("force node side A", force_side_a_);
  v.array("force node inverse mass", force_inv_mass_);
  v.array("force node of contact node", node_force_);
  v.array("force nodes of segments", seg_force_);
}

}  // namespace plyimpact::contact
