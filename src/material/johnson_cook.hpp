// Johnson-Cook plasticity for metal impactors: *MAT_015 (JOHNSON_COOK, with thermal softening from
// adiabatic heating, the Johnson-Cook fracture strain and an equation of state for the pressure) and
// *MAT_098 (SIMPLIFIED_JOHNSON_COOK: no temperature, no damage, elastic bulk response, flow stress
// capped by SIGMAX before and SIGSAT after the rate term). Flow stress (Johnson & Cook 1983):
//   sigma_y = (A + B ep^N) (1 + C ln(max(rate*, 1))) (1 - T*^M),  rate* = rate / EPSO,
//   T* = (T - TR) / (TM - TR);
// fracture strain (Johnson & Cook 1985): eps_f = [D1 + D2 exp(D3 sigma*)] [1 + D4 ln rate*]
// [1 + D5 T*], sigma* = mean stress / effective stress, damage D = sum(dep / eps_f), failure at 1.
// The deviatoric stress is a J2 radial return on the hypoelastic trial stress (objective through
// the incremental rotation R), solved to round-off by a safeguarded Newton iteration (LS-DYNA's IT 1;
// its IT 0 linearisation is not used). Adiabatic heating: dT = TQC sigma_y dep / (rho CP).
// Voigt order xx yy zz xy yz zx, tensor strain rates; SI units, temperatures in K.
#pragma once

#include <limits>

#include "material/eos.hpp"

namespace plyimpact::material {

struct JohnsonCookParams {
  bool simplified = false;        // *MAT_098: no temperature, no damage, elastic bulk response
  double rho0 = 0;                // reference density RO, kg/m^3
  double shear = 0;               // G, Pa
  double bulk = 0;                // K of the elastic bulk response (no EOS), Pa
  double A = 0, B = 0, N = 1, C = 0;
  double M = 1, TM = 0, TR = 293, EPSO = 1, CP = 0;  // thermal: TM > TR and CP > 0
  double TQC = 1;                 // Taylor-Quinney: fraction of plastic work that heats the metal
  int VP = 0;                     // 0: rate* from the effective deviatoric strain rate; 1: from the plastic strain rate
  double PC = 0;                  // pressure cutoff (< 0), 0 = none
  int SPALL = 1;                  // 1: p >= PC; 2: max principal stress >= -PC spalls; 3: p < PC spalls
  double D1 = 0, D2 = 0, D3 = 0, D4 = 0, D5 = 0, EFMIN = 0;
  int EROD = 0;                   // 0: a failed point erodes the element; 1: it keeps pressure >= 0 only
  double PSFAIL = 0;              // *MAT_098 effective plastic strain at failure; 0 = none
  double SIGMAX = std::numeric_limits<double>::infinity();  // *MAT_098 cap of A + B ep^N
  double SIGSAT = std::numeric_limits<double>::infinity();  // *MAT_098 cap after the rate term
  EosParams eos;                  // kind None: p from the bulk modulus

  bool thermal() const { return !simplified && CP > 0 && TM > TR; }
  bool damage() const { return !simplified && (D1 != 0 || D2 != 0 || D3 != 0 || D4 != 0 || D5 != 0); }
  bool can_fail() const { return damage() || PSFAIL > 0 || (PC < 0 && SPALL != 1); }
};

// History per integration point.
namespace jc_history {
inline constexpr int kPlasticStrain = 0;   // effective plastic strain
inline constexpr int kTemperatureRise = 1; // T - TR, K
inline constexpr int kDamage = 2;          // Johnson-Cook damage D
inline constexpr int kLogVolume = 3;       // ln V, V = relative volume (integral of tr D dt)
inline constexpr int kEnergy = 4;          // internal energy per reference volume minus E0, Pa
inline constexpr int kPlasticWork = 5;     // plastic work per reference volume, Pa
inline constexpr int kFailed = 6;          // 1: failed without erosion (EROD 1, spall): no deviatoric stress, no tension
}  // namespace jc_history
inline constexpr int kJohnsonCookHistory = 7;

struct JohnsonCookResult {
  bool failed = false;            // the point reached failure and the element is to erode
  double plastic_increment = 0;
};

// sigma_y at plastic strain ep, normalised rate rate* and homologous temperature T*.
double johnson_cook_flow_stress(const JohnsonCookParams& p, double ep, double rate_star, double T_star);

// Johnson-Cook fracture strain (bounded below by EFMIN).
double johnson_cook_fracture_strain(const JohnsonCookParams& p, double triaxiality, double rate_star, double T_star);

// Homologous temperature T* in [0, 1] of a temperature rise dT above TR (0 for *MAT_098).
double homologous_temperature(const JohnsonCookParams& p, double temperature_rise);

// One step: rotate the stress by R (row-major), add the trial increment of D (tensor Voigt) over
// dt, return the deviator to the flow stress, take the pressure from the EOS (or K), heat, damage.
JohnsonCookResult johnson_cook_update(const JohnsonCookParams& p, const double R[9], const double D[6], double dt,
                                      double stress[6], double history[kJohnsonCookHistory]);

}  // namespace plyimpact::material
