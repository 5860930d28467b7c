// A steel base of 3 x 3 x 2 elements of 1 mm (ids: base first, x fastest; the top layer is 10..18,
// its middle 14, the element the eroding-contact tests delete) and a small steel punch box given
// by origin, size and elements (YAML lists, m), moving at `velocity` (YAML list, m/s), with penalty
// contact SOFT 1 of the given type between punch and base: the scene of the eroding-contact tests.
#pragma once

#include <string>

namespace plyimpact::test {

inline std::string punch_on_base(const std::string& punch_origin, const std::string& punch_size,
                                 const std::string& punch_elements, const std::string& velocity,
                                 const std::string& contact_type, const std::string& section = "{ELFORM: 2}") {
  return std::string("units: SI\ncontrol: {termination_time: 1.0}\n") +
         "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
         "sections:\n  s: " + section + "\n"
         "parts:\n  base: {material: steel, section: s}\n  punch: {material: steel, section: s}\n"
         "mesh:\n  merge_nodes: false\n  boxes:\n"
         "    - {part: base, origin: [0, 0, 0], size: [0.003, 0.003, 0.002], elements: [3, 3, 2]}\n"
         "    - {part: punch, origin: " + punch_origin + ", size: " + punch_size + ", elements: " + punch_elements + "}\n"
         "initial_velocity:\n  - {part: punch, velocity: " + velocity + "}\n"
         "contacts:\n  - {name: slot, type: " + contact_type + ", surfaces: [punch, base], SOFT: 1}\n";
}

}  // namespace plyimpact::test
