// Reader of the *MAT_054/055 card. See mat054_reader.hpp.
#include "config/mat054_reader.hpp"

#include "config/orthotropic_card.hpp"

#include <cctype>
#include <cmath>

#include "core/error.hpp"

namespace plyimpact::config::detail {
namespace {

namespace u = units;

// ALPH multiplies tau^3 in a strain: stress^-3 = m^3 kg^-3 s^6.
constexpr u::Dimension kPerStressCubed{3, -3, 6};

std::string card_name(const Reader& r) {
  const auto c = r.find("card");
  if (!c) return "MAT_054";
  std::string s = c->as_name();
  if (!s.empty() && s.front() == '*') s.erase(0, 1);
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

// A material-axis vector as LS-DYNA's three fields (A1, A2, A3; blank = 0) or as one list A: [..].
// `used`: the AOPT needs it, so it must not be zero; an unused all-zero vector (a copied card's
// blank fields) keeps the default.
Vec3 read_vector(const Reader& r, const char* list_key, const char* k1, const char* k2, const char* k3,
                 Vec3 fallback, bool used) {
  const bool split = r.has(k1) || r.has(k2) || r.has(k3);
  Vec3 v = fallback;
  if (const auto l = r.find(list_key)) {
    if (split)
      l->fail(msg() << "give the vector either as " << list_key << ": [x, y, z] or as " << k1 << ", " << k2 << ", "
                    << k3 << ", not both",
              "one of the two forms");
    v = l->as_vec3(u::dimensionless);
  } else if (split) {
    v = {r.quantity_or(k1, u::dimensionless, 0.0), r.quantity_or(k2, u::dimensionless, 0.0),
         r.quantity_or(k3, u::dimensionless, 0.0)};
  } else {
    return fallback;
  }
  if (v[0] == 0 && v[1] == 0 && v[2] == 0) {
    if (!used) return fallback;
    const auto at = r.find(list_key) ? r.find(list_key) : r.find(r.has(k1) ? k1 : r.has(k2) ? k2 : k3);
    at->fail(msg() << "the vector must not be zero (AOPT " << r.integer_or("AOPT", 0) << " uses it)",
             "a non-zero direction");
  }
  return v;
}

MaterialAxes read_axes054(const Reader& r) {
  MaterialAxes a;
  a.AOPT = static_cast<int>(r.integer_or("AOPT", 0));  // values other than 0, 2, 3: unsupported_field
  a.A = read_vector(r, "A", "A1", "A2", "A3", a.A, a.AOPT == 2);
  a.D = read_vector(r, "D", "D1", "D2", "D3", a.D, a.AOPT == 2);
  a.V = read_vector(r, "V", "V1", "V2", "V3", a.V, a.AOPT == 3);
  if (a.AOPT == 2) {
    const Vec3 c{a.A[1] * a.D[2] - a.A[2] * a.D[1], a.A[2] * a.D[0] - a.A[0] * a.D[2],
                 a.A[0] * a.D[1] - a.A[1] * a.D[0]};
    const double na = std::hypot(a.A[0], a.A[1], a.A[2]), nd = std::hypot(a.D[0], a.D[1], a.D[2]);
    if (std::hypot(c[0], c[1], c[2]) <= 1e-10 * na * nd) {
      const auto d = r.find("D") ? r.find("D") : r.find("D1") ? r.find("D1") : r.find("D2") ? r.find("D2") : r.find("D3");
      (d ? *d : r).fail("with AOPT 2 the vectors A and D must not be parallel", "D not parallel to A");
    }
  }
  a.BETA = r.angle_or("MANGLE", 0.0);
  return a;
}

// TFAIL: <= 0 off; a plain number > 0.1 is the ratio dt/dt0; otherwise an absolute time step.
double read_tfail(const Reader& r) {
  const auto t = r.find("TFAIL");
  if (!t) return 0.0;
  const char* allowed = "<= 0 (off), a time step limit up to 0.1 s, or a plain ratio dt/dt0 in (0.1, 1)";
  t->require_scalar(allowed);
  try {
    const double v = u::parse_number(t->node().Scalar());
    if (v > 0.1) {
      if (!(v < 1.0)) t->fail("TFAIL > 0.1 is the ratio dt/dt0, which is 1 at the start: every element would be deleted", allowed);
      return v;
    }
  } catch (const u::UnitError&) {
    // not a plain number: a time with its unit, read below
  }
  const double s = t->as_quantity(u::time);
  if (s <= 0) return 0.0;
  if (s > 0.1) t->fail("an absolute TFAIL above 0.1 s would be read as the ratio dt/dt0", allowed);
  return s;
}

// Card defaults that LS-DYNA substitutes for a blank (= 0) field.
double default_if_zero(const Reader& r, const char* key, double fallback, const Limits& lim) {
  const double v = r.quantity_or(key, u::dimensionless, fallback, lim);
  return v == 0 ? fallback : v;
}

}  // namespace

MatCompositeDamage read_mat054(const Reader& r) {
  r.allow_keys({"card",   "RO",     "EA",     "EB",     "EC",     "PRBA",   "PRCA",   "PRCB",   "GAB",    "GBC",
                "GCA",    "KF",     "AOPT",   "2WAY",   "TI",     "XP",     "YP",     "ZP",     "A1",     "A2",
                "A3",     "MANGLE", "V1",     "V2",     "V3",     "D1",     "D2",     "D3",     "DFAILM", "DFAILS",
                "TFAIL",  "ALPH",   "SOFT",   "FBRT",   "YCFAC",  "DFAILT", "DFAILC", "EFS",    "XC",     "XT",
                "YC",     "YT",     "SC",     "CRIT",   "BETA",   "PFL",    "EPSF",   "EPSR",   "TSMD",   "SOFT2",
                "SLIMT1", "SLIMC1", "SLIMT2", "SLIMC2", "SLIMS",  "NCYRED", "SOFTG",  "LCXC",   "LCXT",   "LCYC",
                "LCYT",   "LCSC",   "DT",     "A",      "D",      "V",      "erosion_reference_length",
                "erosion_nonlocal"});
  const Limits fraction01 = Limits::interval(0, false, 1, false, "the factor");
  MatCompositeDamage m;
  // Card 1-2: elastic constants (all needed by a solid).
  read_orthotropic_constants(r, m);
  m.KF = r.quantity_or("KF", u::stress, 0.0, Limits::non_negative("KF"));
  m.TWOWAY = static_cast<int>(r.integer_or("2WAY", 0, Limits::interval(0, false, 1, false, "2WAY")));
  m.TI = static_cast<int>(r.integer_or("TI", 0, Limits::interval(0, false, 1, false, "TI")));
  // Cards 3-4: axes.
  m.axes = read_axes054(r);
  m.XP = r.quantity_or("XP", u::length, 0.0);
  m.YP = r.quantity_or("YP", u::length, 0.0);
  m.ZP = r.quantity_or("ZP", u::length, 0.0);
  m.DFAILM = r.quantity_or("DFAILM", u::dimensionless, 0.0, Limits::non_negative("DFAILM (a strain magnitude)"));
  m.DFAILS = r.quantity_or("DFAILS", u::dimensionless, 0.0, Limits::non_negative("DFAILS (a strain magnitude)"));
  // Card 5.
  m.TFAIL = read_tfail(r);
  m.ALPH = r.quantity_or("ALPH", kPerStressCubed, 0.0, Limits::non_negative("ALPH"));
  m.SOFT = default_if_zero(r, "SOFT", 1.0, fraction01);
  m.FBRT = r.quantity_or("FBRT", u::dimensionless, 0.0, fraction01);
  m.YCFAC = default_if_zero(r, "YCFAC", 2.0, Limits::non_negative("YCFAC"));
  m.DFAILT = r.quantity_or("DFAILT", u::dimensionless, 0.0, Limits::non_negative("DFAILT"));
  m.DFAILC = r.quantity_or("DFAILC", u::dimensionless, 0.0,
                           Limits{std::nullopt, 0.0, false, false, "DFAILC (entered negative, -1 = 100 % compression)"});
  m.EFS = r.quantity_or("EFS", u::dimensionless, 0.0, Limits::non_negative("EFS"));
  // Card 6.
  m.XC = r.quantity("XC", u::stress, Limits::positive("XC (entered positive)").of(QuantityKind::strength));
  m.XT = r.quantity("XT", u::stress, Limits::positive("XT").of(QuantityKind::strength));
  m.YC = r.quantity("YC", u::stress, Limits::positive("YC (entered positive)").of(QuantityKind::strength));
  m.YT = r.quantity("YT", u::stress, Limits::positive("YT").of(QuantityKind::strength));
  m.SC = r.quantity("SC", u::stress, Limits::positive("SC").of(QuantityKind::strength));
  const std::string card = card_name(r);
  const int crit_default = card == "MAT_055" ? 55 : 54;
  m.CRIT = r.int_choice_or("CRIT", crit_default, {54, 55});
  if (card == "MAT_055" && m.CRIT != 55)
    r.at("CRIT", "").fail("card MAT_055 is the Tsai-Wu matrix variant", "CRIT: 55 (or card MAT_054 for CRIT 54)");
  m.BETA = r.quantity_or("BETA", u::dimensionless, 0.0, fraction01);
  // Card 7.
  m.PFL = r.quantity_or("PFL", u::dimensionless, 0.0, Limits::interval(0, false, 100, false, "PFL (percent)"));
  m.EPSF = r.quantity_or("EPSF", u::dimensionless, 0.0, Limits::non_negative("EPSF"));
  m.EPSR = r.quantity_or("EPSR", u::dimensionless, 0.0);
  if (m.EPSR != 0 && !(m.EPSF > 0))
    r.at("EPSR", "").fail("EPSR acts only with EPSF > 0 (transverse shear damage starts at EPSF)",
                          "EPSR with EPSF > 0, or no EPSR");
  if (m.EPSF > 0 && !(std::abs(m.EPSR) > m.EPSF))
    (r.has("EPSR") ? r.at("EPSR", "") : r.at("EPSF", ""))
        .fail("transverse shear damage needs |EPSR| > EPSF (damage grows from EPSF to |EPSR|)",
              "|EPSR| > EPSF; a negative EPSR also erodes the element at full damage");
  m.TSMD = r.quantity_or("TSMD", u::dimensionless, 0.0, fraction01);
  m.SOFT2 = default_if_zero(r, "SOFT2", 1.0, Limits::non_negative("SOFT2"));
  // Card 8.
  m.SLIMT1 = r.quantity_or("SLIMT1", u::dimensionless, 0.0, fraction01);
  m.SLIMC1 = r.quantity_or("SLIMC1", u::dimensionless, 0.0, fraction01);
  m.SLIMT2 = r.quantity_or("SLIMT2", u::dimensionless, 0.0, fraction01);
  m.SLIMC2 = r.quantity_or("SLIMC2", u::dimensionless, 0.0, fraction01);
  m.SLIMS = r.quantity_or("SLIMS", u::dimensionless, 0.0, fraction01);
  m.NCYRED = static_cast<int>(r.integer_or("NCYRED", 0, Limits::interval(0, false, 1e6, false, "NCYRED")));
  m.SOFTG = default_if_zero(r, "SOFTG", 1.0, fraction01);
  // Card 9.
  const Limits curve_id = Limits::non_negative("a curve id");
  m.LCXC = static_cast<int>(r.integer_or("LCXC", 0, curve_id));
  m.LCXT = static_cast<int>(r.integer_or("LCXT", 0, curve_id));
  m.LCYC = static_cast<int>(r.integer_or("LCYC", 0, curve_id));
  m.LCYT = static_cast<int>(r.integer_or("LCYT", 0, curve_id));
  m.LCSC = static_cast<int>(r.integer_or("LCSC", 0, curve_id));
  m.DT = r.quantity_or("DT", u::time, 0.0, Limits::non_negative("DT"));
  m.erosion_reference_length =
      r.quantity_or("erosion_reference_length", u::length, 0.0,
                    Limits::non_negative("erosion_reference_length (an element length; 0 = off)"));
  if (m.erosion_reference_length > 0 && !(m.DFAILT > 0 || m.EFS > 0))
    r.at("erosion_reference_length", "")
        .fail("erosion_reference_length scales the erosion strains, and none is set",
              "DFAILT > 0 (with DFAILC, DFAILM, DFAILS) or EFS > 0, or no erosion_reference_length");
  if (const auto n = r.find("erosion_nonlocal")) m.erosion_nonlocal = n->as_choice({"true", "false"}) == "true";
  if (m.erosion_nonlocal && !(m.erosion_reference_length > 0))
    r.at("erosion_nonlocal", "")
        .fail("erosion_nonlocal averages the erosion strains over erosion_reference_length, which is not set",
              "erosion_reference_length > 0 (an element length), or no erosion_nonlocal");

  if (const auto bad = unsupported_field(m)) {
    const std::string name = bad->substr(0, bad->find('='));
    const auto at = r.find(name);
    (at ? *at : r).fail("field not implemented: " + *bad, "the card without this field (or its default)");
  }
  return m;
}

}  // namespace plyimpact::config::detail
