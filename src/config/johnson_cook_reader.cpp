// Readers of the Johnson-Cook cards. See johnson_cook_reader.hpp.
#include "config/johnson_cook_reader.hpp"

#include <cctype>

namespace plyimpact::config::detail {
namespace {

namespace u = units;

constexpr u::Dimension kSpecificHeat{2, 0, -2};  // J/(kg K): temperature carries no dimension here

const char* kPoissonText = "Poisson's ratio";

EosSpec read_eos(const Reader& r) {
  const std::string allowed = "EOS_LINEAR_POLYNOMIAL or EOS_GRUNEISEN";
  r.require_map("an equation of state: a mapping with card (" + allowed + ") and its constants");
  const Reader c = r.at("card", allowed);
  std::string s = c.as_name();
  if (!s.empty() && s.front() == '*') s.erase(0, 1);
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  if (s.rfind("EOS_", 0) != 0) s = "EOS_" + s;
  EosSpec e;
  const Limits unit_volume = Limits::interval(1, false, 1, false, "V0 (an initial relative volume other than 1 is not implemented)");
  if (s == "EOS_LINEAR_POLYNOMIAL") {
    r.allow_keys({"card", "C0", "C1", "C2", "C3", "C4", "C5", "C6", "E0", "V0"});
    e.C0 = r.quantity_or("C0", u::stress, 0.0);
    e.C1 = r.quantity("C1", u::stress, Limits::positive("C1 (the bulk modulus)"));
    e.C2 = r.quantity_or("C2", u::stress, 0.0);
    e.C3 = r.quantity_or("C3", u::stress, 0.0);
    e.C4 = r.quantity_or("C4", u::dimensionless, 0.0);
    e.C5 = r.quantity_or("C5", u::dimensionless, 0.0);
    e.C6 = r.quantity_or("C6", u::dimensionless, 0.0);
  } else if (s == "EOS_GRUNEISEN") {
    r.allow_keys({"card", "C", "S1", "S2", "S3", "GAMAO", "A", "E0", "V0"});
    e.C = r.quantity("C", u::velocity, Limits::positive("C (bulk sound speed)"));
    e.S1 = r.quantity_or("S1", u::dimensionless, 0.0);
    e.S2 = r.quantity_or("S2", u::dimensionless, 0.0);
    e.S3 = r.quantity_or("S3", u::dimensionless, 0.0);
    e.GAMAO = r.quantity_or("GAMAO", u::dimensionless, 0.0, Limits::non_negative("GAMAO"));
    e.A = r.quantity_or("A", u::dimensionless, 0.0);
  } else {
    c.fail("unknown equation of state", allowed);
  }
  e.card = s;
  e.E0 = r.quantity_or("E0", u::stress, 0.0);
  r.quantity_or("V0", u::dimensionless, 1.0, unit_volume);
  return e;
}

// A, B, N, C of both cards.
template <class Card>
void read_flow_stress(const Reader& r, Card& m) {
  m.A = r.quantity("A", u::stress, Limits::positive("A (initial yield stress)"));
  m.B = r.quantity_or("B", u::stress, 0.0, Limits::non_negative("B"));
  m.N = r.quantity_or("N", u::dimensionless, 1.0, Limits::positive("N"));
  m.C = r.quantity_or("C", u::dimensionless, 0.0, Limits::non_negative("C"));
  m.VP = r.int_choice_or("VP", 0, {0, 1});
}

// EPSO: needed once a rate term uses it (C, or D4 on MAT_015); 1/s otherwise (unused then).
double read_epso(const Reader& r, bool needed) {
  if (!needed) return r.quantity_or("EPSO", u::frequency, 1.0, Limits::positive("EPSO"));
  return r.quantity("EPSO", u::frequency, Limits::positive("EPSO (reference strain rate, needed by C or D4)"));
}

}  // namespace

MatJohnsonCook read_mat015(const Reader& r) {
  r.allow_keys({"card", "RO", "G", "E", "PR", "VP", "RATEOP", "A", "B", "N", "C", "M", "TM", "TR", "EPSO", "CP", "PC",
                "SPALL", "IT", "D1", "D2", "D3", "D4", "D5", "EROD", "EFMIN", "TQC", "eos"});
  MatJohnsonCook m;
  m.RO = r.quantity("RO", u::density, Limits::positive("density"));
  m.G = r.quantity("G", u::stress, Limits::positive("shear modulus"));
  r.int_choice_or("RATEOP", 0, {0});  // 1-3 (other rate laws) are not implemented
  read_flow_stress(r, m);
  m.M = r.quantity_or("M", u::dimensionless, 1.0, Limits::positive("M"));
  m.CP = r.quantity_or("CP", kSpecificHeat, 0.0, Limits::non_negative("CP (specific heat)"));
  if (m.CP > 0) {
    m.TR = r.quantity("TR", u::dimensionless, Limits::positive("TR (room temperature, K)"));
    m.TM = r.quantity("TM", u::dimensionless, Limits::interval(m.TR, true, 1e5, false, "TM (melting temperature, K, above TR)"));
  } else {
    m.TR = r.quantity_or("TR", u::dimensionless, m.TR, Limits::positive("TR (room temperature, K)"));
    m.TM = r.quantity_or("TM", u::dimensionless, 0.0, Limits::non_negative("TM (melting temperature, K)"));
  }
  m.TQC = r.quantity_or("TQC", u::dimensionless, 1.0, Limits::interval(0, false, 1, false, "TQC (Taylor-Quinney coefficient)"));
  m.PC = r.quantity_or("PC", u::stress, 0.0, Limits::interval(-1e300, false, 0, false, "PC (pressure cutoff, <= 0)"));
  m.SPALL = r.int_choice_or("SPALL", 0, {0, 1, 2, 3});
  if (m.SPALL == 0) m.SPALL = 2;  // the card's default
  m.IT = r.int_choice_or("IT", 0, {0, 1});
  m.D1 = r.quantity_or("D1", u::dimensionless, 0.0);
  m.D2 = r.quantity_or("D2", u::dimensionless, 0.0);
  m.D3 = r.quantity_or("D3", u::dimensionless, 0.0);
  m.D4 = r.quantity_or("D4", u::dimensionless, 0.0);
  m.D5 = r.quantity_or("D5", u::dimensionless, 0.0);
  m.EFMIN = r.quantity_or("EFMIN", u::dimensionless, m.EFMIN, Limits::non_negative("EFMIN"));
  m.EROD = r.int_choice_or("EROD", 0, {0, 1});
  m.EPSO = read_epso(r, m.C > 0 || m.D4 != 0);
  if (const auto e = r.find("eos")) {
    m.eos = read_eos(*e);
    for (const char* k : {"E", "PR"})
      if (const auto f = r.find(k))
        f->fail("with an eos the pressure comes from the equation of state (LS-DYNA's E and PR serve shells)",
                "no E or PR next to eos");
  } else {
    m.E = r.quantity("E", u::stress, Limits::positive("Young's modulus (elastic bulk response without an eos)"));
    m.PR = r.quantity("PR", u::dimensionless, Limits::interval(-1, true, 0.5, true, kPoissonText));
  }
  return m;
}

MatSimplifiedJohnsonCook read_mat098(const Reader& r) {
  r.allow_keys({"card", "RO", "E", "PR", "VP", "A", "B", "N", "C", "PSFAIL", "SIGMAX", "SIGSAT", "EPSO"});
  MatSimplifiedJohnsonCook m;
  m.RO = r.quantity("RO", u::density, Limits::positive("density"));
  m.E = r.quantity("E", u::stress, Limits::positive("Young's modulus"));
  m.PR = r.quantity("PR", u::dimensionless, Limits::interval(-1, true, 0.5, true, kPoissonText));
  read_flow_stress(r, m);
  m.PSFAIL = r.quantity_or("PSFAIL", u::dimensionless, 0.0, Limits::non_negative("PSFAIL (0: no failure)"));
  m.SIGMAX = r.quantity_or("SIGMAX", u::stress, m.SIGMAX, Limits::positive("SIGMAX"));
  m.SIGSAT = r.quantity_or("SIGSAT", u::stress, m.SIGSAT, Limits::positive("SIGSAT"));
  m.EPSO = read_epso(r, m.C > 0);
  return m;
}

}  // namespace plyimpact::config::detail
