// Elasto-plastic metal for the steel projectile: *MAT_003 (PLASTIC_KINEMATIC: linear hardening,
// kinematic/isotropic mix BETA, Cowper-Symonds rate factor SRC/SRP, failure strain FS) and *MAT_024
// (PIECEWISE_LINEAR_PLASTICITY: hardening curve, C/P rate factor, FAIL). J2 radial return on the
// hypoelastic stress, objective through the incremental rotation R applied to stress and back
// stress (LS-DYNA Theory Manual "Material Model 3"; Simo & Hughes, Computational Inelasticity, 1998,
// box 3.1 for the return map). Voigt order xx yy zz xy yz zx; strain rates are tensor components.
#pragma once

#include <vector>

namespace plyimpact::material {

struct PlasticityParams {
  double E = 0, nu = 0;
  double shear = 0, lambda = 0;  // elastic G and lambda
  double sigy = 0;               // initial yield stress
  double hardening = 0;          // MAT_003: plastic hardening modulus E_p = E ETAN / (E - ETAN)
  double beta = 0;               // MAT_003 BETA: 0 kinematic, 1 isotropic hardening
  double rate_c = 0, rate_p = 0; // Cowper-Symonds C (1/s) and P; C = 0: no rate effect
  double failure_strain = 0;     // effective plastic strain that erodes the element; 0 = none
  // MAT_024: yield stress vs effective plastic strain (piecewise linear, constant beyond the last
  // point); empty for MAT_003. Isotropic hardening.
  std::vector<double> curve_strain, curve_stress;
};

// MAT_003 from its card (ETAN < E required); MAT_024 with a curve (first plastic strain 0, stresses
// non-decreasing) or, without one, with the linear hardening of SIGY and ETAN.
PlasticityParams plastic_kinematic(double E, double PR, double SIGY, double ETAN, double BETA, double SRC,
                                   double SRP, double FS);
PlasticityParams piecewise_linear(double E, double PR, double SIGY, double ETAN, double C, double P, double FAIL,
                                  const std::vector<double>& eps, const std::vector<double>& sig);

// History per integration point: [0] effective plastic strain, [1..6] back stress (Voigt).
inline constexpr int kPlasticityHistory = 7;

struct PlasticityResult {
  bool failed = false;              // effective plastic strain reached the failure strain
  double plastic_increment = 0;     // effective plastic strain increment of this step
};

// One step: rotate stress and back stress by R (row-major 3x3), add the elastic trial increment of
// the strain rate D (tensor Voigt) over dt, return to the (rate-scaled) yield surface.
PlasticityResult plasticity_update(const PlasticityParams& p, const double R[9], const double D[6], double dt,
                                   double stress[6], double history[kPlasticityHistory]);

// Yield stress at effective plastic strain ep without rate effect.
double yield_stress(const PlasticityParams& p, double ep);

}  // namespace plyimpact::material
