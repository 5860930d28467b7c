// Two steel blocks (2x2x2 and 3x3x4 ELFORM 2 elements, offset in plane so the meshes do not match)
// flying at each other at 5 m/s each through automatic surface-to-surface contact `hit`, with the
// contact options given (e.g. "SOFT: 0"): the head-on impact of the contact tests.
#pragma once

#include <string>

namespace plyimpact::test {

inline std::string head_on_blocks(const std::string& contact_options) {
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
         "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
         "sections:\n  s: {ELFORM: 2, Q1: 0, Q2: 0}\n"
         "parts:\n  a: {material: steel, section: s}\n  b: {material: steel, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: a, origin: [0, 0, 0], size: [0.004, 0.004, 0.004], elements: [2, 2, 2]}\n"
         "    - {part: b, origin: [0.0005, 0.0005, 0.0042], size: [0.003, 0.003, 0.004], elements: [3, 3, 4]}\n"
         "initial_velocity:\n  - {part: a, velocity: [0, 0, 5]}\n  - {part: b, velocity: [0, 0, -5]}\n"
         "contacts:\n  - {name: hit, type: automatic_surface_to_surface, surfaces: [a, b], " +
         contact_options + "}\n";
}

}  // namespace plyimpact::test
