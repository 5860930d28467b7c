// Shared scene text for the mesher tests: a T800S/M21-like ply card, a steel card and a section.
#pragma once

namespace plyimpact::test {

inline constexpr const char* kPlyAndSteelCards = R"(materials:
  ply: {card: MAT_002, RO: 1.55e-9, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.019, PRCA: 0.019,
        PRCB: 0.53, GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}
  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}
sections:
  s: {ELFORM: 1, IHQ: 4}
)";

// The same ply card and section without the steel.
inline constexpr const char* kPlyCards = R"(materials:
  ply: {card: MAT_002, RO: 1.55e-9, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.019, PRCA: 0.019,
        PRCB: 0.53, GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}
sections:
  s: {ELFORM: 1, IHQ: 4}
)";

}  // namespace plyimpact::test
