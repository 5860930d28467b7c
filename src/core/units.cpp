// Unit systems, unit expressions and quantity strings -> SI. See units.hpp.
#include "core/units.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace plyimpact::units {
namespace {

constexpr const char* kUnitSyntaxHelp =
    "SI units with prefixes (Pa kPa MPa GPa, N kN, J mJ, m mm cm um, s ms us, kg g t, Hz), "
    "combined with '*', '/' and integer powers '^' (e.g. kg/m^3, J/m^2, kN/mm^3, 1/s)";

struct BaseUnit {
  std::string_view name;
  double factor;
  Dimension dim;
  bool prefixable;
};

constexpr std::array kBaseUnits{
    BaseUnit{"m", 1.0, length, true},          BaseUnit{"g", 1e-3, mass, true},
    BaseUnit{"s", 1.0, time, true},            BaseUnit{"t", 1e3, mass, false},
    BaseUnit{"tonne", 1e3, mass, false},       BaseUnit{"N", 1.0, force, true},
    BaseUnit{"Pa", 1.0, stress, true},         BaseUnit{"J", 1.0, energy, true},
    BaseUnit{"W", 1.0, power, true},           BaseUnit{"Hz", 1.0, frequency, true},
    BaseUnit{"bar", 1e5, stress, true},
};

struct Prefix {
  std::string_view name;
  double factor;
};

constexpr std::array kPrefixes{
    Prefix{"T", 1e12}, Prefix{"G", 1e9},  Prefix{"M", 1e6},       Prefix{"k", 1e3},
    Prefix{"h", 1e2},  Prefix{"d", 1e-1}, Prefix{"c", 1e-2},      Prefix{"m", 1e-3},
    Prefix{"u", 1e-6}, Prefix{"\xC2\xB5", 1e-6} /* micro sign */, Prefix{"\xCE\xBC", 1e-6} /* mu */,
    Prefix{"n", 1e-9}, Prefix{"p", 1e-12},
};

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::optional<Unit> lookup_unit(std::string_view token) {
  for (const auto& b : kBaseUnits)
    if (b.name == token) return Unit{b.factor, b.dim};
  for (const auto& p : kPrefixes) {
    if (!token.starts_with(p.name)) continue;
    const std::string_view rest = token.substr(p.name.size());
    for (const auto& b : kBaseUnits)
      if (b.prefixable && b.name == rest) return Unit{p.factor * b.factor, b.dim};
  }
  return std::nullopt;
}

bool is_unit_char(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || (static_cast<unsigned char>(c) >= 0x80);
}

// Splits "number [unit]"; the number is the longest prefix std::from_chars accepts.
struct Split {
  double number;
  std::string_view unit;  // trimmed, may be empty
};

Split split_quantity(std::string_view text) {
  const std::string_view s = trim(text);
  if (s.empty())
    throw UnitError("empty value", "a number, optionally followed by a unit (e.g. '210 GPa')");
  std::string_view body = s;
  if (body.front() == '+') body.remove_prefix(1);
  double v = 0;
  const auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), v);
  if (ec != std::errc() || ptr == body.data())
    throw UnitError("not a number: " + quoted(s),
                    "a number such as 210, -5, 1.5e-6, optionally followed by a unit (e.g. '210 GPa')");
  if (!std::isfinite(v))
    throw UnitError("not a finite number: " + quoted(s), "a finite number");
  return {v, trim(body.substr(static_cast<std::size_t>(ptr - body.data())))};
}

}  // namespace

namespace {

struct NamedDimension {
  Dimension d;
  const char* name;
  const char* examples;
};

constexpr std::array kNamedDimensions{
    NamedDimension{dimensionless, "a dimensionless number", "e.g. 0.3"},
    NamedDimension{length, "a length", "e.g. mm, m"},
    NamedDimension{mass, "a mass", "e.g. kg, g, t"},
    NamedDimension{time, "a time", "e.g. s, ms, us"},
    NamedDimension{frequency, "a frequency", "e.g. Hz, 1/s"},
    NamedDimension{velocity, "a velocity", "e.g. m/s, mm/ms"},
    NamedDimension{acceleration, "an acceleration", "e.g. m/s^2"},
    NamedDimension{force, "a force", "e.g. N, kN"},
    NamedDimension{stress, "a stress", "e.g. MPa, GPa, Pa"},
    NamedDimension{density, "a density", "e.g. kg/m^3, g/cm^3, t/mm^3"},
    NamedDimension{energy, "an energy", "e.g. J, mJ"},
    NamedDimension{power, "a power", "e.g. W, kW"},
    NamedDimension{energy_per_area, "an energy per area", "e.g. J/m^2, N/mm"},
    NamedDimension{stiffness_per_area, "a stiffness per area", "e.g. N/mm^3, GPa/mm"},
};

}  // namespace

std::string name_of(Dimension d) {
  for (const auto& n : kNamedDimensions)
    if (n.d == d) return n.name;
  return msg() << "a quantity of dimension m^" << d.L << " kg^" << d.M << " s^" << d.T;
}

std::string describe(Dimension d) {
  for (const auto& n : kNamedDimensions)
    if (n.d == d) return std::string(n.name) + " (" + n.examples + ")";
  return name_of(d);
}

namespace {

struct SystemSpelling {
  const char* canonical;
  double length, mass, time;
  std::vector<std::string_view> length_names, mass_names, time_names, force_names, stress_names;
};

const std::vector<SystemSpelling>& systems() {
  static const std::vector<SystemSpelling> s{
      {"SI", 1.0, 1.0, 1.0, {"m"}, {"kg"}, {"s"}, {"n"}, {"pa"}},
      {"mm-t-s-MPa", 1e-3, 1e3, 1.0, {"mm"}, {"t", "ton", "tonne"}, {"s"}, {"n"}, {"mpa"}},
      {"mm-kg-ms-GPa", 1e-3, 1.0, 1e-3, {"mm"}, {"kg"}, {"ms"}, {"kn"}, {"gpa"}},
  };
  return s;
}

bool contains(const std::vector<std::string_view>& v, std::string_view x) {
  for (auto e : v)
    if (e == x) return true;
  return false;
}

}  // namespace

std::string allowed_unit_systems() {
  return "SI, mm-t-s-MPa, mm-kg-ms-GPa (case-insensitive; also spellings such as m-kg-s, "
         "mm-ton-s, mm-tonne-s-N-MPa, mm-kg-ms, mm-kg-ms-kN-GPa)";
}

UnitSystem parse_unit_system(std::string_view text) {
  std::string norm;
  for (char c : trim(text)) {
    const char l = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    norm += (l == '_' || l == ' ' || l == '/') ? '-' : l;
  }
  std::vector<std::string_view> tok;
  for (std::string_view rest = norm; !rest.empty();) {
    const auto pos = rest.find('-');
    const std::string_view t = rest.substr(0, pos);
    if (!t.empty()) tok.push_back(t);
    if (pos == std::string_view::npos) break;
    rest.remove_prefix(pos + 1);
  }
  for (const auto& sys : systems()) {
    const UnitSystem us{sys.canonical, sys.length, sys.mass, sys.time};
    if (norm == "si" && us.name == "SI") return us;
    if (norm == "mks" && us.name == "SI") return us;
    if (tok.size() < 3 || tok.size() > 5) continue;
    if (!contains(sys.length_names, tok[0]) || !contains(sys.mass_names, tok[1]) ||
        !contains(sys.time_names, tok[2]))
      continue;
    // Optional derived units after L-M-T: force then stress, either may be left out.
    std::size_t i = 3;
    if (i < tok.size() && contains(sys.force_names, tok[i])) ++i;
    if (i < tok.size() && contains(sys.stress_names, tok[i])) ++i;
    if (i == tok.size()) return us;
  }
  throw UnitError("unknown unit system " + quoted(trim(text)), allowed_unit_systems());
}

double to_si(double value, Dimension d, const UnitSystem& us) {
  return value * std::pow(us.length, d.L) * std::pow(us.mass, d.M) * std::pow(us.time, d.T);
}

Unit parse_unit(std::string_view expr) {
  const std::string_view s = trim(expr);
  if (s.empty()) throw UnitError("empty unit", kUnitSyntaxHelp);
  Unit result{1.0, dimensionless};
  std::size_t i = 0;
  int sign = +1;  // +1 multiply the next factor, -1 divide by it
  bool expect_factor = true;
  auto skip_space = [&] {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  };
  auto bad = [&](const std::string& what) -> UnitError {
    return UnitError(what + " in unit " + quoted(s), kUnitSyntaxHelp);
  };
  while (true) {
    skip_space();
    if (expect_factor) {
      if (i >= s.size()) throw bad("missing unit after operator");
      Unit u{1.0, dimensionless};
      if (s[i] == '1') {  // "1/s"
        ++i;
      } else {
        const std::size_t start = i;
        while (i < s.size() && is_unit_char(s[i])) ++i;
        const std::string_view name = s.substr(start, i - start);
        if (name.empty()) throw bad(msg() << "unexpected character '" << s[i] << "'");
        const auto found = lookup_unit(name);
        if (!found) throw bad("unknown unit " + quoted(name));
        u = *found;
        if (i < s.size() && s[i] == '^') {
          ++i;
          const std::size_t es = i;
          if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
          while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
          std::string_view etext = s.substr(es, i - es);
          if (!etext.empty() && etext.front() == '+') etext.remove_prefix(1);
          int e = 0;
          const auto [p, ec] = std::from_chars(etext.data(), etext.data() + etext.size(), e);
          if (ec != std::errc() || p != etext.data() + etext.size() || etext.empty())
            throw bad("bad exponent after " + quoted(name));
          u.factor = std::pow(u.factor, e);
          u.dim = {u.dim.L * e, u.dim.M * e, u.dim.T * e};
        }
      }
      result.factor = sign > 0 ? result.factor * u.factor : result.factor / u.factor;
      result.dim = {result.dim.L + sign * u.dim.L, result.dim.M + sign * u.dim.M,
                    result.dim.T + sign * u.dim.T};
      expect_factor = false;
    } else {
      if (i >= s.size()) break;
      if (s[i] == '*' || s[i] == '.') {
        sign = +1;
      } else if (s[i] == '/') {
        sign = -1;
      } else {
        throw bad(msg() << "expected '*' or '/' before '" << s.substr(i) << "'");
      }
      ++i;
      expect_factor = true;
    }
  }
  return result;
}

double parse_number(std::string_view text) {
  const Split sp = split_quantity(text);
  if (!sp.unit.empty())
    throw UnitError("not a number: " + quoted(trim(text)), "a plain number such as 0.3, -5, 1.5e-6");
  return sp.number;
}

long parse_integer(std::string_view text) {
  std::string_view s = trim(text);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  long v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size() || s.empty())
    throw UnitError("not an integer: " + quoted(trim(text)), "a whole number such as 1, 4, 100");
  return v;
}

double quantity_to_si(std::string_view text, Dimension expected, const UnitSystem& us) {
  const Split sp = split_quantity(text);
  if (sp.unit.empty()) return to_si(sp.number, expected, us);
  Unit u;
  try {
    u = parse_unit(sp.unit);
  } catch (const UnitError& e) {
    throw UnitError(e.problem(), "a plain number (scene units) or '<number> <unit>' for " +
                                     describe(expected) + "; units are " + e.allowed());
  }
  if (u.dim != expected && expected == dimensionless)
    throw UnitError("expected a dimensionless number; got unit " + quoted(sp.unit) + " (" + name_of(u.dim) + ")",
                    "a plain number without unit");
  if (u.dim != expected)
    throw UnitError("expected " + describe(expected) + "; got " + quoted(sp.unit) + " (" +
                        name_of(u.dim) + ")",
                    "a plain number (scene units) or '<number> <unit>' for " + describe(expected));
  return sp.number * u.factor;
}

double angle_to_rad(std::string_view text) {
  const Split sp = split_quantity(text);
  if (sp.unit.empty() || sp.unit == "deg" || sp.unit == "degree" || sp.unit == "degrees")
    return sp.number * std::numbers::pi / 180.0;
  if (sp.unit == "rad") return sp.number;
  throw UnitError("expected an angle; got unit " + quoted(sp.unit),
                  "a number in degrees, or a number followed by 'deg' or 'rad' (e.g. 45, '0.5 rad')");
}

}  // namespace plyimpact::units
