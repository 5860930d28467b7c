// Plausible input ranges; see plausible_range.hpp.
#include "config/plausible_range.hpp"

#include <cmath>
#include <sstream>

namespace plyimpact::config {

const std::vector<PlausibleRange>& plausible_ranges() {
  using K = QuantityKind;
  // Bounds one to four orders of magnitude beyond the extremes of engineering materials and
  // impact tests, so that no real input is refused: aerogels (~1 kg/m^3) to osmium (22 600 kg/m^3)
  // with mass scaling by 1e4; gels (~1 kPa) to diamond (1.2 TPa); strengths up to the ideal
  // strength of solids (~E/10, 1e11 Pa); hypervelocity impact below 20 km/s.
  static const std::vector<PlausibleRange> table = {
      {K::density, "a density", 1e-2, 1e9, "kg/m^3", "aerogels to osmium, with mass scaling up to 1e4"},
      {K::modulus, "an elastic modulus", 1e3, 1e13, "Pa", "gels to ten times diamond"},
      {K::strength, "a strength", 1.0, 1e11, "Pa", "up to the ideal strength of solids"},
      {K::stress, "a stress", 0.0, 1e13, "Pa", "any stress-like constant"},
      {K::velocity, "a velocity", 0.0, 1e5, "m/s", "five times hypervelocity impact"},
      {K::size, "a size (thickness, element size, edge length)", 1e-7, 1e4, "m", "0.1 um films to 10 km"},
      {K::coordinate, "a coordinate or length", 0.0, 1e4, "m", "a 10 km model"},
      {K::time, "a time", 0.0, 1e4, "s", "almost 3 hours of simulated time"},
      {K::mass, "a mass", 0.0, 1e6, "kg", "a thousand tonnes"},
      {K::acceleration, "an acceleration", 0.0, 1e9, "m/s^2", "1e8 g"},
      {K::rate, "a rate", 0.0, 1e12, "1/s", "strain rates and frequencies"},
      {K::fracture_energy, "a fracture energy", 0.0, 1e7, "J/m^2", "ten times the toughest metals"},
      {K::penalty_stiffness, "a penalty stiffness per area", 0.0, 1e22, "N/m^3", "1e6 times stiff cohesive laws"},
      {K::factor, "a dimensionless factor", 0.0, 1e9, "", "scale factors, exponents and ids"},
  };
  return table;
}

const PlausibleRange& plausible_range(QuantityKind kind) {
  for (const auto& r : plausible_ranges())
    if (r.kind == kind) return r;
  return plausible_ranges().front();  // unreachable: every kind is in the table
}

std::optional<QuantityKind> default_kind(units::Dimension d) {
  namespace u = units;
  if (d == u::density) return QuantityKind::density;
  if (d == u::stress) return QuantityKind::stress;
  if (d == u::velocity) return QuantityKind::velocity;
  if (d == u::length) return QuantityKind::coordinate;
  if (d == u::time) return QuantityKind::time;
  if (d == u::mass) return QuantityKind::mass;
  if (d == u::acceleration) return QuantityKind::acceleration;
  if (d == u::frequency) return QuantityKind::rate;
  if (d == u::energy_per_area) return QuantityKind::fracture_energy;
  if (d == u::stiffness_per_area) return QuantityKind::penalty_stiffness;
  if (d == u::dimensionless) return QuantityKind::factor;
  return std::nullopt;
}

bool is_plausible(double v, const PlausibleRange& range) {
  if (v == 0) return true;
  const double a = std::abs(v);
  return a >= range.lo && a <= range.hi;  // false for nan
}

std::string range_text(const PlausibleRange& range) {
  std::ostringstream s;
  s.precision(6);
  const std::string unit = *range.unit ? std::string(" ") + range.unit : std::string();
  if (range.lo > 0) s << "a magnitude in [" << range.lo << ", " << range.hi << "]" << unit;
  else s << "a magnitude of at most " << range.hi << unit;
  return s.str();
}

}  // namespace plyimpact::config
