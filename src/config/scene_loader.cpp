// Scene loader: one small function per YAML section on top of detail::Reader. See scene_loader.hpp.
#include "config/scene_loader.hpp"

#include "config/johnson_cook_reader.hpp"
#include "config/mat054_reader.hpp"
#include "config/orthotropic_card.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "config/coupon_reader.hpp"
#include "config/laminate_reader.hpp"
#include "config/yaml_reader.hpp"
#include "core/error.hpp"

namespace plyimpact::config {
namespace {

using detail::Limits;
using detail::Reader;
namespace u = units;

template <class Spec>
std::vector<std::string> names_of(const std::vector<Spec>& specs) {
  std::vector<std::string> out;
  for (const auto& s : specs) out.push_back(s.name);
  return out;
}

std::string fmt(double v) { return msg() << v; }

// ---------------------------------------------------------------- control / output

// *CONTROL_TIMESTEP DT2MS with LS-DYNA's sign: negative, |DT2MS| the element step mass scaling
// keeps (docs/theory.md, "Mass scaling"). Positive DT2MS (LS-DYNA also removes mass from elements
// above the target, for quasi-static runs) is refused, as is a target longer than the run.
void read_mass_scaling(const Reader& r, ControlSpec& c) {
  c.dt2ms = r.quantity_or("dt2ms", u::time, 0.0,
                          Limits::interval(-c.termination_time, false, 0, false,
                                           "dt2ms (negative: |DT2MS| is the target element step, at most "
                                           "termination_time; positive DT2MS, uniform scaling, is not supported)"));
  c.endmas = r.quantity_or("endmas", u::dimensionless, 0.0,
                           Limits::interval(0, false, 1e4, false, "endmas (percent of the deformable mass)"));
  if (c.endmas > 0 && c.dt2ms == 0)
    r.at("endmas", "").fail("endmas limits the mass added by mass scaling, which is off", "dt2ms < 0 together with endmas");
}

ControlSpec read_control(const Reader& r) {
  r.require_map("a mapping with termination_time and optional tssfac, dt_min_ratio, ...");
  r.allow_keys({"termination_time", "tssfac", "dt_min_ratio", "energy_ratio_limit", "erode_tsmin",
                "hourglass_warn_ratio", "max_cycles", "max_elements", "cycle_limit", "threads", "dt2ms", "endmas",
                "termination_contact"});
  ControlSpec c;
  c.termination_time = r.quantity("termination_time", u::time, Limits::positive("termination time"));
  c.tssfac = r.quantity_or("tssfac", u::dimensionless, c.tssfac, Limits::interval(0, true, 1, false, "tssfac"));
  c.dt_min_ratio =
      r.quantity_or("dt_min_ratio", u::dimensionless, c.dt_min_ratio, Limits::interval(0, true, 1, true, "dt_min_ratio"));
  c.energy_ratio_limit = r.quantity_or("energy_ratio_limit", u::dimensionless, c.energy_ratio_limit,
                                       Limits::at_least(0, "energy_ratio_limit"));
  c.erode_tsmin = r.quantity_or("erode_tsmin", u::time, 0.0, Limits::non_negative("erode_tsmin"));
  c.hourglass_warn_ratio = r.quantity_or("hourglass_warn_ratio", u::dimensionless, c.hourglass_warn_ratio,
                                         Limits::positive("hourglass_warn_ratio"));
  c.max_cycles = r.integer_or("max_cycles", c.max_cycles, Limits::non_negative("max_cycles"));
  c.max_elements = r.integer_or("max_elements", c.max_elements, Limits::at_least(1, "max_elements"));
  c.cycle_limit = r.integer_or("cycle_limit", c.cycle_limit, Limits::at_least(1, "cycle_limit"));
  c.threads = static_cast<int>(r.integer_or("threads", c.threads, Limits::interval(0, false, 4096, false, "threads")));
  read_mass_scaling(r, c);
  return c;
}

// control.termination_contact, read once the contacts are known (CID names one of them).
TerminationContactSpec read_termination_contact(const Reader& r, const Scene& scene) {
  r.require_map("a mapping {contact: NAME, ACTIM: time, DOF: 0-3, THRES: force, DUR: time} (*TERMINATION_CONTACT)");
  r.allow_keys({"contact", "ACTIM", "DOF", "THRES", "DUR"});
  TerminationContactSpec t;
  t.where = r.where();
  t.ACTIM = r.quantity_or("ACTIM", u::time, 0.0,
                          Limits::interval(0, false, scene.control.termination_time, true,
                                           "ACTIM (activation time, before termination_time)"));
  t.DOF = r.int_choice_or("DOF", 0, {0, 1, 2, 3});
  t.THRES = r.quantity_or("THRES", u::force, 0.0, Limits::non_negative("THRES (force counted as none)"));
  t.DUR = r.quantity_or("DUR", u::time, 0.0, Limits::non_negative("DUR (duration of no force before the stop)"));
  t.contact = r.reference("contact", names_of(scene.contacts), "contact", "contacts");
  return t;
}

OutputSpec read_output(const Reader& r) {
  r.require_map("a mapping with optional interval, history_interval and restart_interval (times) and compression");
  r.allow_keys({"interval", "history_interval", "restart_interval", "compression"});
  OutputSpec o;
  o.interval = r.quantity_or("interval", u::time, 0.0, Limits::non_negative("output interval"));
  o.history_interval = r.quantity_or("history_interval", u::time, 0.0, Limits::non_negative("history interval"));
  o.restart_interval = r.quantity_or("restart_interval", u::time, 0.0, Limits::non_negative("restart interval"));
  if (const auto c = r.find("compression")) {
    const std::string name = c->as_choice({"zlib", "lz4", "none"});
    o.compression = name == "zlib"  ? OutputSpec::Compression::ZLib
                    : name == "lz4" ? OutputSpec::Compression::LZ4
                                    : OutputSpec::Compression::None;
  }
  return o;
}

// ---------------------------------------------------------------- materials

std::string read_card(const Reader& r) {
  const std::string allowed =
      "MAT_001 (ELASTIC), MAT_002 (ORTHOTROPIC_ELASTIC), MAT_003 (PLASTIC_KINEMATIC), MAT_020 (RIGID), MAT_024 "
      "(PIECEWISE_LINEAR_PLASTICITY), MAT_054 / MAT_055 (ENHANCED_COMPOSITE_DAMAGE), MAT_015 (JOHNSON_COOK), MAT_098 "
      "(SIMPLIFIED_JOHNSON_COOK)";
  const Reader c = r.at("card", allowed);
  c.require_scalar(allowed);
  std::string s = c.node().Scalar();
  if (!s.empty() && s.front() == '*') s.erase(0, 1);
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  if (s == "MAT_001" || s == "MAT_ELASTIC" || s == "ELASTIC") return "MAT_001";
  if (s == "MAT_002" || s == "MAT_ORTHOTROPIC_ELASTIC" || s == "ORTHOTROPIC_ELASTIC") return "MAT_002";
  if (s == "MAT_020" || s == "MAT_RIGID" || s == "RIGID") return "MAT_020";
  if (s == "MAT_003" || s == "MAT_PLASTIC_KINEMATIC" || s == "PLASTIC_KINEMATIC") return "MAT_003";
  if (s == "MAT_054" || s == "MAT_ENHANCED_COMPOSITE_DAMAGE" || s == "ENHANCED_COMPOSITE_DAMAGE") return "MAT_054";
  if (s == "MAT_055") return "MAT_055";
  if (s == "MAT_024" || s == "MAT_PIECEWISE_LINEAR_PLASTICITY" || s == "PIECEWISE_LINEAR_PLASTICITY") return "MAT_024";
  if (s == "MAT_015" || s == "MAT_JOHNSON_COOK" || s == "JOHNSON_COOK") return "MAT_015";
  if (s == "MAT_098" || s == "MAT_SIMPLIFIED_JOHNSON_COOK" || s == "SIMPLIFIED_JOHNSON_COOK") return "MAT_098";
  c.fail("unknown material card", allowed);
}

MatElastic read_elastic(const Reader& r) {
  r.allow_keys({"card", "RO", "E", "PR"});
  MatElastic m;
  m.RO = r.quantity("RO", u::density, Limits::positive("density"));
  m.E = r.quantity("E", u::stress, Limits::positive("Young's modulus").of(QuantityKind::modulus));
  m.PR = r.quantity("PR", u::dimensionless, Limits::interval(-1, true, 0.5, true, "Poisson's ratio"));
  return m;
}

MatRigid read_rigid(const Reader& r) {
  r.allow_keys({"card", "RO", "E", "PR", "CMO", "CON1", "CON2"});
  MatRigid m;
  m.RO = r.quantity("RO", u::density, Limits::positive("density"));
  m.E = r.quantity("E", u::stress, Limits::positive("Young's modulus (used for the contact stiffness)").of(QuantityKind::modulus));
  m.PR = r.quantity("PR", u::dimensionless, Limits::interval(-1, true, 0.5, true, "Poisson's ratio"));
  m.CMO = r.int_choice_or("CMO", 0, {0, 1});
  m.CON1 = r.int_choice_or("CON1", 0, {0, 1, 2, 3, 4, 5, 6, 7});
  m.CON2 = r.int_choice_or("CON2", 0, {0, 1, 2, 3, 4, 5, 6, 7});
  if (m.CMO == 0 && (m.CON1 != 0 || m.CON2 != 0))
    r.at(m.CON1 != 0 ? "CON1" : "CON2", "")
        .fail("CON1/CON2 act only with CMO: 1 (global constraints)", "CMO: 1 together with CON1/CON2");
  return m;
}

MatPlasticKinematic read_plastic_kinematic(const Reader& r) {
  r.allow_keys({"card", "RO", "E", "PR", "SIGY", "ETAN", "BETA", "SRC", "SRP", "FS"});
  MatPlasticKinematic m;
  m.RO = r.quantity("RO", u::density, Limits::positive("density"));
  m.E = r.quantity("E", u::stress, Limits::positive("Young's modulus").of(QuantityKind::modulus));
  m.PR = r.quantity("PR", u::dimensionless, Limits::interval(-1, true, 0.5, true, "Poisson's ratio"));
  m.SIGY = r.quantity("SIGY", u::stress, Limits::positive("yield stress").of(QuantityKind::strength));
  m.ETAN = r.quantity_or("ETAN", u::stress, 0.0, Limits::interval(0, false, m.E, true, "tangent modulus (below E)").of(QuantityKind::modulus));
  m.BETA = r.quantity_or("BETA", u::dimensionless, 0.0, Limits::interval(0, false, 1, false, "BETA"));
  m.SRC = r.quantity_or("SRC", u::frequency, 0.0, Limits::non_negative("SRC"));
  m.SRP = r.quantity_or("SRP", u::dimensionless, 0.0, Limits::non_negative("SRP"));
  if (m.SRC > 0 && !(m.SRP > 0)) r.at("SRC", "").fail("SRC needs a positive SRP (Cowper-Symonds exponent)", "SRP > 0");
  m.FS = r.quantity_or("FS", u::dimensionless, 0.0, Limits::non_negative("failure strain"));
  return m;
}

MatPiecewiseLinear read_piecewise_linear(const Reader& r) {
  r.allow_keys({"card", "RO", "E", "PR", "SIGY", "ETAN", "FAIL", "C", "P", "LCSS"});
  MatPiecewiseLinear m;
  m.RO = r.quantity("RO", u::density, Limits::positive("density"));
  m.E = r.quantity("E", u::stress, Limits::positive("Young's modulus").of(QuantityKind::modulus));
  m.PR = r.quantity("PR", u::dimensionless, Limits::interval(-1, true, 0.5, true, "Poisson's ratio"));
  m.ETAN = r.quantity_or("ETAN", u::stress, 0.0, Limits::interval(0, false, m.E, true, "tangent modulus (below E)").of(QuantityKind::modulus));
  m.FAIL = r.quantity_or("FAIL", u::dimensionless, 0.0, Limits::non_negative("failure strain"));
  m.C = r.quantity_or("C", u::frequency, 0.0, Limits::non_negative("C"));
  m.P = r.quantity_or("P", u::dimensionless, 0.0, Limits::non_negative("P"));
  if (m.C > 0 && !(m.P > 0)) r.at("C", "").fail("C needs a positive P (Cowper-Symonds exponent)", "P > 0");
  const char* curve_text = "a list of [effective plastic strain, yield stress] pairs starting at strain 0";
  if (const auto c = r.find("LCSS")) {
    c->require_list(curve_text, true);
    for (const Reader& pt : c->items()) {
      pt.require_list(curve_text, true);
      const auto xy = pt.items();
      if (xy.size() != 2) pt.fail("expected a [strain, stress] pair", curve_text);
      const double e = xy[0].as_quantity(u::dimensionless, Limits::non_negative("plastic strain"));
      const double sy = xy[1].as_quantity(u::stress, Limits::positive("yield stress").of(QuantityKind::strength));
      if (m.LCSS_strain.empty() ? e != 0.0 : e <= m.LCSS_strain.back())
        xy[0].fail("plastic strains must start at 0 and increase", curve_text);
      if (!m.LCSS_stress.empty() && sy < m.LCSS_stress.back())
        xy[1].fail("yield stresses must not decrease (no softening in MAT_024 here)", "non-decreasing stresses");
      m.LCSS_strain.push_back(e);
      m.LCSS_stress.push_back(sy);
    }
    m.SIGY = m.LCSS_stress.front();
  } else {
    m.SIGY = r.quantity("SIGY", u::stress, Limits::positive("yield stress (or give the curve LCSS)").of(QuantityKind::strength));
  }
  return m;
}

MaterialAxes read_axes(const Reader& r) {
  MaterialAxes a;
  a.AOPT = r.int_choice_or("AOPT", 0, {0, 2, 3});
  auto nonzero_vec = [&](std::string_view key, Vec3 fallback) {
    const auto v = r.find(key);
    if (!v) return fallback;
    const Vec3 x = v->as_vec3(u::dimensionless);
    if (x[0] == 0 && x[1] == 0 && x[2] == 0) v->fail("the vector must not be zero", "a non-zero direction [x, y, z]");
    return x;
  };
  a.A = nonzero_vec("A", a.A);
  a.D = nonzero_vec("D", a.D);
  a.V = nonzero_vec("V", a.V);
  if (a.AOPT == 2) {
    const Vec3 c{a.A[1] * a.D[2] - a.A[2] * a.D[1], a.A[2] * a.D[0] - a.A[0] * a.D[2],
                 a.A[0] * a.D[1] - a.A[1] * a.D[0]};
    const double na = std::hypot(a.A[0], a.A[1], a.A[2]), nd = std::hypot(a.D[0], a.D[1], a.D[2]);
    if (std::hypot(c[0], c[1], c[2]) <= 1e-10 * na * nd) {
      const auto d = r.find("D");
      (d ? *d : r).fail("with AOPT 2 the vectors A and D must not be parallel", "D not parallel to A");
    }
  }
  a.BETA = r.angle_or("BETA", 0.0);
  return a;
}

MatOrthotropicElastic read_orthotropic(const Reader& r) {
  r.allow_keys({"card", "RO", "EA", "EB", "EC", "PRBA", "PRCA", "PRCB", "GAB", "GBC", "GCA", "AOPT", "A", "D", "V",
                "BETA"});
  MatOrthotropicElastic m;
  read_orthotropic_constants(r, m);
  m.axes = read_axes(r);
  return m;
}

std::vector<MaterialSpec> read_materials(const Reader& r) {
  r.require_map("a mapping of material name -> card (e.g. steel: {card: MAT_001, RO: ..., E: ..., PR: ...})");
  if (r.node().size() == 0) r.fail("at least one material is needed", "a mapping of material name -> card");
  std::vector<MaterialSpec> out;
  for (const auto& [name, m] : r.entries()) {
    m.require_map("a material card: a mapping with card, RO and the card's constants");
    MaterialSpec spec{name, read_card(m), {}, m.where()};
    if (spec.card == "MAT_001")
      spec.params = read_elastic(m);
    else if (spec.card == "MAT_020")
      spec.params = read_rigid(m);
    else if (spec.card == "MAT_003")
      spec.params = read_plastic_kinematic(m);
    else if (spec.card == "MAT_024")
      spec.params = read_piecewise_linear(m);
    else if (spec.card == "MAT_054" || spec.card == "MAT_055")
      spec.params = detail::read_mat054(m);
    else if (spec.card == "MAT_015")
      spec.params = detail::read_mat015(m);
    else if (spec.card == "MAT_098")
      spec.params = detail::read_mat098(m);
    else
      spec.params = read_orthotropic(m);
    out.push_back(std::move(spec));
  }
  return out;
}

// ---------------------------------------------------------------- sections and parts

std::vector<SectionSpec> read_sections(const Reader& r) {
  r.require_map("a mapping of section name -> {ELFORM, IHQ, QM, Q1, Q2}");
  if (r.node().size() == 0) r.fail("at least one section is needed", "a mapping of section name -> section");
  std::vector<SectionSpec> out;
  for (const auto& [name, s] : r.entries()) {
    s.require_map("a mapping with optional ELFORM, IHQ, QM, Q1, Q2 (use {} for all defaults)");
    s.allow_keys({"ELFORM", "IHQ", "QM", "Q1", "Q2"});
    SectionSpec spec;
    spec.name = name;
    spec.ELFORM = s.int_choice_or("ELFORM", spec.ELFORM, {1, 2, -2});
    spec.IHQ = s.int_choice_or("IHQ", spec.IHQ, {1, 2, 3, 4, 5, 6});
    // IHQ 6 (assumed strain) scales the element's own elastic bending stiffness: QM = 1 is the
    // physical value (LS-DYNA's recommendation for elastic materials), more would stiffen it.
    // The Flanagan-Belytschko forms lose stability above ~0.2 (README), hence their cap of 0.5.
    spec.QM = spec.IHQ == 6 ? s.quantity_or("QM", u::dimensionless, spec.QM, Limits::interval(0, true, 1.0, false, "QM"))
                            : s.quantity_or("QM", u::dimensionless, spec.QM, Limits::interval(0, true, 0.5, false, "QM"));
    spec.Q1 = s.quantity_or("Q1", u::dimensionless, spec.Q1, Limits::non_negative("Q1"));
    spec.Q2 = s.quantity_or("Q2", u::dimensionless, spec.Q2, Limits::non_negative("Q2"));
    spec.where = s.where();
    out.push_back(std::move(spec));
  }
  return out;
}

std::vector<PartSpec> read_parts(const Reader& r, const Scene& scene) {
  r.require_map("a mapping of part name -> {material, section, id, beta}");
  if (r.node().size() == 0) r.fail("at least one part is needed", "a mapping of part name -> part");
  const auto materials = names_of(scene.materials), sections = names_of(scene.sections);
  std::vector<PartSpec> out;
  std::map<long, std::string> ids;
  for (const auto& [name, p] : r.entries()) {
    p.require_map("a mapping with material, section and optional id, beta");
    p.allow_keys({"id", "material", "section", "beta"});
    PartSpec spec;
    spec.name = name;
    const long id = p.integer_or("id", static_cast<long>(out.size()) + 1,
                                 Limits::interval(1, false, 2147483647.0, false, "part id"));
    if (const auto [it, fresh] = ids.emplace(id, name); !fresh) {
      const auto at = p.find("id");
      (at ? *at : p).fail(msg() << "duplicate part id " << id << " (already used by part '" << it->second << "')",
                          "a part id not used by another part");
    }
    spec.id = static_cast<int>(id);
    spec.material = p.reference("material", materials, "material", "materials");
    spec.section = p.reference("section", sections, "section", "sections");
    spec.beta = p.angle_or("beta", 0.0);
    spec.where = p.where();
    out.push_back(std::move(spec));
  }
  return out;
}

// ---------------------------------------------------------------- mesh

// mesh: {file: model.msh, length_unit: mm}: coordinates in length_unit (default: the scene's).
MeshFileSpec read_mesh_file(const Reader& r, const detail::Context& ctx) {
  MeshFileSpec spec;
  spec.where = r.at("file", "").where();
  const std::string file = r.at("file", "a path to a gmsh .msh file (relative to the scene file)").as_name();
  const auto folder = std::filesystem::path(ctx.file).parent_path();
  spec.path = (std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : folder / file).string();
  spec.length_scale = ctx.unit_system.length;
  if (const auto lu = r.find("length_unit")) {
    lu->require_scalar("a length unit (m, mm, ...)");
    try {
      const auto unit = u::parse_unit(lu->node().Scalar());
      if (!(unit.dim == u::length)) lu->fail("not a length unit", "a length unit (m, mm, ...)");
      spec.length_scale = unit.factor;
    } catch (const u::UnitError& e) {
      lu->fail(e.problem(), e.allowed());
    }
  }
  return spec;
}

// Two boxes that share volume would both get elements there, welded into one body by merge_nodes
// (twice the mass and stiffness); boxes may touch along faces, edges or corners. With merge_nodes:
// false the boxes are separate bodies and an overlap is theirs to resolve (an initial penetration
// the contact reports, or a punch in a slot cut into the other body), so it is allowed.
bool read_merge_nodes(const Reader& mesh);

void refuse_overlap(const Reader& box, const BoxSpec& spec, const std::vector<BoxSpec>& earlier) {
  for (std::size_t j = 0; j < earlier.size(); ++j) {
    const BoxSpec& o = earlier[j];
    bool overlap = true;
    for (int d = 0; d < 3; ++d) {
      const double lo = std::max(spec.origin[d], o.origin[d]);
      const double hi = std::min(spec.origin[d] + spec.size[d], o.origin[d] + o.size[d]);
      const double tol = 1e-9 * std::max(spec.size[d], o.size[d]);
      overlap = overlap && hi - lo > tol;
    }
    if (overlap)
      box.fail(msg() << "the box overlaps mesh.boxes[" << j << "] (part '" << o.part << "', " << o.where.file << ":"
                     << o.where.line << ":" << o.where.column << "): their elements would share volume, doubling "
                     << "mass and stiffness there",
               "boxes that touch at most along faces (move origin or change size of one of them)");
  }
}

std::vector<BoxSpec> read_mesh(const Reader& r, const Scene& scene) {
  r.require_map("a mapping with 'boxes' or 'file'");
  r.allow_keys({"boxes", "merge_nodes", "file", "length_unit"});
  if (r.exactly_one({"boxes", "file"}) == "file") {
    if (r.has("merge_nodes")) r.at("merge_nodes", "").fail("merge_nodes applies to boxes only", "file without merge_nodes");
    return {};
  }
  if (r.has("length_unit")) r.at("length_unit", "").fail("length_unit applies to a mesh file only", "boxes without length_unit");
  const Reader boxes = r.at("boxes", "a list of boxes {part, origin, size, elements}");
  boxes.require_list("a list of boxes {part, origin, size, elements}", true);
  const auto parts = names_of(scene.parts);
  std::vector<BoxSpec> out;
  for (const Reader& b : boxes.items()) {
    b.require_map("a box: {part, origin, size, elements}");
    b.allow_keys({"part", "origin", "size", "elements"});
    BoxSpec spec;
    spec.part = b.reference("part", parts, "part", "parts");
    spec.origin = b.vec3_or("origin", u::length, spec.origin);
    spec.size = b.vec3("size", u::length, Limits::positive("box size").of(QuantityKind::size));
    const Reader e = b.at("elements", "a list [nx, ny, nz] of integers >= 1");
    e.require_list("a list [nx, ny, nz] of integers >= 1", false);
    if (e.node().size() != 3) e.fail("expected exactly 3 element counts", "a list [nx, ny, nz] of integers >= 1");
    const auto counts = e.items();
    for (int i = 0; i < 3; ++i)
      spec.elements[i] = counts[i].as_int(Limits::at_least(1, "element count"));
    spec.where = b.where();
    if (read_merge_nodes(r)) refuse_overlap(b, spec, out);
    out.push_back(std::move(spec));
  }
  return out;
}

bool read_merge_nodes(const Reader& mesh) {
  const auto m = mesh.find("merge_nodes");
  return !m || m->as_choice({"true", "false"}) == "true";
}

// ---------------------------------------------------------------- node sets

int read_axis(const Reader& r) {
  const std::string a = r.as_choice({"x", "y", "z"});
  return a == "x" ? 0 : a == "y" ? 1 : 2;
}

std::vector<NodeSetSpec> read_node_sets(const Reader& r, const Scene& scene) {
  const char* selectors = "exactly one selector: {plane: {axis, value, tolerance}}, {box: {min, max}}, {part: name} or all";
  r.require_map("a mapping of node set name -> selector");
  const auto parts = names_of(scene.parts);
  std::vector<NodeSetSpec> out;
  for (const auto& [name, s] : r.entries()) {
    NodeSetSpec spec;
    spec.name = name;
    spec.where = s.where();
    if (s.node().IsScalar()) {
      if (scene.mesh_file && s.node().Scalar() == "from_mesh") {  // the mesh file's physical group of this name
        spec.kind = NodeSetSpec::Kind::Generated;
        out.push_back(std::move(spec));
        continue;
      }
      if (s.node().Scalar() != "all")
        s.fail("unknown node selector", scene.mesh_file ? std::string(selectors) + ", or from_mesh" : selectors);
      spec.kind = NodeSetSpec::Kind::All;
      out.push_back(std::move(spec));
      continue;
    }
    s.require_map(selectors);
    s.allow_keys({"plane", "box", "part"});
    const std::string kind = s.exactly_one({"plane", "box", "part"});
    if (kind == "plane") {
      const Reader p = s.at("plane", "");
      p.require_map("{axis: x|y|z, value: <length>, tolerance: <length>}");
      p.allow_keys({"axis", "value", "tolerance"});
      spec.kind = NodeSetSpec::Kind::Plane;
      spec.plane_axis = read_axis(p.at("axis", "one of x, y, z"));
      spec.plane_value = p.quantity("value", u::length);
      spec.tolerance = p.quantity_or("tolerance", u::length, 0.0, Limits::non_negative("tolerance"));
    } else if (kind == "box") {
      const Reader b = s.at("box", "");
      b.require_map("{min: [x, y, z], max: [x, y, z]}");
      b.allow_keys({"min", "max"});
      spec.kind = NodeSetSpec::Kind::Box;
      spec.box_min = b.vec3("min", u::length);
      spec.box_max = b.vec3("max", u::length);
      const auto max_items = b.at("max", "").items();
      for (int i = 0; i < 3; ++i)
        if (spec.box_max[i] < spec.box_min[i])
          max_items[i].fail(msg() << "box max must be >= min (min is " << fmt(spec.box_min[i]) << " m)",
                            msg() << "a value >= " << fmt(spec.box_min[i]) << " m");
    } else {
      spec.kind = NodeSetSpec::Kind::Part;
      spec.part = s.reference("part", parts, "part", "parts");
    }
    out.push_back(std::move(spec));
  }
  return out;
}

// ---------------------------------------------------------------- boundary and initial conditions

std::array<bool, 3> read_dofs(const Reader& r) {
  const char* allowed = "a non-empty list of distinct dofs from x, y, z (e.g. [x, z])";
  r.require_list(allowed, true);
  std::array<bool, 3> dofs{false, false, false};
  for (const Reader& d : r.items()) {
    const int axis = read_axis(d);
    if (dofs[axis]) d.fail("dof listed twice", allowed);
    dofs[axis] = true;
  }
  return dofs;
}

CurveSpec read_curve(const Reader& r) {
  const char* allowed = "a list of [time, velocity] pairs with strictly increasing times";
  r.require_list(allowed, true);
  CurveSpec c;
  for (const Reader& pt : r.items()) {
    pt.require_list("a pair [time, velocity]", false);
    if (pt.node().size() != 2) pt.fail("expected a pair [time, velocity]", "a pair [time, velocity]");
    const auto tv = pt.items();
    const double t = tv[0].as_quantity(u::time);
    if (!c.t.empty() && !(t > c.t.back()))
      tv[0].fail(msg() << "curve times must be strictly increasing (previous time " << fmt(c.t.back()) << " s)",
                 msg() << "a time > " << fmt(c.t.back()) << " s");
    c.t.push_back(t);
    c.y.push_back(tv[1].as_quantity(u::velocity));
  }
  return c;
}

std::vector<BoundaryConditionSpec> read_bcs(const Reader& r, const Scene& scene) {
  r.require_list("a list of {node_set, fix: [dofs]} or {node_set, velocity: {dofs, value [, ramp] | curve}}", false);
  const auto sets = names_of(scene.node_sets);
  std::vector<BoundaryConditionSpec> out;
  for (const Reader& b : r.items()) {
    b.require_map("{node_set, fix: [dofs]} or {node_set, velocity: {dofs, value | curve}}");
    b.allow_keys({"node_set", "fix", "velocity"});
    BoundaryConditionSpec spec;
    spec.node_set = b.reference("node_set", sets, "node set", "node_sets");
    spec.where = b.where();
    if (b.exactly_one({"fix", "velocity"}) == "fix") {
      spec.kind = BoundaryConditionSpec::Kind::Fixed;
      spec.dofs = read_dofs(b.at("fix", ""));
    } else {
      const Reader v = b.at("velocity", "");
      v.require_map("{dofs: [x, y, z], value: <velocity>, optional ramp: <time>} or {dofs: [...], curve: [[t, v], ...]}");
      v.allow_keys({"dofs", "value", "ramp", "curve"});
      spec.kind = BoundaryConditionSpec::Kind::Velocity;
      spec.dofs = read_dofs(v.at("dofs", "a list of dofs from x, y, z"));
      if (v.exactly_one({"value", "curve"}) == "value")
        spec.curve = smooth_ramp_curve(v.quantity("value", u::velocity),
                                       v.quantity_or("ramp", u::time, 0.0, Limits::non_negative("ramp time")));
      else if (const auto ramp = v.find("ramp"))
        ramp->fail("a ramp applies to a constant value", "ramp together with value (the curve gives its own shape)");
      else
        spec.curve = read_curve(v.at("curve", ""));
    }
    out.push_back(std::move(spec));
  }
  return out;
}

std::vector<InitialVelocitySpec> read_initial_velocities(const Reader& r, const Scene& scene) {
  r.require_list("a list of {part | node_set, velocity: [vx, vy, vz]}", false);
  const auto parts = names_of(scene.parts), sets = names_of(scene.node_sets);
  std::vector<InitialVelocitySpec> out;
  for (const Reader& iv : r.items()) {
    iv.require_map("{part: name, velocity: [vx, vy, vz]} or {node_set: name, velocity: [...]}");
    iv.allow_keys({"part", "node_set", "velocity"});
    InitialVelocitySpec spec;
    if (iv.exactly_one({"part", "node_set"}) == "part")
      spec.part = iv.reference("part", parts, "part", "parts");
    else
      spec.node_set = iv.reference("node_set", sets, "node set", "node_sets");
    spec.velocity = iv.vec3("velocity", u::velocity);
    spec.where = iv.where();
    out.push_back(std::move(spec));
  }
  return out;
}

// ---------------------------------------------------------------- rigid bodies, walls, contacts

// Names a contact surface or rigid body may refer to: the scene's parts plus the meshed rigid
// impactor ("impactor"), which has no part of its own.
std::vector<std::string> body_names(const Scene& scene) {
  auto names = names_of(scene.parts);
  if (scene.impactor && scene.impactor->rigid) names.push_back("impactor");
  return names;
}

bool is_rigid_part(const Scene& scene, const std::string& part) {
  if (part == "impactor" && scene.impactor && scene.impactor->rigid) return true;
  for (const auto& p : scene.parts)
    if (p.name == part)
      for (const auto& m : scene.materials)
        if (m.name == p.material) return std::holds_alternative<MatRigid>(m.params);
  return false;
}

std::vector<RigidBodySpec> read_rigid_bodies(const Reader& r, const Scene& scene) {
  const char* shape = "{part, fix: [x, y, z, rx, ry, rz], velocity: {dofs, value | curve}}";
  r.require_list(std::string("a list of ") + shape, false);
  const auto names = body_names(scene);
  std::vector<RigidBodySpec> out;
  for (const Reader& b : r.items()) {
    b.require_map(shape);
    b.allow_keys({"part", "fix", "velocity"});
    RigidBodySpec spec;
    spec.where = b.where();
    spec.part = b.reference("part", names, "part", "parts");
    if (!is_rigid_part(scene, spec.part))
      b.at("part", "").fail("the part is not rigid", "a part whose material is MAT_020, or the rigid impactor");
    for (const auto& other : out)
      if (other.part == spec.part) b.at("part", "").fail("rigid body listed twice", "one entry per rigid part");
    const std::vector<std::string> dof_names = {"x", "y", "z", "rx", "ry", "rz"};
    auto read_dof_list = [&](const Reader& l, std::array<bool, 6>& dofs) {
      const char* allowed = "a non-empty list of distinct dofs from x, y, z, rx, ry, rz";
      l.require_list(allowed, true);
      for (const Reader& d : l.items()) {
        const std::string n = d.as_choice(dof_names);
        const int i = int(std::find(dof_names.begin(), dof_names.end(), n) - dof_names.begin());
        if (dofs[i]) d.fail("dof listed twice", allowed);
        dofs[i] = true;
      }
    };
    if (const auto f = b.find("fix")) read_dof_list(*f, spec.fix);
    if (const auto v = b.find("velocity")) {
      v->require_map("{dofs: [z], value: <velocity>} or {dofs: [...], curve: [[t, v], ...]}");
      v->allow_keys({"dofs", "value", "curve"});
      read_dof_list(v->at("dofs", "a list of dofs from x, y, z, rx, ry, rz"), spec.prescribed);
      if (v->exactly_one({"value", "curve"}) == "value")
        spec.curve = CurveSpec{{0.0}, {v->quantity("value", u::velocity)}};
      else
        spec.curve = read_curve(v->at("curve", ""));
      for (int i = 0; i < 6; ++i)
        if (spec.fix[i] && spec.prescribed[i])
          v->at("dofs", "").fail(msg() << "dof " << dof_names[i] << " is both fixed and prescribed",
                                 "each dof either fixed or prescribed");
    }
    out.push_back(std::move(spec));
  }
  return out;
}

Vec3 unit_vector(const Reader& r, std::string_view key, Vec3 fallback) {
  const auto v = r.find(key);
  if (!v) return fallback;
  Vec3 x = v->as_vec3(u::dimensionless);
  const double n = std::hypot(x[0], x[1], x[2]);
  if (!(n > 0)) v->fail("the vector must not be zero", "a non-zero direction [x, y, z]");
  for (double& c : x) c /= n;
  return x;
}

// The impact-zone part (LaminateSpec::impact_zone_section) of the ply part `name`, or "" if none.
std::string impact_zone_partner(const Scene& scene, const std::string& name) {
  if (!scene.laminate) return "";
  for (const PlySpec& ply : scene.laminate->plies)
    if (ply.zone_part >= 0 && scene.parts[std::size_t(ply.part)].name == name)
      return scene.parts[std::size_t(ply.zone_part)].name;
  return "";
}

// Adds to a list of parts the impact-zone parts of the plies it names (not listed already): a ply
// named in a contact or a wall is the whole ply; without its zone part the ply's faces around the
// zone would become an exposed surface and the zone's faces none.
void add_impact_zone_parts(const Scene& scene, std::vector<std::string>& parts) {
  const std::size_t named = parts.size();
  for (std::size_t i = 0; i < named; ++i) {
    const std::string zone = impact_zone_partner(scene, parts[i]);
    if (!zone.empty() && std::find(parts.begin(), parts.end(), zone) == parts.end()) parts.push_back(zone);
  }
}

std::vector<RigidWallSpec> read_rigid_walls(const Reader& r, const Scene& scene) {
  const char* shape = "{name, point: [x, y, z], normal: [nx, ny, nz], optional friction, velocity, size: [a, b], "
                      "u: [ux, uy, uz], parts: [...]}";
  r.require_list(std::string("a list of ") + shape, false);
  const auto parts = names_of(scene.parts);
  std::vector<RigidWallSpec> out;
  for (const Reader& w : r.items()) {
    w.require_map(shape);
    w.allow_keys({"name", "point", "normal", "velocity", "friction", "size", "u", "parts"});
    RigidWallSpec spec;
    spec.where = w.where();
    spec.name = w.at("name", "a wall name").as_name();
    for (const auto& other : out)
      if (other.name == spec.name) w.at("name", "").fail("duplicate rigid wall name", "a name not used by another wall");
    spec.point = w.vec3_or("point", u::length, spec.point);
    spec.normal = unit_vector(w, "normal", {0, 0, 1});
    spec.velocity = w.vec3_or("velocity", u::velocity, spec.velocity);
    spec.friction = w.quantity_or("friction", u::dimensionless, 0.0, Limits::non_negative("friction coefficient"));
    if (const auto sz = w.find("size")) {
      sz->require_list("[length_u, length_v] of the finite wall", false);
      if (sz->node().size() != 2) sz->fail("expected two lengths", "[length_u, length_v]");
      const auto it = sz->items();
      spec.length_u = it[0].as_quantity(u::length, Limits::positive("wall length").of(QuantityKind::size));
      spec.length_v = it[1].as_quantity(u::length, Limits::positive("wall width").of(QuantityKind::size));
      Vec3 uu = unit_vector(w, "u", {1, 0, 0});
      const double un = uu[0] * spec.normal[0] + uu[1] * spec.normal[1] + uu[2] * spec.normal[2];
      for (int d = 0; d < 3; ++d) uu[d] -= un * spec.normal[d];
      const double len = std::hypot(uu[0], uu[1], uu[2]);
      if (len < 1e-6) (w.find("u") ? *w.find("u") : w).fail("u is parallel to the normal", "u: a direction in the wall plane");
      for (double& c : uu) c /= len;
      spec.u = uu;
    } else if (w.has("u")) {
      w.at("u", "").fail("u applies to a finite wall only", "size: [a, b] together with u");
    }
    if (const auto ps = w.find("parts")) {
      ps->require_list("a list of part names", true);
      for (const Reader& p : ps->items()) {
        const std::string name = p.as_name();
        if (std::find(parts.begin(), parts.end(), name) == parts.end())
          p.fail("unknown part", "one of the parts: " + detail::join(parts));
        if (is_rigid_part(scene, name))
          p.fail("rigid walls act on deformable parts only", "a part whose material is not MAT_020");
        spec.parts.push_back(name);
      }
      add_impact_zone_parts(scene, spec.parts);
    }
    out.push_back(std::move(spec));
  }
  return out;
}

std::vector<std::string> read_surface(const Reader& r, const Scene& scene) {
  const auto names = body_names(scene);
  std::vector<std::string> out;
  auto one = [&](const Reader& n) {
    const std::string name = n.as_name();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      const std::string hint = detail::did_you_mean(name, names);
      n.fail(hint.empty() ? "unknown part" : "unknown part (did you mean '" + hint + "'?)",
             "one of the parts: " + detail::join(names));
    }
    if (std::find(out.begin(), out.end(), name) != out.end()) n.fail("part listed twice", "distinct parts");
    out.push_back(name);
  };
  if (r.node().IsScalar()) one(r);
  else {
    r.require_list("a part name or a list of part names", true);
    for (const Reader& n : r.items()) one(n);
  }
  add_impact_zone_parts(scene, out);
  return out;
}

// The tiebreak card (OPTION, NFLS, SFLS, PARAM, ERATEN, ERATES, CN, CT2CN, FS) and the contact
// thicknesses SST, MST of a tiebreak contact; surfaces [slave, master] must both be deformable parts.
void read_tiebreak_contact(const Reader& c, const Scene& scene, ContactSpec& spec) {
  cohesive::TractionLawParams law;
  detail::read_tiebreak_law_keys(c, law);
  const SourceLocation w = c.where();
  cohesive::require_valid_traction_law(law, msg() << w.file << ":" << w.line << ":" << w.column << ": " << w.key_path);
  spec.tiebreak = law;
  for (const char* key : {"SOFT", "SOFSCL", "SLSFAC", "SFS", "SFM", "FD", "DC", "VDC", "PENMAX", "MAXPAR", "DTSTIF",
                          "BSORT", "ENMASS", "initial_penetration"})
    if (c.has(key)) c.at(key, "").fail("a penalty-contact field on a tiebreak contact, which does not use it",
                                       "the tiebreak card (OPTION, NFLS, SFLS, PARAM, ERATEN, ERATES, CN, CT2CN), "
                                       "FS and the contact thicknesses SST, MST");
  spec.SST = c.quantity_or("SST", u::length, 0.0, Limits::non_negative("SST"));
  spec.MST = c.quantity_or("MST", u::length, 0.0, Limits::non_negative("MST"));
  if (const auto s = c.find("surfaces"))
    for (const Reader& side : s->items())
      for (const auto& name : read_surface(side, scene))
        if (name == "impactor" || is_rigid_part(scene, name))
          side.fail("part '" + name + "' is rigid: a tiebreak ties deformable surfaces",
                    "[slave, master]: deformable part names");
}

std::vector<ContactSpec> read_contacts(const Reader& r, const Scene& scene) {
  const char* shape = "{name, type, surfaces: [a, b] | parts: [...], SOFT, SOFSCL, SLSFAC, SFS, SFM, FS, FD, DC, VDC, ...}";
  r.require_list(std::string("a list of ") + shape, false);
  std::vector<ContactSpec> out;
  for (const Reader& c : r.items()) {
    c.require_map(shape);
    c.allow_keys({"name", "type", "surfaces", "parts", "SOFT", "SOFSCL", "SLSFAC", "SFS", "SFM", "FS", "FD", "DC",
                  "VDC", "PENMAX", "MAXPAR", "DTSTIF", "BSORT", "ENMASS", "initial_penetration", "OPTION", "NFLS",
                  "SFLS", "PARAM", "ERATEN", "ERATES", "CN", "CT2CN", "SST", "MST"});
    ContactSpec spec;
    spec.where = c.where();
    spec.name = c.at("name", "a contact name").as_name();
    for (const auto& other : out)
      if (other.name == spec.name) c.at("name", "").fail("duplicate contact name", "a name not used by another contact");
    const std::string type = c.at("type", "automatic_surface_to_surface, automatic_single_surface, "
                                          "eroding_surface_to_surface, eroding_single_surface or "
                                          "tiebreak_surface_to_surface")
                                 .as_choice({"automatic_surface_to_surface", "automatic_single_surface",
                                             "eroding_surface_to_surface", "eroding_single_surface",
                                             "tiebreak_surface_to_surface"});
    if (type == "tiebreak_surface_to_surface") read_tiebreak_contact(c, scene, spec);
    else
      for (const char* key : {"OPTION", "NFLS", "SFLS", "PARAM", "ERATEN", "ERATES", "CN", "CT2CN", "SST", "MST"})
        if (c.has(key)) c.at(key, "").fail("a tiebreak field on a contact without a tiebreak",
                                           "type: tiebreak_surface_to_surface to tie the surfaces");
    spec.eroding = type.rfind("eroding", 0) == 0;
    spec.type = type.find("single") != std::string::npos ? ContactSpec::Type::SingleSurface
                                                         : ContactSpec::Type::SurfaceToSurface;
    if (spec.type == ContactSpec::Type::SurfaceToSurface) {
      if (c.has("parts")) c.at("parts", "").fail("parts is for single-surface contact", "surfaces: [a, b]");
      const Reader s = c.at("surfaces", "[a, b]: two part names or lists of part names");
      s.require_list("[a, b]: two part names or lists of part names", false);
      if (s.node().size() != 2) s.fail("expected two surfaces", "[a, b]: two part names or lists of part names");
      const auto items = s.items();
      spec.surface_a = read_surface(items[0], scene);
      spec.surface_b = read_surface(items[1], scene);
      for (const auto& a : spec.surface_a)
        if (std::find(spec.surface_b.begin(), spec.surface_b.end(), a) != spec.surface_b.end())
          items[1].fail("part '" + a + "' is on both sides", "disjoint part lists (use a single-surface contact)");
      if (is_rigid_part(scene, spec.surface_a[0]) && spec.surface_a.size() == 1 && spec.surface_b.size() == 1 &&
          is_rigid_part(scene, spec.surface_b[0]))
        s.fail("both surfaces are rigid", "at least one deformable surface");
    } else {
      // One surface: its parts under `parts`, or as the one list of `surfaces` (the plies' contact
      // reads as `surfaces: [ply_1, ply_2, ...]` like the surface-to-surface ones).
      if (c.has("surfaces") && c.has("parts"))
        c.at("surfaces", "").fail("both surfaces and parts on a single-surface contact", "one list: parts: [...] or surfaces: [...]");
      const char* what = "a list of part names (one surface in contact with itself)";
      spec.surface_a = read_surface(c.has("surfaces") ? c.at("surfaces", what) : c.at("parts", what), scene);
    }
    spec.SOFT = c.int_choice_or("SOFT", 0, {0, 1, 2});
    spec.SOFSCL = c.quantity_or("SOFSCL", u::dimensionless, spec.SOFSCL,
                                Limits::interval(0, true, spec.type == ContactSpec::Type::SingleSurface ? 0.5 : 1.0,
                                                 false, "SOFSCL"));
    spec.SLSFAC = c.quantity_or("SLSFAC", u::dimensionless, spec.SLSFAC, Limits::positive("SLSFAC"));
    spec.SFS = c.quantity_or("SFS", u::dimensionless, spec.SFS, Limits::positive("SFS"));
    spec.SFM = c.quantity_or("SFM", u::dimensionless, spec.SFM, Limits::positive("SFM"));
    spec.FS = c.quantity_or("FS", u::dimensionless, 0.0, Limits::non_negative("FS"));
    spec.FD = c.quantity_or("FD", u::dimensionless, 0.0, Limits::non_negative("FD"));
    spec.DC = c.quantity_or("DC", u::dimensionless, 0.0, Limits::non_negative("DC (s/m)"));
    spec.VDC = c.quantity_or("VDC", u::dimensionless, 0.0, Limits::interval(0, false, 100, false, "VDC (% of critical)"));
    spec.PENMAX = c.quantity_or("PENMAX", u::length, 0.0, Limits::non_negative("PENMAX"));
    spec.MAXPAR = c.quantity_or("MAXPAR", u::dimensionless, spec.MAXPAR, Limits::interval(1, false, 1.5, false, "MAXPAR"));
    spec.DTSTIF = c.quantity_or("DTSTIF", u::time, 0.0, Limits::non_negative("DTSTIF"));
    spec.BSORT = int(c.integer_or("BSORT", spec.BSORT, Limits::interval(0, false, 1000, false, "BSORT (cycles; 0: automatic)")));
    spec.ENMASS = c.int_choice_or("ENMASS", 0, {0, 1});
    if (const auto ip = c.find("initial_penetration"))
      spec.initial_penetration = ip->as_choice({"move", "offset"}) == "move" ? ContactSpec::InitialPenetration::Move
                                                                             : ContactSpec::InitialPenetration::Offset;
    out.push_back(std::move(spec));
  }
  return out;
}

// ---------------------------------------------------------------- whole scene

Scene read_scene(const Reader& root, detail::Context& ctx) {
  const char* top = "a mapping with units, control, materials, sections, parts, mesh and optional output, "
                    "node_sets, boundary_conditions, initial_velocity, rigid_bodies, rigid_walls, contacts, gravity, coupon";
  if (!root.node().IsDefined() || root.node().IsNull()) root.fail("the scene is empty", top);
  root.require_map(top);
  if (const auto i = root.find("interfaces"))
    i->fail(root.has("laminate") ? "interfaces belong inside the laminate section"
                                 : "delaminating interfaces need a laminate, and this scene has none",
            "laminate.interfaces: {select: ..., model: tiebreak, ...} in a scene with a laminate section");
  root.allow_keys({"units", "control", "output", "materials", "sections", "parts", "mesh", "laminate", "impactor",
                   "node_sets", "boundary_conditions", "initial_velocity", "rigid_bodies", "rigid_walls", "contacts",
                   "gravity", "coupon"});
  Scene scene;
  const Reader units_node = root.at("units", u::allowed_unit_systems());
  units_node.require_scalar(u::allowed_unit_systems());
  try {
    ctx.unit_system = u::parse_unit_system(units_node.node().Scalar());
  } catch (const u::UnitError& e) {
    units_node.fail(e.problem(), e.allowed());
  }
  scene.unit_system = ctx.unit_system.name;
  scene.control = read_control(root.at("control", "a mapping with termination_time and optional tssfac, ..."));
  if (const auto o = root.find("output")) scene.output = read_output(*o);
  scene.materials = read_materials(root.at("materials", "a mapping of material name -> card"));
  scene.sections = read_sections(root.at("sections", "a mapping of section name -> {ELFORM, IHQ, QM, Q1, Q2}"));
  // A laminate (and impactor) generate their own parts and mesh; `parts` and `mesh` are then optional.
  const auto laminate = root.find("laminate");
  const auto impactor = root.find("impactor");
  if (laminate && root.has("parts"))
    root.at("parts", "").fail("parts beside a laminate would have no elements (the laminate makes one part per ply "
                              "and the impactor its own; a scene has either a laminate or a mesh)",
                              "a laminate without parts, or parts with mesh.boxes or mesh.file");
  if (root.has("parts") || (!laminate && !impactor))
    scene.parts = read_parts(root.at("parts", "a mapping of part name -> {material, section}"), scene);
  if (const auto mesh = root.find("mesh")) {
    if (laminate) mesh->fail("mesh.boxes and laminate cannot be combined", "either mesh (boxes) or laminate");
    scene.boxes = read_mesh(*mesh, scene);
    if (scene.boxes.empty()) scene.mesh_file = read_mesh_file(*mesh, ctx);
    else scene.merge_coincident_nodes = read_merge_nodes(*mesh);
  } else if (!laminate) {
    root.at("mesh", "a mapping with 'boxes' or 'file' (or a laminate section)");
  }
  if (laminate) detail::read_laminate(*laminate, scene);
  if (impactor) detail::read_impactor(*impactor, scene);
  const std::size_t generated_sets = scene.node_sets.size();
  if (const auto n = root.find("node_sets")) {
    for (auto& set : read_node_sets(*n, scene)) {
      for (std::size_t i = 0; i < generated_sets; ++i)
        if (scene.node_sets[i].name == set.name)
          throw InputError(msg() << set.where.file << ":" << set.where.line << ":" << set.where.column << ": "
                                 << set.where.key_path << ": node set name already used by the laminate (support or "
                                 << "symmetry plane); found '" << set.name << "'; allowed another name");
      scene.node_sets.push_back(std::move(set));
    }
  }
  if (const auto b = root.find("boundary_conditions"))
    for (auto& bc : read_bcs(*b, scene)) scene.boundary_conditions.push_back(std::move(bc));
  if (const auto iv = root.find("initial_velocity"))
    for (auto& v : read_initial_velocities(*iv, scene)) scene.initial_velocities.push_back(std::move(v));
  if (const auto rb = root.find("rigid_bodies")) scene.rigid_bodies = read_rigid_bodies(*rb, scene);
  if (const auto rw = root.find("rigid_walls")) scene.rigid_walls = read_rigid_walls(*rw, scene);
  if (const auto c = root.find("contacts")) scene.contacts = read_contacts(*c, scene);
  if (const auto t = root.at("control", "").find("termination_contact"))
    scene.control.termination_contact = read_termination_contact(*t, scene);
  if (const auto g = root.find("gravity")) scene.gravity = g->as_vec3(u::acceleration);
  if (const auto c = root.find("coupon")) scene.coupon = detail::read_coupon(*c, scene);
  return scene;
}

// The scene's one YAML document. yaml-cpp's Load reads the first document and drops the rest
// silently, so a file holding two (separated by '---') would run with half of what it says.
YAML::Node load_single_document(const std::string& yaml_text, const std::string& file_label) {
  std::vector<YAML::Node> docs = YAML::LoadAll(yaml_text);
  for (std::size_t i = 1; i < docs.size(); ++i)
    if (docs[i].IsDefined() && !docs[i].IsNull())
      throw InputError(msg() << detail::location(file_label, docs[i].Mark()) << ": (top level): a second YAML "
                             << "document (after '---') would be ignored; found " << docs.size()
                             << " documents; allowed one scene per file (remove the '---' line and merge the "
                             << "sections, or put each scene in its own file)");
  return docs.empty() ? YAML::Node() : docs.front();
}

}  // namespace

Scene load_scene_from_string(const std::string& yaml_text, const std::string& file_label,
                             const std::vector<SceneOverride>& overrides) {
  detail::Context ctx{file_label, {}};
  Scene scene;
  try {
    YAML::Node root;
    try {
      root = load_single_document(yaml_text, file_label);
    } catch (const YAML::Exception& e) {
      throw InputError(msg() << detail::location(file_label, e.mark) << ": YAML syntax error: " << e.msg
                             << "; found text that is not valid YAML here (or on the line before)"
                             << "; allowed a YAML mapping (check indentation, ':' after keys, closing ] and })");
    }
    detail::apply_overrides(root, overrides, ctx);
    YAML::Mark start;  // 1:1
    scene = read_scene(Reader(root, "", &ctx, start), ctx);
  } catch (const YAML::Exception& e) {  // should not happen: Reader checks types before access
    throw InputError(msg() << detail::location(file_label, e.mark) << ": internal YAML error: " << e.msg);
  }
  scene.file = file_label;
  scene.name = std::filesystem::path(file_label).stem().string();
  scene.key_locations = std::move(ctx.key_locations);
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides) {
  std::error_code ec;
  std::ifstream in;
  if (!std::filesystem::is_directory(path, ec)) in.open(path, std::ios::binary);
  if (!in.is_open())
    throw InputError(msg() << path << ": cannot open the scene file; found no readable file at this path"
                           << "; allowed a path to an existing .yaml scene file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(msg() << path << ": error while reading the scene file");
  return load_scene_from_string(text.str(), path, overrides);
}

}  // namespace plyimpact::config
