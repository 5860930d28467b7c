#include "model/material_builder.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace plyimpact::model {

namespace {

template <class Card>
material::OrthotropicConstants orthotropic_constants(const Card& m) {
  return {m.EA, m.EB, m.EC, m.PRBA, m.PRCA, m.PRCB, m.GAB, m.GBC, m.GCA};
}

material::Stiffness6 admissible_stiffness(const material::OrthotropicConstants& m, const config::SourceLocation& where) {
  if (!material::admissible(m))
    throw InputError(config::at(where)
                     << "orthotropic constants give a stiffness that is not positive definite (1 - nu_ab nu_ba"
                        " - nu_bc nu_cb - nu_ca nu_ac - 2 nu_ba nu_cb nu_ac = "
                     << material::orthotropic_determinant(m) << "); found PRBA=" << m.PRBA << " PRCA=" << m.PRCA
                     << " PRCB=" << m.PRCB
                     << "; allowed: constants with a positive definite compliance. PRBA is LS-DYNA's minor "
                        "ratio nu_ba = nu_ab*EB/EA (about 0.02 for a carbon ply, not 0.3)");
  return material::orthotropic_stiffness(m);
}

// Reuss bound of the bulk modulus, 1 / sum_{i,j<=3} S_ij, for the SOFT 0 contact stiffness (our
// choice; LS-DYNA's is not published); a third of the wave modulus if the sum is not positive.
template <class Card>
double reuss_bulk_modulus(const Card& c, double wave_modulus) {
  const double s_sum = 1 / c.EA + 1 / c.EB + 1 / c.EC - 2 * (c.PRBA / c.EB + c.PRCA / c.EC + c.PRCB / c.EC);
  return s_sum > 0 ? 1 / s_sum : wave_modulus / 3;
}

void set_isotropic(Material& m, double RO, double E, double PR) {
  m.density = RO;
  m.iso = material::isotropic_constants(E, PR);
  m.wave_modulus = m.iso.lambda + 2 * m.iso.mu;
  m.bulk_modulus = E / (3 * (1 - 2 * PR));
}

material::EosParams eos_params(const config::EosSpec& e, double rho0) {
  material::EosParams q;
  q.kind = e.card == "EOS_GRUNEISEN" ? material::EosParams::Kind::Gruneisen : material::EosParams::Kind::LinearPolynomial;
  q.C0 = e.C0, q.C1 = e.C1, q.C2 = e.C2, q.C3 = e.C3, q.C4 = e.C4, q.C5 = e.C5, q.C6 = e.C6;
  q.C = e.C, q.S1 = e.S1, q.S2 = e.S2, q.S3 = e.S3, q.GAMAO = e.GAMAO, q.A = e.A;
  q.E0 = e.E0;
  q.rho0 = rho0;
  return q;
}

// *MAT_015 / *MAT_098: density, wave and bulk moduli from G and the reference bulk modulus (the
// EOS's at mu = 0, or E / (3 (1 - 2 PR))). The step uses this reference stiffness: an EOS that
// stiffens under compression (Gruneisen: about (1 + 2 S1 mu) rho0 C^2) needs TSSFAC to cover it.
void set_johnson_cook(Material& m, const material::JohnsonCookParams& p) {
  m.kind = MaterialKind::JohnsonCook;
  m.johnson_cook = p;
  m.density = p.rho0;
  m.bulk_modulus = p.eos.kind != material::EosParams::Kind::None ? material::eos_reference_bulk_modulus(p.eos) : p.bulk;
  m.wave_modulus = m.bulk_modulus + 4 * p.shear / 3;
}

}  // namespace

material::JohnsonCookParams johnson_cook_params(const config::MatJohnsonCook& c) {
  material::JohnsonCookParams p;
  p.rho0 = c.RO;
  p.shear = c.G;
  p.bulk = c.eos ? 0.0 : c.E / (3 * (1 - 2 * c.PR));
  p.A = c.A, p.B = c.B, p.N = c.N, p.C = c.C, p.M = c.M, p.TM = c.TM, p.TR = c.TR, p.EPSO = c.EPSO, p.CP = c.CP;
  p.TQC = c.TQC, p.VP = c.VP, p.PC = c.PC, p.SPALL = c.SPALL;
  p.D1 = c.D1, p.D2 = c.D2, p.D3 = c.D3, p.D4 = c.D4, p.D5 = c.D5, p.EFMIN = c.EFMIN, p.EROD = c.EROD;
  if (c.eos) p.eos = eos_params(*c.eos, c.RO);
  return p;
}

material::JohnsonCookParams simplified_johnson_cook_params(const config::MatSimplifiedJohnsonCook& c) {
  material::JohnsonCookParams p;
  p.simplified = true;
  p.rho0 = c.RO;
  p.shear = c.E / (2 * (1 + c.PR));
  p.bulk = c.E / (3 * (1 - 2 * c.PR));
  p.A = c.A, p.B = c.B, p.N = c.N, p.C = c.C, p.EPSO = c.EPSO, p.VP = c.VP;
  p.PSFAIL = c.PSFAIL, p.SIGMAX = c.SIGMAX, p.SIGSAT = c.SIGSAT;
  return p;
}

material::MaterialAxes material_axes_of(const config::MaterialAxes& a) { return {a.AOPT, a.A, a.D, a.V, a.BETA}; }

material::Stiffness6 orthotropic_stiffness(const config::MatOrthotropicElastic& card,
                                           const config::SourceLocation& where) {
  return admissible_stiffness(orthotropic_constants(card), where);
}

material::CompositeDamageParams composite_damage_params(const config::MatCompositeDamage& m,
                                                        const config::SourceLocation& where) {
  material::CompositeDamageParams p;
  p.C = admissible_stiffness(orthotropic_constants(m), where);
  p.RO = m.RO;
  p.wave_modulus = material::max_wave_modulus(p.C);
  p.GAB = m.GAB, p.GBC = m.GBC, p.GCA = m.GCA;
  p.strength = {m.XT, m.XC, m.YT, m.YC, m.SC};
  p.CRIT = m.CRIT, p.BETA = m.BETA, p.ALPH = m.ALPH;
  p.FBRT = m.FBRT, p.YCFAC = m.YCFAC, p.SOFT = m.SOFT, p.SOFTG = m.SOFTG;
  p.SLIMT1 = m.SLIMT1, p.SLIMC1 = m.SLIMC1, p.SLIMT2 = m.SLIMT2, p.SLIMC2 = m.SLIMC2, p.SLIMS = m.SLIMS;
  p.NCYRED = std::max(1, m.NCYRED);
  p.DFAILT = m.DFAILT, p.DFAILC = m.DFAILC, p.DFAILM = m.DFAILM, p.DFAILS = m.DFAILS, p.EFS = m.EFS;
  p.TFAIL = m.TFAIL;
  p.EPSF = m.EPSF, p.EPSR = m.EPSR, p.TSMD = m.TSMD > 0 ? m.TSMD : 0.9;
  p.erosion_reference_length = m.erosion_reference_length;
  p.erosion_nonlocal = m.erosion_nonlocal;
  return p;
}

Material make_material(const config::MaterialSpec& spec) {
  Material m;
  m.name = spec.name;
  m.card = spec.card;
  if (const auto* iso = std::get_if<config::MatElastic>(&spec.params)) {
    m.kind = MaterialKind::IsotropicElastic;
    set_isotropic(m, iso->RO, iso->E, iso->PR);
  } else if (const auto* rig = std::get_if<config::MatRigid>(&spec.params)) {
    m.kind = MaterialKind::Rigid;
    set_isotropic(m, rig->RO, rig->E, rig->PR);
  } else if (const auto* pk = std::get_if<config::MatPlasticKinematic>(&spec.params)) {
    m.kind = MaterialKind::Plastic;
    m.plastic = material::plastic_kinematic(pk->E, pk->PR, pk->SIGY, pk->ETAN, pk->BETA, pk->SRC, pk->SRP, pk->FS);
    set_isotropic(m, pk->RO, pk->E, pk->PR);  // elastic moduli for the step (conservative)
  } else if (const auto* pl = std::get_if<config::MatPiecewiseLinear>(&spec.params)) {
    m.kind = MaterialKind::Plastic;
    m.plastic = material::piecewise_linear(pl->E, pl->PR, pl->SIGY, pl->ETAN, pl->C, pl->P, pl->FAIL, pl->LCSS_strain,
                                           pl->LCSS_stress);
    set_isotropic(m, pl->RO, pl->E, pl->PR);
  } else if (const auto* jc = std::get_if<config::MatJohnsonCook>(&spec.params)) {
    set_johnson_cook(m, johnson_cook_params(*jc));
  } else if (const auto* sjc = std::get_if<config::MatSimplifiedJohnsonCook>(&spec.params)) {
    set_johnson_cook(m, simplified_johnson_cook_params(*sjc));
  } else if (const auto* cd = std::get_if<config::MatCompositeDamage>(&spec.params)) {
    m.kind = MaterialKind::CompositeDamage;
    m.density = cd->RO;
    m.composite = composite_damage_params(*cd, spec.where);
    m.c_material = m.composite.C;
    m.modulus_c = cd->EC;
    m.wave_modulus = m.composite.wave_modulus;  // undamaged stiffness, as LS-DYNA (docs/theory.md section 2)
    m.bulk_modulus = reuss_bulk_modulus(*cd, m.wave_modulus);
    m.axes = material_axes_of(cd->axes);
    if (m.axes.AOPT != 3 && m.axes.BETA != 0.0)
      throw InputError(at(spec.where) << "MANGLE acts only with AOPT 3 (as in LS-DYNA); found AOPT " << m.axes.AOPT
                                      << "; give a ply angle with parts.<name>.beta instead");
  } else {
    const auto& ortho = std::get<config::MatOrthotropicElastic>(spec.params);
    m.kind = MaterialKind::OrthotropicElastic;
    m.density = ortho.RO;
    m.c_material = orthotropic_stiffness(ortho, spec.where);
    m.modulus_c = ortho.EC;
    m.wave_modulus = material::max_wave_modulus(m.c_material);
    m.bulk_modulus = reuss_bulk_modulus(ortho, m.wave_modulus);
    m.axes = material_axes_of(ortho.axes);
    if (m.axes.AOPT != 3 && m.axes.BETA != 0.0)
      throw InputError(at(spec.where) << "BETA on the material card acts only with AOPT 3 (as in LS-DYNA); found "
                                         "AOPT "
                                      << m.axes.AOPT << "; give a ply angle with parts.<name>.beta instead");
  }
  if (m.modulus_c == 0 && m.iso.mu > 0)  // isotropic: E = mu (3 lambda + 2 mu) / (lambda + mu)
    m.modulus_c = m.iso.mu * (3 * m.iso.lambda + 2 * m.iso.mu) / (m.iso.lambda + m.iso.mu);
  m.wave_speed = std::sqrt(m.wave_modulus / m.density);
  return m;
}

}  // namespace plyimpact::model
