#include "cohesive/mat138_parameters.hpp"

#include <cmath>

#include "core/error.hpp"

namespace plyimpact::cohesive {
namespace {

bool given(double v) { return !std::isnan(v); }

// Peak traction from the card: T itself, or 2 G / U when T is 0 or blank and U is given (the
// bilinear triangle's area G = T U / 2 solved for T). NaN when neither is usable.
double peak_traction(double t, double g, double u) {
  if (given(t) && t != 0) return t;
  if (given(u) && u > 0 && given(g) && g > 0) return 2 * g / u;
  return kMissing;
}

}  // namespace

TractionLawParams traction_law_of(const Mat138Params& p) {
  TractionLawParams law;
  law.option = TiebreakOption::MixedMode;
  law.CN = p.EN;
  law.CT2CN = p.ET / p.EN;
  law.ERATEN = p.GIC;
  law.ERATES = p.GIIC;
  law.PARAM = p.XMU;
  law.NFLS = peak_traction(p.T, p.GIC, p.UND);
  law.SFLS = peak_traction(p.S, p.GIIC, p.UTD);
  law.FS = 0;  // the card has no friction: a separated point resists only interpenetration
  return law;
}

std::vector<std::string> validate_mat138(const Mat138Params& p) {
  std::vector<std::string> out;
  // Fields the law translation cannot name itself: ET (it enters as ET/EN), XMU (blank is no
  // default here), the UND/UTD alternatives to T/S, RO.
  bool et_ok = true;
  if (!given(p.ET)) {
    out.push_back("ET is missing (Pa/m, > 0)");
    et_ok = false;
  } else if (!(p.ET > 0) || !std::isfinite(p.ET)) {
    out.push_back(msg() << "ET must be > 0 Pa/m (got " << p.ET << ")");
    et_ok = false;
  }
  if (!given(p.XMU)) out.push_back("XMU is missing (> 0: power-law exponent, < 0: Benzeggagh-Kenane with eta = |XMU|)");
  const auto pair_check = [&](const char* t_name, double t, const char* u_name, double u) {
    if (given(t) && t != 0 && given(u))
      out.push_back(msg() << u_name << " is read only when " << t_name << " is 0 or blank (" << t_name << " = 2 G / "
                          << u_name << "); give one of them (got " << t_name << " = " << t << ", " << u_name << " = "
                          << u << ")");
    if ((!given(t) || t == 0) && given(u) && !(u > 0))
      out.push_back(msg() << u_name << " must be > 0 m (got " << u << ")");
    if (given(t) && t == 0 && !given(u))
      out.push_back(msg() << t_name << " = 0 needs " << u_name << " (" << t_name << " = 2 G / " << u_name << ")");
  };
  pair_check("T", p.T, "UND", p.UND);
  pair_check("S", p.S, "UTD", p.UTD);
  if (!(p.RO >= 0) || !std::isfinite(p.RO)) out.push_back(msg() << "RO must be >= 0 kg/m^2 (got " << p.RO << ")");

  Mat138Params q = p;
  if (!et_ok) q.ET = q.EN;        // reported above; keep the law's checks free of a second message
  if (!given(q.XMU)) q.XMU = 1;   // reported above
  if (given(q.T) && q.T == 0 && !given(q.UND)) q.T = kMissing;
  if (given(q.S) && q.S == 0 && !given(q.UTD)) q.S = kMissing;
  TractionLawParams law = traction_law_of(q);
  if (!given(q.EN) || !(q.EN > 0)) law.CT2CN = 1;  // EN's own message says it
  for (auto& m : validate_traction_law(law, kMat138Names)) out.push_back(std::move(m));
  return out;
}

void require_valid_mat138(const Mat138Params& p, const std::string& where) {
  const auto problems = validate_mat138(p);
  if (problems.empty()) return;
  std::string text = where + ": ";
  for (std::size_t i = 0; i < problems.size(); ++i) text += (i ? "; " : "") + problems[i];
  throw InputError(text);
}

}  // namespace plyimpact::cohesive
