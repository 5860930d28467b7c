// Internal to config/: readers of a `card: MAT_015` / `MAT_JOHNSON_COOK` material mapping (with its
// `eos:` block) and of a `card: MAT_098` / `MAT_SIMPLIFIED_JOHNSON_COOK` one. Keys are the LS-DYNA
// card names; plain numbers are in the scene's unit system, temperatures (TM, TR) in K, CP in
// energy / (mass K). Fields of the cards that serve shells only (DTF, NUMINT, EPPFR, LCDM), other
// rate forms (RATEOP 1-3, C2/P) and EOS initial states V0 != 1 are not keys here: a key outside the
// implemented set is refused with the list of the allowed ones.
#pragma once

#include "config/johnson_cook_spec.hpp"
#include "config/yaml_reader.hpp"

namespace plyimpact::config::detail {

MatJohnsonCook read_mat015(const Reader& card);
MatSimplifiedJohnsonCook read_mat098(const Reader& card);

}  // namespace plyimpact::config::detail
