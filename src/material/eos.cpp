#include "material/eos.hpp"

namespace plyimpact::material {

void eos_coefficients(const EosParams& q, double mu, double& a, double& b) {
  if (q.kind == EosParams::Kind::LinearPolynomial) {
    const double mu2 = mu > 0 ? mu * mu : 0.0;  // the card drops C2 and C6 in expansion
    a = q.C0 + q.C1 * mu + q.C2 * mu2 + q.C3 * mu * mu * mu;
    b = q.C4 + q.C5 * mu + q.C6 * mu2;
    return;
  }
  if (q.kind == EosParams::Kind::Gruneisen) {
    const double rc2 = q.rho0 * q.C * q.C;
    b = q.GAMAO + q.A * mu;
    if (mu > 0) {
      // Mie-Grueneisen on the linear-to-cubic Us-up Hugoniot (the card's compressed form).
      const double den = 1 - (q.S1 - 1) * mu - q.S2 * mu * mu / (mu + 1) - q.S3 * mu * mu * mu / ((mu + 1) * (mu + 1));
      a = rc2 * mu * (1 + (1 - 0.5 * q.GAMAO) * mu - 0.5 * q.A * mu * mu) / (den * den);
    } else {
      a = rc2 * mu;
    }
    return;
  }
  a = 0, b = 0;
}

double eos_pressure(const EosParams& eos, double mu, double E) {
  double a, b;
  eos_coefficients(eos, mu, a, b);
  return a + b * E;
}

double eos_reference_bulk_modulus(const EosParams& q) {
  if (q.kind == EosParams::Kind::LinearPolynomial) return q.C1 + q.C5 * q.E0;
  if (q.kind == EosParams::Kind::Gruneisen) return q.rho0 * q.C * q.C + q.A * q.E0;
  return 0;
}

}  // namespace plyimpact::material
