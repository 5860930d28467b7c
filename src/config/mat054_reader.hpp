// Internal to config/: reader of a `card: MAT_054` / `MAT_055` / `ENHANCED_COMPOSITE_DAMAGE` material
// mapping into MatCompositeDamage. Keys are the LS-DYNA card names (2WAY included); the material
// axis vectors may also be given as A: [..], D: [..], V: [..] as on MAT_002. Note that on this card
// BETA is the fibre-tension shear weight and MANGLE the material angle.
#pragma once

#include "config/mat054_spec.hpp"
#include "config/yaml_reader.hpp"

namespace plyimpact::config::detail {

// `card` is the material's mapping (the one holding `card:`). Every value is converted to SI;
// plain numbers are in the scene's unit system. Unit conventions beyond the obvious:
//   ALPH  stress^-3 (e.g. "1e-7 1/MPa^3"); plain numbers in the scene's stress unit^-3.
//   TFAIL a plain number > 0.1 is the ratio dt/dt0 (must be < 1); otherwise a time (scene units or
//         with a unit) that must not exceed 0.1 s.
//   SOFT, YCFAC, SOFT2, SOFTG written as 0 take their card default (LS-DYNA reads a blank field as
//         0 and substitutes the default), so a card copied with 0.0 behaves as in LS-DYNA.
// Fails (InputError, house format) on unknown keys, out-of-range values and on any field
// unsupported_field() names, pointing at that key. For card MAT_055 CRIT defaults to 55.
MatCompositeDamage read_mat054(const Reader& card);

}  // namespace plyimpact::config::detail
