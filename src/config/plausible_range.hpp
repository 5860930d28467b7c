// Plausible ranges of physical inputs: generous bounds that no real impact model leaves, so that a
// finite but absurd value (a density of 1e300, a velocity of 1e300 m/s, a ply 1 nm thick) is refused
// at its line instead of reaching the solver, which would stop at cycle 0 with nan everywhere. The
// table below is the one place these numbers live; docs/commands.md ("Input limits") prints it.
// A range bounds the magnitude of a non-zero value: zero, where a key allows it, means "off" and
// is left to the key's own limits; so are signs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/units.hpp"

namespace plyimpact::config {

enum class QuantityKind {
  density, modulus, strength, stress, velocity, size, coordinate, time, mass, acceleration, rate,
  fracture_energy, penalty_stiffness, factor
};

struct PlausibleRange {
  QuantityKind kind;
  const char* name;    // "a density"
  double lo, hi;       // SI magnitudes; lo = 0: no lower bound
  const char* unit;    // SI unit, for messages
  const char* reason;  // what the bounds are wide enough for
};

/// The whole table, in a fixed order (docs and tests print it).
const std::vector<PlausibleRange>& plausible_ranges();

/// Range of one kind.
const PlausibleRange& plausible_range(QuantityKind kind);

/// The kind a value of dimension `d` gets when its key names none (stress -> stress, length ->
/// coordinate, ...); nullopt for dimensions without a range.
std::optional<QuantityKind> default_kind(units::Dimension d);

/// True when |v| lies in the range (or v is 0).
bool is_plausible(double v, const PlausibleRange& range);

/// "[0.01, 1e+09] kg/m^3" or "at most 1e+05 m/s".
std::string range_text(const PlausibleRange& range);

}  // namespace plyimpact::config
