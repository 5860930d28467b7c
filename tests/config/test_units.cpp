// core/units: unit expressions, unit systems, quantity strings and strict number parsing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/units.hpp"

namespace u = plyimpact::units;

namespace {

constexpr double kRel = 1e-12;

void expect_rel(double actual, double expected) {
  EXPECT_NEAR(actual, expected, kRel * std::abs(expected)) << "expected " << expected;
}

// Expects `f` to throw UnitError whose message contains every fragment.
template <class F>
void expect_unit_error(F&& f, std::initializer_list<std::string> fragments) {
  try {
    f();
    ADD_FAILURE() << "no UnitError thrown";
  } catch (const u::UnitError& e) {
    for (const auto& frag : fragments)
      EXPECT_NE(std::string(e.what()).find(frag), std::string::npos) << "missing '" << frag << "' in: " << e.what();
  }
}

}  // namespace

TEST(Units, ParsesEveryListedUnit) {
  struct Case {
    const char* expr;
    double factor;
    u::Dimension dim;
  };
  const Case cases[] = {
      {"kg/m^3", 1.0, u::density},         {"N/mm^2", 1e6, u::stress},
      {"J/m^2", 1.0, u::energy_per_area},  {"kN/mm^3", 1e12, u::stiffness_per_area},
      {"1/s", 1.0, u::frequency},          {"mm/ms", 1.0, u::velocity},
      {"t/mm^3", 1e12, u::density},        {"g/cm^3", 1e3, u::density},
      {"MPa", 1e6, u::stress},             {"GPa", 1e9, u::stress},
      {"kPa", 1e3, u::stress},             {"Pa", 1.0, u::stress},
      {"N", 1.0, u::force},                {"kN", 1e3, u::force},
      {"J", 1.0, u::energy},               {"mJ", 1e-3, u::energy},
      {"m", 1.0, u::length},               {"mm", 1e-3, u::length},
      {"cm", 1e-2, u::length},             {"um", 1e-6, u::length},
      {"s", 1.0, u::time},                 {"ms", 1e-3, u::time},
      {"us", 1e-6, u::time},               {"kg", 1.0, u::mass},
      {"g", 1e-3, u::mass},                {"t", 1e3, u::mass},
      {"tonne", 1e3, u::mass},             {"Hz", 1.0, u::frequency},
      {"m/s", 1.0, u::velocity},           {"m/s^2", 1.0, u::acceleration},
      {"kg*m/s^2", 1.0, u::force},         {"GPa/mm", 1e12, u::stiffness_per_area},
      {"N/mm", 1e3, u::energy_per_area},   {"m^-3*kg", 1.0, u::density},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.expr);
    const u::Unit unit = u::parse_unit(c.expr);
    expect_rel(unit.factor, c.factor);
    EXPECT_EQ(unit.dim, c.dim);
  }
}

TEST(Units, QuantityStringsToSI) {
  const u::UnitSystem si = u::parse_unit_system("SI");
  expect_rel(u::quantity_to_si("157 GPa", u::stress, si), 1.57e11);
  expect_rel(u::quantity_to_si("1.55 g/cm^3", u::density, si), 1550.0);
  expect_rel(u::quantity_to_si("5 m/s", u::velocity, si), 5.0);
  expect_rel(u::quantity_to_si("-5 m/s", u::velocity, si), -5.0);
  expect_rel(u::quantity_to_si("765 J/m^2", u::energy_per_area, si), 765.0);
  expect_rel(u::quantity_to_si("100 kN/mm^3", u::stiffness_per_area, si), 1e14);
  expect_rel(u::quantity_to_si("2 ms", u::time, si), 2e-3);
  expect_rel(u::quantity_to_si("2ms", u::time, si), 2e-3);
  expect_rel(u::quantity_to_si("1.5e-6", u::time, si), 1.5e-6);
  expect_rel(u::quantity_to_si("+3 mm", u::length, si), 3e-3);
}

TEST(Units, Angles) {
  expect_rel(u::angle_to_rad("45"), std::numbers::pi / 4);
  expect_rel(u::angle_to_rad("45 deg"), std::numbers::pi / 4);
  expect_rel(u::angle_to_rad("0.5 rad"), 0.5);
  expect_unit_error([] { u::angle_to_rad("0.5 mm"); }, {"expected an angle", "'mm'"});
}

TEST(Units, UnitSystems) {
  const u::UnitSystem mts = u::parse_unit_system("mm-t-s-MPa");
  EXPECT_EQ(mts.name, "mm-t-s-MPa");
  expect_rel(u::to_si(1.55e-9, u::density, mts), 1550.0);
  expect_rel(u::to_si(1.0, u::stress, mts), 1e6);
  expect_rel(u::to_si(1.0, u::force, mts), 1.0);
  expect_rel(u::to_si(1.0, u::velocity, mts), 1e-3);
  expect_rel(u::quantity_to_si("1.55e-9", u::density, mts), 1550.0);

  const u::UnitSystem mkm = u::parse_unit_system("mm-kg-ms-GPa");
  EXPECT_EQ(mkm.name, "mm-kg-ms-GPa");
  expect_rel(u::to_si(1.0, u::stress, mkm), 1e9);
  expect_rel(u::to_si(1.0, u::velocity, mkm), 1.0);
  expect_rel(u::to_si(1.0, u::force, mkm), 1e3);
  expect_rel(u::to_si(1.0, u::density, mkm), 1e9);
  expect_rel(u::to_si(1.0, u::time, mkm), 1e-3);

  for (const char* s : {"SI", "si", "m-kg-s", "M_KG_S", "mks", "m-kg-s-N-Pa"}) EXPECT_EQ(u::parse_unit_system(s).name, "SI") << s;
  for (const char* s : {"mm-ton-s", "mm-t-s", "MM-T-S-MPA", "mm-tonne-s-N-MPa", "mm_t_s_mpa"})
    EXPECT_EQ(u::parse_unit_system(s).name, "mm-t-s-MPa") << s;
  for (const char* s : {"mm-kg-ms", "mm-kg-ms-kN-GPa", "mm kg ms GPa"}) EXPECT_EQ(u::parse_unit_system(s).name, "mm-kg-ms-GPa") << s;

  expect_unit_error([] { u::parse_unit_system("furlong-firkin-fortnight"); }, {"unknown unit system", "mm-t-s-MPa"});
  expect_unit_error([] { u::parse_unit_system("mm-t-s-GPa"); }, {"unknown unit system"});  // inconsistent
}

TEST(Units, DimensionMismatchNamesBoth) {
  const u::UnitSystem si = u::parse_unit_system("SI");
  expect_unit_error([&] { u::quantity_to_si("210 mm", u::stress, si); },
                    {"expected a stress (e.g. MPa, GPa, Pa); got 'mm'", "a length"});
  expect_unit_error([&] { u::quantity_to_si("5 m/s", u::time, si); }, {"expected a time", "'m/s'", "a velocity"});
  expect_unit_error([&] { u::quantity_to_si("0.3 MPa", u::dimensionless, si); }, {"expected a dimensionless number"});
}

TEST(Units, GarbageIsRejected) {
  const u::UnitSystem si = u::parse_unit_system("SI");
  expect_unit_error([&] { u::quantity_to_si("12abc", u::length, si); }, {"unknown unit 'abc'"});
  expect_unit_error([&] { u::quantity_to_si("abc", u::length, si); }, {"not a number"});
  expect_unit_error([&] { u::quantity_to_si("", u::length, si); }, {"empty value"});
  expect_unit_error([&] { u::quantity_to_si("0x10", u::length, si); }, {"unknown unit 'x'"});
  expect_unit_error([&] { u::quantity_to_si("nan", u::length, si); }, {"not a finite number"});
  expect_unit_error([&] { u::quantity_to_si("1e400", u::length, si); }, {"not a number"});
  expect_unit_error([&] { u::quantity_to_si("5 m//s", u::velocity, si); }, {"unexpected character '/'"});
  expect_unit_error([&] { u::quantity_to_si("5 m/", u::velocity, si); }, {"missing unit after operator"});
  expect_unit_error([&] { u::quantity_to_si("5 m^x", u::length, si); }, {"bad exponent"});
  expect_unit_error([&] { u::quantity_to_si("5 m s", u::length, si); }, {"expected '*' or '/'"});
  expect_unit_error([&] { u::parse_unit("kt"); }, {"unknown unit 'kt'"});  // no prefix on tonne
  expect_unit_error([] { u::parse_number("12abc"); }, {"not a number: '12abc'"});
  expect_unit_error([] { u::parse_number("1.0.0"); }, {"not a number"});
  expect_unit_error([] { u::parse_integer("1.5"); }, {"not an integer: '1.5'"});
  expect_unit_error([] { u::parse_integer("1e2"); }, {"not an integer"});
  expect_unit_error([] { u::parse_integer(""); }, {"not an integer"});
  EXPECT_EQ(u::parse_integer(" 42 "), 42);
  EXPECT_EQ(u::parse_integer("-3"), -3);
  EXPECT_DOUBLE_EQ(u::parse_number("-2.5e-3"), -2.5e-3);
}

TEST(Units, DescribeNamesDimensions) {
  EXPECT_EQ(u::describe(u::stress), "a stress (e.g. MPa, GPa, Pa)");
  EXPECT_EQ(u::describe(u::Dimension{4, 0, 0}), "a quantity of dimension m^4 kg^0 s^0");
}
