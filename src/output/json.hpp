// A minimal JSON value for the run summary (summary.json): build a tree, dump() it, write it
// atomically; read one back with parse_json (output/json_reader.hpp). Dependency-free. Objects keep insertion
// order so the summary reads in the order the solver filled it. Doubles are written in the
// shortest form that reads back to the same double (at most 17 significant digits), integers
// exactly, and non-finite doubles as null (JSON has no NaN/inf).
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace plyimpact::output {

class Json {
 public:
  enum class Kind { null, boolean, number, integer, string, array, object };
  using Array = std::vector<Json>;
  using Object = std::vector<std::pair<std::string, Json>>;  // insertion order, unique keys

  Json() = default;  // null
  Json(std::nullptr_t) {}
  Json(bool v) : value_(v) {}
  template <std::floating_point T>
  Json(T v) : value_(static_cast<double>(v)) {}
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  Json(T v) {
    if constexpr (std::is_signed_v<T>) {
      value_ = static_cast<std::int64_t>(v);
    } else {
      value_ = static_cast<std::uint64_t>(v);
    }
  }
  Json(std::string v) : value_(std::move(v)) {}
  Json(std::string_view v) : value_(std::string(v)) {}
  Json(const char* v) : value_(std::string(v)) {}  // else a literal would pick Json(bool)
  Json(Array v) : value_(std::move(v)) {}
  Json(Object v) : value_(std::move(v)) {}

  static Json array() { return Json(Array{}); }
  static Json object() { return Json(Object{}); }

  Kind kind() const;
  /// Elements of an array or members of an object; 0 otherwise.
  std::size_t size() const;

  /// Appends to an array (a null value becomes an empty array first). Returns the new element.
  /// Throws std::logic_error on other kinds.
  Json& push_back(Json v);
  /// Object member, inserted as null at the end if absent (a null value becomes an empty object
  /// first). The reference is invalidated by the next insertion into the same object.
  Json& operator[](std::string_view key);
  /// Object member or nullptr if absent or not an object.
  const Json* find(std::string_view key) const;
  /// Array element; throws std::out_of_range.
  const Json& at(std::size_t index) const;

  // Typed reads; each throws std::logic_error when the value is of another kind.
  bool as_bool() const;
  double as_number() const;  // number or integer
  const std::string& as_string() const;
  const Array& as_array() const;
  const Object& as_object() const;

  /// Serialises the tree. indent > 0: one member per line indented by `indent` spaces per level;
  /// indent <= 0: compact, no whitespace. Strings are escaped per RFC 8259 (quotes, backslash,
  /// control characters as \n, \t ... or \u00XX); other bytes, UTF-8 included, pass through.
  std::string dump(int indent = 2) const;

 private:
  void dump_to(std::string& out, int indent, int depth) const;

  std::variant<std::monostate, bool, double, std::int64_t, std::uint64_t, std::string, Array,
               Object>
      value_;
};

/// Atomically replaces `path` with `value.dump(2)` and a final newline. Throws plyimpact::RunError.
void write_json_atomically(const std::filesystem::path& path, const Json& value);

}  // namespace plyimpact::output
