// Orthotropic elastic constants shared by the *MAT_002 and *MAT_054 cards (RO EA EB EC PRBA PRCA
// PRCB GAB GBC GCA), read once here for both. The Poisson ratios are LS-DYNA's minor ratios
// nu_ji (load along i, contraction along j); |nu_ji| < sqrt(E_j/E_i) must hold, and a value that
// breaks it is most likely the major ratio, which the message then converts.
#pragma once

#include <cmath>

#include "config/yaml_reader.hpp"
#include "core/units.hpp"

namespace plyimpact::config::detail {

template <class Card>
void read_orthotropic_constants(const Reader& r, Card& m) {
  namespace u = units;
  m.RO = r.quantity("RO", u::density, Limits::positive("density"));
  m.EA = r.quantity("EA", u::stress, Limits::positive("EA").of(QuantityKind::modulus));
  m.EB = r.quantity("EB", u::stress, Limits::positive("EB").of(QuantityKind::modulus));
  m.EC = r.quantity("EC", u::stress, Limits::positive("EC").of(QuantityKind::modulus));
  m.PRBA = r.quantity("PRBA", u::dimensionless);
  m.PRCA = r.quantity("PRCA", u::dimensionless);
  m.PRCB = r.quantity("PRCB", u::dimensionless);
  m.GAB = r.quantity("GAB", u::stress, Limits::positive("GAB").of(QuantityKind::modulus));
  m.GBC = r.quantity("GBC", u::stress, Limits::positive("GBC").of(QuantityKind::modulus));
  m.GCA = r.quantity("GCA", u::stress, Limits::positive("GCA").of(QuantityKind::modulus));
  auto check = [&](const char* key, double nu, const char* ei, double e_i, const char* ej, double e_j) {
    const double bound = std::sqrt(e_i / e_j);
    if (std::abs(nu) < bound) return;
    r.at(key, "").fail(msg() << "|" << key << "| must be < sqrt(" << ei << "/" << ej << ") = " << bound
                             << " (minor Poisson ratio; the major ratio would be " << key << "*" << ej << "/" << ei
                             << " = " << nu * e_j / e_i << "; if you entered the major ratio, use "
                             << nu * e_i / e_j << ")",
                       msg() << "|" << key << "| < " << bound);
  };
  check("PRBA", m.PRBA, "EB", m.EB, "EA", m.EA);
  check("PRCA", m.PRCA, "EC", m.EC, "EA", m.EA);
  check("PRCB", m.PRCB, "EC", m.EC, "EB", m.EB);
}

}  // namespace plyimpact::config::detail
