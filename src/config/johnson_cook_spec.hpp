// *MAT_015 (*MAT_JOHNSON_COOK) with its *EOS_LINEAR_POLYNOMIAL / *EOS_GRUNEISEN, and *MAT_098
// (*MAT_SIMPLIFIED_JOHNSON_COOK): the card fields this code implements, under their LS-DYNA names,
// in SI (temperatures in K). Meanings in material/johnson_cook.hpp and material/eos.hpp. Nothing
// here depends on yaml-cpp.
#pragma once

#include <limits>
#include <optional>
#include <string>

namespace plyimpact::config {

// *EOS_LINEAR_POLYNOMIAL (card "EOS_LINEAR_POLYNOMIAL") or *EOS_GRUNEISEN ("EOS_GRUNEISEN").
struct EosSpec {
  std::string card;
  double C0 = 0, C1 = 0, C2 = 0, C3 = 0, C4 = 0, C5 = 0, C6 = 0;  // C0-C3 Pa, C4-C6 dimensionless
  double C = 0, S1 = 0, S2 = 0, S3 = 0, GAMAO = 0, A = 0;         // C m/s
  double E0 = 0;  // Pa (energy per reference volume); V0 = 1 only
};

struct MatJohnsonCook {
  double RO = 0, G = 0;
  double E = 0, PR = 0;  // elastic bulk modulus E / (3 (1 - 2 PR)) when there is no EOS
  int VP = 0;
  double A = 0, B = 0, N = 1, C = 0, M = 1, TM = 0, TR = 293, EPSO = 1, CP = 0;
  double PC = 0;
  int SPALL = 2, IT = 0;
  double D1 = 0, D2 = 0, D3 = 0, D4 = 0, D5 = 0, EFMIN = 1e-6;  // EFMIN: the card default
  int EROD = 0;
  double TQC = 1;  // Taylor-Quinney coefficient (not a *MAT_015 field: LS-DYNA's card has none)
  std::optional<EosSpec> eos;
};

struct MatSimplifiedJohnsonCook {
  double RO = 0, E = 0, PR = 0;
  int VP = 0;
  double A = 0, B = 0, N = 1, C = 0, PSFAIL = 0, EPSO = 1;
  double SIGMAX = std::numeric_limits<double>::infinity(), SIGSAT = std::numeric_limits<double>::infinity();
};

}  // namespace plyimpact::config
