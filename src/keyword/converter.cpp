// Card layouts and defaults follow the LS-DYNA Keyword User's Manual (Vol. I: control, database,
// element, part, section, hourglass, set, boundary, initial, define, contact and rigid-wall
// keywords; Vol. II: the *MAT cards). Each handler names its card; a field whose meaning or
// default could not be confirmed is accepted only blank (or at the default stated beside it).
#include "keyword/converter.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "core/units.hpp"
#include "keyword/fields.hpp"
#include "mesh/scene_mesher.hpp"
#include "output/atomic_file.hpp"

namespace plyimpact::keyword {
namespace {

// Shortest text that reads back as the same double.
std::string num(double v) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string vec(double a, double b, double c) { return "[" + num(a) + ", " + num(b) + ", " + num(c) + "]"; }

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// A card's data lines from `first` on, blank lines skipped (repeated cards) or kept (fixed cards).
std::vector<const DataLine*> nonblank(const Card& c, std::size_t first = 0) {
  std::vector<const DataLine*> out;
  for (std::size_t i = first; i < c.lines.size(); ++i)
    if (c.lines[i].text.find_first_not_of(" \t") != std::string::npos) out.push_back(&c.lines[i]);
  return out;
}

// The fixed cards of a keyword: card k is data line k (missing or blank = all defaults); more
// non-blank lines than `max_cards` are refused (each repetition would be another definition).
class FixedCards {
 public:
  FixedCards(const Card& c, std::size_t max_cards, std::size_t skip = 0) : card_(c), skip_(skip) {
    for (std::size_t i = skip + max_cards; i < c.lines.size(); ++i)
      if (c.lines[i].text.find_first_not_of(" \t") != std::string::npos)
        throw InputError(msg() << where(c, c.lines[i]) << "more data lines than the " << max_cards
                                              << " cards of one definition; allowed: one definition per keyword");
  }
  bool has(std::size_t k) const { return skip_ + k < card_.lines.size(); }
  Fields fields(std::size_t k, const std::vector<FieldSpec>& layout) const {
    return Fields(card_, has(k) ? card_.lines[skip_ + k] : blank_line(), layout);
  }

 private:
  const DataLine& blank_line() const {
    blank_ = DataLine{"", card_.file, card_.lines.empty() ? card_.line : card_.lines.back().line};
    return blank_;
  }
  const Card& card_;
  std::size_t skip_;
  mutable DataLine blank_;
};

struct Material {
  std::string card;  // MAT_001 ...
  std::vector<std::pair<std::string, std::string>> fields;  // YAML key -> value text
  bool rigid = false;
  long lcss = 0;  // MAT_024 curve id, resolved at emission
  const Card* where = nullptr;
  bool takes_eos = false;  // MAT_015: the parts' EOSID gives its eos block
  std::vector<std::pair<std::string, std::string>> without_eos;  // MAT_015 E, PR: written only without an EOS
};

struct Eos {
  std::string card;  // EOS_LINEAR_POLYNOMIAL or EOS_GRUNEISEN
  std::vector<std::pair<std::string, std::string>> fields;
  const Card* where = nullptr;
};

struct PartDef {
  long pid = 0, secid = 0, mid = 0, hgid = 0, eosid = 0;
  std::string heading;
  const Card* where = nullptr;
};

struct Hourglass {
  long ihq = 0;
  double qm = 0.1;
  bool q1_set = false, q2_set = false;
  double q1 = 1.5, q2 = 0.06;
};

struct Curve {
  std::vector<double> t, y;
  const Card* where = nullptr;
};

struct Bc {
  std::string set;
  std::array<bool, 3> fix{};
  long lcid = 0;  // > 0: prescribed velocity, one dof
  double sf = 1;
  const Card* where = nullptr;
};

struct InitialVelocity {
  const Card* where = nullptr;
  std::string node_set;
  std::vector<long> parts;
  double v[3] = {0, 0, 0};
};

struct Contact {
  bool single = false, eroding = false, tiebreak = false;
  bool all_parts = false;  // single surface with SSID 0 / SSTYP 5: every part
  std::vector<long> a, b;  // part ids
  std::vector<std::pair<std::string, std::string>> fields;
};

class Converter {
 public:
  explicit Converter(const ConvertOptions& o) : options_(o), units_(units::parse_unit_system(o.unit_system)) {}

  Conversion run(const Deck& deck) {
    // A deck's order carries no meaning: sets are read first, so a card may name a set defined
    // after it. Coverage stays in deck order.
    out_.coverage.resize(deck.cards.size());
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t i = 0; i < deck.cards.size(); ++i) {
        const Card& c = deck.cards[i];
        if ((c.keyword.rfind("SET_", 0) == 0) != (pass == 0)) continue;
        CoverageEntry e{c.file, c.line, c.keyword, "used", ""};
        try {
          last_note_.clear();
          e.note = dispatch(c, e.status);
          if (e.note.empty()) e.note = last_note_;
        } catch (const InputError& err) {
          e.status = "refused";
          e.note = err.what();
        }
        out_.coverage[i] = std::move(e);
        entry_of_[&c] = i;
      }
    if (!out_.refused()) {
      try {
        emit();
      } catch (const Refusal& r) {
        if (r.card) {
          auto& e = out_.coverage[entry_of_.at(r.card)];
          e.status = "refused";
          e.note = r.what;
        } else {
          out_.coverage.push_back({deck.file, 0, "(deck)", "refused", deck.file + ": " + r.what});
        }
      }
    }
    return std::move(out_);
  }

 private:
  struct Refusal {
    const Card* card;
    std::string what;
  };
  [[noreturn]] void refuse(const Card* c, const std::string& what) { throw Refusal{c, (c ? where(*c) : "") + what}; }

  std::string dispatch(const Card& c, std::string& status) {
    const std::string& k = c.keyword;
    using H = std::string (Converter::*)(const Card&, std::string&);
    static const std::map<std::string, H> handlers = {
        {"KEYWORD", &Converter::structural},
        {"END", &Converter::structural},
        {"INCLUDE", &Converter::structural},
        {"TITLE", &Converter::title},
        {"NODE", &Converter::node},
        {"ELEMENT_SOLID", &Converter::element_solid},
        {"PART", &Converter::part},
        {"SECTION_SOLID", &Converter::section_solid},
        {"HOURGLASS", &Converter::hourglass},
        {"CONTROL_HOURGLASS", &Converter::control_hourglass},
        {"CONTROL_BULK_VISCOSITY", &Converter::control_bulk_viscosity},
        {"CONTROL_TERMINATION", &Converter::control_termination},
        {"CONTROL_TIMESTEP", &Converter::control_timestep},
        {"MAT_ELASTIC", &Converter::mat_elastic},
        {"MAT_001", &Converter::mat_elastic},
        {"MAT_ORTHOTROPIC_ELASTIC", &Converter::mat_orthotropic},
        {"MAT_002", &Converter::mat_orthotropic},
        {"MAT_PLASTIC_KINEMATIC", &Converter::mat_plastic_kinematic},
        {"MAT_003", &Converter::mat_plastic_kinematic},
        {"MAT_RIGID", &Converter::mat_rigid},
        {"MAT_020", &Converter::mat_rigid},
        {"MAT_PIECEWISE_LINEAR_PLASTICITY", &Converter::mat_piecewise},
        {"MAT_024", &Converter::mat_piecewise},
        {"MAT_ENHANCED_COMPOSITE_DAMAGE", &Converter::mat_054},
        {"MAT_054", &Converter::mat_054},
        {"MAT_055", &Converter::mat_054},
        {"MAT_JOHNSON_COOK", &Converter::mat_johnson_cook},
        {"MAT_015", &Converter::mat_johnson_cook},
        {"MAT_SIMPLIFIED_JOHNSON_COOK", &Converter::mat_simplified_johnson_cook},
        {"MAT_098", &Converter::mat_simplified_johnson_cook},
        {"EOS_LINEAR_POLYNOMIAL", &Converter::eos_linear_polynomial},
        {"EOS_GRUNEISEN", &Converter::eos_gruneisen},
        {"MAT_COHESIVE_MIXED_MODE", &Converter::mat_138},
        {"MAT_138", &Converter::mat_138},
        {"SET_NODE_LIST", &Converter::set_node_list},
        {"SET_PART_LIST", &Converter::set_part_list},
        {"SET_SEGMENT", &Converter::set_segment},
        {"BOUNDARY_SPC_SET", &Converter::boundary_spc},
        {"BOUNDARY_SPC_NODE", &Converter::boundary_spc},
        {"BOUNDARY_PRESCRIBED_MOTION_SET", &Converter::prescribed_motion},
        {"INITIAL_VELOCITY", &Converter::initial_velocity},
        {"INITIAL_VELOCITY_GENERATION", &Converter::initial_velocity_generation},
        {"DEFINE_CURVE", &Converter::define_curve},
        {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", &Converter::contact},
        {"CONTACT_ERODING_SURFACE_TO_SURFACE", &Converter::contact},
        {"CONTACT_AUTOMATIC_SINGLE_SURFACE", &Converter::contact},
        {"CONTACT_ERODING_SINGLE_SURFACE", &Converter::contact},
        {"CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE_TIEBREAK", &Converter::contact},
        {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK", &Converter::contact},
        {"RIGIDWALL_PLANAR", &Converter::rigidwall_planar},
        {"DATABASE_BINARY_D3PLOT", &Converter::database},
        {"DATABASE_GLSTAT", &Converter::database},
        {"DATABASE_RCFORC", &Converter::database},
        {"DATABASE_MATSUM", &Converter::database},
    };
    // Options this reader knows: _TITLE (a title line first) on materials, sections, hourglass
    // and curves; _ID / _TITLE (an ID card first) on contacts.
    std::string base = k;
    title_line_ = false;
    contact_id_card_ = false;
    auto strip = [&](const std::string& suffix) {
      if (base.size() > suffix.size() && base.compare(base.size() - suffix.size(), suffix.size(), suffix) == 0) {
        base.erase(base.size() - suffix.size());
        return true;
      }
      return false;
    };
    if (base.rfind("CONTACT_", 0) == 0) {
      contact_id_card_ = strip("_ID") || strip("_TITLE");
    } else if (base.rfind("MAT_", 0) == 0 || base.rfind("EOS_", 0) == 0 || base == "SECTION_SOLID_TITLE" || base == "HOURGLASS_TITLE" ||
               base == "DEFINE_CURVE_TITLE") {
      title_line_ = strip("_TITLE");
    }
    const auto it = handlers.find(base);
    if (it == handlers.end()) {
      std::string known;
      for (const auto& [name, h] : handlers)
        if (k.rfind(name + "_", 0) == 0) known = name;
      if (!known.empty())
        throw InputError(msg() << where(c) << "option '" << k.substr(known.size() + 1) << "' of *" << known
                                  << " is not implemented; allowed: *" << known
                                  << (known.rfind("MAT_", 0) == 0 ? " or *" + known + "_TITLE" : std::string()));
      throw InputError(msg() << where(c) << "keyword not implemented (see `plyimpact convert --coverage` for the cards this "
                                   "reader maps)");
    }
    return (this->*(it->second))(c, status);
  }

  std::size_t skip() const { return title_line_ ? 1 : 0; }

  // ------------------------------------------------------------------ structure, title

  std::string structural(const Card& c, std::string& status) {
    status = "mapped";
    if (c.keyword == "INCLUDE") return "file read in place";
    if (c.keyword == "END") return "end of input";
    return "deck header";
  }

  std::string title(const Card& c, std::string& status) {
    status = "mapped";
    const auto l = nonblank(c);
    if (l.size() > 1) throw InputError(msg() << where(c, *l[1]) << "one title line allowed");
    title_ = l.empty() ? "" : l[0]->text;
    return "comment at the top of the scene";
  }

  // ------------------------------------------------------------------ mesh

  // *NODE (Vol. I): NID I8, X Y Z E16, TC RC I8 (long format: 20 each).
  std::string node(const Card& c, std::string&) {
    const std::vector<FieldSpec> layout = {{"NID", 8}, {"X", 16}, {"Y", 16}, {"Z", 16}, {"TC", 8}, {"RC", 8}};
    for (const DataLine* l : nonblank(c)) {
      const Fields f(c, *l, layout);
      const long nid = f.integer("NID", 0);
      if (nid <= 0) f.fail("NID", "a node needs a positive id");
      f.require_default("TC", 0, "translational constraints: use *BOUNDARY_SPC_NODE");
      f.require_default("RC", 0, "rotational constraints");
      if (!nodes_.emplace(nid, std::array<double, 3>{f.real("X", 0), f.real("Y", 0), f.real("Z", 0)}).second)
        f.fail("NID", "node id defined twice");
    }
    return "mesh nodes (.msh, m)";
  }

  // *ELEMENT_SOLID (Vol. I): EID PID N1..N8, fields of 8 characters (one-card format).
  std::string element_solid(const Card& c, std::string&) {
    const std::vector<FieldSpec> layout = {{"EID", 8}, {"PID", 8}, {"N1", 8}, {"N2", 8}, {"N3", 8},
                                           {"N4", 8},  {"N5", 8},  {"N6", 8}, {"N7", 8}, {"N8", 8}};
    for (const DataLine* l : nonblank(c)) {
      const Fields f(c, *l, layout);
      Element e;
      const long eid = f.integer("EID", 0);
      if (eid <= 0) f.fail("EID", "an element needs a positive id");
      e.pid = f.integer("PID", 0);
      if (f.blank("N1") && f.blank("N8"))
        f.fail("N1", "the two-card (EID PID / N1..N10) format is not supported; allowed: EID PID N1..N8 on one line");
      std::set<long> distinct;
      for (int k = 0; k < 8; ++k) {
        std::string name = "N";
        name += char('1' + k);
        e.n[k] = f.integer(name, 0);
        if (e.n[k] <= 0) f.fail(name, "a node id is needed");
        distinct.insert(e.n[k]);
      }
      if (distinct.size() != 8)
        f.fail("N8", "degenerate element (a node repeated: tetrahedron, pentahedron); allowed: 8-node hexahedra only");
      e.line = l;
      if (!elements_.emplace(eid, e).second) f.fail("EID", "element id defined twice");
    }
    return "mesh hexahedra (.msh, by element id)";
  }

  // *PART (Vol. I): HEADING; PID SECID MID EOSID HGID GRAV ADPOPT TMID.
  std::string part(const Card& c, std::string&) {
    if (c.lines.size() < 2) throw InputError(msg() << where(c) << "a heading line and a card with PID SECID MID are needed");
    const FixedCards cards(c, 2);
    PartDef p;
    p.heading = c.lines[0].text;
    const Fields f = cards.fields(1, tens({"PID", "SECID", "MID", "EOSID", "HGID", "GRAV", "ADPOPT", "TMID"}));
    p.pid = f.integer("PID", 0);
    if (p.pid <= 0) f.fail("PID", "a part needs a positive id");
    p.secid = f.integer("SECID", 0);
    p.mid = f.integer("MID", 0);
    p.eosid = f.integer("EOSID", 0);
    p.hgid = f.integer("HGID", 0);
    f.require_default("GRAV", 0, "gravity initialisation");
    f.require_default("ADPOPT", 0, "adaptivity");
    f.require_default("TMID", 0, "thermal material");
    p.where = &c;
    if (parts_.count(p.pid)) f.fail("PID", "part id defined twice");
    part_order_.push_back(p.pid);
    parts_[p.pid] = p;
    return "part_" + std::to_string(p.pid);
  }

  // Cohesive solids of a deck are explicit elements between parts; the scene format has cohesive
  // elements only as the interfaces of a meshed laminate (they need the laminate's duplicated nodes
  // and its interface numbering), so a deck's ELFORM 19/20 parts have nothing to map onto.
  static constexpr const char* kCohesiveSolidsRefusal =
      "cohesive solids (ELFORM 19/20 with *MAT_138) between parts of a deck are not mapped: the scene "
      "format places *MAT_138 cohesive elements only on a laminate's interfaces (laminate.interfaces: "
      "{model: cohesive, T, S, XMU, GIC, GIIC, EN, ET}, docs/delamination.md)";

  // *MAT_COHESIVE_MIXED_MODE (*MAT_138): refused, see kCohesiveSolidsRefusal.
  std::string mat_138(const Card& c, std::string&) {
    throw InputError(msg() << where(c) << "*" << c.keyword << ": " << kCohesiveSolidsRefusal);
  }

  // *SECTION_SOLID (Vol. I): SECID ELFORM AET; ELFORM 1 (default), 2 or -2. LS-DYNA's -2 is its
  // fully integrated solid for poor aspect ratios; ours has the same purpose by another method
  // (element/hex8_ans.hpp), so a deck asking for it gets ours.
  std::string section_solid(const Card& c, std::string&) {
    const FixedCards cards(c, 1, skip());
    const Fields f = cards.fields(0, tens({"SECID", "ELFORM", "AET", "F4", "F5", "F6", "F7", "F8"}));
    const long id = f.integer("SECID", 0);
    const long elform = f.integer("ELFORM", 1);
    if (elform == 19 || elform == 20)
      f.fail("ELFORM", std::string(kCohesiveSolidsRefusal) + "; allowed here: 1, 2 or -2");
    if (elform != 1 && elform != 2 && elform != -2)
      f.fail("ELFORM", "element formulation not implemented; allowed: 1, 2 or -2");
    f.require_default("AET", 0, "ambient element type");
    for (const char* n : {"F4", "F5", "F6", "F7", "F8"}) f.require_default(n, 0, "fields after AET");
    if (!sections_.emplace(id, elform).second) f.fail("SECID", "section id defined twice");
    return "sections: sec_" + std::to_string(id) + " (ELFORM " + std::to_string(elform) + ")";
  }

  // *HOURGLASS (Vol. I): HGID IHQ QM IBQ Q1 Q2 QB/VDC QW. IHQ 0 takes *CONTROL_HOURGLASS.
  std::string hourglass(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 1, skip());
    const Fields f = cards.fields(0, tens({"HGID", "IHQ", "QM", "IBQ", "Q1", "Q2", "QB", "QW"}));
    Hourglass h;
    const long id = f.integer("HGID", 0);
    h.ihq = f.integer("IHQ", 0);
    if (h.ihq < 0 || h.ihq > 6) f.fail("IHQ", "hourglass type not implemented; allowed: 0 to 6");
    h.qm = f.real("QM", 0.1);
    f.require_default("IBQ", 0, "not used");
    h.q1_set = !f.blank("Q1");
    h.q2_set = !f.blank("Q2");
    h.q1 = f.real("Q1", 1.5);
    h.q2 = f.real("Q2", 0.06);
    if (h.q1_set && h.q1 == 0) f.fail("Q1", "0 (off or default?) not supported; allowed: blank or > 0");
    if (h.q2_set && h.q2 == 0) f.fail("Q2", "0 (off or default?) not supported; allowed: blank or > 0");
    if (!f.blank("QB") && f.real("QB", 0) != h.qm) f.fail("QB", "a bending coefficient other than QM (shells)");
    if (!f.blank("QW") && f.real("QW", 0) != h.qm) f.fail("QW", "a warping coefficient other than QM (shells)");
    if (!hourglass_.emplace(id, h).second) f.fail("HGID", "hourglass id defined twice");
    return "into the sections of the parts that use it (IHQ, QM, Q1, Q2)";
  }

  // *CONTROL_HOURGLASS (Vol. I): IHQ, QH (default 0.1). Blank IHQ: LS-DYNA's default for
  // one-point solids in explicit runs, type 2 since 971 R3.1 (LSTC support FAQ "hourglass").
  std::string control_hourglass(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 1);
    const Fields f = cards.fields(0, tens({"IHQ", "QH"}));
    control_ihq_ = f.integer("IHQ", 2);
    if (control_ihq_ < 1 || control_ihq_ > 6) f.fail("IHQ", "hourglass type not implemented; allowed: 1 to 6");
    control_qh_ = f.real("QH", 0.1);
    return "IHQ/QM of every section without its own *HOURGLASS";
  }

  // *CONTROL_BULK_VISCOSITY (Vol. I): Q1 (1.5), Q2 (0.06), TYPE (1: solids only).
  std::string control_bulk_viscosity(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 1);
    const Fields f = cards.fields(0, tens({"Q1", "Q2", "TYPE", "BTYPE", "TSTYPE"}));
    bulk_q1_ = f.real("Q1", 1.5);
    bulk_q2_ = f.real("Q2", 0.06);
    // Whether an entered 0 switches the viscosity off or means the default was not confirmed.
    if (!f.blank("Q1") && bulk_q1_ == 0) f.fail("Q1", "0 (off or default?) not supported; allowed: blank or > 0");
    if (!f.blank("Q2") && bulk_q2_ == 0) f.fail("Q2", "0 (off or default?) not supported; allowed: blank or > 0");
    f.require_default("TYPE", 1, "bulk viscosity for shells and beams");
    f.require_default("BTYPE", 0, "beam bulk viscosity");
    f.require_default("TSTYPE", 0, "thick shells");
    return "Q1/Q2 of every section (a *HOURGLASS Q1/Q2 given on the card overrides them)";
  }

  // *CONTROL_TERMINATION (Vol. I): ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL.
  std::string control_termination(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 1);
    const Fields f = cards.fields(0, tens({"ENDTIM", "ENDCYC", "DTMIN", "ENDENG", "ENDMAS", "NOSOL"}));
    endtim_ = f.real("ENDTIM", 0);
    if (!(endtim_ > 0)) f.fail("ENDTIM", "a positive termination time is needed");
    endcyc_ = f.integer("ENDCYC", 0);
    dtmin_ = f.real("DTMIN", 0);
    f.require_default("ENDENG", 0, "energy change termination");
    endmas_ = f.real("ENDMAS", 0);  // percent of the model's mass (control.endmas)
    if (endmas_ < 0) f.fail("ENDMAS", "allowed: >= 0 (percent of the model's mass added by DT2MS mass scaling)");
    f.require_default("NOSOL", 0, "no-solution run");
    return dtmin_ > 0 ? "control: termination_time, max_cycles, dt_min_ratio = DTMIN"
                      : "control: termination_time, max_cycles (DTMIN blank: the scene's default stop at 1e-3 dt0 stays)";
  }

  // *CONTROL_TIMESTEP (Vol. I): DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST.
  std::string control_timestep(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 1);
    const Fields f = cards.fields(0, tens({"DTINIT", "TSSFAC", "ISDO", "TSLIMT", "DT2MS", "LCTM", "ERODE", "MS1ST"}));
    f.require_default("DTINIT", 0, "initial step is the stable step");
    tssfac_ = f.real("TSSFAC", 0.9);
    if (tssfac_ == 0) tssfac_ = 0.9;
    if (!(tssfac_ > 0 && tssfac_ <= 1)) f.fail("TSSFAC", "allowed: in (0, 1]");
    f.require_default("ISDO", 0, "shell step options");
    f.require_default("TSLIMT", 0, "shell minimum step");
    // DT2MS < 0: mass scaling to the element step |DT2MS|, which plyimpact applies once at the start
    // (LS-DYNA's MS1ST 1; with MS1ST 0 LS-DYNA re-evaluates it every cycle). DT2MS > 0 (uniform
    // scaling that also removes mass) has no counterpart.
    dt2ms_ = f.real("DT2MS", 0);
    if (dt2ms_ > 0) f.fail("DT2MS", "allowed: 0 or negative (mass added to elements below the step |DT2MS|)");
    f.require_default("LCTM", 0, "step limit curve");
    f.require_default("ERODE", 0, "erosion at TSMIN");
    const int ms1st = int(f.real("MS1ST", 0));
    if (ms1st != 0 && ms1st != 1) f.fail("MS1ST", "allowed: 0 or 1");
    if (dt2ms_ < 0)
      return ms1st == 1 ? "control: tssfac, dt2ms (mass added once at the start, as MS1ST 1)"
                        : "control: tssfac, dt2ms (mass added once at the start, as MS1ST 1; MS1ST 0 would "
                          "re-evaluate it every cycle)";
    return "control: tssfac";
  }

  // ------------------------------------------------------------------ materials (Vol. II)

  Material& new_material(const Fields& f, const Card& c, const std::string& card) {
    const long mid = f.integer("MID", 0);
    if (mid <= 0) f.fail("MID", "a material needs a positive id");
    if (materials_.count(mid)) f.fail("MID", "material id defined twice");
    Material& m = materials_[mid];
    last_note_ = "materials: mat_" + std::to_string(mid) + " (" + card + ")";
    m.card = card;
    m.where = &c;
    return m;
  }

  static void put(Material& m, const Fields& f, const char* name, const char* key = nullptr) {
    if (!f.blank(name)) m.fields.push_back({key ? key : name, num(f.real(name, 0))});
  }

  // *MAT_ELASTIC (*MAT_001): MID RO E PR DA DB K.
  std::string mat_elastic(const Card& c, std::string&) {
    const FixedCards cards(c, 1, skip());
    const Fields f = cards.fields(0, tens({"MID", "RO", "E", "PR", "DA", "DB", "K"}));
    Material& m = new_material(f, c, "MAT_001");
    for (const char* n : {"RO", "E", "PR"}) put(m, f, n);
    f.require_default("DA", 0, "axial damping (beams)");
    f.require_default("DB", 0, "bending damping (beams)");
    f.require_default("K", 0, "bulk modulus (fluid option)");
    return "";
  }

  // *MAT_ORTHOTROPIC_ELASTIC (*MAT_002): MID RO EA EB EC PRBA PRCA PRCB / GAB GBC GCA AOPT G SIGF /
  // XP YP ZP A1 A2 A3 MACF / V1 V2 V3 D1 D2 D3 BETA REF.
  std::string mat_orthotropic(const Card& c, std::string&) {
    const FixedCards cards(c, 4, skip());
    const Fields f1 = cards.fields(0, tens({"MID", "RO", "EA", "EB", "EC", "PRBA", "PRCA", "PRCB"}));
    Material& m = new_material(f1, c, "MAT_002");
    for (const char* n : {"RO", "EA", "EB", "EC", "PRBA", "PRCA", "PRCB"}) put(m, f1, n);
    const Fields f2 = cards.fields(1, tens({"GAB", "GBC", "GCA", "AOPT", "G", "SIGF"}));
    for (const char* n : {"GAB", "GBC", "GCA"}) put(m, f2, n);
    axes(m, f2, cards.fields(2, tens({"XP", "YP", "ZP", "A1", "A2", "A3", "MACF"})),
         cards.fields(3, tens({"V1", "V2", "V3", "D1", "D2", "D3", "BETA", "REF"})), "BETA", true);
    f2.require_default("G", 0, "shear modulus for frequency-independent damping");
    f2.require_default("SIGF", 0, "limit stress for damping");
    return "";
  }

  // AOPT 0, 2, 3 with A, D, V and the angle (*MAT_002 BETA / *MAT_054 MANGLE); AOPT 1 and 4 need XP.
  void axes(Material& m, const Fields& f2, const Fields& f3, const Fields& f4, const char* angle, bool vectors) {
    const long aopt = f2.integer("AOPT", 0);
    if (aopt != 0 && aopt != 2 && aopt != 3) f2.fail("AOPT", "material axes option not implemented; allowed: 0, 2, 3");
    for (const char* n : {"XP", "YP", "ZP"}) f3.require_default(n, 0, "AOPT 1 and 4 only");
    f3.require_default("MACF", 1, "axis change");
    f4.require_default("REF", 0, "reference geometry");
    const bool a = !f3.blank("A1") || !f3.blank("A2") || !f3.blank("A3");
    const bool d = !f4.blank("D1") || !f4.blank("D2") || !f4.blank("D3");
    const bool v = !f4.blank("V1") || !f4.blank("V2") || !f4.blank("V3");
    if (aopt != 0) m.fields.push_back({"AOPT", std::to_string(aopt)});
    if (vectors) {
      if (a) m.fields.push_back({"A", vec(f3.real("A1", 0), f3.real("A2", 0), f3.real("A3", 0))});
      if (d) m.fields.push_back({"D", vec(f4.real("D1", 0), f4.real("D2", 0), f4.real("D3", 0))});
      if (v) m.fields.push_back({"V", vec(f4.real("V1", 0), f4.real("V2", 0), f4.real("V3", 0))});
    } else {
      for (const char* n : {"A1", "A2", "A3"}) put(m, f3, n);
      for (const char* n : {"V1", "V2", "V3", "D1", "D2", "D3"}) put(m, f4, n);
    }
    put(m, vectors ? f4 : f3, angle);
  }

  // *MAT_PLASTIC_KINEMATIC (*MAT_003): MID RO E PR SIGY ETAN BETA / SRC SRP FS VP.
  std::string mat_plastic_kinematic(const Card& c, std::string&) {
    const FixedCards cards(c, 2, skip());
    const Fields f1 = cards.fields(0, tens({"MID", "RO", "E", "PR", "SIGY", "ETAN", "BETA"}));
    Material& m = new_material(f1, c, "MAT_003");
    for (const char* n : {"RO", "E", "PR", "SIGY", "ETAN", "BETA"}) put(m, f1, n);
    const Fields f2 = cards.fields(1, tens({"SRC", "SRP", "FS", "VP"}));
    for (const char* n : {"SRC", "SRP", "FS"}) put(m, f2, n);
    f2.require_default("VP", 0, "viscoplastic rate formulation");
    return "";
  }

  // *MAT_RIGID (*MAT_020): MID RO E PR N COUPLE M ALIAS / CMO CON1 CON2 / LCO|A1 A2 A3 V1 V2 V3.
  std::string mat_rigid(const Card& c, std::string&) {
    const FixedCards cards(c, 3, skip());
    const Fields f1 = cards.fields(0, tens({"MID", "RO", "E", "PR", "N", "COUPLE", "M", "ALIAS"}));
    Material& m = new_material(f1, c, "MAT_020");
    m.rigid = true;
    for (const char* n : {"RO", "E", "PR"}) put(m, f1, n);
    for (const char* n : {"N", "COUPLE", "M"}) f1.require_default(n, 0, "MADYMO coupling");
    if (!f1.blank("ALIAS")) f1.fail("ALIAS", "not supported; allowed: blank");
    const Fields f2 = cards.fields(1, tens({"CMO", "CON1", "CON2"}));
    const long cmo = f2.integer("CMO", 0);
    if (cmo != 0 && cmo != 1) f2.fail("CMO", "local (CMO -1) constraints not implemented; allowed: 0 or 1");
    const long con1 = f2.integer("CON1", 0), con2 = f2.integer("CON2", 0);
    if (con1 < 0 || con1 > 7) f2.fail("CON1", "allowed: 0 to 7");
    if (con2 < 0 || con2 > 7) f2.fail("CON2", "allowed: 0 to 7 (global rotations)");
    if (cmo == 1) {
      m.fields.push_back({"CMO", "1"});
      m.fields.push_back({"CON1", std::to_string(con1)});
      m.fields.push_back({"CON2", std::to_string(con2)});
    } else if (con1 != 0 || con2 != 0) {
      f2.fail(con1 ? "CON1" : "CON2", "constraints need CMO 1; allowed: 0 with CMO 0");
    }
    const Fields f3 = cards.fields(2, tens({"LCO", "A2", "A3", "V1", "V2", "V3"}));
    for (const char* n : {"LCO", "A2", "A3", "V1", "V2", "V3"}) f3.require_default(n, 0, "local axes / output");
    return "";
  }

  // *MAT_PIECEWISE_LINEAR_PLASTICITY (*MAT_024): MID RO E PR SIGY ETAN FAIL TDEL / C P LCSS LCSR VP
  // LCF / EPS1..EPS8 / ES1..ES8.
  std::string mat_piecewise(const Card& c, std::string&) {
    const FixedCards cards(c, 4, skip());
    const Fields f1 = cards.fields(0, tens({"MID", "RO", "E", "PR", "SIGY", "ETAN", "FAIL", "TDEL"}));
    Material& m = new_material(f1, c, "MAT_024");
    for (const char* n : {"RO", "E", "PR", "ETAN"}) put(m, f1, n);
    if (f1.real("FAIL", 0) > 0) put(m, f1, "FAIL");
    else f1.require_default("FAIL", 0, "negative FAIL: user failure subroutine");
    f1.require_default("TDEL", 0, "minimum step for deletion");
    const Fields f2 = cards.fields(1, tens({"C", "P", "LCSS", "LCSR", "VP", "LCF"}));
    for (const char* n : {"C", "P"}) put(m, f2, n);
    m.lcss = f2.integer("LCSS", 0);
    f2.require_default("LCSR", 0, "strain-rate curve");
    f2.require_default("VP", 0, "viscoplastic rate formulation");
    f2.require_default("LCF", 0, "failure curve");
    const Fields f3 = cards.fields(2, tens({"EPS1", "EPS2", "EPS3", "EPS4", "EPS5", "EPS6", "EPS7", "EPS8"}));
    const Fields f4 = cards.fields(3, tens({"ES1", "ES2", "ES3", "ES4", "ES5", "ES6", "ES7", "ES8"}));
    std::string table;
    for (int k = 1; k <= 8; ++k) {
      std::string e = "EPS", s = "ES";
      e += char('0' + k);
      s += char('0' + k);
      if (f3.blank(e) && f4.blank(s)) continue;
      if (m.lcss > 0) f3.fail(e, "both LCSS and the EPS/ES table; allowed: one of them");
      table += std::string(table.empty() ? "" : ", ") + "[" + num(f3.real(e, 0)) + ", " + num(f4.real(s, 0)) + "]";
    }
    if (!table.empty()) m.fields.push_back({"LCSS", "[" + table + "]"});
    else if (m.lcss == 0) put(m, f1, "SIGY");
    return "";
  }

  // *MAT_ENHANCED_COMPOSITE_DAMAGE (*MAT_054 / *MAT_055): the nine cards of the manual, every field
  // handed to the scene by its card name (the scene's MAT_054 reader checks what it implements).
  std::string mat_054(const Card& c, std::string&) {
    const bool is55 = c.keyword.rfind("MAT_055", 0) == 0;
    const FixedCards cards(c, is55 ? 6 : 9, skip());
    const Fields f1 = cards.fields(0, tens({"MID", "RO", "EA", "EB", "EC", "PRBA", "PRCA", "PRCB"}));
    Material& m = new_material(f1, c, is55 ? "MAT_055" : "MAT_054");
    auto all = [&](const Fields& f, std::initializer_list<const char*> names) {
      for (const char* n : names) put(m, f, n);
    };
    all(f1, {"RO", "EA", "EB", "EC", "PRBA", "PRCA", "PRCB"});
    const Fields f2 = cards.fields(1, tens({"GAB", "GBC", "GCA", "KF", "AOPT", "2WAY", "TI"}));
    all(f2, {"GAB", "GBC", "GCA", "KF", "2WAY", "TI"});
    const Fields f3 = cards.fields(2, tens({"XP", "YP", "ZP", "A1", "A2", "A3", "MANGLE"}));
    const Fields f4 = cards.fields(3, tens({"V1", "V2", "V3", "D1", "D2", "D3", "DFAILM", "DFAILS"}));
    const long aopt = f2.integer("AOPT", 0);
    if (aopt != 0 && aopt != 2 && aopt != 3) f2.fail("AOPT", "material axes option not implemented; allowed: 0, 2, 3");
    if (aopt != 0) m.fields.push_back({"AOPT", std::to_string(aopt)});
    all(f3, {"XP", "YP", "ZP", "A1", "A2", "A3", "MANGLE"});
    all(f4, {"V1", "V2", "V3", "D1", "D2", "D3", "DFAILM", "DFAILS"});
    all(cards.fields(4, tens({"TFAIL", "ALPH", "SOFT", "FBRT", "YCFAC", "DFAILT", "DFAILC", "EFS"})),
        {"TFAIL", "ALPH", "SOFT", "FBRT", "YCFAC", "DFAILT", "DFAILC", "EFS"});
    all(cards.fields(5, tens({"XC", "XT", "YC", "YT", "SC", "CRIT", "BETA"})), {"XC", "XT", "YC", "YT", "SC", "CRIT", "BETA"});
    if (!is55) {
      all(cards.fields(6, tens({"PFL", "EPSF", "EPSR", "TSMD", "SOFT2"})), {"PFL", "EPSF", "EPSR", "TSMD", "SOFT2"});
      all(cards.fields(7, tens({"SLIMT1", "SLIMC1", "SLIMT2", "SLIMC2", "SLIMS", "NCYRED", "SOFTG"})),
          {"SLIMT1", "SLIMC1", "SLIMT2", "SLIMC2", "SLIMS", "NCYRED", "SOFTG"});
      all(cards.fields(8, tens({"LCXC", "LCXT", "LCYC", "LCYT", "LCSC", "DT"})), {"LCXC", "LCXT", "LCYC", "LCYT", "LCSC", "DT"});
    }
    return "";
  }

  // *MAT_JOHNSON_COOK (*MAT_015): MID RO G E PR DTF VP RATEOP / A B N C M TM TR EPSO / CP PC SPALL IT
  // D1 D2 D3 D4 / D5 C2/P EROD EFMIN NUMINT K EPS1. The pressure comes from the part's EOSID; E and PR
  // (the card's shell fields) give the elastic bulk response of a part without one.
  std::string mat_johnson_cook(const Card& c, std::string&) {
    const FixedCards cards(c, 4, skip());
    const Fields f1 = cards.fields(0, tens({"MID", "RO", "G", "E", "PR", "DTF", "VP", "RATEOP"}));
    Material& m = new_material(f1, c, "MAT_015");
    m.takes_eos = true;
    for (const char* n : {"RO", "G"}) put(m, f1, n);
    for (const char* n : {"E", "PR"})
      if (!f1.blank(n)) m.without_eos.push_back({n, num(f1.real(n, 0))});
    f1.require_default("DTF", 0, "minimum step for shell deletion");
    flag(m, f1, "VP", {0, 1});
    f1.require_default("RATEOP", 0, "rate forms other than Johnson-Cook's log-linear one");
    const Fields f2 = cards.fields(1, tens({"A", "B", "N", "C", "M", "TM", "TR", "EPSO"}));
    for (const char* n : {"A", "B", "N", "C", "M", "TM", "TR"}) put(m, f2, n);
    epso(m, f2);
    const Fields f3 = cards.fields(2, tens({"CP", "PC", "SPALL", "IT", "D1", "D2", "D3", "D4"}));
    for (const char* n : {"CP", "PC", "D1", "D2", "D3", "D4"}) put(m, f3, n);
    flag(m, f3, "SPALL", {0, 1, 2, 3});
    flag(m, f3, "IT", {0, 1});
    const Fields f4 = cards.fields(3, tens({"D5", "C2/P", "EROD", "EFMIN", "NUMINT", "K", "EPS1"}));
    for (const char* n : {"D5", "EFMIN"}) put(m, f4, n);
    f4.require_default("C2/P", 0, "second rate parameter of RATEOP 1-5");
    if (f4.real("EROD", 0) != 0) m.fields.push_back({"EROD", "1"});  // any non-zero value: no erosion
    f4.require_default("NUMINT", 0, "shell integration points");
    f4.require_default("K", 0, "Couque rate term (RATEOP 5)");
    f4.require_default("EPS1", 0, "Couque rate term (RATEOP 5)");
    return "";
  }

  // *MAT_SIMPLIFIED_JOHNSON_COOK (*MAT_098): MID RO E PR VP EPPFR LCDM NUMINT / A B N C PSFAIL SIGMAX
  // SIGSAT EPSO. PSFAIL 1e17, SIGMAX and SIGSAT 1e28 are the card's "none" defaults.
  std::string mat_simplified_johnson_cook(const Card& c, std::string&) {
    const FixedCards cards(c, 2, skip());
    const Fields f1 = cards.fields(0, tens({"MID", "RO", "E", "PR", "VP", "EPPFR", "LCDM", "NUMINT"}));
    Material& m = new_material(f1, c, "MAT_098");
    for (const char* n : {"RO", "E", "PR"}) put(m, f1, n);
    flag(m, f1, "VP", {0, 1});
    f1.require_default("EPPFR", 0, "shell rupture strain");
    f1.require_default("LCDM", 0, "shell damage curve");
    f1.require_default("NUMINT", 0, "shell integration points");
    const Fields f2 = cards.fields(1, tens({"A", "B", "N", "C", "PSFAIL", "SIGMAX", "SIGSAT", "EPSO"}));
    for (const char* n : {"A", "B", "N", "C"}) put(m, f2, n);
    if (!f2.blank("PSFAIL") && f2.real("PSFAIL", 0) < 1e16) put(m, f2, "PSFAIL");
    for (const char* n : {"SIGMAX", "SIGSAT"})
      if (!f2.blank(n) && f2.real(n, 0) < 1e27) put(m, f2, n);
    epso(m, f2);
    return "";
  }

  // An integer option written as a real field ("2.0" is common on these cards), one of `allowed`.
  static void flag(Material& m, const Fields& f, const char* name, std::initializer_list<int> allowed) {
    if (f.blank(name)) return;
    const double v = f.real(name, 0);
    for (int a : allowed)
      if (v == a) {
        if (a != 0) m.fields.push_back({name, std::to_string(a)});
        return;
      }
    std::string list;
    for (int a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
    f.fail(name, "value not implemented; allowed: " + list);
  }

  // EPSO: the reference strain rate in the deck's time unit; no default is assumed when C uses it.
  static void epso(Material& m, const Fields& f) {
    if (!f.blank("EPSO")) put(m, f, "EPSO");
    else if (f.real("C", 0) != 0) f.fail("EPSO", "blank with a rate coefficient C; allowed: the reference strain rate (1 for seconds)");
  }

  // *EOS_LINEAR_POLYNOMIAL: EOSID C0 C1 C2 C3 C4 C5 C6 / E0 V0.
  std::string eos_linear_polynomial(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 2, skip());
    const Fields f1 = cards.fields(0, tens({"EOSID", "C0", "C1", "C2", "C3", "C4", "C5", "C6"}));
    Eos& e = new_eos(f1, c, "EOS_LINEAR_POLYNOMIAL");
    for (const char* n : {"C0", "C1", "C2", "C3", "C4", "C5", "C6"}) put_eos(e, f1, n);
    const Fields f2 = cards.fields(1, tens({"E0", "V0"}));
    put_eos(e, f2, "E0");
    if (!f2.blank("V0") && f2.real("V0", 1) != 1) f2.fail("V0", "initial relative volume other than 1 not implemented; allowed: blank or 1");
    return "";
  }

  // *EOS_GRUNEISEN: EOSID C S1 S2 S3 GAMAO A E0 / V0 (unused) LCID.
  std::string eos_gruneisen(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 2, skip());
    const Fields f1 = cards.fields(0, tens({"EOSID", "C", "S1", "S2", "S3", "GAMAO", "A", "E0"}));
    Eos& e = new_eos(f1, c, "EOS_GRUNEISEN");
    for (const char* n : {"C", "S1", "S2", "S3", "GAMAO", "A", "E0"}) put_eos(e, f1, n);
    const Fields f2 = cards.fields(1, tens({"V0", "UNUSED", "LCID"}));
    if (!f2.blank("V0") && f2.real("V0", 1) != 1) f2.fail("V0", "initial relative volume other than 1 not implemented; allowed: blank or 1");
    f2.require_default("LCID", 0, "energy deposition curve");
    return "";
  }

  Eos& new_eos(const Fields& f, const Card& c, const std::string& card) {
    const long id = f.integer("EOSID", 0);
    if (id <= 0) f.fail("EOSID", "an equation of state needs a positive id");
    if (eos_.count(id)) f.fail("EOSID", "equation of state id defined twice");
    Eos& e = eos_[id];
    e.card = card;
    e.where = &c;
    last_note_ = "the eos block of the MAT_015 material of every part with EOSID " + std::to_string(id);
    return e;
  }

  static void put_eos(Eos& e, const Fields& f, const char* name) {
    if (!f.blank(name)) e.fields.push_back({name, num(f.real(name, 0))});
  }

  // The eos block of material `mid` (MAT_015) from the EOSID of the parts using it, or E/PR
  // without one; a part's EOSID on another material, or two EOSIDs for one material, are refused.
  std::string eos_text(long mid, const Material& m) {
    long id = 0;
    const PartDef* first = nullptr;
    for (long pid : part_order_) {
      const PartDef& p = parts_.at(pid);
      if (p.mid != mid) continue;
      if (p.eosid != 0 && !m.takes_eos)
        refuse(p.where, "EOSID " + std::to_string(p.eosid) + " on a *" + m.card + " part; allowed: EOSID 0 (an equation of state only with *MAT_JOHNSON_COOK)");
      if (first && p.eosid != id)
        refuse(p.where, "parts " + std::to_string(first->pid) + " and " + std::to_string(pid) + " give material " +
                            std::to_string(mid) + " different EOSIDs; allowed: one equation of state per material");
      first = &p, id = p.eosid;
    }
    std::string out;
    if (id == 0) {
      for (const auto& [key, value] : m.without_eos) out += "    " + key + ": " + value + "\n";
      return out;
    }
    const auto e = eos_.find(id);
    if (e == eos_.end()) refuse(first->where, "EOSID " + std::to_string(id) + " is not defined by an *EOS card");
    used_eos_.insert(id);
    out = "    eos: {card: " + e->second.card;
    for (const auto& [key, value] : e->second.fields) out += ", " + key + ": " + value;
    return out + "}\n";
  }

  // ------------------------------------------------------------------ sets, curves

  // *SET_NODE_LIST / *SET_PART_LIST (Vol. I): SID DA1 DA2 DA3 DA4 SOLVER / ids, 8 per card.
  std::vector<long> read_list(const Card& c, long& sid) {
    const auto l = nonblank(c);
    if (l.empty()) throw InputError(msg() << where(c) << "a card with SID is needed");
    const Fields head(c, *l[0], tens({"SID", "DA1", "DA2", "DA3", "DA4", "SOLVER"}));
    sid = head.integer("SID", 0);
    if (sid <= 0) head.fail("SID", "a set needs a positive id");
    for (const char* n : {"DA1", "DA2", "DA3", "DA4"}) head.require_default(n, 0, "set attributes");
    if (!head.blank("SOLVER") && head.text("SOLVER") != "MECH") head.fail("SOLVER", "allowed: blank or MECH");
    std::vector<long> ids;
    for (std::size_t i = 1; i < l.size(); ++i) {
      const Fields f(c, *l[i], tens({"ID1", "ID2", "ID3", "ID4", "ID5", "ID6", "ID7", "ID8"}));
      for (int k = 1; k <= 8; ++k) {
        std::string name = "ID";
        name += char('0' + k);
        if (const long id = f.integer(name, 0); id > 0) ids.push_back(id);
        else if (id < 0) f.fail(name, "negative ids not supported");
      }
    }
    return ids;
  }

  std::string set_node_list(const Card& c, std::string& status) {
    status = "mapped";
    long sid = 0;
    auto ids = read_list(c, sid);
    if (!node_sets_.emplace(sid, std::move(ids)).second) throw InputError(msg() << where(c) << "node set " << sid << " defined twice");
    node_set_card_[sid] = &c;
    return "node set set_" + std::to_string(sid) + " (a physical point group of the .msh)";
  }

  std::string set_part_list(const Card& c, std::string& status) {
    status = "mapped";
    long sid = 0;
    auto ids = read_list(c, sid);
    if (!part_sets_.emplace(sid, std::move(ids)).second) throw InputError(msg() << where(c) << "part set " << sid << " defined twice");
    return "part list where a contact or initial velocity names it";
  }

  // *SET_SEGMENT: kept only to refuse its use (contacts here take parts, not segments).
  std::string set_segment(const Card& c, std::string& status) {
    status = "mapped";
    const auto l = nonblank(c);
    if (l.empty()) throw InputError(msg() << where(c) << "a card with SID is needed");
    const Fields head(c, *l[0], tens({"SID", "DA1", "DA2", "DA3", "DA4", "SOLVER"}));
    segment_sets_[head.integer("SID", 0)] = &c;
    return "not converted; a card that uses it is refused (contacts take parts here)";
  }

  // *DEFINE_CURVE (Vol. I): LCID SIDR SFA SFO OFFA OFFO DATTYP LCINT / A1 O1 (2 x 20 characters).
  std::string define_curve(const Card& c, std::string& status) {
    status = "mapped";
    const auto l = nonblank(c, skip());
    if (l.empty()) throw InputError(msg() << where(c) << "a card with LCID is needed");
    const Fields f(c, *l[0], tens({"LCID", "SIDR", "SFA", "SFO", "OFFA", "OFFO", "DATTYP", "LCINT"}));
    const long id = f.integer("LCID", 0);
    f.require_default("SIDR", 0, "dynamic relaxation");
    const double sfa = f.real("SFA", 1), sfo = f.real("SFO", 1);
    f.require_default("OFFA", 0, "abscissa offset");
    f.require_default("OFFO", 0, "ordinate offset");
    f.require_default("DATTYP", 0, "data type");
    f.require_default("LCINT", 0, "discretisation");
    Curve curve;
    curve.where = &c;
    for (std::size_t i = 1; i < l.size(); ++i) {
      const Fields p(c, *l[i], {{"A", 20}, {"O", 20}});
      const double t = sfa * p.real("A", 0);
      if (!curve.t.empty() && !(t > curve.t.back())) p.fail("A", "abscissae must increase");
      curve.t.push_back(t);
      curve.y.push_back(sfo * p.real("O", 0));
    }
    if (curve.t.empty()) f.fail("LCID", "a curve needs points");
    if (!curves_.emplace(id, curve).second) f.fail("LCID", "curve id defined twice");
    return "inline curve where used";
  }

  // ------------------------------------------------------------------ conditions

  // *BOUNDARY_SPC_SET / _NODE (Vol. I): NSID|NID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ.
  std::string boundary_spc(const Card& c, std::string& status) {
    status = "mapped";
    const bool by_set = c.keyword == "BOUNDARY_SPC_SET";
    std::map<std::array<bool, 3>, std::vector<long>> single;  // _NODE: nodes by dof pattern
    for (const DataLine* l : nonblank(c)) {
      const Fields f(c, *l, tens({"ID", "CID", "DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"}));
      const long id = f.integer("ID", 0);
      f.require_default("CID", 0, "local coordinate systems");
      std::array<bool, 3> fix{};
      const char* names[3] = {"DOFX", "DOFY", "DOFZ"};
      for (int d = 0; d < 3; ++d) {
        const long v = f.integer(names[d], 0);
        if (v != 0 && v != 1) f.fail(names[d], "allowed: 0 or 1");
        fix[d] = v == 1;
      }
      // Hexahedron nodes carry no rotations, so DOFR* constrain nothing on them; rigid parts'
      // nodes are refused below.
      for (const char* n : {"DOFRX", "DOFRY", "DOFRZ"})
        if (const long v = f.integer(n, 0); v != 0 && v != 1) f.fail(n, "allowed: 0 or 1");
      if (!fix[0] && !fix[1] && !fix[2]) f.fail("DOFX", "no translational dof constrained");
      if (by_set) bcs_.push_back(Bc{"set_" + std::to_string(id), fix, 0, 1, &c});
      else single[fix].push_back(id);
      if (by_set) spc_sets_.push_back({id, &c});
    }
    int k = 0;
    for (auto& [fix, nodes] : single) {
      const std::string name = "spc_" + std::to_string(c.line) + "_" + std::to_string(++k);
      generated_sets_[name] = nodes;
      bcs_.push_back(Bc{name, fix, 0, 1, &c});
    }
    return "boundary_conditions: fix (rotational dofs: none on hexahedron nodes)";
  }

  // *BOUNDARY_PRESCRIBED_MOTION_SET (Vol. I): NSID DOF VAD LCID SF VID DEATH BIRTH.
  std::string prescribed_motion(const Card& c, std::string& status) {
    status = "mapped";
    for (const DataLine* l : nonblank(c)) {
      const Fields f(c, *l, tens({"NSID", "DOF", "VAD", "LCID", "SF", "VID", "DEATH", "BIRTH"}));
      const long nsid = f.integer("NSID", 0), dof = f.integer("DOF", 0);
      if (dof < 1 || dof > 3) f.fail("DOF", "allowed: 1, 2 or 3 (x, y, z translation)");
      f.require_default("VAD", 0, "only velocity (0) is implemented");
      const long lcid = f.integer("LCID", 0);
      if (lcid <= 0) f.fail("LCID", "a curve id is needed");
      f.require_default("VID", 0, "direction vector");
      f.require_default("DEATH", 1e28, "death time");
      f.require_default("BIRTH", 0, "birth time");
      Bc bc{"set_" + std::to_string(nsid), {}, lcid, f.real("SF", 1), &c};
      bc.fix[std::size_t(dof - 1)] = true;
      bcs_.push_back(bc);
      spc_sets_.push_back({nsid, &c});
    }
    return "boundary_conditions: velocity curve (LCID x SF)";
  }

  // *INITIAL_VELOCITY (Vol. I): NSID NSIDEX BOXID IRIGID ICID / VX VY VZ VXR VYR VZR.
  std::string initial_velocity(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 2);
    const Fields f1 = cards.fields(0, tens({"NSID", "NSIDEX", "BOXID", "IRIGID", "ICID"}));
    for (const char* n : {"NSIDEX", "BOXID", "IRIGID", "ICID"}) f1.require_default(n, 0);
    const long nsid = f1.integer("NSID", 0);
    const Fields f2 = cards.fields(1, tens({"VX", "VY", "VZ", "VXR", "VYR", "VZR"}));
    for (const char* n : {"VXR", "VYR", "VZR"}) f2.require_default(n, 0, "rotational velocities");
    InitialVelocity v;
    v.where = &c;
    v.node_set = nsid == 0 ? "all_nodes" : "set_" + std::to_string(nsid);
    if (nsid != 0) spc_sets_.push_back({nsid, &c});
    v.v[0] = f2.real("VX", 0), v.v[1] = f2.real("VY", 0), v.v[2] = f2.real("VZ", 0);
    initial_.push_back(v);
    return nsid == 0 ? "initial_velocity on every node" : "initial_velocity on the node set";
  }

  // *INITIAL_VELOCITY_GENERATION (Vol. I): ID STYP OMEGA VX VY VZ IVATN ICID / XC YC ZC NX NY NZ
  // PHASE IRIGID. STYP 1 part set, 2 part, 3 node set; translation only (OMEGA 0).
  std::string initial_velocity_generation(const Card& c, std::string& status) {
    status = "mapped";
    for (std::size_t i = 0; i < c.lines.size();) {
      if (c.lines[i].text.find_first_not_of(" \t") == std::string::npos) {
        ++i;
        continue;
      }
      const Fields f(c, c.lines[i], tens({"ID", "STYP", "OMEGA", "VX", "VY", "VZ", "IVATN", "ICID"}));
      const DataLine blank{"", c.file, c.lines[i].line};
      const Fields g(c, i + 1 < c.lines.size() ? c.lines[i + 1] : blank,
                     tens({"XC", "YC", "ZC", "NX", "NY", "NZ", "PHASE", "IRIGID"}));
      i += 2;
      const long id = f.integer("ID", 0), styp = f.integer("STYP", 0);
      f.require_default("OMEGA", 0, "angular velocity");
      f.require_default("IVATN", 0, "slave/master velocities");
      f.require_default("ICID", 0, "local coordinate system");
      for (const char* n : {"XC", "YC", "ZC", "NX", "NY", "NZ", "PHASE", "IRIGID"}) g.require_default(n, 0, "rotation");
      InitialVelocity v;
      v.where = &c;
      v.v[0] = f.real("VX", 0), v.v[1] = f.real("VY", 0), v.v[2] = f.real("VZ", 0);
      if (styp == 1) {
        if (!part_sets_.count(id)) f.fail("ID", "no *SET_PART_LIST with this id");
        v.parts = part_sets_[id];
      } else if (styp == 2) {
        v.parts = {id};
      } else if (styp == 3) {
        v.node_set = "set_" + std::to_string(id);
        spc_sets_.push_back({id, &c});
      } else {
        f.fail("STYP", "allowed: 1 (part set), 2 (part) or 3 (node set)");
      }
      initial_.push_back(v);
    }
    return "initial_velocity on the parts or node set";
  }

  // ------------------------------------------------------------------ contact, walls

  // *CONTACT_... (Vol. I): [ID card] / SSID MSID SSTYP MSTYP SBOXID MBOXID SPR MPR /
  // FS FD DC VC VDC PENCHK BT DT / SFS SFM SST MST SFST SFMT FSF VSF / [ERODING: ISYM EROSOP IADJ] /
  // optional A: SOFT SOFSCL LCIDAB MAXPAR SBOPT DEPTH BSORT FRCFRQ / B: PENMAX THKOPT SHLTHK SNLOG
  // ISYM I2D3D SLDTHK SLDSTF / C: IGAP IGNORE DPRFAC DTSTIF.
  std::string contact(const Card& c, std::string& status) {
    status = "mapped";
    Contact k;
    k.single = c.keyword.find("SINGLE_SURFACE") != std::string::npos;
    k.eroding = c.keyword.find("ERODING") != std::string::npos;
    k.tiebreak = c.keyword.find("TIEBREAK") != std::string::npos;
    const std::size_t skip = contact_id_card_ ? 1 : 0;
    const std::size_t fixed = 3 + (k.eroding ? 1 : 0) + (k.tiebreak ? 1 : 0);
    const FixedCards cards(c, fixed + 3, skip);
    const Fields f1 = cards.fields(0, tens({"SSID", "MSID", "SSTYP", "MSTYP", "SBOXID", "MBOXID", "SPR", "MPR"}));
    auto side = [&](const char* id_name, const char* type_name, std::vector<long>& out) {
      const long id = f1.integer(id_name, 0), type = f1.integer(type_name, 0);
      if (type == 3) out = {id};
      else if (type == 2) {
        if (!part_sets_.count(id)) f1.fail(id_name, "no *SET_PART_LIST with this id");
        out = part_sets_[id];
      } else if (type == 0 && segment_sets_.count(id)) {
        f1.fail(type_name, "segment-set surfaces (*SET_SEGMENT) are not implemented; allowed: 2 (part set) or 3 (part)");
      } else {
        f1.fail(type_name, "allowed: 2 (part set) or 3 (part)");
      }
    };
    // Single surface: SSID 0 (or SSTYP 5) includes every part (manual, *CONTACT card 1, SSID EQ.0).
    if (k.single && (f1.integer("SSTYP", 0) == 5 || (f1.integer("SSID", 0) == 0 && f1.integer("SSTYP", 0) != 2 &&
                                                      f1.integer("SSTYP", 0) != 3)))
      k.all_parts = true;
    else
      side("SSID", "SSTYP", k.a);
    if (k.single) {
      f1.require_default("MSID", 0, "single surface");
      f1.require_default("MSTYP", 0, "single surface");
    } else {
      side("MSID", "MSTYP", k.b);
    }
    for (const char* n : {"SBOXID", "MBOXID", "SPR", "MPR"}) f1.require_default(n, 0, "boxes / force output flags");
    const Fields f2 = cards.fields(1, tens({"FS", "FD", "DC", "VC", "VDC", "PENCHK", "BT", "DT"}));
    auto put = [&](const Fields& f, const char* n) {
      if (!f.blank(n)) k.fields.push_back({n, num(f.real(n, 0))});
    };
    put(f2, "FS");
    put(f2, "FD");
    f2.require_default("DC", 0, "its unit (time/length) is not converted by the scene");
    f2.require_default("VC", 0, "viscous friction");
    put(f2, "VDC");
    f2.require_default("PENCHK", 0, "penetration check");
    f2.require_default("BT", 0, "birth time");
    f2.require_default("DT", 1e20, "death time");
    const Fields f3 = cards.fields(2, tens({"SFS", "SFM", "SST", "MST", "SFST", "SFMT", "FSF", "VSF"}));
    if (k.tiebreak) {
      // SST and MST set the tying distance of eq. 7.40; a tiebreak has no penalty scale factors here.
      for (const char* n : {"SFS", "SFM"}) f3.require_default(n, 1, "the tiebreak's stiffness is CN");
      for (const char* n : {"SST", "MST"})
        if (!f3.blank(n) && f3.real(n, 0) < 0) f3.fail(n, "a negative contact thickness (tying tolerance) is not implemented; allowed: >= 0");
      put(f3, "SST");
      put(f3, "MST");
    } else {
      put(f3, "SFS");
      put(f3, "SFM");
      for (const char* n : {"SST", "MST"}) f3.require_default(n, 0, "contact thickness");
    }
    for (const char* n : {"SFST", "SFMT", "FSF", "VSF"}) f3.require_default(n, 1, "scale factors");
    if (k.eroding) {
      const Fields e = cards.fields(3, tens({"ISYM", "EROSOP", "IADJ"}));
      e.require_default("ISYM", 0, "symmetry planes");
      // The scene's eroding contact adds the faces that erosion exposes (EROSOP 1).
      if (e.integer("EROSOP", 0) != 1) e.fail("EROSOP", "the eroding contact here always adds exposed faces; allowed: 1");
      e.require_default("IADJ", 0, "adjacent-material treatment");
    }
    if (k.tiebreak) {
      // Card 4 of the *_TIEBREAK contacts (Vol. I): OPTION NFLS SFLS PARAM ERATEN ERATES CT2CN CN.
      const Fields t = cards.fields(3, tens({"OPTION", "NFLS", "SFLS", "PARAM", "ERATEN", "ERATES", "CT2CN", "CN"}));
      const long option = t.integer("OPTION", 0);
      if (option != 6 && option != 7 && option != 9)
        t.fail("OPTION", "allowed: 6 (stress onset, linear softening), 7 (discrete crack, assumed law) or 9 "
                         "(bilinear mixed mode); docs/delamination.md");
      k.fields.push_back({"OPTION", std::to_string(option)});
      if (t.blank("CN"))
        t.fail("CN", "required: LS-DYNA's default (the penalty stiffness per segment area) is not implemented; "
                     "give the interface stiffness");
      for (const char* n : {"NFLS", "SFLS", "PARAM", "ERATEN", "ERATES", "CT2CN", "CN"}) put(t, n);
      for (std::size_t extra = fixed; extra < fixed + 3; ++extra)
        if (cards.has(extra)) t.fail("OPTION", "optional cards A-C after the tiebreak card are not implemented for tiebreak contacts");
    }
    if (!k.tiebreak && cards.has(fixed)) {
      const Fields a = cards.fields(fixed, tens({"SOFT", "SOFSCL", "LCIDAB", "MAXPAR", "SBOPT", "DEPTH", "BSORT", "FRCFRQ"}));
      if (!a.blank("SOFT")) k.fields.push_back({"SOFT", std::to_string(a.integer("SOFT", 0))});
      put(a, "SOFSCL");
      a.require_default("LCIDAB", 0, "airbag curve");
      put(a, "MAXPAR");
      a.require_default("SBOPT", 2, "SOFT 2 options");
      a.require_default("DEPTH", 2, "SOFT 2 search depth");
      if (!a.blank("BSORT")) k.fields.push_back({"BSORT", std::to_string(a.integer("BSORT", 0))});
      a.require_default("FRCFRQ", 1, "friction update");
    }
    if (!k.tiebreak && cards.has(fixed + 1)) {
      const Fields b = cards.fields(fixed + 1, tens({"PENMAX", "THKOPT", "SHLTHK", "SNLOG", "ISYM", "I2D3D", "SLDTHK", "SLDSTF"}));
      put(b, "PENMAX");
      for (const char* n : {"THKOPT", "SHLTHK", "SNLOG", "ISYM", "I2D3D", "SLDTHK", "SLDSTF"}) b.require_default(n, 0);
    }
    if (!k.tiebreak && cards.has(fixed + 2)) {
      const Fields cc = cards.fields(fixed + 2, tens({"IGAP", "IGNORE", "DPRFAC", "DTSTIF", "U5", "U6", "FLANGL", "CID_RCF"}));
      cc.require_default("IGAP", 1, "gap option");
      const long ignore = cc.integer("IGNORE", 0);
      if (ignore == 1) k.fields.push_back({"initial_penetration", "offset"});
      else if (ignore != 0) cc.fail("IGNORE", "allowed: 0 (move nodes out) or 1 (track as offset)");
      cc.require_default("DPRFAC", 0);
      put(cc, "DTSTIF");
      for (const char* n : {"U5", "U6", "FLANGL", "CID_RCF"}) cc.require_default(n, 0);
    }
    contacts_.push_back(std::move(k));
    contact_cards_.push_back(&c);
    return "contacts: contact_" + std::to_string(contacts_.size());
  }

  // *RIGIDWALL_PLANAR (Vol. I): NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF / XT YT ZT XH YH ZH FRIC WVEL.
  std::string rigidwall_planar(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 2);
    const Fields f1 = cards.fields(0, tens({"NSID", "NSIDEX", "BOXID", "OFFSET", "BIRTH", "DEATH", "RWKSF"}));
    f1.require_default("NSID", 0, "node set slaves; 0 = every node, i.e. every deformable part here");
    for (const char* n : {"NSIDEX", "BOXID", "OFFSET", "BIRTH"}) f1.require_default(n, 0);
    f1.require_default("DEATH", 1e20, "death time");
    f1.require_default("RWKSF", 1, "stiffness scale");
    const Fields f2 = cards.fields(1, tens({"XT", "YT", "ZT", "XH", "YH", "ZH", "FRIC", "WVEL"}));
    const double t[3] = {f2.real("XT", 0), f2.real("YT", 0), f2.real("ZT", 0)};
    const double n[3] = {f2.real("XH", 0) - t[0], f2.real("YH", 0) - t[1], f2.real("ZH", 0) - t[2]};
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) f2.fail("XH", "head and tail coincide: no normal");
    const double fric = f2.real("FRIC", 0);
    if (fric < 0 || fric >= 1) f2.fail("FRIC", "allowed: 0 <= FRIC < 1 (Coulomb; 1 = stick is not implemented)");
    f2.require_default("WVEL", 0, "welding");
    walls_.push_back("{name: wall_" + std::to_string(walls_.size() + 1) + ", point: " + vec(t[0], t[1], t[2]) +
                     ", normal: " + vec(n[0], n[1], n[2]) + (fric > 0 ? ", friction: " + num(fric) : "") + "}");
    return "rigid_walls: wall_" + std::to_string(walls_.size());
  }

  // *DATABASE_BINARY_D3PLOT: DT LCDT BEAM NPLTC PSETID; *DATABASE_GLSTAT/_RCFORC/_MATSUM: DT BINARY LCUR IOOPT.
  std::string database(const Card& c, std::string& status) {
    status = "mapped";
    const FixedCards cards(c, 1);
    if (c.keyword == "DATABASE_BINARY_D3PLOT") {
      const Fields f = cards.fields(0, tens({"DT", "LCDT", "BEAM", "NPLTC", "PSETID"}));
      frame_dt_ = f.real("DT", 0);
      if (!(frame_dt_ > 0)) f.fail("DT", "a positive interval is needed");
      for (const char* n : {"LCDT", "BEAM", "NPLTC", "PSETID"}) f.require_default(n, 0);
      return "output: interval (VTU frames)";
    }
    const Fields f = cards.fields(0, tens({"DT", "BINARY", "LCUR", "IOOPT"}));
    const double dt = f.real("DT", 0);
    if (!(dt > 0)) f.fail("DT", "a positive interval is needed");
    if (history_dt_ > 0 && dt != history_dt_)
      f.fail("DT", "another interval than an earlier *DATABASE card; allowed: one history interval (history.csv)");
    history_dt_ = dt;
    if (!f.blank("BINARY") && f.integer("BINARY", 1) != 1) f.fail("BINARY", "allowed: blank or 1 (ASCII); history.csv is written");
    f.require_default("LCUR", 0);
    f.require_default("IOOPT", 1);
    return "output: history_interval (history.csv)";
  }

  // ------------------------------------------------------------------ emission

  std::string part_name(long pid) const { return "part_" + std::to_string(pid); }

  const PartDef& part_of(long pid, const Card* card) {
    const auto it = parts_.find(pid);
    if (it == parts_.end()) refuse(card, "part " + std::to_string(pid) + " is not defined by a *PART");
    return it->second;
  }

  std::string section_of(const PartDef& p) {
    if (!sections_.count(p.secid)) refuse(p.where, "section " + std::to_string(p.secid) + " is not defined");
    if (p.hgid && !hourglass_.count(p.hgid)) refuse(p.where, "hourglass " + std::to_string(p.hgid) + " is not defined");
    const std::string name = "sec_" + std::to_string(p.secid) + (p.hgid ? "_hg" + std::to_string(p.hgid) : "");
    if (!emitted_sections_.count(name)) {
      Hourglass h;
      h.ihq = control_ihq_;
      h.qm = control_qh_;
      if (p.hgid) {
        const Hourglass& g = hourglass_.at(p.hgid);
        h.ihq = g.ihq ? g.ihq : control_ihq_;
        h.qm = g.qm;
        h.q1 = g.q1_set ? g.q1 : bulk_q1_;
        h.q2 = g.q2_set ? g.q2 : bulk_q2_;
      } else {
        h.q1 = bulk_q1_;
        h.q2 = bulk_q2_;
      }
      emitted_sections_[name] = "{ELFORM: " + std::to_string(sections_.at(p.secid)) + ", IHQ: " + std::to_string(h.ihq) +
                                ", QM: " + num(h.qm) + ", Q1: " + num(h.q1) + ", Q2: " + num(h.q2) + "}";
    }
    return name;
  }

  std::vector<std::string> part_names(const std::vector<long>& ids, const Card* card) {
    std::vector<std::string> out;
    for (long id : ids) out.push_back(part_name(part_of(id, card).pid));
    return out;
  }

  std::string curve_text(long lcid, double sf, const Card* card) {
    const auto it = curves_.find(lcid);
    if (it == curves_.end()) refuse(card, "curve " + std::to_string(lcid) + " is not defined by a *DEFINE_CURVE");
    const Curve& c = it->second;
    // The scene holds a curve's end values beyond its ends; require the curve to span the run.
    if (c.t.front() > 0 || c.t.back() < endtim_)
      refuse(card, "curve " + std::to_string(lcid) + " spans [" + num(c.t.front()) + ", " + num(c.t.back()) +
                       "]; allowed: a curve from time <= 0 to ENDTIM or later (no extrapolation)");
    std::string s;
    for (std::size_t i = 0; i < c.t.size(); ++i) s += std::string(i ? ", " : "") + "[" + num(c.t[i]) + ", " + num(sf * c.y[i]) + "]";
    return "[" + s + "]";
  }

  void emit() {
    std::ostringstream y;
    y << "# Converted from an LS-DYNA keyword deck by plyimpact convert (units as stated by the user).\n";
    if (!title_.empty()) y << "# *TITLE: " << title_ << "\n";
    if (!(endtim_ > 0)) refuse(nullptr, "no *CONTROL_TERMINATION with ENDTIM; allowed: a deck with a termination time");
    y << "units: " << units_.name << "\n";
    y << "control:\n  termination_time: " << num(endtim_) << "\n  tssfac: " << num(tssfac_) << "\n";
    if (dtmin_ > 0) y << "  dt_min_ratio: " << num(dtmin_) << "\n";
    if (dt2ms_ < 0) y << "  dt2ms: " << num(dt2ms_) << "\n";
    if (endmas_ > 0 && dt2ms_ < 0) y << "  endmas: " << num(endmas_) << "\n";
    if (endcyc_ > 0) y << "  max_cycles: " << endcyc_ << "\n";
    if (frame_dt_ > 0 || history_dt_ > 0) {
      y << "output:\n";
      if (frame_dt_ > 0) y << "  interval: " << num(frame_dt_) << "\n";
      if (history_dt_ > 0) y << "  history_interval: " << num(history_dt_) << "\n";
    }
    // Materials, sections and parts in part order.
    std::ostringstream mats, secs, parts;
    std::set<long> used_mats;
    for (long pid : part_order_) {
      const PartDef& p = parts_.at(pid);
      const auto m = materials_.find(p.mid);
      if (m == materials_.end()) refuse(p.where, "material " + std::to_string(p.mid) + " is not defined");
      if (used_mats.insert(p.mid).second) {
        mats << "  mat_" << p.mid << ":\n    card: " << m->second.card << "\n";
        for (const auto& [key, value] : m->second.fields) mats << "    " << key << ": " << value << "\n";
        if (m->second.takes_eos) mats << eos_text(p.mid, m->second);
        else eos_text(p.mid, m->second);  // refuses an EOSID on its parts
        if (m->second.lcss > 0) {
          const auto& curve = curves_.find(m->second.lcss);
          if (curve == curves_.end()) refuse(m->second.where, "LCSS curve " + std::to_string(m->second.lcss) + " is not defined");
          std::string s;
          for (std::size_t i = 0; i < curve->second.t.size(); ++i)
            s += std::string(i ? ", " : "") + "[" + num(curve->second.t[i]) + ", " + num(curve->second.y[i]) + "]";
          mats << "    LCSS: [" << s << "]\n";
        }
      }
      const std::string sec = section_of(p);
      parts << "  " << part_name(pid) << ": {id: " << pid << ", material: mat_" << p.mid << ", section: " << sec << "}";
      if (!p.heading.empty() && p.heading.find_first_not_of(' ') != std::string::npos) parts << "  # " << p.heading;
      parts << "\n";
    }
    for (const auto& [id, m] : materials_)
      if (!used_mats.count(id)) refuse(m.where, "material " + std::to_string(id) + " is used by no part (not converted)");
    for (const auto& [id, e] : eos_)
      if (!used_eos_.count(id)) refuse(e.where, "equation of state " + std::to_string(id) + " is used by no *MAT_JOHNSON_COOK part (not converted)");
    y << "materials:\n" << mats.str() << "sections:\n";
    for (const auto& [name, text] : emitted_sections_) y << "  " << name << ": " << text << "\n";
    y << "parts:\n" << parts.str();
    y << "mesh: {file: " << options_.mesh_file_name << ", length_unit: m}\n";
    build_mesh();
    // Node sets: every set a condition names, from the .msh's point groups.
    std::set<std::string> sets;
    for (const auto& bc : bcs_) sets.insert(bc.set);
    bool all_nodes = false;
    for (const auto& v : initial_)
      if (v.node_set == "all_nodes") all_nodes = true;
      else if (!v.node_set.empty()) sets.insert(v.node_set);
    if (!sets.empty() || all_nodes) {
      y << "node_sets:\n";
      if (all_nodes) y << "  all_nodes: all\n";
      for (const auto& s : sets) y << "  " << s << ": from_mesh\n";
    }
    if (!bcs_.empty()) {
      y << "boundary_conditions:\n";
      for (const auto& bc : bcs_) {
        std::vector<std::string> dofs;
        for (int d = 0; d < 3; ++d)
          if (bc.fix[std::size_t(d)]) dofs.push_back(std::string(1, "xyz"[d]));
        if (bc.lcid == 0) y << "  - {node_set: " << bc.set << ", fix: [" << join(dofs) << "]}\n";
        else y << "  - {node_set: " << bc.set << ", velocity: {dofs: [" << join(dofs) << "], curve: " << curve_text(bc.lcid, bc.sf, bc.where) << "}}\n";
      }
    }
    if (!initial_.empty()) {
      y << "initial_velocity:\n";
      for (const auto& v : initial_) {
        if (!v.node_set.empty()) y << "  - {node_set: " << v.node_set << ", velocity: " << vec(v.v[0], v.v[1], v.v[2]) << "}\n";
        for (const auto& name : part_names(v.parts, v.where))
          y << "  - {part: " << name << ", velocity: " << vec(v.v[0], v.v[1], v.v[2]) << "}\n";
      }
    }
    if (!walls_.empty()) {
      y << "rigid_walls:\n";
      for (const auto& w : walls_) y << "  - " << w << "\n";
    }
    if (!contacts_.empty()) {
      y << "contacts:\n";
      for (std::size_t i = 0; i < contacts_.size(); ++i) {
        const Contact& k = contacts_[i];
        const std::string type = k.tiebreak ? std::string("tiebreak_surface_to_surface")
                                            : std::string(k.eroding ? "eroding" : "automatic") +
                                                  (k.single ? "_single_surface" : "_surface_to_surface");
        y << "  - name: contact_" << i + 1 << "\n    type: " << type << "\n";
        const auto a = k.all_parts ? part_names(part_order_, contact_cards_[i]) : part_names(k.a, contact_cards_[i]);
        if (k.single) y << "    parts: [" << join(a) << "]\n";
        else y << "    surfaces: [[" << join(a) << "], [" << join(part_names(k.b, contact_cards_[i])) << "]]\n";
        for (const auto& [key, value] : k.fields) y << "    " << key << ": " << value << "\n";
      }
    }
    out_.yaml = y.str();
  }

  void build_mesh() {
    mesh::Mesh& m = out_.mesh;
    std::map<long, int> part_index;
    for (long pid : part_order_) {
      config::PartSpec ps;
      ps.name = part_name(pid);
      ps.id = int(pid);
      part_index[pid] = int(out_.parts.size());
      out_.parts.push_back(ps);
    }
    // Nodes of no element carry no mass and take no part in the run: left out.
    std::set<long> used;
    for (const auto& [eid, e] : elements_) used.insert(e.n, e.n + 8);
    std::map<long, Index> index;
    for (const auto& [nid, x] : nodes_) {
      if (!used.count(nid)) continue;
      index[nid] = Index(index.size());
      for (double c : x) m.coords.push_back(c * units_.length);
    }
    if (index.size() < nodes_.size())
      for (auto& e : out_.coverage)
        if (e.keyword == "NODE")
          e.note += msg() << "; " << nodes_.size() - index.size() << " node(s) of no element left out (no mass, no effect)";
    for (const auto& [eid, e] : elements_) {
      const auto p = part_index.find(e.pid);
      if (p == part_index.end())
        throw Refusal{element_card_of(e), where_line(e) + "element " + std::to_string(eid) + ": part " + std::to_string(e.pid) + " is not defined by a *PART"};
      for (long n : e.n) {
        const auto it = index.find(n);
        if (it == index.end())
          throw Refusal{element_card_of(e), where_line(e) + "element " + std::to_string(eid) + ": node " + std::to_string(n) + " is not defined by a *NODE"};
        m.hex.push_back(it->second);
      }
      m.element_part.push_back(p->second);
    }
    auto to_list = [&](const std::string& name, const std::vector<long>& ids, const Card* card) {
      mesh::NodeList l{name, {}};
      for (long id : ids) {
        const auto it = index.find(id);
        if (it == index.end())
          refuse(card, "node " + std::to_string(id) + " of " + name + " is not a node of any element");
        l.nodes.push_back(it->second);
      }
      m.node_sets.push_back(std::move(l));
    };
    std::set<long> wanted;
    for (const auto& [id, card] : spc_sets_) {
      if (!node_sets_.count(id)) refuse(card, "node set " + std::to_string(id) + " is not defined by a *SET_NODE_LIST");
      wanted.insert(id);
    }
    for (long id : wanted) to_list("set_" + std::to_string(id), node_sets_.at(id), node_set_card_.at(id));
    for (const auto& [name, ids] : generated_sets_) to_list(name, ids, nullptr);
    // Constraints on rigid-part nodes would fight the rigid body (use MAT_020 CMO/CON1/CON2).
    std::vector<char> rigid(m.num_nodes(), 0);
    for (std::size_t e = 0; e < m.num_elements(); ++e) {
      const PartDef& p = parts_.at(out_.parts[std::size_t(m.element_part[e])].id);
      if (materials_.count(p.mid) && materials_.at(p.mid).rigid)
        for (int k = 0; k < 8; ++k) rigid[std::size_t(m.hex[8 * e + k])] = 1;
    }
    for (const auto& bc : bcs_)
      for (const auto& l : m.node_sets)
        if (l.name == bc.set)
          for (Index n : l.nodes)
            if (rigid[std::size_t(n)]) refuse(bc.where, "node set " + bc.set + " holds nodes of a MAT_RIGID part; allowed: constrain rigid bodies with CMO/CON1/CON2");
  }

  struct Element {
    long pid = 0;
    long n[8] = {};
    const DataLine* line = nullptr;
  };
  const Card* element_card_of(const Element& e) const {
    for (const auto& [card, idx] : entry_of_)
      if (card->keyword == "ELEMENT_SOLID")
        for (const auto& l : card->lines)
          if (&l == e.line) return card;
    return nullptr;
  }
  static std::string where_line(const Element& e) { return msg() << e.line->file << ":" << e.line->line << ": *ELEMENT_SOLID: "; }

  ConvertOptions options_;
  units::UnitSystem units_;
  Conversion out_;
  std::map<const Card*, std::size_t> entry_of_;
  bool title_line_ = false, contact_id_card_ = false;
  std::string last_note_;  // a handler's note when it returns none
  std::string title_;
  std::map<long, std::array<double, 3>> nodes_;
  std::map<long, Element> elements_;
  std::map<long, PartDef> parts_;
  std::vector<long> part_order_;
  std::map<long, long> sections_;
  std::map<long, Hourglass> hourglass_;
  long control_ihq_ = 2;  // explicit default for solids (see control_hourglass)
  double control_qh_ = 0.1, bulk_q1_ = 1.5, bulk_q2_ = 0.06;
  double endtim_ = 0, dtmin_ = 0, tssfac_ = 0.9, frame_dt_ = 0, history_dt_ = 0, dt2ms_ = 0, endmas_ = 0;
  long endcyc_ = 0;
  std::map<long, Material> materials_;
  std::map<long, Eos> eos_;
  std::set<long> used_eos_;
  std::map<long, std::vector<long>> node_sets_, part_sets_;
  std::map<long, const Card*> node_set_card_, segment_sets_;
  std::map<long, Curve> curves_;
  std::vector<Bc> bcs_;
  std::vector<std::pair<long, const Card*>> spc_sets_;
  std::map<std::string, std::vector<long>> generated_sets_;
  std::vector<InitialVelocity> initial_;
  std::vector<Contact> contacts_;
  std::vector<const Card*> contact_cards_;
  std::vector<std::string> walls_;
  std::map<std::string, std::string> emitted_sections_;
};

}  // namespace

bool Conversion::refused() const {
  return std::any_of(coverage.begin(), coverage.end(), [](const CoverageEntry& e) { return e.status == "refused"; });
}

Conversion convert_deck(const Deck& deck, const ConvertOptions& options) { return Converter(options).run(deck); }

std::string coverage_table(const Conversion& c) {
  std::ostringstream out;
  std::size_t w = 8;
  for (const auto& e : c.coverage) w = std::max(w, e.keyword.size() + 1);
  std::map<std::string, int> counts;
  for (const auto& e : c.coverage) {
    char head[64];
    std::snprintf(head, sizeof head, "%s:%d", std::filesystem::path(e.file).filename().string().c_str(), e.line);
    out << head << std::string(head[0] && std::strlen(head) < 24 ? 24 - std::strlen(head) : 1, ' ') << "*" << e.keyword
        << std::string(w - e.keyword.size(), ' ') << e.status << std::string(9 - e.status.size(), ' ') << e.note << "\n";
    ++counts[e.status];
  }
  out << c.coverage.size() << " cards: " << counts["used"] << " used, " << counts["mapped"] << " mapped, "
      << counts["refused"] << " refused\n";
  return out.str();
}

std::string refusals(const Conversion& c) {
  std::string out;
  for (const auto& e : c.coverage)
    if (e.status == "refused") out += e.note + "\n";
  return out;
}

Conversion convert_deck_file(const std::string& deck_path, const std::string& unit_system,
                             const std::filesystem::path& yaml_path) {
  const Deck deck = read_deck(deck_path);
  ConvertOptions o{unit_system, yaml_path.stem().string() + ".msh"};
  Conversion c = convert_deck(deck, o);
  if (c.refused())
    throw InputError(msg() << deck_path << ": the deck uses what this reader does not implement (nothing is dropped "
                              "silently; `--coverage` lists every card):\n" << refusals(c));
  std::error_code ec;
  if (!yaml_path.parent_path().empty()) std::filesystem::create_directories(yaml_path.parent_path(), ec);
  config::Scene parts_only;
  parts_only.parts = c.parts;
  mesh::write_msh(parts_only, c.mesh, (yaml_path.parent_path() / o.mesh_file_name).string());
  output::write_text_atomically(yaml_path, c.yaml);
  return c;
}

}  // namespace plyimpact::keyword
