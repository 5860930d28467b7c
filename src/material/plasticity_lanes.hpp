// *MAT_003 / *MAT_024 update of the element pass: the J2 radial return of plasticity.hpp point by
// point, each with its own rotation of stress and back stress.
#pragma once

#include "material/plasticity.hpp"
#include "material/pointwise_return_lanes.hpp"

namespace plyimpact::material {

using PlasticityLanes = PointwiseReturnLanes<PlasticityParams, plasticity_update, kPlasticityHistory>;

}  // namespace plyimpact::material
