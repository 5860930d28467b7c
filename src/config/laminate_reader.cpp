// `laminate:` and `impactor:` sections; see laminate_reader.hpp. Lengths in scene units or with
// units, angles in degrees, as everywhere in a scene.
#include "config/laminate_reader.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <cstdlib>

#include "config/layup_notation.hpp"
#include "core/error.hpp"

namespace plyimpact::config::detail {
namespace {

// Density field of the metal cards a deformable impactor may use (MAT_001, MAT_003, MAT_024, MAT_015,
// MAT_098).
double* density_of(MaterialSpec& m) {
  if (auto* e = std::get_if<MatElastic>(&m.params)) return &e->RO;
  if (auto* p = std::get_if<MatPlasticKinematic>(&m.params)) return &p->RO;
  if (auto* p = std::get_if<MatPiecewiseLinear>(&m.params)) return &p->RO;
  if (auto* p = std::get_if<MatJohnsonCook>(&m.params)) return &p->RO;
  if (auto* p = std::get_if<MatSimplifiedJohnsonCook>(&m.params)) return &p->RO;
  return nullptr;
}
const double* density_of(const MaterialSpec& m) { return density_of(const_cast<MaterialSpec&>(m)); }


namespace u = units;
constexpr double kDeg = std::numbers::pi / 180.0;

template <class Spec>
std::vector<std::string> names_of(const std::vector<Spec>& specs) {
  std::vector<std::string> out;
  for (const auto& s : specs) out.push_back(s.name);
  return out;
}

const MaterialSpec* find_material(const Scene& scene, const std::string& name) {
  for (const auto& m : scene.materials)
    if (m.name == name) return &m;
  return nullptr;
}

// Ply angles in degrees from `stacking`: a quoted notation string or a list of angles.
std::vector<double> read_stacking(const Reader& r) {
  if (r.node().IsSequence()) {
    r.require_list("a list of ply angles in degrees, bottom ply first", true);
    std::vector<double> out;
    for (const Reader& a : r.items()) out.push_back(a.as_angle() / kDeg);
    return out;
  }
  r.require_scalar("laminate notation in quotes, e.g. \"[0/45/-45/90]2s\", or a list of angles");
  try {
    return expand_layup(r.node().Scalar());
  } catch (const LayupNotationError& e) {
    // Point at the offending character: the scalar's mark is its first character (the quote).
    YAML::Mark m = r.mark();
    if (!m.is_null()) m.column += int(e.position()) + (r.node().Tag() == "!" ? 1 : 0);
    throw InputError(msg() << location(r.where().file, m) << ": " << r.path() << ": bad laminate notation: "
                           << e.what() << " (at character " << e.position() + 1 << ")"
                           << "; found " << r.found_text() << "; allowed " << e.allowed());
  }
}

std::string angle_label(double deg) {
  std::string s = msg() << std::abs(deg);
  std::replace(s.begin(), s.end(), '.', 'p');
  return (deg < 0 ? "m" : "") + s;
}

// Materials per ply: one name, a mapping angle -> name, or a list with one name per ply.
std::vector<std::string> read_ply_materials(const Reader& r, const Scene& scene, const std::vector<double>& angles) {
  const auto names = names_of(scene.materials);
  std::vector<std::string> out(angles.size());
  if (r.node().IsScalar()) {
    std::fill(out.begin(), out.end(), r.as_name());
    if (!find_material(scene, out[0])) r.fail("unknown material", "one of the materials: " + join(names));
  } else if (r.node().IsSequence()) {
    if (r.node().size() != angles.size())
      r.fail(msg() << "one material per ply is needed (" << angles.size() << " plies)",
             msg() << "a list of " << angles.size() << " material names");
    const auto items = r.items();
    for (std::size_t i = 0; i < items.size(); ++i) {
      out[i] = items[i].as_name();
      if (!find_material(scene, out[i])) items[i].fail("unknown material", "one of the materials: " + join(names));
    }
  } else {
    r.require_map("a material name, a mapping ply angle -> material, or a list with one material per ply");
    std::vector<std::pair<double, std::string>> by_angle;
    for (const auto& [key, m] : r.entries()) {
      double deg = 0;
      try {
        deg = std::stod(key);
      } catch (...) {
        m.fail("the key must be a ply angle in degrees", "keys that are ply angles, e.g. {0: m0, 90: m90}");
      }
      const std::string name = m.as_name();
      if (!find_material(scene, name)) m.fail("unknown material", "one of the materials: " + join(names));
      by_angle.emplace_back(deg, name);
    }
    for (std::size_t i = 0; i < angles.size(); ++i) {
      const auto it = std::find_if(by_angle.begin(), by_angle.end(),
                                   [&](const auto& p) { return std::abs(p.first - angles[i]) < 1e-9; });
      if (it == by_angle.end())
        r.fail(msg() << "no material for ply " << i + 1 << " at " << angles[i] << " degrees",
               "a material for every ply angle of the stacking sequence");
      out[i] = it->second;
    }
  }
  // Each ply's axes come from its own geometry-independent vectors (AOPT 2), never from node order.
  for (const auto& name : out) {
    const auto* mat = find_material(scene, name);
    if (const auto* o = std::get_if<MatOrthotropicElastic>(&mat->params)) {
      const auto& a = o->axes;
      const Vec3 c{a.A[1] * a.D[2] - a.A[2] * a.D[1], a.A[2] * a.D[0] - a.A[0] * a.D[2],
                   a.A[0] * a.D[1] - a.A[1] * a.D[0]};
      if (a.AOPT != 2 || std::abs(c[0]) + std::abs(c[1]) > 1e-12 * std::abs(c[2]))
        r.fail(msg() << "ply material '" << name << "' must use AOPT 2 with A and D in the plate plane (c along z)",
               "an orthotropic card with AOPT: 2, A and D in the x-y plane (ply angles turn about z)");
    }
  }
  return out;
}

std::vector<bool> read_interfaces(const Reader& r, const std::vector<double>& angles) {
  const std::size_t n = angles.empty() ? 0 : angles.size() - 1;
  std::vector<bool> out(n, false);
  const char* allowed = "all, angle-change, none, or a list of interface numbers (interface i lies between plies i and i+1)";
  if (r.node().IsScalar()) {
    const std::string mode = r.as_choice({"all", "angle-change", "none"});
    for (std::size_t i = 0; i < n; ++i)
      out[i] = mode == "all" || (mode == "angle-change" && std::abs(angles[i] - angles[i + 1]) > 1e-9);
    return out;
  }
  r.require_list(allowed, false);
  for (const Reader& item : r.items()) {
    const long i = item.as_integer(Limits::interval(1, false, double(n), false, "interface number"));
    if (out[std::size_t(i - 1)]) item.fail("interface listed twice", allowed);
    out[std::size_t(i - 1)] = true;
  }
  return out;
}

// Lower and upper bounds [lo, hi] of a pre-crack region along one plate side of length `side`.
void read_range(const Reader& r, double side, double out[2]) {
  const std::string allowed = msg() << "[lo, hi] with 0 <= lo < hi <= " << side << " m (inside the plate)";
  r.require_list(allowed, false);
  if (r.node().size() != 2) r.fail("expected [lo, hi]", allowed);
  const auto v = r.items();
  out[0] = v[0].as_quantity(u::length, Limits::interval(0, false, side, false, "pre-crack bound (inside the plate)"));
  out[1] = v[1].as_quantity(u::length, Limits::interval(0, false, side * (1 + 1e-12), false, "pre-crack bound (inside the plate)"));
  if (!(out[0] < out[1])) r.fail("a pre-crack region outside the plate or empty", allowed);
}

// The law keys of `r` (a map) on top of `law`; each given value must be > 0 where the card needs it.
void read_law_keys(const Reader& r, cohesive::TractionLawParams& law) {
  law.option = cohesive::TiebreakOption(r.int_choice_or("OPTION", int(law.option), {6, 7, 9}));
  const auto positive = [&](const char* key, u::Dimension d, double& field) {
    if (r.has(key)) field = r.quantity(key, d, Limits::positive(key));
  };
  positive("NFLS", u::stress, law.NFLS);
  positive("SFLS", u::stress, law.SFLS);
  positive("ERATEN", u::energy_per_area, law.ERATEN);
  positive("ERATES", u::energy_per_area, law.ERATES);
  positive("CN", u::stiffness_per_area, law.CN);
  positive("CT2CN", u::dimensionless, law.CT2CN);
  if (r.has("FS")) law.FS = r.quantity("FS", u::dimensionless, Limits::non_negative("FS"));
  if (r.has("PARAM")) {
    // PARAM is CCRIT (a length) for OPTION 6, a friction angle in degrees for 7, an exponent for 9.
    if (law.option == cohesive::TiebreakOption::StressCcrit)
      law.PARAM = r.quantity("PARAM", u::length, Limits::positive("PARAM (CCRIT)"));
    else if (law.option == cohesive::TiebreakOption::DiscreteCrack)
      law.PARAM = r.angle_or("PARAM", 0.0) / kDeg;
    else
      law.PARAM = r.quantity("PARAM", u::dimensionless);
  }
}

void read_precrack(const Reader& r, const LaminateSpec& lam, InterfaceLawSpec& spec) {
  r.require_map("{x: [lo, hi], y: [lo, hi]} (y optional: the whole width)");
  r.allow_keys({"x", "y"});
  read_range(r.at("x", "[lo, hi]"), lam.length, spec.precrack_x);
  spec.precrack_y[0] = 0;
  spec.precrack_y[1] = lam.width;
  if (const auto y = r.find("y")) read_range(*y, lam.width, spec.precrack_y);
  spec.has_precrack = true;
}

const std::initializer_list<std::string_view> kLawKeys = {"OPTION", "NFLS", "SFLS", "PARAM", "ERATEN",     "ERATES",
                                                           "CN",     "CT2CN", "FS", "precrack", "process_zone_elements"};
// *MAT_138 card fields of `model: cohesive` (RO as mass per unit area: the card's ROFLG = 1).
const std::initializer_list<std::string_view> kMat138Keys = {"T",   "S",   "XMU", "GIC",     "GIIC",     "EN",
                                                             "ET",  "UND", "UTD", "RO",      "INTFAIL",  "precrack",
                                                             "process_zone_elements"};

bool listed(const std::initializer_list<std::string_view>& keys, std::string_view key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// The *MAT_138 keys of `r` (a map) on top of `p`. T and S may be 0 (then UND, UTD give them).
void read_mat138_keys(const Reader& r, cohesive::Mat138Params& p) {
  constexpr u::Dimension mass_per_area{-2, 1, 0};
  const auto positive = [&](const char* key, u::Dimension d, double& field) {
    if (r.has(key)) field = r.quantity(key, d, Limits::positive(key));
  };
  const auto non_negative = [&](const char* key, u::Dimension d, double& field) {
    if (r.has(key)) field = r.quantity(key, d, Limits::non_negative(key));
  };
  positive("EN", u::stiffness_per_area, p.EN);
  positive("ET", u::stiffness_per_area, p.ET);
  positive("GIC", u::energy_per_area, p.GIC);
  positive("GIIC", u::energy_per_area, p.GIIC);
  non_negative("T", u::stress, p.T);
  non_negative("S", u::stress, p.S);
  positive("UND", u::length, p.UND);
  positive("UTD", u::length, p.UTD);
  non_negative("RO", mass_per_area, p.RO);
  if (r.has("XMU")) p.XMU = r.quantity("XMU", u::dimensionless);
  if (r.has("INTFAIL")) p.INTFAIL = r.quantity("INTFAIL", u::dimensionless, Limits::interval(-4, false, 4, false, "INTFAIL"));
}

// process_zone_elements: at least one segment (Turon et al. 2007 recommend three or more).
void read_process_zone_elements(const Reader& r, InterfaceLawSpec& spec) {
  if (r.has("process_zone_elements"))
    spec.process_zone_elements = r.quantity("process_zone_elements", u::dimensionless,
                                            Limits::at_least(1, "process_zone_elements (segments in the process zone)"));
}

// Keys of the other model in `r` are refused, naming the model they belong to.
void refuse_other_model_keys(const Reader& r, bool cohesive) {
  const auto& other = cohesive ? kLawKeys : kMat138Keys;
  const auto& own = cohesive ? kMat138Keys : kLawKeys;
  for (const auto& [key, item] : r.entries())
    if (listed(other, key) && !listed(own, key))
      item.fail(msg() << "a " << (cohesive ? "tiebreak" : "*MAT_138") << " key with model: "
                      << (cohesive ? "cohesive" : "tiebreak"),
                cohesive ? "the *MAT_138 keys T, S, XMU, GIC, GIIC, EN, ET, UND, UTD, RO, INTFAIL, precrack"
                         : "the tiebreak keys OPTION, NFLS, SFLS, PARAM, ERATEN, ERATES, CN, CT2CN, FS, precrack");
}

// `interfaces:` as a mapping: {select: <all | angle-change | none | list>, model: merged | tiebreak |
// cohesive, law keys (tiebreak card 4 or *MAT_138), precrack, per_interface: {k: {law keys,
// precrack}}}. Fills lam.delaminating and lam.interface_law.
void read_interface_laws(const Reader& r, const std::vector<double>& angles, LaminateSpec& lam) {
  r.require_map("{select: all | angle-change | none | [numbers], model: merged | tiebreak | cohesive, law keys ...}");
  r.allow_keys({"select", "model", "OPTION", "NFLS", "SFLS", "PARAM", "ERATEN", "ERATES", "CN", "CT2CN", "FS",
                "precrack", "per_interface", "T", "S", "XMU", "GIC", "GIIC", "EN", "ET", "UND", "UTD", "RO",
                "INTFAIL", "process_zone_elements"});
  lam.delaminating = read_interfaces(r.at("select", "all, angle-change, none, or a list of interface numbers"), angles);
  lam.interface_law.assign(lam.delaminating.size(), std::nullopt);
  const std::string model =
      r.has("model") ? r.at("model", "").as_choice({"merged", "tiebreak", "cohesive"}) : "merged";
  if (model == "merged") {
    for (const auto& [key, item] : r.entries())
      if (key != "select" && key != "model")
        item.fail("a law parameter with model: merged (the plies stay bonded)",
                  "model: tiebreak or model: cohesive to give the interfaces a law");
    return;
  }
  const bool cohesive = model == "cohesive";
  refuse_other_model_keys(r, cohesive);
  InterfaceLawSpec base;
  base.where = r.where();
  base.model = cohesive ? InterfaceLawSpec::Model::Cohesive : InterfaceLawSpec::Model::Tiebreak;
  const auto read_keys = [&](const Reader& from, InterfaceLawSpec& spec) {
    if (cohesive)
      read_mat138_keys(from, spec.mat138);
    else
      read_law_keys(from, spec.law);
    read_process_zone_elements(from, spec);
  };
  read_keys(r, base);
  if (const auto p = r.find("precrack")) read_precrack(*p, lam, base);
  std::map<std::size_t, Reader> overrides;
  if (const auto per = r.find("per_interface")) {
    per->require_map("a mapping of interface number -> {law keys, precrack}");
    for (const auto& [key, item] : per->entries()) {
      char* end = nullptr;
      const long k = std::strtol(key.c_str(), &end, 10);
      if (*end != '\0' || k < 1 || std::size_t(k) > lam.delaminating.size() || !lam.delaminating[std::size_t(k - 1)])
        item.fail(msg() << "interface " << key << " is not a delaminating interface of this laminate",
                  "the number of an interface chosen by select (interface i lies between plies i and i+1)");
      item.require_map(cohesive ? "a mapping of *MAT_138 keys (T, S, XMU, GIC, GIIC, EN, ET, UND, UTD, RO, INTFAIL) and precrack"
                                : "a mapping of law keys (OPTION, NFLS, SFLS, PARAM, ERATEN, ERATES, CN, CT2CN, FS) and precrack");
      item.allow_keys(cohesive ? kMat138Keys : kLawKeys);
      overrides.emplace(std::size_t(k - 1), item);
    }
  }
  for (std::size_t i = 0; i < lam.delaminating.size(); ++i) {
    if (!lam.delaminating[i]) continue;
    InterfaceLawSpec spec = base;
    const auto it = overrides.find(i);
    if (it != overrides.end()) {
      spec.where = it->second.where();
      read_keys(it->second, spec);
      if (const auto p = it->second.find("precrack")) read_precrack(*p, lam, spec);
    }
    const Reader& at_reader = it != overrides.end() ? it->second : r;
    const SourceLocation w = at_reader.where();
    const std::string where = msg() << w.file << ":" << w.line << ":" << w.column << ": " << w.key_path << " (interface "
                                    << i + 1 << (cohesive ? ", *MAT_138)" : ")");
    if (cohesive) {
      cohesive::require_valid_mat138(spec.mat138, where);
      spec.law = cohesive::traction_law_of(spec.mat138);
    } else {
      cohesive::require_valid_traction_law(spec.law, where);
    }
    if (spec.process_zone_elements > 0 && spec.law.option == cohesive::TiebreakOption::StressCcrit) {
      const bool own = it != overrides.end() && it->second.has("process_zone_elements");
      (own ? it->second : r)
          .at("process_zone_elements", "")
          .fail("process_zone_elements with OPTION 6, whose energy is set by NFLS and CCRIT (lowering NFLS would "
                "change it)",
                "OPTION 7 or 9, or model: cohesive, whose energies ERATEN/ERATES (GIC/GIIC) the lowered strengths keep");
    }
    lam.interface_law[i] = spec;
  }
}

std::array<bool, 3> read_fix(const Reader& r) {
  const char* allowed = "a non-empty list of distinct dofs from x, y, z (e.g. [z])";
  r.require_list(allowed, true);
  std::array<bool, 3> dofs{};
  for (const Reader& d : r.items()) {
    const std::string a = d.as_choice({"x", "y", "z"});
    const int axis = a == "x" ? 0 : a == "y" ? 1 : 2;
    if (dofs[axis]) d.fail("dof listed twice", allowed);
    dofs[axis] = true;
  }
  return dofs;
}

std::vector<SupportSpec> read_supports(const Reader& r, const LaminateSpec& lam) {
  const char* kinds = "{window: [x, y]} (simply supported opening on the bottom face) or {clamped: [x0, x1, y0, y1]}";
  r.require_map("a mapping of node set name -> support");
  std::vector<SupportSpec> out;
  for (const auto& [name, s] : r.entries()) {
    s.require_map(kinds);
    s.allow_keys({"window", "clamped", "fix"});
    SupportSpec spec;
    spec.name = name;
    spec.where = s.where();
    if (s.exactly_one({"window", "clamped"}) == "window") {
      const Reader w = s.at("window", "");
      w.require_list("[x, y]: the opening's size (e.g. [125, 75] for ASTM D7136)", false);
      if (w.node().size() != 2) w.fail("expected the two sizes of the opening", "[x, y]");
      const auto xy = w.items();
      spec.kind = SupportSpec::Kind::Window;
      spec.window_x = xy[0].as_quantity(u::length, Limits::positive("window size").of(QuantityKind::size));
      spec.window_y = xy[1].as_quantity(u::length, Limits::positive("window size").of(QuantityKind::size));
      const double hx = std::min(lam.impact_x, lam.length - lam.impact_x);
      const double hy = std::min(lam.impact_y, lam.width - lam.impact_y);
      if (spec.window_x / 2 >= hx) xy[0].fail("the opening does not fit inside the plate around the impact point",
                                             msg() << "a size < " << 2 * hx << " m");
      if (spec.window_y / 2 >= hy) xy[1].fail("the opening does not fit inside the plate around the impact point",
                                             msg() << "a size < " << 2 * hy << " m");
      spec.fix = {false, false, true};
    } else {
      const Reader c = s.at("clamped", "");
      c.require_list("a list of plate edges from x0, x1, y0, y1", true);
      spec.kind = SupportSpec::Kind::Clamped;
      for (const Reader& e : c.items()) {
        const std::string edge = e.as_choice({"x0", "x1", "y0", "y1"});
        const int k = edge == "x0" ? 0 : edge == "x1" ? 1 : edge == "y0" ? 2 : 3;
        if (spec.edges[k]) e.fail("edge listed twice", "distinct edges from x0, x1, y0, y1");
        if ((k == 1 && lam.symmetry[0]) || (k == 3 && lam.symmetry[1]))
          e.fail("this edge is not in the model: the symmetry plane replaces it", "the edges kept by the symmetry");
        spec.edges[k] = true;
      }
      spec.fix = {true, true, true};
    }
    if (const auto f = s.find("fix")) spec.fix = read_fix(*f);
    out.push_back(std::move(spec));
  }
  return out;
}

// Mirror symmetry about x = const maps a ply angle t to -t: the model is symmetric only if every
// ply maps to itself (0 or 90 degrees, mod 180). The same holds for y = const.
void check_symmetry(const Reader& r, const std::vector<double>& angles) {
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double t = std::fmod(std::abs(angles[i]), 180.0);
    if (std::abs(t) > 1e-9 && std::abs(t - 90.0) > 1e-9 && std::abs(t - 180.0) > 1e-9)
      r.fail(msg() << "the layup is not symmetric about this plane: ply " << i + 1 << " at " << angles[i]
                   << " degrees becomes " << -angles[i] << " degrees in the mirror image",
             "a symmetry plane only when every ply is at 0 or 90 degrees (use the full plate otherwise)");
  }
}

// `size: [x, y]` of a zone centred on the impact point, which must lie inside the plate.
void read_zone_size(const Reader& zone, const LaminateSpec& lam, const char* what, double& x, double& y) {
  const Reader size = zone.at("size", "[x, y]");
  size.require_list("[x, y]", false);
  if (size.node().size() != 2) size.fail("expected [x, y]", "[x, y]");
  const auto xy = size.items();
  x = xy[0].as_quantity(u::length, Limits::positive(msg() << what << " size").of(QuantityKind::size));
  y = xy[1].as_quantity(u::length, Limits::positive(msg() << what << " size").of(QuantityKind::size));
  if (lam.impact_x - x / 2 <= 0 || lam.impact_x + x / 2 >= lam.length)
    xy[0].fail(msg() << "the " << what << " reaches the plate edge", "a zone inside the plate");
  if (lam.impact_y - y / 2 <= 0 || lam.impact_y + y / 2 >= lam.width)
    xy[1].fail(msg() << "the " << what << " reaches the plate edge", "a zone inside the plate");
}

}  // namespace

void read_laminate(const Reader& r, Scene& scene) {
  r.require_map("a mapping with length, width, ply_thickness, stacking, material, section, element_size, ...");
  r.allow_keys({"length", "width", "ply_thickness", "stacking", "material", "section", "elements_per_ply",
                "element_size", "impact_point", "refined_zone", "impact_zone", "refinement_level", "interfaces", "group_plies",
                "symmetry", "supports"});
  LaminateSpec lam;
  lam.where = r.where();
  lam.length = r.quantity("length", u::length, Limits::positive("plate length").of(QuantityKind::size));
  lam.width = r.quantity("width", u::length, Limits::positive("plate width").of(QuantityKind::size));
  const Reader stacking = r.at("stacking", "laminate notation in quotes, e.g. \"[0/45/-45/90]2s\", or a list of angles");
  const std::vector<double> angles = read_stacking(stacking);
  const Reader t = r.at("ply_thickness", "one thickness, or a list with one thickness per ply");
  std::vector<double> thickness(angles.size());
  if (t.node().IsSequence()) {
    if (t.node().size() != angles.size())
      t.fail(msg() << "one thickness per ply is needed (" << angles.size() << " plies)",
             msg() << "a list of " << angles.size() << " thicknesses");
    const auto items = t.items();
    for (std::size_t i = 0; i < items.size(); ++i) thickness[i] = items[i].as_quantity(u::length, Limits::positive("ply thickness").of(QuantityKind::size));
  } else {
    std::fill(thickness.begin(), thickness.end(), t.as_quantity(u::length, Limits::positive("ply thickness").of(QuantityKind::size)));
  }
  const auto materials = read_ply_materials(r.at("material", "a material name, {angle: material}, or one per ply"),
                                            scene, angles);
  lam.section = r.reference("section", names_of(scene.sections), "section", "sections");
  lam.elements_per_ply = int(r.integer_or("elements_per_ply", 1, Limits::interval(1, false, 64, false, "elements per ply")));
  lam.element_size = r.quantity("element_size", u::length, Limits::positive("element size").of(QuantityKind::size));
  lam.impact_x = lam.length / 2;
  lam.impact_y = lam.width / 2;
  if (const auto p = r.find("impact_point")) {
    p->require_list("[x, y] inside the plate", false);
    if (p->node().size() != 2) p->fail("expected [x, y]", "[x, y] inside the plate");
    const auto xy = p->items();
    lam.impact_x = xy[0].as_quantity(u::length, Limits::interval(0, true, lam.length, true, "impact x"));
    lam.impact_y = xy[1].as_quantity(u::length, Limits::interval(0, true, lam.width, true, "impact y"));
  }
  if (const auto s = r.find("symmetry")) {
    s->require_list("a list of symmetry planes from x, y (x: the plane x = length/2)", false);
    for (const Reader& a : s->items()) {
      const int k = a.as_choice({"x", "y"}) == "x" ? 0 : 1;
      if (lam.symmetry[k]) a.fail("symmetry plane listed twice", "distinct planes from x, y");
      const double centre = k == 0 ? lam.length / 2 : lam.width / 2;
      const double impact = k == 0 ? lam.impact_x : lam.impact_y;
      if (std::abs(impact - centre) > 1e-12 * centre)
        a.fail("a symmetry plane needs the impact point on it", "impact_point on the plate centre line");
      check_symmetry(a, angles);
      lam.symmetry[k] = true;
    }
  }
  if (const auto z = r.find("refined_zone")) {
    z->require_map("{size: [x, y], element_size: h}");
    z->allow_keys({"size", "element_size"});
    read_zone_size(*z, lam, "refined zone", lam.zone_x, lam.zone_y);
    lam.zone_element_size = z->quantity("element_size", u::length,
                                        Limits::interval(0, true, lam.element_size, false, "zone element size").of(QuantityKind::size));
  }
  if (const auto z = r.find("impact_zone")) {
    z->require_map("{size: [x, y], section: name}");
    z->allow_keys({"size", "section"});
    read_zone_size(*z, lam, "impact zone", lam.impact_zone_x, lam.impact_zone_y);
    lam.impact_zone_section = z->reference("section", names_of(scene.sections), "section", "sections");
    lam.impact_zone_where = z->where();
  }
  lam.refinement_level = int(r.integer_or("refinement_level", 0, Limits::interval(0, false, 6, false, "refinement level")));
  lam.delaminating = angles.size() > 1 ? std::vector<bool>(angles.size() - 1, false) : std::vector<bool>{};
  if (const auto i = r.find("interfaces")) {
    if (i->node().IsMap()) read_interface_laws(*i, angles, lam);
    else lam.delaminating = read_interfaces(*i, angles);
  }
  if (lam.interface_law.empty()) lam.interface_law.assign(lam.delaminating.size(), std::nullopt);
  if (const auto g = r.find("group_plies")) lam.group_plies = g->as_choice({"true", "false"}) == "true";
  if (const auto s = r.find("supports")) lam.supports = read_supports(*s, lam);

  // One part per ply, or per block of adjacent equal-angle, equal-material plies not separated by a
  // delaminating interface (group_plies).
  int next_id = 1;
  for (const auto& p : scene.parts) next_id = std::max(next_id, p.id + 1);
  const auto user_parts = names_of(scene.parts);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    PlySpec ply{angles[i] * kDeg, thickness[i], materials[i], -1};
    const bool join_previous = lam.group_plies && i > 0 && !lam.delaminating[i - 1] &&
                               std::abs(angles[i] - angles[i - 1]) < 1e-9 && materials[i] == materials[i - 1];
    if (join_previous) {
      ply.part = lam.plies.back().part;
      std::size_t first = i - 1;
      while (first > 0 && lam.plies[first - 1].part == ply.part) --first;
      scene.parts[std::size_t(ply.part)].name = msg() << "plies_" << first + 1 << "-" << i + 1 << "_" << angle_label(angles[i]);
      ply.zone_part = lam.plies.back().zone_part;
      if (ply.zone_part >= 0) scene.parts[std::size_t(ply.zone_part)].name = scene.parts[std::size_t(ply.part)].name + "_zone";
    } else {
      PartSpec part;
      part.name = msg() << "ply_" << i + 1 << "_" << angle_label(angles[i]);
      if (std::find(user_parts.begin(), user_parts.end(), part.name) != user_parts.end())
        r.fail(msg() << "the generated part name '" << part.name << "' is already used in parts",
               "part names that do not start with ply_");
      part.id = next_id++;
      part.material = materials[i];
      part.section = lam.section;
      part.beta = ply.angle;
      part.where = stacking.where();
      ply.part = int(scene.parts.size());
      scene.parts.push_back(part);
      if (!lam.impact_zone_section.empty()) {
        part.name += "_zone";
        if (std::find(user_parts.begin(), user_parts.end(), part.name) != user_parts.end())
          r.fail(msg() << "the generated part name '" << part.name << "' is already used in parts",
                 "part names that do not start with ply_");
        part.id = next_id++;
        part.section = lam.impact_zone_section;
        ply.zone_part = int(scene.parts.size());
        scene.parts.push_back(std::move(part));
      }
    }
    lam.plies.push_back(ply);
  }

  // Generated node sets (filled by the mesher) and their fixed conditions.
  auto add_set = [&](const std::string& name, const std::array<bool, 3>& fix, const SourceLocation& where) {
    NodeSetSpec set;
    set.name = name;
    set.kind = NodeSetSpec::Kind::Generated;
    set.where = where;
    scene.node_sets.push_back(set);
    BoundaryConditionSpec bc;
    bc.node_set = name;
    bc.kind = BoundaryConditionSpec::Kind::Fixed;
    bc.dofs = fix;
    bc.where = where;
    scene.boundary_conditions.push_back(bc);
  };
  for (const auto& s : lam.supports) add_set(s.name, s.fix, s.where);
  if (lam.symmetry[0]) add_set("symmetry_x", {true, false, false}, lam.where);
  if (lam.symmetry[1]) add_set("symmetry_y", {false, true, false}, lam.where);
  scene.laminate = std::move(lam);
}

void read_impactor(const Reader& r, Scene& scene) {
  r.require_map("a mapping with shape, diameter, velocity and optional length, mass, material, rigid, gap, ...");
  r.allow_keys({"shape", "diameter", "length", "mass", "density", "material", "section", "rigid", "gap", "position",
                "velocity", "element_size"});
  ImpactorSpec imp;
  imp.where = r.where();
  const std::string shape =
      r.at("shape", "hemispherical_cylinder, sphere, flat_cylinder or cube")
          .as_choice({"hemispherical_cylinder", "sphere", "flat_cylinder", "cube"});
  using S = ImpactorSpec::Shape;
  imp.shape = shape == "sphere" ? S::Sphere : shape == "flat_cylinder" ? S::FlatCylinder : shape == "cube" ? S::Cube
                                                                                                           : S::HemisphericalCylinder;
  imp.diameter = r.quantity("diameter", u::length, Limits::positive("diameter").of(QuantityKind::size));
  const double radius = imp.diameter / 2;
  imp.length = imp.diameter;
  if (imp.shape == S::HemisphericalCylinder || imp.shape == S::FlatCylinder) {
    imp.length = r.quantity_or("length", u::length, imp.diameter,
                               Limits::interval(imp.shape == S::HemisphericalCylinder ? radius : 0.0, true, 1e300,
                                                false, "impactor length"));
  } else if (r.has("length")) {
    r.at("length", "").fail("length applies to cylinder shapes only", "no length for a sphere or a cube");
  }
  imp.rigid = !r.has("rigid") || r.at("rigid", "").as_choice({"true", "false"}) == "true";
  imp.gap = r.quantity_or("gap", u::length, 0.0, Limits::non_negative("gap"));
  // At most the radius: the mesher puts at least two elements on a quarter circumference, so a
  // larger size would be silently replaced by a mesh the user did not ask for.
  imp.element_size = r.quantity_or("element_size", u::length, imp.diameter / 8,
                                   Limits::interval(0, true, radius, false, "impactor element size (at most the radius)")
                                       .of(QuantityKind::size));
  imp.x = scene.laminate ? scene.laminate->impact_x : 0;
  imp.y = scene.laminate ? scene.laminate->impact_y : 0;
  if (const auto p = r.find("position")) {
    p->require_list("[x, y] of the impactor axis", false);
    if (p->node().size() != 2) p->fail("expected [x, y]", "[x, y] of the impactor axis");
    const auto xy = p->items();
    imp.x = xy[0].as_quantity(u::length);
    imp.y = xy[1].as_quantity(u::length);
  }
  const Reader v = r.at("velocity", "a downward speed (e.g. 3 m/s) or a vector [vx, vy, vz]");
  if (v.node().IsScalar()) imp.velocity = {0, 0, -v.as_quantity(u::velocity, Limits::positive("impact speed"))};
  else imp.velocity = v.as_vec3(u::velocity);

  // Nominal (exact-geometry) volume: the density for a stated mass, and the rigid body's mass.
  const double pi = std::numbers::pi;
  double volume = 0;
  switch (imp.shape) {
    case S::Sphere: volume = pi * imp.diameter * imp.diameter * imp.diameter / 6; break;
    case S::HemisphericalCylinder: volume = pi * radius * radius * (imp.length - radius) + 2 * pi * radius * radius * radius / 3; break;
    case S::FlatCylinder: volume = pi * radius * radius * imp.length; break;
    case S::Cube: volume = imp.diameter * imp.diameter * imp.diameter; break;
  }
  const MaterialSpec* mat = nullptr;
  if (const auto m = r.find("material")) {
    imp.material = m->as_name();
    mat = find_material(scene, imp.material);
    if (!mat) m->fail("unknown material", "one of the materials: " + join(names_of(scene.materials)));
    if (!density_of(*mat)) m->fail("the impactor material must be a metal card", "a MAT_001, MAT_003, MAT_024, MAT_015 or MAT_098 material");
  }
  const bool has_mass = r.has("mass"), has_density = r.has("density");
  if (has_mass && has_density) r.at("density", "").fail("give mass or density, not both", "mass or density");
  if (has_mass) {
    imp.mass = r.quantity("mass", u::mass, Limits::positive("impactor mass"));
    imp.density = imp.mass / volume;  // density adjusted to the stated mass
  } else {
    imp.density = has_density ? r.quantity("density", u::density, Limits::positive("density"))
                              : mat ? *density_of(*mat) : 0.0;
    if (imp.density <= 0) r.fail("the impactor needs a mass, a density or a material", "mass, density or material");
    imp.mass = imp.density * volume;
  }
  if (!imp.rigid) {
    if (!mat) r.at("material", "a MAT_001, MAT_003 or MAT_024 material for a deformable impactor");
    MaterialSpec copy = *mat;
    if (std::abs(*density_of(copy) - imp.density) > 1e-12 * imp.density) {
      copy.name = mat->name + "_impactor";  // same card, density adjusted to the stated mass
      *density_of(copy) = imp.density;
      scene.materials.push_back(copy);
    }
    PartSpec part;
    part.name = "impactor";
    for (const auto& p : scene.parts)
      if (p.name == part.name) r.fail("a part named 'impactor' already exists", "no user part named impactor");
    int next_id = 1;
    for (const auto& p : scene.parts) next_id = std::max(next_id, p.id + 1);
    part.id = next_id;
    part.material = copy.name;
    part.section = r.reference("section", names_of(scene.sections), "section", "sections");
    part.where = imp.where;
    imp.part = int(scene.parts.size());
    scene.parts.push_back(part);
    scene.initial_velocities.push_back({part.name, "", imp.velocity, imp.where});
  }
  scene.impactor = std::move(imp);
}

void read_tiebreak_law_keys(const Reader& r, cohesive::TractionLawParams& law) { read_law_keys(r, law); }

}  // namespace plyimpact::config::detail
