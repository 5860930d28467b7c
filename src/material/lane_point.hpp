// What a material's update sees of one integration point: the kinematics the element family
// computed for it. Two forms, one per element family layout:
//  - LanePoint: the centre points of kLanes one-point elements (ELFORM 1), lane arrays;
//  - Point: one Gauss point of one element (ELFORM 2, and next families), scalars.
// A material's class (material/*_lanes.hpp) takes either and returns its new stress; it declares
// with kTotalLagrangian / kElementRotation which of the optional fields it reads, and the family
// computes only those. Erosion codes: 0 = alive, else the solver's ErosionCause of the failure
// (the material is told its code base when it is built).
#pragma once

#include "core/lanes.hpp"
#include "core/types.hpp"

namespace plyimpact::material {

struct LanePoint {
  const Index (&elem)[kLanes];  // element index in the block per lane (a partial group repeats its last)
  int n;                        // lanes 0 .. n-1 are real elements
  const bool (&ok)[kLanes];     // valid geometry (the others are skipped and discarded)
  double dt;                    // Delta t^{n+1/2} (0 in the initial evaluation)
  const LaneVec<6>& D;          // mid-step rate of deformation, tensor Voigt
  const LaneScalar& trD;
  const LaneVec<9>& R;          // Hughes-Winget incremental rotation (incremental materials)
  const LaneVec<9>& Jx;         // end-of-step centre Jacobian dx/dxi (total-Lagrangian materials)
  const LaneScalar& element_dt; // stable step of each element (before the material update)
};

struct Point {
  Index element;              // index in the block
  int point;                  // integration point of the element
  double dt;
  const double* D;            // rate of deformation at the point (after the family's B-bar correction)
  const double* W;            // spin at the point
  const double* F = nullptr;  // deformation gradient (kTotalLagrangian), F-bar corrected
  double J = 1;               // det F used for the Cauchy stress (kTotalLagrangian)
  // Green-Lagrange strain added to the one of F (kTotalLagrangian; engineering Voigt, reference
  // axes): ELFORM -2's tied transverse shear (element/hex8_ans.hpp); null: none.
  const double* dE = nullptr;
  double element_dt = 0;      // stable step of the element
};

}  // namespace plyimpact::material
