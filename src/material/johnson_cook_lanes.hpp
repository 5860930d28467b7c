// *MAT_015 / *MAT_098 update of the element pass: the Johnson-Cook return of johnson_cook.hpp point
// by point.
#pragma once

#include "material/johnson_cook.hpp"
#include "material/pointwise_return_lanes.hpp"

namespace plyimpact::material {

using JohnsonCookLanes = PointwiseReturnLanes<JohnsonCookParams, johnson_cook_update, kJohnsonCookHistory>;

}  // namespace plyimpact::material
