#include "output/json.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "output/atomic_file.hpp"

namespace plyimpact::output {

namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

void append_string(std::string& out, std::string_view s) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          out += "\\u00";
          out += kHex[c >> 4];
          out += kHex[c & 0xf];
        } else {
          out += ch;  // bytes >= 0x80 are UTF-8 sequences, copied unchanged
        }
    }
  }
  out += '"';
}

void append_double(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  // Shortest representation that parses back to the same double (<= 17 significant digits).
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  const std::string_view text(buf, static_cast<std::size_t>(end - buf));
  out += text;
  // Keep a double recognisable as one ("1.0", not "1") so readers that type by syntax (Python)
  // don't turn a time or an energy into an int.
  if (text.find_first_of(".eE") == std::string_view::npos) out += ".0";
}

template <class T>
void append_integer(std::string& out, T v) {
  char buf[24];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, end);
}

void newline(std::string& out, int indent, int depth) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(depth), ' ');
}

}  // namespace

Json::Kind Json::kind() const {
  return std::visit(Overloaded{
                        [](std::monostate) { return Kind::null; },
                        [](bool) { return Kind::boolean; },
                        [](double) { return Kind::number; },
                        [](std::int64_t) { return Kind::integer; },
                        [](std::uint64_t) { return Kind::integer; },
                        [](const std::string&) { return Kind::string; },
                        [](const Array&) { return Kind::array; },
                        [](const Object&) { return Kind::object; },
                    },
                    value_);
}

std::size_t Json::size() const {
  if (const auto* a = std::get_if<Array>(&value_)) return a->size();
  if (const auto* o = std::get_if<Object>(&value_)) return o->size();
  return 0;
}

Json& Json::push_back(Json v) {
  if (std::holds_alternative<std::monostate>(value_)) value_ = Array{};
  auto* a = std::get_if<Array>(&value_);
  if (a == nullptr) throw std::logic_error("Json::push_back on a value that is not an array");
  a->push_back(std::move(v));
  return a->back();
}

Json& Json::operator[](std::string_view key) {
  if (std::holds_alternative<std::monostate>(value_)) value_ = Object{};
  auto* o = std::get_if<Object>(&value_);
  if (o == nullptr) throw std::logic_error("Json::operator[] on a value that is not an object");
  for (auto& [k, v] : *o) {
    if (k == key) return v;
  }
  o->emplace_back(std::string(key), Json());
  return o->back().second;
}

const Json* Json::find(std::string_view key) const {
  if (const auto* o = std::get_if<Object>(&value_)) {
    for (const auto& [k, v] : *o) {
      if (k == key) return &v;
    }
  }
  return nullptr;
}

const Json& Json::at(std::size_t index) const {
  const auto* a = std::get_if<Array>(&value_);
  if (a == nullptr || index >= a->size()) throw std::out_of_range("Json::at: no such element");
  return (*a)[index];
}

bool Json::as_bool() const {
  if (const auto* b = std::get_if<bool>(&value_)) return *b;
  throw std::logic_error("Json: not a boolean");
}

double Json::as_number() const {
  if (const auto* d = std::get_if<double>(&value_)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&value_)) return static_cast<double>(*i);
  if (const auto* u = std::get_if<std::uint64_t>(&value_)) return static_cast<double>(*u);
  throw std::logic_error("Json: not a number");
}

const std::string& Json::as_string() const {
  if (const auto* s = std::get_if<std::string>(&value_)) return *s;
  throw std::logic_error("Json: not a string");
}

const Json::Array& Json::as_array() const {
  if (const auto* a = std::get_if<Array>(&value_)) return *a;
  throw std::logic_error("Json: not an array");
}

const Json::Object& Json::as_object() const {
  if (const auto* o = std::get_if<Object>(&value_)) return *o;
  throw std::logic_error("Json: not an object");
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  return out;
}

void Json::dump_to(std::string& out, int indent, int depth) const {
  std::visit(Overloaded{
                 [&](std::monostate) { out += "null"; },
                 [&](bool v) { out += v ? "true" : "false"; },
                 [&](double v) { append_double(out, v); },
                 [&](std::int64_t v) { append_integer(out, v); },
                 [&](std::uint64_t v) { append_integer(out, v); },
                 [&](const std::string& v) { append_string(out, v); },
                 [&](const Array& a) {
                   if (a.empty()) {
                     out += "[]";
                     return;
                   }
                   out += '[';
                   for (std::size_t i = 0; i < a.size(); ++i) {
                     if (i > 0) out += ',';
                     newline(out, indent, depth + 1);
                     a[i].dump_to(out, indent, depth + 1);
                   }
                   newline(out, indent, depth);
                   out += ']';
                 },
                 [&](const Object& o) {
                   if (o.empty()) {
                     out += "{}";
                     return;
                   }
                   out += '{';
                   for (std::size_t i = 0; i < o.size(); ++i) {
                     if (i > 0) out += ',';
                     newline(out, indent, depth + 1);
                     append_string(out, o[i].first);
                     out += indent > 0 ? ": " : ":";
                     o[i].second.dump_to(out, indent, depth + 1);
                   }
                   newline(out, indent, depth);
                   out += '}';
                 },
             },
             value_);
}

void write_json_atomically(const std::filesystem::path& path, const Json& value) {
  write_text_atomically(path, value.dump(2) + '\n');
}

}  // namespace plyimpact::output
