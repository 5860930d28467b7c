#include "cohesive/tiebreak_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace plyimpact::cohesive {
namespace {

inline void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
inline double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Any unit vector perpendicular to the unit vector n.
void perpendicular(const double n[3], double t[3]) {
  const double ax[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[k])) k = i;
  cross(n, ax[k], t);
  const double len = std::sqrt(dot(t, t));
  for (int i = 0; i < 3; ++i) t[i] /= len;
}

// Component of the force of traction (t0, t1, t2) in the frame (n, a, b) on a pair's lower node:
// area (t0 n + t1 a + t2 b), fused explicitly so that both paths of apply round it alike.
[[gnu::always_inline]] inline double frame_force(double area, double t0, double t1, double t2, double n, double a,
                                                 double b) {
  return area * std::fma(t2, b, std::fma(t1, a, t0 * n));
}

}  // namespace

// Mid-surface points of pairs [begin, end), the corners of the faces (computed once per pair, not
// once per face corner: a pair is the corner of up to four faces).
void TiebreakPairs::compute_midpoints(const double* x, std::size_t begin, std::size_t end) {
  for (std::size_t p = begin; p < end; ++p) {
    const auto& c = pairs_[p];
    for (int i = 0; i < 3; ++i) midpoints_[3 * p + i] = 0.5 * (x[3 * c.lower + i] + x[3 * c.upper + i]);
  }
}

// Vector areas 1/2 (d_02 x d_13) of faces [begin, end) on the mid-surface of the last
// compute_midpoints. A cut face keeps the vector it had when erosion cut it: its released corner's
// mid-point is wherever the eroded ply's nodes are, not the interface (a face recomputed from it
// turned the normals of the pairs beside a hole by up to 125 degrees), and dropping the face from
// the sum would turn those normals in one step, which a damaged pair's law turns into energy.
void TiebreakPairs::compute_face_vectors(std::size_t begin, std::size_t end) {
  for (std::size_t f = begin; f < end; ++f) {
    if (!face_cut_.empty() && face_cut_[f]) continue;
    const Index* q = &faces_[4 * f];
    const double* m0 = &midpoints_[3 * std::size_t(q[0])];
    const double* m1 = &midpoints_[3 * std::size_t(q[1])];
    const double* m2 = &midpoints_[3 * std::size_t(q[2])];
    const double* m3 = &midpoints_[3 * std::size_t(q[3])];
    const double d1[3] = {m2[0] - m0[0], m2[1] - m0[1], m2[2] - m0[2]};
    const double d2[3] = {m3[0] - m1[0], m3[1] - m1[1], m3[2] - m1[2]};
    double* a = &face_vector_[3 * f];
    cross(d1, d2, a);
    for (int i = 0; i < 3; ++i) a[i] *= 0.5;
  }
}

// Unit normals of pairs [begin, end) from the face vector areas around each (current face_vector_).
void TiebreakPairs::normals_from_faces(std::size_t begin, std::size_t end) {
  for (std::size_t p = begin; p < end; ++p) {
    double n[3] = {0, 0, 0};
    for (Index k = pair_face_offset_[p]; k < pair_face_offset_[p + 1]; ++k) {
      const double* a = &face_vector_[3 * pair_face_[k]];
      for (int i = 0; i < 3; ++i) n[i] += a[i];
    }
    const double inv = 1 / std::sqrt(dot(n, n));
    for (int i = 0; i < 3; ++i) normals_[3 * p + i] = n[i] * inv;
  }
}

// The frame: n, then t_1 = the reference tangent projected on the plane normal to n (zero if it
// is parallel to n), t_2 = n x t_1; the opening d = x_upper - x_lower - g_0 resolved in it. The
// operations are those of dot and cross above, in their order.
void TiebreakPairs::frames_and_openings(const double* __restrict normals, const PairConst* __restrict pairs,
                                        const double* __restrict x, std::size_t begin, std::size_t m,
                                        double (*__restrict out)[kChunk]) {
#pragma omp simd
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t p = begin + j;
    const PairConst& c = pairs[p];
    const double n0 = normals[3 * p], n1 = normals[3 * p + 1], n2 = normals[3 * p + 2];
    const double* t = c.t1_ref;
    const double tn = t[0] * n0 + t[1] * n1 + t[2] * n2;
    double a0 = t[0] - tn * n0, a1 = t[1] - tn * n1, a2 = t[2] - tn * n2;
    const double len_sq = a0 * a0 + a1 * a1 + a2 * a2;
    const double inv_len = len_sq > 0 ? 1 / std::sqrt(len_sq) : 0.0;
    a0 *= inv_len, a1 *= inv_len, a2 *= inv_len;
    const double b0 = n1 * a2 - n2 * a1, b1 = n2 * a0 - n0 * a2, b2 = n0 * a1 - n1 * a0;
    const std::size_t up = 3 * std::size_t(c.upper), lo = 3 * std::size_t(c.lower);
    const double d0 = x[up] - x[lo] - c.g0[0], d1 = x[up + 1] - x[lo + 1] - c.g0[1], d2 = x[up + 2] - x[lo + 2] - c.g0[2];
    out[0][j] = n0, out[1][j] = n1, out[2][j] = n2;
    out[3][j] = a0, out[4][j] = a1, out[5][j] = a2;
    out[6][j] = b0, out[7][j] = b1, out[8][j] = b2;
    out[9][j] = d0 * n0 + d1 * n1 + d2 * n2;
    out[10][j] = d0 * a0 + d1 * a1 + d2 * a2;
    out[11][j] = d0 * b0 + d1 * b1 + d2 * b2;
  }
}

void TiebreakPairs::intact_pairs(const TractionLaw& law, const double* __restrict elastic_limit,
                                 const double* __restrict damage,
                                 double* __restrict max_opening, const PairConst* __restrict pairs, std::size_t begin,
                                 std::size_t m, const double (*__restrict fo)[kChunk], double (*__restrict out)[kChunk],
                                 unsigned char* __restrict elastic) {
  // K_n and K_t are the card's for every pair (only the strengths differ between pairs).
  const double kn = law.kn, kt = law.kt;
#pragma omp simd
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t p = begin + j;
    const double u0 = fo[9][j], u1 = fo[10][j], u2 = fo[11][j];
    const double ui = u0 > 0 ? u0 : 0;
    const double us_sq = shear_opening_sq(u1, u2);
    const double open = opening_norm(ui, us_sq), mo = max_opening[p];
    // Undamaged (keep = 1: the stiffnesses are K_n and K_t exactly) and no damage to grow.
    const bool take = damage[p] == 0 && (open <= mo || open <= elastic_limit[p]);
    max_opening[p] = take && open > mo ? open : mo;
    const double t0 = kn * u0, t1 = kt * u1, t2 = kt * u2, area = pairs[p].area;
    for (int i = 0; i < 3; ++i) out[i][j] = frame_force(area, t0, t1, t2, fo[i][j], fo[3 + i][j], fo[6 + i][j]);
    out[3][j] = secant_energy(kn, kt, u0, us_sq);
    elastic[j] = take ? 1 : 0;
  }
}

// A separated pair is contact between two faces only while its nodes lie over each other. It is
// taken as open when they have slid apart by more than its tributary width sqrt(A) (one element
// width on a regular grid: the node has left the faces around its partner, which the plies' surface
// contact skips for a separated pair, contact/bonded_interfaces) or when it is pressed deeper than
// the release depth.
// Why: its "normal opening" is the projection of the pair's separation on a normal that the faces
// around it, distorted or eroded, may have turned. In the default scene a pair 29 mm apart read
// 29 um of compression on a tilted normal and its penalty threw 0.27 J into the nodes, and a pair
// 1.25 mm apart (within reach) read 0.43 mm of compression on a normal 58 degrees off the
// interface's and held 58 J (energy ratio 0.995 -> 4.1 within four cycles). No ply presses 0.4 of
// its thickness into its neighbour with its elements intact. A pair released for good
// (release_pair) is open whatever its opening. Contact between separated plies beyond these limits
// is the job of a surface contact (eroding single surface over the plies), which sees the real
// geometry.
namespace {
// Returns true when it opened a pressed pair.
[[gnu::always_inline]] inline bool open_beyond_reach(const PointHistory& h, double area, double release_depth,
                                                     bool released, double u[3]) {
  if (h.damage >= 1 && u[0] < 0 && (released || u[1] * u[1] + u[2] * u[2] > area || u[0] < -release_depth)) {
    u[0] = 0;
    return true;
  }
  return false;
}
}  // namespace

std::vector<Index> pair_faces_from_segments(const std::vector<Index>& lower_nodes,
                                            const std::vector<Index>& lower_segments) {
  Index max_node = -1;
  for (Index node : lower_nodes) max_node = std::max(max_node, node);
  std::vector<Index> pair_of(std::size_t(max_node) + 1, -1);
  for (std::size_t p = 0; p < lower_nodes.size(); ++p) pair_of[lower_nodes[p]] = Index(p);
  std::vector<Index> faces(lower_segments.size());
  for (std::size_t k = 0; k < lower_segments.size(); ++k) {
    const Index node = lower_segments[k];
    const Index pair = node >= 0 && node <= max_node ? pair_of[node] : -1;
    if (pair < 0)
      throw InputError(msg() << "tiebreak pairs: segment " << k / 4 << " has corner node " << node
                             << ", which is not the lower node of any pair");
    faces[k] = pair;
  }
  return faces;
}

void TiebreakPairs::set_normal_refresh_interval(int passes) {
  if (passes < 1) throw InputError(msg() << "tiebreak pairs: normal refresh interval must be >= 1 (got " << passes << ")");
  normal_refresh_interval_ = passes;
}

TiebreakPairs::TiebreakPairs(const TractionLawParams& params, TiebreakPairsSpec spec, const double* x_ref,
                             const double* nodal_mass)
    : laws_(params, spec.lower.size(), spec.nfls, spec.sfls),
      faces_(std::move(spec.faces)),
      release_depth_(spec.release_depth) {
  if (!(release_depth_ > 0))
    throw InputError(msg() << "tiebreak pairs: release depth " << release_depth_ << " m; allowed a positive depth");
  const std::size_t n = spec.lower.size();
  if (spec.upper.size() != n) throw InputError(msg() << "tiebreak pairs: " << n << " lower nodes but " << spec.upper.size() << " upper");
  if (!spec.area.empty() && spec.area.size() != n)
    throw InputError(msg() << "tiebreak pairs: " << spec.area.size() << " areas for " << n << " pairs");
  if (faces_.empty() && spec.normals.size() != 3 * n)
    throw InputError(msg() << "tiebreak pairs: neither interface faces nor " << n << " normals given");
  if (faces_.size() % 4) throw InputError("tiebreak pairs: faces must be quads of pair indices");
  for (Index p : faces_)
    if (p < 0 || std::size_t(p) >= n) throw InputError(msg() << "tiebreak pairs: face refers to pair " << p << " of " << n);

  pairs_.resize(n);
  released_.assign(n, 0);
  Index max_node = -1;
  for (std::size_t p = 0; p < n; ++p) {
    auto& c = pairs_[p];
    c.lower = spec.lower[p];
    c.upper = spec.upper[p];
    if (c.lower < 0 || c.upper < 0 || c.lower == c.upper)
      throw InputError(msg() << "tiebreak pairs: pair " << p << " has nodes " << c.lower << ", " << c.upper);
    max_node = std::max({max_node, c.lower, c.upper});
    for (int i = 0; i < 3; ++i) c.g0[i] = x_ref[3 * c.upper + i] - x_ref[3 * c.lower + i];
    if (!spec.area.empty()) c.area = spec.area[p];
  }
  std::vector<char> seen(std::size_t(max_node) + 1, 0);
  for (const auto& c : pairs_) {
    for (Index node : {c.lower, c.upper}) {
      if (seen[node]) nodes_distinct_ = false;
      seen[node] = 1;
    }
  }

  if (faces_.empty()) {
    normals_ = std::move(spec.normals);
    for (std::size_t p = 0; p < n; ++p) {
      double* nn = &normals_[3 * p];
      const double len = std::sqrt(dot(nn, nn));
      if (!(len > 0)) throw InputError(msg() << "tiebreak pairs: pair " << p << " has a zero normal");
      for (int i = 0; i < 3; ++i) nn[i] /= len;
    }
  } else {
    build_face_adjacency(x_ref, spec.area.empty());
    normals_.assign(3 * n, 0.0);
    normals_from_faces(0, n);
    for (std::size_t p = 0; p < n; ++p)
      if (!std::isfinite(normals_[3 * p]) || !std::isfinite(normals_[3 * p + 1]) || !std::isfinite(normals_[3 * p + 2]))
        throw InputError(msg() << "tiebreak pairs: the faces around pair " << p << " have no area (no normal)");
  }
  for (std::size_t p = 0; p < n; ++p) {
    if (!(pairs_[p].area > 0)) throw InputError(msg() << "tiebreak pairs: pair " << p << " has no tributary area");
    perpendicular(&normals_[3 * p], pairs_[p].t1_ref);
  }

  elastic_limit_.resize(n);
  for (std::size_t p = 0; p < n; ++p) elastic_limit_[p] = laws_.of(p).elastic_limit;
  history_.assign(n);
  point_elastic_.assign(n, 0.0);
  sums_.assign((n + kChunk - 1) / kChunk);
  set_nodal_mass(nodal_mass);
}

void TiebreakPairs::build_face_adjacency(const double* x_ref, bool areas_from_faces) {
  const std::size_t n = pairs_.size(), nf = faces_.size() / 4;
  face_vector_.assign(3 * nf, 0.0);
  face_cut_.assign(nf, 0);
  midpoints_.assign(3 * n, 0.0);
  compute_midpoints(x_ref, 0, n);
  compute_face_vectors(0, nf);
  std::vector<Index> count(n + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const Index* q = &faces_[4 * f];
    const int distinct = q[3] == q[2] ? 3 : 4;
    const double a = std::sqrt(dot(&face_vector_[3 * f], &face_vector_[3 * f]));
    for (int k = 0; k < distinct; ++k) {
      ++count[q[k] + 1];
      if (areas_from_faces) pairs_[q[k]].area += a / distinct;
    }
  }
  for (std::size_t p = 0; p < n; ++p) count[p + 1] += count[p];
  pair_face_offset_ = count;
  pair_face_.resize(count[n]);
  for (std::size_t f = 0; f < nf; ++f) {
    const Index* q = &faces_[4 * f];
    const int distinct = q[3] == q[2] ? 3 : 4;
    for (int k = 0; k < distinct; ++k) pair_face_[count[q[k]]++] = Index(f);
  }
  for (std::size_t p = 0; p < n; ++p)
    if (pair_face_offset_[p] == pair_face_offset_[p + 1])
      throw InputError(msg() << "tiebreak pairs: pair " << p << " lies on no interface face (no normal)");
}

void TiebreakPairs::cut_faces_around(std::size_t pair) {
  if (pair_face_offset_.empty()) return;  // fixed normals: no faces
  for (Index k = pair_face_offset_[pair]; k < pair_face_offset_[pair + 1]; ++k) face_cut_[std::size_t(pair_face_[k])] = 1;
}

void TiebreakPairs::release_pair(std::size_t pair) {
  released_[pair] = 1;
  cut_faces_around(pair);
  dissipated_energy_ += pairs_[pair].area * point_elastic_[pair];
  point_elastic_[pair] = 0;
  history_.release(pair);
}

void TiebreakPairs::apply(const double* x, const double* /*v*/, double* f, double /*dt*/) {
  const std::size_t n = pairs_.size(), nf = faces_.size() / 4;
  const std::size_t chunks = sums_.size();
  const bool parallel = nodes_distinct_ && n >= 2 * kChunk;
  const bool refresh = nf && passes_ % std::uint64_t(normal_refresh_interval_) == 0;
  ++passes_;
#pragma omp parallel if (parallel)
  {
    if (refresh) {
#pragma omp for schedule(static)
      for (std::size_t b = 0; b < n; b += kChunk) compute_midpoints(x, b, std::min(n, b + kChunk));
#pragma omp for schedule(static)
      for (std::size_t b = 0; b < nf; b += kChunk) compute_face_vectors(b, std::min(nf, b + kChunk));
#pragma omp for schedule(static)
      for (std::size_t b = 0; b < n; b += kChunk) normals_from_faces(b, std::min(n, b + kChunk));
    }
#pragma omp for schedule(static)
    for (std::size_t ch = 0; ch < chunks; ++ch) {
      double elastic = 0, dissipated = 0, separated = 0;
      const std::size_t begin = ch * kChunk, end = std::min(n, begin + kChunk);
      alignas(64) double fo[12][kChunk], fi[4][kChunk];
      alignas(64) unsigned char intact[kChunk];
      frames_and_openings(normals_.data(), pairs_.data(), x, begin, end - begin, fo);
      intact_pairs(laws_.card(), elastic_limit_.data(), history_.damage().data(), history_.max_opening_data(),
                   pairs_.data(), begin, end - begin, fo, fi, intact);
      for (std::size_t p = begin; p < end; ++p) {
        const std::size_t j = p - begin;
        const auto& c = pairs_[p];
        if (intact[j]) {  // no dissipation, not separated
          point_elastic_[p] = fi[3][j];
          for (int i = 0; i < 3; ++i) {
            f[3 * c.lower + i] += fi[i][j];
            f[3 * c.upper + i] -= fi[i][j];
          }
          elastic += c.area * fi[3][j];
          continue;
        }
        double u[3] = {fo[9][j], fo[10][j], fo[11][j]};
        PointHistory h = history_.load(p);
        // A pair let go by the rules above drops the penalty energy of its compression at once;
        // like an eroded element's energy it stays in the balance, booked as dissipated (the
        // stick spring's share the law books itself when the pair opens).
        const double dropped = open_beyond_reach(h, c.area, release_depth_, released_[p] != 0, u)
                                   ? std::max(0.0, point_elastic_[p] - h.stick_energy)
                                   : 0.0;
        PointResponse r;
        traction_update(laws_.of(p), u, h, r);
        r.dissipated_increment += dropped;
        point_elastic_[p] = r.elastic_energy;
        history_.store(p, h);
        const double* t = r.traction;
        for (int i = 0; i < 3; ++i) {
          const double force = frame_force(c.area, t[0], t[1], t[2], fo[i][j], fo[3 + i][j], fo[6 + i][j]);
          f[3 * c.lower + i] += force;
          f[3 * c.upper + i] -= force;
        }
        elastic += c.area * r.elastic_energy;
        dissipated += c.area * r.dissipated_increment;
        if (h.damage >= 1 && !released_[p]) separated += c.area;  // a released pair is the hole, not a delamination
      }
      sums_.set(ch, elastic, dissipated, separated);
    }
  }
  const ChunkSums::Totals total = sums_.total();
  elastic_energy_ = total.elastic;
  dissipated_energy_ += total.dissipated;
  separated_area_ = total.separated;
}

void TiebreakPairs::set_nodal_mass(const double* nodal_mass) {
  stable_step_ = std::numeric_limits<double>::infinity();
  stable_step_pair_ = -1;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    const auto& c = pairs_[p];
    const double k = laws_.card().k_max * c.area;  // the strengths do not change the stiffness
    const double omega_sq = k * (1 / nodal_mass[c.lower] + 1 / nodal_mass[c.upper]);
    const double dt = 2 / std::sqrt(omega_sq);
    if (dt < stable_step_) {
      stable_step_ = dt;
      stable_step_pair_ = Index(p);
    }
  }
}

void TiebreakPairs::sample(const double* x, PairSample* out) const {
  const std::size_t n = pairs_.size();
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t end = std::min(n, begin + kChunk);
    alignas(64) double fo[12][kChunk];
    frames_and_openings(normals_.data(), pairs_.data(), x, begin, end - begin, fo);
    for (std::size_t p = begin; p < end; ++p) {
      PairSample& s = out[p];
      for (int i = 0; i < 3; ++i) s.opening[i] = fo[9 + i][p - begin];
      const PointHistory h = history_.load(p);
      open_beyond_reach(h, pairs_[p].area, release_depth_, released_[p] != 0, s.opening);
      sample_point(laws_.of(p), h, s);
    }
  }
}

void TiebreakPairs::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "tiebreak pairs");
  history_.visit_state(visitor);
  visitor.scalar("dissipated_energy", dissipated_energy_);
  visitor.array("normal", normals_);
  visitor.scalar("passes", passes_);
  visitor.fixed_array("released", released_);
  visitor.fixed_array("face_vector", face_vector_);
  // Which faces are cut follows from the released pairs (a reader has just replaced them).
  std::fill(face_cut_.begin(), face_cut_.end(), 0);
  for (std::size_t p = 0; p < released_.size(); ++p)
    if (released_[p]) cut_faces_around(p);
  visitor.fixed_array("point_elastic", point_elastic_);
}

}  // namespace plyimpact::cohesive
