#include "config/scene_digest.hpp"

#include <fstream>
#include <sstream>

#include "config/yaml_reader.hpp"
#include "core/error.hpp"

namespace plyimpact::config {

namespace {

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

// Canonical text of a tree: the same values give the same text whether the file wrote them in
// block or flow style, with comments or without. Scalars keep their spelling (1e-3 is not 0.001:
// a stricter identity than the value, never a looser one).
void canonical(const YAML::Node& n, std::string& out) {
  if (n.IsMap()) {
    out += '{';
    for (const auto& kv : n) {
      canonical(kv.first, out);
      out += ':';
      canonical(kv.second, out);
      out += ',';
    }
    out += '}';
  } else if (n.IsSequence()) {
    out += '[';
    for (const auto& item : n) {
      canonical(item, out);
      out += ',';
    }
    out += ']';
  } else if (n.IsScalar()) {
    out += std::to_string(n.Scalar().size());  // length-prefixed: no separator inside a value can fool it
    out += '\'';
    out += n.Scalar();
  } else {
    out += '~';
  }
}

YAML::Node parse(const std::string& yaml_text, const std::string& file_label) {
  try {
    return YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError(msg() << detail::location(file_label, e.mark) << ": YAML syntax error: " << e.msg);
  }
}

}  // namespace

std::string canonical_scene_text(const std::string& yaml_text, const std::string& file_label) {
  std::string text;
  canonical(parse(yaml_text, file_label), text);
  return text;
}

std::uint64_t scene_digest_from_string(const std::string& yaml_text, const std::string& file_label,
                                       const std::vector<SceneOverride>& overrides) {
  YAML::Node root = parse(yaml_text, file_label);
  detail::Context ctx{file_label, {}};
  detail::apply_overrides(root, overrides, ctx);
  if (root.IsMap()) {
    root.remove("output");
    const YAML::Node& lookup = root;  // a const lookup adds no empty key
    if (YAML::Node control = lookup["control"]; control.IsDefined() && control.IsMap())
      for (const char* key : {"termination_time", "max_cycles", "threads"}) control.remove(key);
  }
  std::string text;
  canonical(root, text);
  return fnv1a(text);
}

std::uint64_t scene_digest(const std::string& path, const std::vector<SceneOverride>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(msg() << path << ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return scene_digest_from_string(text.str(), path, overrides);
}

}  // namespace plyimpact::config
