// Internal to config/: the `coupon:` scene section (fracture-coupon history columns; see
// CouponSpec in scene.hpp and docs/coupons.md).
#pragma once

#include "config/scene.hpp"
#include "config/yaml_reader.hpp"

namespace plyimpact::config::detail {

// Needs the laminate, the node sets and the boundary conditions already read: the coupon names an
// interface with a tiebreak law and node sets, and its load set must carry a prescribed velocity.
CouponSpec read_coupon(const Reader& r, const Scene& scene);

}  // namespace plyimpact::config::detail
