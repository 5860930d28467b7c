// Reader: typed, located access to a YAML node. See yaml_reader.hpp.
#include "config/yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <set>
#include <sstream>

#include "core/error.hpp"

namespace plyimpact::config::detail {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

}  // namespace

bool Limits::ok(double v) const {
  if (lo && (lo_open ? !(v > *lo) : !(v >= *lo))) return false;
  if (hi && (hi_open ? !(v < *hi) : !(v <= *hi))) return false;
  return true;
}

std::string Limits::text() const {
  if (lo && hi)
    return msg() << "in " << (lo_open ? "(" : "[") << fmt(*lo) << ", " << fmt(*hi) << (hi_open ? ")" : "]");
  if (lo) return msg() << (lo_open ? "> " : ">= ") << fmt(*lo);
  if (hi) return msg() << (hi_open ? "< " : "<= ") << fmt(*hi);
  return "any value";
}

std::string location(const std::string& file, const YAML::Mark& mark) {
  if (mark.is_null()) return file;
  return msg() << file << ":" << mark.line + 1 << ":" << mark.column + 1;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = 3;
  const std::string w = lower(word);
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(w, lower(c));
    if (d < best_d && d < w.size()) {  // "q" -> "x" is no suggestion
      best_d = d;
      best = c;
    }
  }
  return best;
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "(none defined)" : out;
}

Reader::Reader(YAML::Node node, std::string path, const Context* ctx, YAML::Mark fallback, YAML::Mark key_mark)
    : node_(std::move(node)), path_(std::move(path)), ctx_(ctx), fallback_(fallback), key_mark_(key_mark) {}

const std::string* Reader::override_origin() const {
  if (!node_.IsDefined()) return nullptr;
  for (const auto& o : ctx_->override_nodes)
    if (o.node.is(node_)) return &o.origin;
  return nullptr;
}

std::string Reader::location_text() const {
  if (const std::string* origin = override_origin()) return *origin;
  return location(ctx_->file, mark());
}

YAML::Mark Reader::mark() const {
  if (override_origin()) return YAML::Mark::null_mark();  // no file position; where() names the override
  const bool empty = !node_.IsDefined() || node_.IsNull();
  if (empty && !key_mark_.is_null()) return key_mark_;
  const YAML::Mark m = node_.IsDefined() ? node_.Mark() : YAML::Mark::null_mark();
  return m.is_null() ? fallback_ : m;
}

SourceLocation Reader::where() const {
  if (const std::string* origin = override_origin()) return {*origin, 0, 0, path_};
  const YAML::Mark m = mark();
  return {ctx_->file, m.is_null() ? 0 : m.line + 1, m.is_null() ? 0 : m.column + 1, path_};
}

void Reader::fail(const std::string& what, const std::string& allowed) const {
  fail(what, found_text(), allowed);
}

void Reader::fail(const std::string& what, const std::string& found, const std::string& allowed) const {
  throw InputError(msg() << location_text() << ": " << (path_.empty() ? "(top level)" : path_)
                         << ": " << what << "; found " << found << "; allowed " << allowed);
}

std::string Reader::found_text() const {
  if (!node_.IsDefined() || node_.IsNull()) return "an empty value";
  if (node_.IsScalar()) return quoted(node_.Scalar());
  if (node_.IsSequence() && node_.size() > 0 && node_.size() <= 6 &&
      std::all_of(node_.begin(), node_.end(), [](const YAML::Node& n) { return n.IsScalar(); })) {
    std::string out = "[";
    for (std::size_t i = 0; i < node_.size(); ++i) out += (i ? ", " : "") + node_[i].Scalar();
    return out + "]";
  }
  if (node_.IsSequence()) return msg() << "a list of " << node_.size() << " item" << (node_.size() == 1 ? "" : "s");
  std::vector<std::string> keys;
  for (auto it = node_.begin(); it != node_.end(); ++it)
    keys.push_back(it->first.IsScalar() ? it->first.Scalar() : "?");
  if (keys.empty()) return "an empty mapping";
  return "a mapping with keys [" + join(keys) + "]";
}

void Reader::require_map(const std::string& expected) const {
  if (!node_.IsMap()) fail("wrong type, expected a mapping", expected);
}

void Reader::require_list(const std::string& expected, bool non_empty) const {
  if (!node_.IsSequence()) fail("wrong type, expected a list", expected);
  if (non_empty && node_.size() == 0) fail("the list must not be empty", expected);
}

void Reader::require_scalar(const std::string& expected) const {
  if (!node_.IsScalar()) fail(node_.IsNull() ? "missing value" : "wrong type, expected a single value", expected);
}

void Reader::allow_keys(std::initializer_list<std::string_view> allowed) const {
  const std::vector<std::string> names(allowed.begin(), allowed.end());
  std::set<std::string> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const Reader key = child(it->first, path_);
    if (!it->first.IsScalar()) key.fail("a key must be a plain name", join(names));
    const std::string& k = it->first.Scalar();
    const std::string key_path = path_.empty() ? k : path_ + "." + k;
    const Reader located(it->first, key_path, ctx_, mark());
    if (std::find(names.begin(), names.end(), k) == names.end()) {
      const std::string hint = did_you_mean(k, names);
      located.fail("unknown key " + quoted(k) + (hint.empty() ? "" : " (did you mean " + quoted(hint) + "?)"),
                   "keys " + join(names));
    }
    if (!seen.insert(k).second) located.fail("duplicate key " + quoted(k), "each key once");
  }
}

bool Reader::has(std::string_view key) const { return find(key).has_value(); }

Reader Reader::at(std::string_view key, const std::string& expected) const {
  if (auto r = find(key)) return *r;
  const std::string key_path = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  throw InputError(msg() << location_text() << ": " << key_path << ": missing required key "
                         << quoted(key) << "; found " << found_text() << "; allowed " << expected);
}

std::optional<Reader> Reader::find(std::string_view key) const {
  if (!node_.IsMap()) return std::nullopt;
  for (auto it = node_.begin(); it != node_.end(); ++it)  // first match, as node[key] would
    if (it->first.IsScalar() && it->first.Scalar() == key) {
      Reader r = child(it->second, path_.empty() ? std::string(key) : path_ + "." + std::string(key), it->first.Mark());
      ctx_->key_locations[r.path()] = r.where();
      return r;
    }
  return std::nullopt;
}

std::string Reader::exactly_one(std::initializer_list<std::string_view> keys) const {
  std::vector<std::string> names(keys.begin(), keys.end()), present;
  for (const auto& k : names)
    if (has(k)) present.push_back(k);
  if (present.size() != 1) {
    std::string alternatives;
    for (std::size_t i = 0; i < names.size(); ++i)
      alternatives += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + quoted(names[i]);
    fail(present.empty() ? "needs one of " + alternatives : "needs exactly one of " + alternatives + ", not several",
         "exactly one of " + alternatives);
  }
  return present.front();
}

Reader Reader::child(const YAML::Node& n, std::string path, YAML::Mark key_mark) const {
  return Reader(n, std::move(path), ctx_, mark(), key_mark);
}

std::vector<std::pair<std::string, Reader>> Reader::entries() const {
  std::vector<std::pair<std::string, Reader>> out;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (!it->first.IsScalar()) child(it->first, path_).fail("a name must be a plain string", "plain names");
    const std::string k = it->first.Scalar();
    out.emplace_back(k, child(it->second, path_.empty() ? k : path_ + "." + k, it->first.Mark()));
  }
  return out;
}

std::vector<Reader> Reader::items() const {
  std::vector<Reader> out;
  for (std::size_t i = 0; i < node_.size(); ++i) out.push_back(child(node_[i], msg() << path_ << "[" << i << "]"));
  return out;
}

std::string Reader::as_name() const {
  require_scalar("a name");
  if (node_.Scalar().empty()) fail("empty name", "a non-empty name");
  return node_.Scalar();
}

double Reader::as_quantity(units::Dimension d, const Limits& lim) const {
  const std::string allowed = d == units::dimensionless
                                  ? std::string("a plain number")
                                  : "a plain number (scene units, " + ctx_->unit_system.name +
                                        ") or '<number> <unit>' for " + units::describe(d);
  require_scalar(allowed);
  double v = 0;
  try {
    v = units::quantity_to_si(node_.Scalar(), d, ctx_->unit_system);
  } catch (const units::UnitError& e) {
    fail(e.problem(), e.allowed());
  }
  const std::string key = path_.substr(path_.rfind('.') + 1);
  if (!lim.ok(v)) {
    const std::string label = lim.label.empty() ? "the value" : lim.label;
    fail(label + " must be " + lim.text(), msg() << quoted(node_.Scalar()) << " (= " << fmt(v) << " SI)",
         msg() << key << " " << lim.text());
  }
  if (const auto kind = lim.kind ? lim.kind : default_kind(d)) {
    const PlausibleRange& range = plausible_range(*kind);
    if (!is_plausible(v, range))
      fail(msg() << fmt(v) << (*range.unit ? " " : "") << range.unit << " is outside the plausible range of "
                 << range.name,
           msg() << quoted(node_.Scalar()) << " (= " << fmt(v) << " SI)",
           msg() << key << " with " << range_text(range) << " (SI; " << range.reason
                 << "; see 'Input limits' in docs/commands.md)");
  }
  return v;
}

double Reader::as_angle() const {
  require_scalar("an angle: a number in degrees, or '<number> deg' / '<number> rad'");
  try {
    return units::angle_to_rad(node_.Scalar());
  } catch (const units::UnitError& e) {
    fail(e.problem(), e.allowed());
  }
}

long Reader::as_integer(const Limits& lim) const {
  const std::string allowed = lim.lo || lim.hi ? "an integer " + lim.text() : "an integer";
  require_scalar(allowed);
  long v = 0;
  try {
    v = units::parse_integer(node_.Scalar());
  } catch (const units::UnitError&) {
    const std::string& s = node_.Scalar();
    const bool digits = s.find_first_not_of("+-0123456789 ") == std::string::npos &&
                        s.find_first_of("0123456789") != std::string::npos;
    fail(digits ? "the integer is too large to represent" : "expected an integer", allowed);
  }
  if (!lim.ok(static_cast<double>(v)))
    fail((lim.label.empty() ? "the value" : lim.label) + " must be " + lim.text(), allowed);
  return v;
}

int Reader::as_int(const Limits& lim) const {
  const long v = as_integer(lim);
  Limits l = lim;  // the key's own bounds, cut to what an int holds
  if (!l.lo || *l.lo < double(INT_MIN)) l.lo = double(INT_MIN), l.lo_open = false;
  if (!l.hi || *l.hi > double(INT_MAX)) l.hi = double(INT_MAX), l.hi_open = false;
  if (!l.ok(double(v)))
    fail((lim.label.empty() ? "the value" : lim.label) + " is out of range (it would wrap around)",
         "an integer " + l.text());
  return static_cast<int>(v);
}

Vec3 Reader::as_vec3(units::Dimension d, const Limits& lim) const {
  require_list("a list of 3 numbers [x, y, z], each a number or '<number> <unit>' for " + units::describe(d), false);
  if (node_.size() != 3) fail("expected exactly 3 components", "a list [x, y, z]");
  const auto it = items();
  return {it[0].as_quantity(d, lim), it[1].as_quantity(d, lim), it[2].as_quantity(d, lim)};
}

std::string Reader::as_choice(const std::vector<std::string>& choices) const {
  require_scalar("one of " + join(choices));
  const std::string& s = node_.Scalar();
  if (std::find(choices.begin(), choices.end(), s) == choices.end()) {
    const std::string hint = did_you_mean(s, choices);
    fail("invalid value" + (hint.empty() ? "" : " (did you mean " + quoted(hint) + "?)"), "one of " + join(choices));
  }
  return s;
}

double Reader::quantity(std::string_view key, units::Dimension d, const Limits& lim) const {
  return at(key, units::describe(d)).as_quantity(d, lim);
}

double Reader::quantity_or(std::string_view key, units::Dimension d, double fallback_si, const Limits& lim) const {
  const auto r = find(key);
  return r ? r->as_quantity(d, lim) : fallback_si;
}

double Reader::angle_or(std::string_view key, double fallback_rad) const {
  const auto r = find(key);
  return r ? r->as_angle() : fallback_rad;
}

long Reader::integer_or(std::string_view key, long fallback, const Limits& lim) const {
  const auto r = find(key);
  return r ? r->as_integer(lim) : fallback;
}

int Reader::int_or(std::string_view key, int fallback, const Limits& lim) const {
  const auto r = find(key);
  return r ? r->as_int(lim) : fallback;
}

int Reader::int_choice_or(std::string_view key, int fallback, std::initializer_list<int> choices) const {
  const auto r = find(key);
  if (!r) return fallback;
  std::string list;
  for (int c : choices) list += (list.empty() ? "" : ", ") + std::to_string(c);
  const long v = r->as_integer();
  if (std::find(choices.begin(), choices.end(), v) == choices.end())
    r->fail(msg() << key << " must be one of " << list, "one of " + list);
  return static_cast<int>(v);
}

Vec3 Reader::vec3(std::string_view key, units::Dimension d, const Limits& lim) const {
  return at(key, "a list [x, y, z] of " + units::describe(d)).as_vec3(d, lim);
}

Vec3 Reader::vec3_or(std::string_view key, units::Dimension d, Vec3 fallback, const Limits& lim) const {
  const auto r = find(key);
  return r ? r->as_vec3(d, lim) : fallback;
}

std::string Reader::reference(std::string_view key, const std::vector<std::string>& names, std::string_view kind,
                              std::string_view section) const {
  const Reader r = at(key, msg() << "the name of a " << kind << " defined under '" << section << "'");
  const std::string name = r.as_name();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    const std::string hint = did_you_mean(name, names);
    r.fail(msg() << "unknown " << kind << " " << quoted(name) << (hint.empty() ? "" : " (did you mean " + quoted(hint) + "?)"),
           msg() << "a " << kind << " defined under '" << section << "': " << join(names));
  }
  return name;
}

}  // namespace plyimpact::config::detail
