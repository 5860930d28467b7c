// Tiebreak of slave nodes tied to points of master segments: the general (non-matching mesh) form of
// *CONTACT_..._TIEBREAK, where a slave node is held to the point of a master quad it projected onto
// when the contact was set up (natural coordinates (xi, eta) fixed from then on). The law is the
// one of the matching node pairs (traction_law.hpp); only the kinematics differ:
//   master point : x_m = sum_k N_k(xi, eta) x_k over the segment's four nodes;
//   frame        : n = t_xi x t_eta / |.| of the current segment at (xi, eta) (outward from the master
//                  body, so towards the slave), t_1 = t_xi with its n part removed, t_2 = n x t_1 —
//                  the frame turns with the segment;
//   opening      : u = R (x_s - x_m) - u_0, u_0 the reference offset in the reference frame (the tie
//                  accepts a gap, eq. 7.40 of the seed; holding it in the local frame keeps a rotated,
//                  unloaded interface free of spurious opening);
//   force        : F = A (t_n n + t_1 e_1 + t_2 e_2) on the master point, distributed N_k F to its
//                  nodes, and -F on the slave node (momentum conserved to round-off); A is the slave
//                  node's tributary area on the tied part of the slave surface;
//   step         : the spring k = max(K_n, K_t) A between the slave mass and the master point, whose
//                  effective mass for a force distributed with weights N_k is 1 / sum_k N_k^2 / m_k:
//                  dt = 2 / sqrt(k (1/m_s + sum_k N_k^2 / m_k)). For a tie at a segment corner this is
//                  the matching pair's step.
// Energies, separated area and thread-count independence as in tiebreak_pairs.hpp: per-tie results in
// fixed chunks, the forces gathered per tie in parallel and scattered in tie order (master nodes are
// shared by neighbouring ties), so any thread count gives the same bits. No allocation per call.
#pragma once

#include <cstddef>
#include <vector>

#include "cohesive/point_histories.hpp"
#include "cohesive/point_sample.hpp"
#include "cohesive/traction_law.hpp"
#include "core/state_visitor.hpp"
#include "core/types.hpp"

namespace plyimpact::cohesive {

// One slave node tied to a point of one master segment.
struct SegmentTie {
  Index slave = 0;
  Index master[4] = {0, 0, 0, 0};  // segment nodes, quad order, t_xi x t_eta pointing to the slave side
  double xi = 0, eta = 0;          // natural coordinates of the tied point, in [-1, 1]
  double area = 0;                 // m^2, the slave node's tributary area
};

class SegmentTiebreaks {
 public:
  // x_ref: (num_nodes, 3); nodal_mass: (num_nodes). Throws InputError on a bad law or tie.
  SegmentTiebreaks(const TractionLawParams& params, std::vector<SegmentTie> ties, const double* x_ref,
                   const double* nodal_mass);

  void apply(const double* x, double* f);

  double elastic_energy() const { return elastic_energy_; }
  double dissipated_energy() const { return dissipated_energy_; }
  double separated_area() const { return separated_area_; }
  double stable_step() const { return stable_step_; }
  void set_nodal_mass(const double* nodal_mass);

  // A tie whose master segment is gone (its element eroded) carries nothing from now on; it counts
  // as separated. Its elastic energy at that moment is released (counted as dissipated).
  void release(std::size_t tie);
  bool released(std::size_t tie) const { return released_[tie] != 0; }

  std::size_t size() const { return ties_.size(); }
  const SegmentTie& tie(std::size_t k) const { return ties_[k]; }
  const TractionLaw& law() const { return law_; }
  const std::vector<double>& damage() const { return history_.damage(); }
  void sample(const double* x, PairSample* out) const;

  void visit_state(StateVisitor& visitor);

 private:
  struct Frame {
    double n[3], t1[3], t2[3];
  };
  Frame frame(const double* x, std::size_t k, double xm[3]) const;
  void opening(const double* x, std::size_t k, Frame& fr, double u[3]) const;

  TractionLaw law_;
  std::vector<SegmentTie> ties_;
  std::vector<double> weights_;   // (num_ties, 4) N_k(xi, eta)
  std::vector<double> offset_;    // (num_ties, 3) reference opening in the reference frame
  PointHistories history_;        // (num_ties)
  std::vector<char> released_;
  std::vector<double> held_;      // (num_ties) J held by each tie's springs at the last pass
  double dissipated_energy_ = 0;
  std::vector<double> force_;     // (num_ties, 3) scratch: the force on each master point
  ChunkSums sums_;                // scratch of the last pass
  double elastic_energy_ = 0, separated_area_ = 0, stable_step_ = 0;
};

}  // namespace plyimpact::cohesive
