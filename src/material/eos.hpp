// Equations of state for the pressure of *MAT_015: *EOS_LINEAR_POLYNOMIAL and *EOS_GRUNEISEN, in
// the form LS-DYNA gives them (Keyword User's Manual Vol. II, "*EOS"). Both are linear in the
// internal energy, p = a(mu) + b(mu) E, which lets the material close the energy equation of a step
// exactly (material/johnson_cook.cpp). mu = rho / rho0 - 1 = 1 / V - 1 with V the relative volume;
// E is the internal energy per unit reference volume (Pa); pressure positive in compression. SI.
#pragma once

namespace plyimpact::material {

struct EosParams {
  enum class Kind { None, LinearPolynomial, Gruneisen };
  Kind kind = Kind::None;
  // *EOS_LINEAR_POLYNOMIAL: p = C0 + C1 mu + C2 mu^2 + C3 mu^3 + (C4 + C5 mu + C6 mu^2) E, with the
  // mu^2 terms (C2, C6) dropped in expansion (mu < 0), as on the card.
  double C0 = 0, C1 = 0, C2 = 0, C3 = 0, C4 = 0, C5 = 0, C6 = 0;
  // *EOS_GRUNEISEN: shock velocity Us = C + S1 up + S2 up^2/Us + S3 up^3/Us^2 (m/s), Grueneisen
  // gamma GAMAO with its first-order volume correction A.
  double C = 0, S1 = 0, S2 = 0, S3 = 0, GAMAO = 0, A = 0;
  double E0 = 0;     // initial internal energy per reference volume, Pa
  double rho0 = 0;   // reference density of the material, kg/m^3 (Gruneisen)
};

// Coefficients of p = a + b E at compression mu.
void eos_coefficients(const EosParams& eos, double mu, double& a, double& b);

// p(mu, E).
double eos_pressure(const EosParams& eos, double mu, double E);

// Bulk modulus of the reference state, dp/dmu at mu = 0, E = E0 (Pa): C1 + C5 E0, or rho0 C^2 + A E0.
double eos_reference_bulk_modulus(const EosParams& eos);

}  // namespace plyimpact::material
