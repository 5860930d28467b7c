// Zero-thickness 8-node cohesive elements between two plies (the layout of LS-DYNA's *SECTION_SOLID
// ELFORM 19 with *MAT_138): four lower nodes and the four upper nodes over them, a bilinear quad on
// the mid-surface with 2 x 2 Gauss points or the 4 corner (Newton-Cotes) points. At each point
//   opening : delta = sum_a N_a (x_upper,a - x_lower,a) (zero thickness: no reference offset, so
//             rigid translations and rotations of the element open nothing),
//   frame   : from the current mid-surface x_mid = (x_lower + x_upper) / 2: a_1 = dx_mid/dxi,
//             a_2 = dx_mid/deta, n = a_1 x a_2 / |a_1 x a_2| (from the lower to the upper ply),
//             e_1 = a_1 / |a_1|, e_2 = n x e_1; local opening (delta.n, delta.e_1, delta.e_2),
//   law     : traction_law.hpp (one PointHistory per point; the same law as tiebreak OPTION 9),
//   force   : f_lower,a += A_g N_a(g) t, f_upper,a -= A_g N_a(g) t with t = t_n n + t_1 e_1 + t_2 e_2
//             and A_g = |a_1 x a_2| at the reference (weight 1 in both rules): tractions per reference area,
//             as the tiebreak's pairs; the forces sum to zero per point (momentum to round-off).
//   energy  : elastic = sum A_g e (now); dissipated = running sum of A_g dD; sums per fixed chunk of
//             elements added in order, so bit-identical for any thread count.
//   area    : delaminated area = sum of A_g over the points with d = 1 (area-weighted by points).
//   step    : like the tiebreak's pairs: each lower/upper node pair is two masses on the spring
//             max(K_n, K_t) A_a, A_a the node's tributary area sum_g A_g N_a(g) over its elements
//             (the row sums of the interface stiffness); stable_step() is the smallest 2/omega.
// Assembly without races: each element writes its 8 nodal forces to its own slot, then one loop over
// the nodes sums their slots in a fixed order (gather-then-reduce), so the forces are bit-identical
// for any thread count. No allocation per call.
#pragma once

#include <cstddef>
#include <vector>

#include "cohesive/law_table.hpp"
#include "cohesive/point_histories.hpp"
#include "cohesive/point_sample.hpp"
#include "cohesive/traction_law.hpp"
#include "core/state_visitor.hpp"
#include "core/types.hpp"

namespace plyimpact::cohesive {

// Where the law is sampled on the mid-surface (LS-DYNA *MAT_138 INTFAIL > 0: Gauss, <= 0: Newton-Cotes).
enum class CohesiveIntegration {
  Gauss,        // 2 x 2 Gauss points at (+-1/sqrt 3, +-1/sqrt 3)
  NewtonCotes,  // the 4 corners (nodal integration: the tiebreak's quadrature)
};

struct CohesiveElementsSpec {
  CohesiveIntegration integration = CohesiveIntegration::Gauss;
  // (num_elements, 8): lower face counter-clockwise seen from the upper ply, then the upper node
  // over each lower node in the same order (LS-DYNA's ELFORM 19 numbering).
  std::vector<Index> nodes;
  // Pa: each element's own peak tractions in place of the law's T (NFLS) and S (SFLS), e.g. lowered
  // so that the process zone spans a number of elements (law_parameters.hpp); both empty: the law's.
  std::vector<double> nfls, sfls;
};

class CohesiveElements {
 public:
  static constexpr int kPoints = 4;  // 2 x 2 Gauss or 4 corner points per element
  struct QuadTables;                 // shape functions of a rule at its points (defined in the .cpp)

  // x_ref: (num_nodes, 3) reference coordinates; nodal_mass: (num_nodes) kg. Throws InputError on a
  // bad law, a node index out of range, an element of non-zero thickness or without area.
  CohesiveElements(const TractionLawParams& params, CohesiveElementsSpec spec, const double* x_ref,
                   const double* nodal_mass);

  // Adds the cohesive forces for configuration x ((num_nodes, 3)) to f and updates the history.
  void apply(const double* x, const double* v, double* f, double dt);

  double elastic_energy() const { return elastic_energy_; }         // J, at the last apply
  double dissipated_energy() const { return dissipated_energy_; }   // J, since the start
  double separated_area() const { return separated_area_; }         // m^2 of points with d = 1
  double stable_step() const { return stable_step_; }               // s, stiffest node pair alone
  Index stable_step_element() const { return stable_step_element_; }

  // Recomputes the stable step after the nodal masses change (mass scaling, erosion).
  void set_nodal_mass(const double* nodal_mass);

  std::size_t size() const { return num_elements_; }
  std::size_t num_points() const { return kPoints * num_elements_; }
  const TractionLaw& law() const { return laws_.card(); }                     // the card's
  const TractionLaw& law(std::size_t element) const { return laws_.of(element); }  // with its strengths
  const LawTable& laws() const { return laws_; }
  const std::vector<Index>& nodes() const { return nodes_; }        // (num_elements, 8)
  const std::vector<double>& damage() const { return history_.damage(); }  // (num_elements, 4)
  double point_area(std::size_t point) const { return point_area_[point]; }  // m^2, A_g
  double element_area(std::size_t e) const;                                // m^2, reference mid-surface

  // Initial history: point p starts separated (a pre-crack).
  void separate_point(std::size_t point) { history_.separate(point); }

  // Positions of the points on the mid-surface of configuration x into out ((num_points, 3)).
  void point_positions(const double* x, double* out) const;

  // Per-point output for configuration x into out[0 .. num_points()) (element-major), without
  // changing the state.
  void sample(const double* x, PairSample* out) const;

  // Names the per-point history (max_opening, damage, slip_1, slip_2, stick_energy) and the
  // dissipated energy. The frame is recomputed from x every pass, so it is not state.
  void visit_state(StateVisitor& visitor);

 private:
  void element_forces(const double* x, std::size_t e, double* fe, double& elastic, double& dissipated,
                      double& separated);

  LawTable laws_;  // (num_elements) the law of each element
  const QuadTables* quad_ = nullptr;  // the integration rule's shape functions at its points
  std::size_t num_elements_ = 0;
  std::vector<Index> nodes_;          // (num_elements, 8)
  std::vector<double> point_area_;    // (num_elements, 4) A_g
  std::vector<double> corner_area_;   // (num_elements, 4) tributary area of each lower corner node
  // Gather: the distinct nodes, and for each the slots (element * 8 + corner) of element_force_ it sums.
  std::vector<Index> gather_node_;
  std::vector<Index> gather_offset_;  // (num_gather_nodes + 1)
  std::vector<Index> gather_slot_;
  std::vector<double> element_force_; // (num_elements, 8, 3) scratch of the last pass

  PointHistories history_;  // (num_elements, 4)
  double dissipated_energy_ = 0;

  ChunkSums sums_;  // scratch of the last pass
  double elastic_energy_ = 0;
  double separated_area_ = 0;
  double stable_step_ = 0;
  Index stable_step_element_ = -1;
};

}  // namespace plyimpact::cohesive
