// read_mat054 (YAML card -> MatCompositeDamage in SI) and unsupported_field (refusal of fields
// the material does not implement). Conversions are checked to 1e-12 relative (one or two
// floating-point multiplications by powers of ten).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "config/mat054_reader.hpp"
#include "config/mat054_spec.hpp"
#include "core/error.hpp"
#include "mat054_support.hpp"

namespace plyimpact::config {
namespace {

// The seed's Figure 7.3 card as a scene would hold it, in the card's own mm-t-s-MPa units.
const char* kSeedCard = R"(materials:
  ply:
    card: MAT_054
    RO: 1.550e-09
    EA: 1.650e+05
    EB: 7640.0
    EC: 7640.0
    PRBA: 0.0162
    PRCA: 0.0162
    PRCB: 0.4
    GAB: 5610.0
    GBC: 2750.0
    GCA: 5610.0
    KF: 0.0
    AOPT: 2
    2WAY: 0
    XP: 0.0
    YP: 0.0
    ZP: 0.0
    A1: -0.7071
    A2: 0.7071
    A3: 0.0
    MANGLE: 0.0
    V1: 0.0
    V2: 0.0
    V3: 0.0
    D1: -0.7071
    D2: -0.7071
    D3: 0.0
    DFAILM: 0.0366
    DFAILS: 0.0
    TFAIL: 0.0
    ALPH: 0.0
    SOFT: 1.0
    FBRT: 0.0
    YCFAC: 2.0
    DFAILT: 0.0133
    DFAILC: -0.00727
    EFS: 0.0
    XC: 1200.0
    XT: 2200.0
    YC: 280.0
    YT: 45.0
    SC: 50.0
    CRIT: 54
    BETA: 1.0
    PFL: 0.0
    EPSF: 0.0
    EPSR: 0.0
    TSMD: 0.0
    SOFT2: 1.0
    SLIMT1: 0.0
    SLIMC1: 0.0
    SLIMT2: 0.0
    SLIMC2: 0.0
    SLIMS: 0.0
    NCYRED: 0
    SOFTG: 1.0
    LCXC: 0
    LCXT: 0
    LCYC: 0
    LCYT: 0
    LCSC: 0
    DT: 0.0
)";

MatCompositeDamage read(const std::string& yaml, const std::string& units = "mm-t-s-MPa") {
  const detail::Context ctx{"card.yaml", units::parse_unit_system(units)};
  const YAML::Node root = YAML::Load(yaml);
  return detail::read_mat054(detail::Reader(root["materials"]["ply"], "materials.ply", &ctx, root.Mark()));
}

// The seed card with `line` appended to the ply mapping (a later duplicate would be refused, so
// the key must not be in kSeedCard) or with `key` replaced.
std::string with(const std::string& key, const std::string& value) {
  std::string s = kSeedCard;
  const std::string needle = "    " + key + ": ";
  const auto at = s.find(needle);
  if (at == std::string::npos) return s + "    " + key + ": " + value + "\n";
  const auto end = s.find('\n', at);
  return s.substr(0, at) + needle + value + s.substr(end);
}

void expect_error(const std::string& yaml, std::initializer_list<std::string> fragments,
                  const std::string& units = "mm-t-s-MPa") {
  try {
    read(yaml, units);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    for (const auto& f : fragments)
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos) << "missing '" << f << "' in: " << e.what();
  }
}

void expect_rel(double actual, double expected) {
  EXPECT_NEAR(actual, expected, 1e-12 * std::abs(expected)) << "expected " << expected;
}

TEST(Mat054Reader, SeedCardInMmTonneSecondsIsReadIntoSI) {
  const MatCompositeDamage m = read(kSeedCard);
  const MatCompositeDamage ref = test::t800_card();
  expect_rel(m.RO, ref.RO);
  expect_rel(m.EA, ref.EA);
  expect_rel(m.EB, ref.EB);
  expect_rel(m.GBC, ref.GBC);
  expect_rel(m.XT, ref.XT);
  expect_rel(m.YC, ref.YC);
  expect_rel(m.SC, ref.SC);
  EXPECT_EQ(m.PRBA, ref.PRBA);
  EXPECT_EQ(m.DFAILT, ref.DFAILT);
  EXPECT_EQ(m.DFAILC, ref.DFAILC);
  EXPECT_EQ(m.DFAILM, ref.DFAILM);
  EXPECT_EQ(m.axes.AOPT, 2);
  EXPECT_EQ(m.axes.A, ref.axes.A);
  EXPECT_EQ(m.axes.D, ref.axes.D);
  EXPECT_EQ(m.CRIT, 54);
  EXPECT_EQ(m.BETA, 1.0);
  EXPECT_EQ(m.TSMD, 0.0);  // internal 0.90 applied by the material
  EXPECT_EQ(m.YCFAC, 2.0);
  EXPECT_FALSE(unsupported_field(m).has_value());
}

TEST(Mat054Reader, DefaultsAndUnitsOfTheSpecialFields) {
  EXPECT_EQ(read(with("SOFT", "0.0")).SOFT, 1.0);  // blank/0 takes the card default, as LS-DYNA does
  EXPECT_EQ(read(with("YCFAC", "0")).YCFAC, 2.0);
  EXPECT_EQ(read(with("TFAIL", "0.5")).TFAIL, 0.5);                     // > 0.1: ratio dt/dt0
  expect_rel(read(with("TFAIL", "0.05 ms")).TFAIL, 5e-5);              // <= 0.1: a time, here in ms
  // (The seed card's moduli are MPa numbers: read in mm-kg-ms-GPa they would be 1e3 times too large,
  // beyond the plausible range of a modulus, and the card is refused.)
  expect_rel(read(with("TFAIL", "2 us")).TFAIL, 2e-6);
  expect_rel(read(with("ALPH", "1e-7")).ALPH, 1e-25);  // MPa^-3 -> Pa^-3
  expect_rel(read(with("ALPH", "1e-7 1/MPa^3")).ALPH, 1e-25);
  expect_rel(read(with("MANGLE", "30")).axes.BETA, M_PI / 6);  // degrees, as on the card
  // MAT_055: CRIT defaults to 55; an explicit CRIT 54 contradicts the card name.
  std::string no_crit = kSeedCard;
  no_crit.erase(no_crit.find("    CRIT: 54\n"), 13);
  EXPECT_EQ(read(no_crit).CRIT, 54);
  std::string card55 = no_crit;
  card55.replace(card55.find("MAT_054"), 7, "MAT_055");
  card55.replace(card55.find("DFAILM: 0.0366"), 14, "DFAILM: 0.0");  // MAT_054-only field
  EXPECT_EQ(read(card55).CRIT, 55);
  expect_error(with("card", "MAT_055"), {"materials.ply.CRIT", "Tsai-Wu"});
}

TEST(Mat054Reader, UnsupportedFieldsAreRefusedAtTheirKey) {
  expect_error(with("2WAY", "1"), {"card.yaml:", "materials.ply.2WAY", "2WAY=1", "thin shells only"});
  expect_error(with("SOFT2", "0.5"), {"materials.ply.SOFT2", "SOFT2=0.5"});
  expect_error(with("LCXT", "7"), {"materials.ply.LCXT", "LCXT=7", "strain-rate"});
  expect_error(with("KF", "100"), {"materials.ply.KF", "KF=1e+08"});
  expect_error(with("TI", "1"), {"materials.ply.TI", "TI=1"});
  expect_error(with("AOPT", "4"), {"materials.ply.AOPT", "AOPT=4"});
  expect_error(with("XP", "1"), {"materials.ply.XP", "AOPT 1 and 4"});
  expect_error(with("PFL", "50"), {"materials.ply.PFL", "PFL=50"});
  expect_error(with("DT", "0.001"), {"materials.ply.DT"});
  expect_error(with("CRIT", "55"), {"materials.ply.DFAILM", "DFAILM=0.0366", "CRIT 54"});
}

TEST(Mat054Reader, BadValuesAreRefusedInTheHouseFormat) {
  expect_error(with("DFAILC", "0.0105"), {"card.yaml:", "materials.ply.DFAILC", "DFAILC (entered negative",
                                          "found '0.0105'", "allowed"});
  expect_error(with("CRIT", "22"), {"materials.ply.CRIT", "CRIT must be one of 54, 55"});
  expect_error(with("PRBA", "0.35"), {"materials.ply.PRBA", "minor Poisson ratio"});
  expect_error(with("TFAIL", "1.5"), {"materials.ply.TFAIL", "ratio dt/dt0"});
  expect_error(with("BETA", "2"), {"materials.ply.BETA", "in [0, 1]"});
  expect_error(with("EPSF", "0.01"), {"materials.ply.EPSR", "|EPSR| > EPSF"});
  expect_error(with("DFAILZ", "0.01"), {"materials.ply.DFAILZ", "unknown key 'DFAILZ'", "did you mean"});
  expect_error(with("A", "[1, 0, 0]"), {"materials.ply.A", "not both"});
  std::string no_xt = kSeedCard;
  no_xt.erase(no_xt.find("    XT: 2200.0\n"), 15);
  expect_error(no_xt, {"materials.ply.XT", "missing required key 'XT'"});
}

TEST(Mat054Reader, ErosionReferenceLengthIsALengthAndNeedsAnErosionStrain) {
  expect_rel(read(with("erosion_reference_length", "2.5")).erosion_reference_length, 2.5e-3);  // mm
  expect_rel(read(with("erosion_reference_length", "0.25 cm")).erosion_reference_length, 2.5e-3);
  EXPECT_EQ(read(kSeedCard).erosion_reference_length, 0.0);  // off unless given
  expect_error(with("erosion_reference_length", "-1"),
               {"card.yaml:", "materials.ply.erosion_reference_length", "an element length"});
  std::string no_strains = with("DFAILT", "0.0");
  no_strains = no_strains + "    erosion_reference_length: 2.5\n";
  expect_error(no_strains, {"materials.ply.erosion_reference_length", "none is set", "DFAILT > 0"});
}

TEST(Mat054Reader, ErosionNonlocalNeedsTheReferenceLength) {
  EXPECT_FALSE(read(kSeedCard).erosion_nonlocal);  // off unless given
  const std::string both = with("erosion_reference_length", "2.5") + "    erosion_nonlocal: true\n";
  EXPECT_TRUE(read(both).erosion_nonlocal);
  expect_error(with("erosion_nonlocal", "true"),
               {"card.yaml:", "materials.ply.erosion_nonlocal", "erosion_reference_length > 0"});
  expect_error(with("erosion_reference_length", "2.5") + "    erosion_nonlocal: yes\n",
               {"materials.ply.erosion_nonlocal", "true", "false"});
}

TEST(Mat054Reader, UnsupportedFieldNamesTheFirstOffendingField) {
  MatCompositeDamage m = test::t800_card();
  EXPECT_FALSE(unsupported_field(m).has_value());
  const struct {
    void (*set)(MatCompositeDamage&);
    const char* name;
  } cases[] = {
      {[](MatCompositeDamage& x) { x.CRIT = 22; }, "CRIT=22"},
      {[](MatCompositeDamage& x) { x.TWOWAY = 1; }, "2WAY=1"},
      {[](MatCompositeDamage& x) { x.TI = 1; }, "TI=1"},
      {[](MatCompositeDamage& x) { x.KF = 1e9; }, "KF="},
      {[](MatCompositeDamage& x) { x.axes.AOPT = 1; }, "AOPT=1"},
      {[](MatCompositeDamage& x) { x.ZP = 1; }, "ZP=1"},
      {[](MatCompositeDamage& x) { x.PFL = 10; }, "PFL=10"},
      {[](MatCompositeDamage& x) { x.SOFT2 = 0.8; }, "SOFT2=0.8"},
      {[](MatCompositeDamage& x) { x.LCSC = 2; }, "LCSC=2"},
      {[](MatCompositeDamage& x) { x.DT = 1e-6; }, "DT="},
      {[](MatCompositeDamage& x) { x.CRIT = 55; }, "DFAILM="},
  };
  for (const auto& c : cases) {
    MatCompositeDamage x = test::t800_card();
    c.set(x);
    const auto bad = unsupported_field(x);
    ASSERT_TRUE(bad.has_value()) << c.name;
    EXPECT_EQ(bad->rfind(c.name, 0), 0u) << *bad;
  }
}

}  // namespace
}  // namespace plyimpact::config
