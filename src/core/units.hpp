// Units: the scene's unit systems and the "157 GPa" quantity strings, converted to SI (m, kg, s).
// A Dimension is the exponent triple (L, M, T); a unit expression ("kg/m^3", "kN/mm^3", "1/s") is a
// product/quotient of base units (m, g, s, t, N, Pa, J, W, Hz, bar) with SI prefixes (p n u m c d h
// k M G T) and integer exponents. Angles are separate: plain numbers are degrees, "rad"/"deg" accepted.
// Numbers are parsed strictly with std::from_chars ("12abc" is an error, never 12).
// Errors throw UnitError (an InputError) carrying what is wrong and what is allowed, without a
// location; config/ adds file:line:col and the key path.
#pragma once

#include <string>
#include <string_view>

#include "core/error.hpp"

namespace plyimpact::units {

// Exponents of length, mass and time.
struct Dimension {
  int L = 0, M = 0, T = 0;
  friend constexpr bool operator==(const Dimension&, const Dimension&) = default;
};

inline constexpr Dimension dimensionless{0, 0, 0};
inline constexpr Dimension length{1, 0, 0};
inline constexpr Dimension mass{0, 1, 0};
inline constexpr Dimension time{0, 0, 1};
inline constexpr Dimension frequency{0, 0, -1};
inline constexpr Dimension velocity{1, 0, -1};
inline constexpr Dimension acceleration{1, 0, -2};
inline constexpr Dimension force{1, 1, -2};
inline constexpr Dimension stress{-1, 1, -2};
inline constexpr Dimension density{-3, 1, 0};
inline constexpr Dimension energy{2, 1, -2};
inline constexpr Dimension power{2, 1, -3};
inline constexpr Dimension energy_per_area{0, 1, -2};      // J/m^2 = N/m (fracture toughness)
inline constexpr Dimension stiffness_per_area{-2, 1, -2};  // stress/length = N/m^3 (penalty, cohesive K)

// "a stress (e.g. MPa, GPa, Pa)"; unnamed dimensions as "a quantity of dimension m^a kg^b s^c".
std::string describe(Dimension d);
// "a stress"; same fallback as describe().
std::string name_of(Dimension d);

// A consistent unit system: the SI value of its length, mass and time units.
struct UnitSystem {
  std::string name;  // canonical: "SI", "mm-t-s-MPa", "mm-kg-ms-GPa"
  double length = 1, mass = 1, time = 1;
};

// Accepts SI, mm-t-s-MPa, mm-kg-ms-GPa and spellings of them, case-insensitively, with '-', '_' or
// ' ' as separators: "m-kg-s", "mks", "mm-ton-s", "mm-tonne-s-N-MPa", "mm-kg-ms-kN-GPa", ...
UnitSystem parse_unit_system(std::string_view text);

// Text listing the accepted unit systems, for messages.
std::string allowed_unit_systems();

// value given in system `us` with dimension d -> SI.
double to_si(double value, Dimension d, const UnitSystem& us);

// A unit expression: SI value of one of it, and its dimension.
struct Unit {
  double factor = 1;
  Dimension dim;
};

// "kN/mm^3" -> {1e12, stiffness_per_area}. Throws UnitError for unknown units or bad syntax.
Unit parse_unit(std::string_view expr);

// Strict whole-string number: optional sign, decimal or exponent form, finite. Throws UnitError.
double parse_number(std::string_view text);
// Strict whole-string integer ("1.5", "1e2", "3x" are errors). Throws UnitError.
long parse_integer(std::string_view text);

// "157 GPa" -> 1.57e11 (the unit must have dimension `expected`); a plain number "157" is taken in
// the unit system `us`. Whitespace between number and unit is optional ("2ms").
double quantity_to_si(std::string_view text, Dimension expected, const UnitSystem& us);

// "45", "45 deg" -> pi/4; "0.5 rad" -> 0.5.
double angle_to_rad(std::string_view text);

// Thrown by everything above. problem(): what is wrong; allowed(): what would be accepted.
class UnitError : public InputError {
 public:
  UnitError(std::string problem, std::string allowed)
      : InputError(problem + "; allowed " + allowed),
        problem_(std::move(problem)),
        allowed_(std::move(allowed)) {}
  const std::string& problem() const { return problem_; }
  const std::string& allowed() const { return allowed_; }

 private:
  std::string problem_, allowed_;
};

}  // namespace plyimpact::units
