// Laminate (stacking-sequence) notation -> list of ply angles, bottom ply first, in degrees.
// Grammar (whitespace ignored):
//   laminate := group
//   group    := '[' item ('/' item)* ']' [ ['_'] count ] [ 's' ]      e.g. [0/45/-45/90]2s
//   item     := (angle | group) [ '_' count ]                          e.g. 0_2, [45/-45]_2
//   angle    := ['+' | '-' | '±' | '+-' | '∓' | '-+'] number           ±45 -> 45/-45, ∓45 -> -45/45
// `s` mirrors the whole sequence (even count); a middle ply written with a trailing '~' ([0/90~]s,
// the bar of the textbook notation) is not repeated: [0/90~]s = 0/90/0.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace plyimpact::config {

class LayupNotationError : public std::runtime_error {
 public:
  LayupNotationError(std::size_t position, const std::string& what, const std::string& allowed)
      : std::runtime_error(what), position_(position), allowed_(allowed) {}
  std::size_t position() const { return position_; }  // 0-based character (byte) offset in the text
  const std::string& allowed() const { return allowed_; }

 private:
  std::size_t position_;
  std::string allowed_;
};

/// Expands laminate notation to ply angles in degrees, bottom ply first.
/// @throws LayupNotationError with the offending position, what is wrong and what is allowed.
std::vector<double> expand_layup(const std::string& notation);

}  // namespace plyimpact::config
