// Bad interface parameters are refused with the field, the unit and the numbers; the process-zone
// strength rule (Turon et al. 2007) gives the strength at which N segments span the cohesive zone.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cohesive/law_parameters.hpp"
#include "cohesive/traction_law.hpp"
#include "core/error.hpp"
#include "law_paths.hpp"

namespace plyimpact::cohesive {
namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& m : v) s += m + "\n";
  return s;
}

TEST(LawValidation, Table86ValuesAreAccepted) {
  EXPECT_TRUE(validate_traction_law(test::table_8_6_option9()).empty());
}

TEST(LawValidation, MissingAndNonPositiveFieldsAreNamedWithTheirValues) {
  auto p = test::table_8_6_option9();
  p.NFLS = kMissing;
  p.SFLS = -5e6;
  p.ERATEN = 0;
  p.CN = kMissing;
  const auto text = joined(validate_traction_law(p));
  EXPECT_NE(text.find("NFLS is missing (Pa, > 0)"), std::string::npos) << text;
  EXPECT_NE(text.find("SFLS must be > 0 Pa (got -5e+06)"), std::string::npos) << text;
  EXPECT_NE(text.find("ERATEN must be > 0 J/m^2 (got 0)"), std::string::npos) << text;
  EXPECT_NE(text.find("CN is missing (Pa/m, > 0)"), std::string::npos) << text;
  auto q = test::table_8_6_option9();
  q.ERATES = kMissing;
  EXPECT_NE(joined(validate_traction_law(q)).find("ERATES is missing"), std::string::npos);
}

// A stiffness so low that the onset opening NFLS/CN passes the final opening 2 ERATEN/NFLS.
TEST(LawValidation, OnsetNotBelowFinalOpeningIsRefusedWithTheNumbers) {
  auto p = test::table_8_6_option9();
  p.CN = 1e9;  // onset 60e6/1e9 = 0.06 m, final 2*765/60e6 = 2.55e-05 m
  const auto problems = validate_traction_law(p);
  const auto text = joined(problems);
  EXPECT_NE(text.find("mode I: the onset opening NFLS/CN = 0.06 m is not below the final opening 2 ERATEN/NFLS = 2.55e-05 m"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("2G/sigma <= sigma/K"), std::string::npos) << text;
  EXPECT_NE(text.find("mode II: the onset opening SFLS/(CT2CN CN)"), std::string::npos) << text;
  try {
    require_valid_traction_law(p, "plate.yaml:12:5: interfaces.law");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("plate.yaml:12:5: interfaces.law: mode I", 0), 0u) << e.what();
  }
  EXPECT_THROW(make_traction_law(p), InputError);
}

TEST(LawValidation, OptionSpecificFields) {
  TractionLawParams six;
  six.option = TiebreakOption::StressCcrit;
  six.NFLS = 60e6;
  six.SFLS = 60e6;
  six.CN = 1e13;
  six.PARAM = 1e-6;  // below the onset opening 6e-6 m
  const auto text6 = joined(validate_traction_law(six));
  EXPECT_NE(text6.find("mode I: the onset opening NFLS/CN = 6e-06 m is not below CCRIT = 1e-06 m"), std::string::npos)
      << text6;
  six.PARAM = kMissing;
  EXPECT_NE(joined(validate_traction_law(six)).find("PARAM (CCRIT) is missing (m, > 0)"), std::string::npos);
  six.PARAM = 2.5e-5;
  EXPECT_TRUE(validate_traction_law(six).empty());  // ERATEN/ERATES are not read by OPTION 6

  TractionLawParams seven = six;
  seven.option = TiebreakOption::DiscreteCrack;
  seven.ERATEN = 765;
  seven.ERATES = 1250;
  seven.PARAM = 95;
  EXPECT_NE(joined(validate_traction_law(seven)).find("friction angle) must be in [0, 90) degrees (got 95)"),
            std::string::npos);

  auto nine = test::table_8_6_option9();
  nine.PARAM = 0;
  EXPECT_NE(joined(validate_traction_law(nine)).find("PARAM must be > 0 (power-law exponent) or < 0"),
            std::string::npos);
  nine.PARAM = kMissing;  // blank: LS-DYNA's default 1.0
  EXPECT_TRUE(validate_traction_law(nine).empty());
  EXPECT_EQ(make_traction_law(nine).alpha, 1.0);
  nine.PARAM = -2.3;
  const auto law = make_traction_law(nine);
  EXPECT_EQ(law.bk_eta, 2.3);

  auto eight = test::table_8_6_option9();
  eight.option = TiebreakOption(8);
  EXPECT_NE(joined(validate_traction_law(eight)).find("OPTION 8 is not implemented (allowed: 6, 7, 9)"),
            std::string::npos);
}

// Turon et al. (2007): l_cz = M E G_c / tau^2 with M = 9 pi / 32; the strength returned makes the
// zone exactly N segments long. T800S/M21: E_c = 8.5 GPa, G_Ic = 765 J/m^2.
TEST(ProcessZoneStrength, ZoneSpansTheRequestedNumberOfSegments) {
  const double e = 8.5e9, g = 765;
  for (double le : {0.25e-3, 0.5e-3, 2.5e-3}) {
    const double tau = process_zone_strength(e, g, le, 3);
    const double l_cz = 9 * std::numbers::pi / 32 * e * g / (tau * tau);
    EXPECT_NEAR(l_cz, 3 * le, 1e-12 * le);
  }
  auto p = test::table_8_6_option9();
  // 0.5 mm segments: tau_3 = 61.9 MPa > 60 MPa, the law is kept as given.
  const auto fine = scale_strengths_to_length(p, e, 0.5e-3 * 0.5e-3, 3);
  EXPECT_EQ(fine.NFLS, p.NFLS);
  // 2.5 mm segments: tau_3 = 27.7 MPa for mode I; energies and stiffness unchanged.
  const auto coarse = scale_strengths_to_length(p, e, 2.5e-3 * 2.5e-3, 3);
  EXPECT_NEAR(coarse.NFLS, process_zone_strength(e, p.ERATEN, 2.5e-3, 3), 1e-6);
  EXPECT_NEAR(coarse.NFLS, 27.7e6, 0.05e6);
  EXPECT_LT(coarse.SFLS, p.SFLS);
  EXPECT_EQ(coarse.ERATEN, p.ERATEN);
  EXPECT_EQ(coarse.CN, p.CN);
  EXPECT_TRUE(validate_traction_law(coarse).empty());
  // OPTION 6's energy is set by NFLS and CCRIT: not scaled.
  TractionLawParams six = p;
  six.option = TiebreakOption::StressCcrit;
  EXPECT_EQ(scale_strengths_to_length(six, e, 2.5e-3 * 2.5e-3, 3).NFLS, p.NFLS);
}

}  // namespace
}  // namespace plyimpact::cohesive
