// Element-length scaling of the *MAT_054 erosion strains (erosion_reference_length): why and how in
// docs/theory.md, "Erosion strains and the element length".
#pragma once

#include "core/types.hpp"

namespace plyimpact::model {

// An element's length in the plane of its ply: the square root of its reference volume over its
// thickness, the extent of its corners along the material c axis (axes row 2). For a ply element of
// h x h x t this is h; a crack through the ply's thickness crosses the element over this length.
double ply_plane_length(const double (&x)[3][8], double volume, const Mat3& axes);

// Factor on the erosion strains of an element of that length: reference / length when the element
// is shorter than the reference (its elongation at erosion is then the reference element's), else 1
// (a longer element keeps the card's strains: lowering them could erode it before it fails). An
// element of the reference length to round-off (1e-9) keeps the card's strains exactly.
inline double erosion_strain_scale(double reference_length, double length) {
  return reference_length > length * (1 + 1e-9) ? reference_length / length : 1.0;
}

}  // namespace plyimpact::model
