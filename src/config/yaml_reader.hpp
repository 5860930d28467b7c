// Internal to config/: a Reader is a YAML node plus its key path ("materials.ply.EA") and the scene
// context (file label, unit system). It checks allowed keys, node types, units and ranges, and every
// failure throws InputError in the one house format:
//   <file>:<line>:<col>: <key.path>: <what is wrong>; found <value>; allowed <what is allowed>
// with 1-based line/column (yaml-cpp marks are 0-based). Not a public header: it includes yaml-cpp.
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/overrides.hpp"
#include "config/plausible_range.hpp"
#include "config/scene.hpp"
#include "core/types.hpp"
#include "core/units.hpp"

namespace plyimpact::config::detail {

// A node that a command-line override put into the tree (the value, its descendants, and a key it
// added); messages about it name the override instead of a file position.
struct OverrideNode {
  YAML::Node node;
  std::string origin;  // "--set key.path=value"
};

struct Context {
  std::string file;
  units::UnitSystem unit_system;  // set once `units:` has been read
  std::vector<OverrideNode> override_nodes{};  // empty when the scene is read without overrides
  // Where every key that was looked up sits ("laminate.element_size" -> file:line:col), so checks
  // made after reading (mesh size, cycle count) can point at the key that causes them.
  mutable std::map<std::string, SourceLocation> key_locations{};
};

// Applies `overrides` in order to the tree `root` (a mapping) and records in ctx the nodes they
// create. Structural problems (index out of range, a value where a section is needed, a value that
// is not YAML) throw InputError naming the override; everything else is left to the scene reader.
void apply_overrides(YAML::Node& root, const std::vector<SceneOverride>& overrides, Context& ctx);

// Allowed range of a number; text() gives "> 0", "in (0, 1]", ... A quantity is also held to the
// plausible range of its kind (config/plausible_range.hpp): the kind given with of(), else the
// default kind of its dimension.
struct Limits {
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;
  std::string label;  // what the number is, for "<label> must be > 0"
  std::optional<QuantityKind> kind{};

  Limits of(QuantityKind k) const {
    Limits l = *this;
    l.kind = k;
    return l;
  }

  static Limits none() { return {}; }
  static Limits positive(std::string label) { return {0.0, std::nullopt, true, false, std::move(label)}; }
  static Limits non_negative(std::string label) { return {0.0, std::nullopt, false, false, std::move(label)}; }
  static Limits at_least(double lo, std::string label) { return {lo, std::nullopt, false, false, std::move(label)}; }
  static Limits interval(double lo, bool lo_open, double hi, bool hi_open, std::string label) {
    return {lo, hi, lo_open, hi_open, std::move(label)};
  }
  bool ok(double v) const;
  std::string text() const;
};

// "file:line:col" (1-based) from a 0-based yaml-cpp mark; just "file" for a null mark.
std::string location(const std::string& file, const YAML::Mark& mark);

// Closest candidate within edit distance 2 (case-insensitive), or empty.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

// "a, b, c"
std::string join(const std::vector<std::string>& names);

class Reader {
 public:
  // fallback: where to point when the node has no mark of its own (its parent).
  // key_mark: the mark of the key this node is the value of; used for empty values ("E:"), whose
  // own mark yaml-cpp puts at the next token.
  Reader(YAML::Node node, std::string path, const Context* ctx, YAML::Mark fallback,
         YAML::Mark key_mark = YAML::Mark::null_mark());

  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  YAML::Mark mark() const;
  SourceLocation where() const;

  // --- failures (all throw InputError) ---
  [[noreturn]] void fail(const std::string& what, const std::string& allowed) const;
  [[noreturn]] void fail(const std::string& what, const std::string& found, const std::string& allowed) const;
  // Text used after "found": 'scalar', "a list of 3 items", "a mapping with keys [a, b]", ...
  std::string found_text() const;

  // --- shape ---
  void require_map(const std::string& expected) const;   // expected: description of the mapping
  void require_list(const std::string& expected, bool non_empty) const;
  void require_scalar(const std::string& expected) const;

  // --- keys of a mapping ---
  // Every key must be in `allowed` (else "unknown key 'x' (did you mean 'y'?)"); no duplicates.
  void allow_keys(std::initializer_list<std::string_view> allowed) const;
  bool has(std::string_view key) const;
  // Required child; missing -> error at this mapping: "missing required key 'k'", allowed = expected.
  Reader at(std::string_view key, const std::string& expected) const;
  std::optional<Reader> find(std::string_view key) const;
  // Exactly one of `keys` present; returns it.
  std::string exactly_one(std::initializer_list<std::string_view> keys) const;

  // --- children ---
  std::vector<std::pair<std::string, Reader>> entries() const;  // mapping, in file order
  std::vector<Reader> items() const;                            // list

  // --- this node as a value ---
  std::string as_name() const;  // non-empty scalar
  double as_quantity(units::Dimension d, const Limits& lim = Limits::none()) const;  // SI
  double as_angle() const;                                                           // rad
  long as_integer(const Limits& lim = Limits::none()) const;
  // An integer that must also fit an int: out-of-range values are refused, never wrapped.
  int as_int(const Limits& lim) const;
  Vec3 as_vec3(units::Dimension d, const Limits& lim = Limits::none()) const;
  // Scalar that must be one of `choices` (exact match).
  std::string as_choice(const std::vector<std::string>& choices) const;

  // --- convenience: child by key ---
  double quantity(std::string_view key, units::Dimension d, const Limits& lim = Limits::none()) const;
  double quantity_or(std::string_view key, units::Dimension d, double fallback_si,
                     const Limits& lim = Limits::none()) const;
  double angle_or(std::string_view key, double fallback_rad) const;
  long integer_or(std::string_view key, long fallback, const Limits& lim = Limits::none()) const;
  int int_or(std::string_view key, int fallback, const Limits& lim) const;
  int int_choice_or(std::string_view key, int fallback, std::initializer_list<int> choices) const;
  Vec3 vec3(std::string_view key, units::Dimension d, const Limits& lim = Limits::none()) const;
  Vec3 vec3_or(std::string_view key, units::Dimension d, Vec3 fallback, const Limits& lim = Limits::none()) const;
  // Name that must be one of `names` (cross reference); `kind` e.g. "material", `section` e.g. "materials".
  std::string reference(std::string_view key, const std::vector<std::string>& names, std::string_view kind,
                        std::string_view section) const;

 private:
  Reader child(const YAML::Node& n, std::string path, YAML::Mark key_mark = YAML::Mark::null_mark()) const;
  // The override this node came from, or nullptr for a node of the file.
  const std::string* override_origin() const;
  // "file:line:col", or the override's text for a node an override supplied.
  std::string location_text() const;

  YAML::Node node_;
  std::string path_;
  const Context* ctx_;
  YAML::Mark fallback_;
  YAML::Mark key_mark_;
};

}  // namespace plyimpact::config::detail
