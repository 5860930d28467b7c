// Tiebreak on matching node pairs: the duplicated nodes of a ply interface (lower node on the ply
// below, upper node on the ply above) held together by a traction-separation law (traction_law.hpp)
// acting on each pair's tributary area, until the pair separates and only contact is left.
//   opening : delta = (x_upper - x_lower) - g_0 (g_0 the reference offset, normally 0), resolved in
//             the pair's frame: n from the current mid-surface (area-weighted normal of the interface
//             faces around the pair, faces given as quads of pair indices; refreshed every pass or
//             every K passes) or a fixed given normal;
//             t_1 = the reference tangent projected on the current tangent plane, t_2 = n x t_1.
//   force   : F = A (t_n n + t_1 e_1 + t_2 e_2) on the lower node and -F on the upper one, so linear
//             momentum is conserved to round-off. A is the reference tributary area (fixed: the spring
//             of each pair is then conservative, and its energy is the work of its forces).
//   energy  : elastic = sum A e (now); dissipated = running sum of A dD (damage, friction, released
//             stick springs). Sums are taken per fixed chunk of pairs and the chunks added in order, so
//             the result is bit-identical for any thread count.
//   step    : each pair is two masses on a spring k = max(K_n, K_t) A (the compression penalty never
//             softens): dt = 2 / sqrt(k (1/m_l + 1/m_u)); stable_step() is the smallest. It bounds the
//             pair alone; combine it with the element step as the solver combines contact springs
//             (1/dt^2 = 1/dt_e^2 + 1/dt_p^2, Solver::combined_step).
// No allocation per call; OpenMP over pairs (static schedule; nodes of different pairs must be
// distinct for the parallel scatter, otherwise the pass runs serially).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "cohesive/law_table.hpp"
#include "cohesive/point_histories.hpp"
#include "cohesive/point_sample.hpp"
#include "cohesive/traction_law.hpp"
#include "core/aligned_allocator.hpp"
#include "core/state_visitor.hpp"
#include "core/types.hpp"

namespace plyimpact::cohesive {

struct TiebreakPairsSpec {
  std::vector<Index> lower;      // (num_pairs) node indices on the lower ply
  std::vector<Index> upper;      // (num_pairs) matching node indices on the upper ply
  std::vector<double> area;      // (num_pairs) m^2 tributary areas; empty: a quarter of each adjacent face
  std::vector<Index> faces;      // (num_faces, 4) pair indices, counter-clockwise seen from the upper ply
                                 // (a triangle repeats its last pair); empty: fixed `normals`
  std::vector<double> normals;   // (num_pairs, 3) unit normals pointing from the lower to the upper ply
  // m: a separated pair pressed deeper than this is taken as open (released), as a penalty contact
  // releases a node behind its release depth; infinite: never.
  double release_depth = std::numeric_limits<double>::infinity();
  // Pa: each pair's own peak tractions in place of the law's NFLS and SFLS (e.g. lowered so that the
  // process zone spans a number of segments, law_parameters.hpp); both empty: the law's.
  std::vector<double> nfls, sfls;
};

// Interface faces as quads of pair indices from quads of lower-side node indices (faces whose normal
// points to the upper ply, as the mesher's lower segments are). Throws InputError when a segment
// corner is not a lower node of a pair.
std::vector<Index> pair_faces_from_segments(const std::vector<Index>& lower_nodes,
                                            const std::vector<Index>& lower_segments);

class TiebreakPairs {
 public:
  // x_ref: (num_nodes, 3) reference coordinates; nodal_mass: (num_nodes) kg. Throws InputError on a
  // bad law or spec (sizes, indices, a pair without area or normal).
  TiebreakPairs(const TractionLawParams& params, TiebreakPairsSpec spec, const double* x_ref, const double* nodal_mass);

  // Adds the interface forces for the configuration x ((num_nodes, 3)) to f and updates the history.
  // v and dt are part of the force-contributor interface; the laws are rate independent.
  void apply(const double* x, const double* v, double* f, double dt);

  double elastic_energy() const { return elastic_energy_; }         // J, at the last apply
  double dissipated_energy() const { return dissipated_energy_; }   // J, since the start
  double separated_area() const { return separated_area_; }         // m^2 of pairs with d = 1, not released
  double stable_step() const { return stable_step_; }               // s, stiffest pair alone
  Index stable_step_pair() const { return stable_step_pair_; }      // the pair that sets it

  // With faces, the normals are recomputed from the current mid-surface every `passes` calls of
  // apply() (default 1: every pass). Between refreshes opening and force use the same frame, so each
  // pair's spring stays conservative; the lag is the interface rotation over `passes` steps.
  void set_normal_refresh_interval(int passes);

  // Recomputes the stable step after the nodal masses change (mass scaling, erosion).
  void set_nodal_mass(const double* nodal_mass);

  std::size_t size() const { return pairs_.size(); }
  const TractionLaw& law() const { return laws_.card(); }                  // the card's
  const TractionLaw& law(std::size_t pair) const { return laws_.of(pair); }  // with the pair's strengths
  const LawTable& laws() const { return laws_; }
  const std::vector<double>& damage() const { return history_.damage(); }  // (num_pairs)
  double area(std::size_t pair) const { return pairs_[pair].area; }
  // Initial history of a pre-crack: the pair starts separated.
  void separate_pair(std::size_t pair) { history_.separate(pair); }
  // A pair whose ply is gone on one side (every element around its lower or its upper node eroded)
  // joins nothing: separated for good, no contact, no force from then on (as LS-DYNA drops the
  // segments of eroded elements from a contact). The energy it held stays in the balance, booked
  // as dissipated, as an eroded element's energy stays in the totals.
  void release_pair(std::size_t pair);
  bool released(std::size_t pair) const { return released_[pair] != 0; }
  const std::vector<char>& released_flags() const { return released_; }  // (num_pairs) 1: released

  // Per-pair output for configuration x into out[0 .. size()), in the frames of the last pass.
  void sample(const double* x, PairSample* out) const;

  // Names the per-pair history (max_opening, damage, slip_1, slip_2, stick_energy), the dissipated
  // energy, the normals and the pass count (both decide the frame when the refresh interval is > 1).
  void visit_state(StateVisitor& visitor);

 private:
  // Marks the faces around a released pair as cut (face_cut_).
  void cut_faces_around(std::size_t pair);
  struct alignas(64) PairConst {  // one cache line per pair
    Index lower = 0, upper = 0;
    double area = 0;     // m^2
    double g0[3]{};      // m, reference offset upper - lower
    double t1_ref[3]{};  // reference tangent (unit)
  };
  // Pairs per block of frames and openings, and per chunk of the energy sums (fixed, so that the
  // sums do not depend on the thread count).
  static constexpr std::size_t kChunk = 1024;
  // Frames and openings of pairs [begin, begin + m), m <= kChunk, lane-major: out[0..2][j] = n,
  // out[3..5][j] = t_1, out[6..8][j] = t_2, out[9..11][j] = the opening in that frame (m). One loop
  // without branches on the history, which GCC vectorises (gathers of the node positions).
  static void frames_and_openings(const double* __restrict normals, const PairConst* __restrict pairs,
                                  const double* __restrict x, std::size_t begin, std::size_t m,
                                  double (*__restrict out)[kChunk]);

  // Pairs [begin, begin + m) that are undamaged and stay below every onset (traction_update's
  // first shortcut: most pairs of an impact, most of the time), in one SIMD loop from the frames
  // and openings `fo`: elastic[j] = 1 for such a pair, with its largest opening updated in place,
  // its force on the lower node (out[0..2][j]) and its elastic energy per unit area (out[3][j]),
  // through the helpers traction_update and the general path use (so to the last bit the law's);
  // elastic[j] = 0 for the others (their history keeps its values), which take the general law.
  static void intact_pairs(const TractionLaw& law, const double* __restrict elastic_limit,
                           const double* __restrict damage, double* __restrict max_opening,
                           const PairConst* __restrict pairs, std::size_t begin, std::size_t m,
                           const double (*__restrict fo)[kChunk], double (*__restrict out)[kChunk],
                           unsigned char* __restrict elastic);

  void compute_midpoints(const double* x, std::size_t begin, std::size_t end);
  void compute_face_vectors(std::size_t begin, std::size_t end);
  void normals_from_faces(std::size_t begin, std::size_t end);
  void build_face_adjacency(const double* x_ref, bool areas_from_faces);

  LawTable laws_;                          // (num_pairs) the law of each pair
  std::vector<double> elastic_limit_;      // (num_pairs) m, its law's elastic_limit, for the SIMD path
  AlignedVector<PairConst, 64> pairs_;
  std::vector<double> normals_;            // (num_pairs, 3) unit normals: given, or from the faces
  std::vector<Index> faces_;               // (num_faces, 4)
  std::vector<Index> pair_face_offset_;    // (num_pairs + 1) CSR of the faces around each pair
  std::vector<Index> pair_face_;
  std::vector<double> midpoints_;          // (num_pairs, 3) mid-surface points of the last refresh (scratch)
  // (num_faces, 3) vector areas of the last refresh; a cut face (face_cut_) keeps the one it had
  // when the first of its corner pairs was released, so it is run state.
  std::vector<double> face_vector_;
  std::vector<char> face_cut_;             // (num_faces) 1: a corner pair is released (from released_)
  int normal_refresh_interval_ = 1;
  double release_depth_;  // m, TiebreakPairsSpec::release_depth
  std::vector<char> released_;             // (num_pairs) 1: released for good (release_pair)
  std::vector<double> point_elastic_;      // (num_pairs) J/m^2 each pair held after the last apply
  std::uint64_t passes_ = 0;               // apply() calls so far (when the normals are refreshed)
  bool nodes_distinct_ = true;

  PointHistories history_;  // (num_pairs)
  double dissipated_energy_ = 0;

  ChunkSums sums_;  // scratch of the last pass
  double elastic_energy_ = 0;
  double separated_area_ = 0;
  double stable_step_ = 0;
  Index stable_step_pair_ = -1;
};

}  // namespace plyimpact::cohesive
