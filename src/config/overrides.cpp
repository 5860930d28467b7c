// Command-line overrides applied to the scene's YAML tree. See overrides.hpp.
#include "config/overrides.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "config/yaml_reader.hpp"
#include "core/error.hpp"

namespace plyimpact::config {
namespace {

// One step of a key path: a mapping key, or a list item by index or by its `name:`.
struct Step {
  enum class Kind { key, index, name } kind = Kind::key;
  std::string text;
};

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

[[noreturn]] void refuse(const std::string& origin, const std::string& what, const std::string& allowed) {
  throw InputError(msg() << origin << ": " << what << "; allowed " << allowed);
}

const char* kPathHelp = "key.path=value, e.g. impactor.velocity=5 m/s, materials.ply.EA=130 GPa, contacts[0].SOFT=2";

std::vector<Step> parse_path(std::string_view path, const std::string& origin) {
  std::vector<Step> steps;
  std::size_t i = 0;
  auto bad = [&](const std::string& why) { refuse(origin, "bad key path '" + std::string(path) + "': " + why, kPathHelp); };
  while (i < path.size()) {
    std::size_t end = path.find_first_of(".[", i);
    if (end == std::string_view::npos) end = path.size();
    if (end == i) bad("an empty name");
    const std::string_view name = path.substr(i, end - i);
    steps.push_back({all_digits(name) ? Step::Kind::index : Step::Kind::key, std::string(name)});
    i = end;
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos || close == i + 1) bad("'[' without an index or name and ']'");
      const std::string_view sel = path.substr(i + 1, close - i - 1);
      steps.push_back({all_digits(sel) ? Step::Kind::index : Step::Kind::name, std::string(sel)});
      i = close + 1;
    }
    if (i < path.size()) {
      if (path[i] != '.') bad("expected '.' or '[' after ']'");
      if (++i == path.size()) bad("ends with '.'");
    }
  }
  if (steps.empty()) bad("empty");
  return steps;
}

std::string step_path(const std::string& parent, const Step& s) {
  if (s.kind == Step::Kind::key) return parent.empty() ? s.text : parent + "." + s.text;
  return parent + "[" + s.text + "]";
}

// A copy of `n` built node by node: no file marks, so nothing can point into the scene file.
YAML::Node rebuild(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Scalar: {
      YAML::Node c(n.Scalar());
      c.SetTag(n.Tag());
      return c;
    }
    case YAML::NodeType::Sequence: {
      YAML::Node c(YAML::NodeType::Sequence);
      for (const auto& item : n) c.push_back(rebuild(item));
      return c;
    }
    case YAML::NodeType::Map: {
      YAML::Node c(YAML::NodeType::Map);
      for (auto it = n.begin(); it != n.end(); ++it) c.force_insert(rebuild(it->first), rebuild(it->second));
      return c;
    }
    default:
      return YAML::Node(YAML::NodeType::Null);
  }
}

void record_tree(const YAML::Node& n, const std::string& origin, detail::Context& ctx) {
  ctx.override_nodes.push_back({n, origin});
  if (n.IsSequence())
    for (const auto& item : n) record_tree(item, origin, ctx);
  if (n.IsMap())
    for (auto it = n.begin(); it != n.end(); ++it) {
      record_tree(it->first, origin, ctx);
      record_tree(it->second, origin, ctx);
    }
}

std::optional<YAML::Node> map_value(const YAML::Node& map, const std::string& key) {
  for (auto it = map.begin(); it != map.end(); ++it)
    if (it->first.IsScalar() && it->first.Scalar() == key) return it->second;
  return std::nullopt;
}

void record_key(const YAML::Node& map, const std::string& key, const std::string& origin, detail::Context& ctx) {
  for (auto it = map.begin(); it != map.end(); ++it)
    if (it->first.IsScalar() && it->first.Scalar() == key) ctx.override_nodes.push_back({it->first, origin});
}

std::string list_names(const YAML::Node& list) {
  std::vector<std::string> names;
  for (const auto& item : list)
    if (item.IsMap())
      if (const auto n = map_value(item, "name"); n && n->IsScalar()) names.push_back(n->Scalar());
  return names.empty() ? std::string() : " or a name: " + detail::join(names);
}

// The list item `s` selects in `list` (walked: its path so far).
YAML::Node list_item(const YAML::Node& list, const Step& s, const std::string& walked, const std::string& origin) {
  const std::string allowed = (list.size() ? std::string(msg() << "an index 0.." << list.size() - 1)
                                            : std::string("no index (the list is empty)")) +
                              list_names(list);
  if (s.kind == Step::Kind::index) {
    const std::size_t i = std::stoul(s.text);
    if (i >= list.size())
      refuse(origin, msg() << walked << ": index " << i << " is past the end of a list of " << list.size() << " item"
                           << (list.size() == 1 ? "" : "s"),
             allowed);
    return list[i];
  }
  for (const auto& item : list)
    if (item.IsMap())
      if (const auto n = map_value(item, "name"); n && n->IsScalar() && n->Scalar() == s.text) return item;
  refuse(origin, msg() << walked << ": no item named '" << s.text << "'", allowed);
}

void apply_one(YAML::Node& root, const SceneOverride& ov, detail::Context& ctx) {
  const std::vector<Step> steps = parse_path(ov.key_path, ov.origin);
  YAML::Node parsed;
  try {
    parsed = YAML::Load(ov.value);
  } catch (const YAML::Exception& e) {
    refuse(ov.origin, "the value is not valid YAML (" + e.msg + ")",
           "a number, '<number> <unit>', a name, [a, b, c] or {key: value}; quote it for the shell");
  }
  const YAML::Node value = rebuild(parsed);
  record_tree(value, ov.origin, ctx);

  YAML::Node cur = root;
  std::string walked;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const Step& s = steps[k];
    const bool last = k + 1 == steps.size();
    const std::string here = step_path(walked, s);
    YAML::Node next;
    if (cur.IsSequence()) {
      if (s.kind == Step::Kind::key)
        refuse(ov.origin, msg() << walked << " is a list, so '" << s.text << "' cannot follow it",
               msg() << walked << "[INDEX] or " << walked << "[NAME]");
      next.reset(list_item(cur, s, walked, ov.origin));
      if (last) {
        next = value;  // replaces the item in place (the node takes the value's content)
        return;
      }
    } else if (cur.IsMap() && s.kind == Step::Kind::key) {
      if (const auto existing = map_value(cur, s.text)) {
        next.reset(*existing);
        if (last) {
          next = value;
          return;
        }
      } else {
        // A key the scene does not set: add it; the reader refuses it if the format has no such key.
        if (last) {
          cur[s.text] = value;
        } else {
          YAML::Node section(YAML::NodeType::Map);
          cur[s.text] = section;
          ctx.override_nodes.push_back({section, ov.origin});
          next.reset(section);
        }
        record_key(cur, s.text, ov.origin, ctx);
        if (last) return;
      }
    } else if (cur.IsMap()) {
      refuse(ov.origin, msg() << (walked.empty() ? "the scene" : walked) << " is a mapping, not a list",
             msg() << (walked.empty() ? "" : walked + ".") << "KEY");
    } else {
      refuse(ov.origin,
             msg() << walked << " is a single value, not a section, so '" << here << "' cannot be set"
                   << (cur.IsScalar() ? "; found '" + cur.Scalar() + "'" : std::string()),
             msg() << "a key path that ends at " << walked);
    }
    cur.reset(next);
    walked = here;
  }
}

}  // namespace

SceneOverride parse_set_argument(std::string_view text) {
  const std::string origin = "--set " + std::string(text);
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    refuse(origin, "expected key.path=value", kPathHelp);
  SceneOverride o{std::string(text.substr(0, eq)), std::string(text.substr(eq + 1)), origin};
  parse_path(o.key_path, origin);  // refuse a malformed path now, before any scene is read
  return o;
}

SceneOverride threads_override(std::string_view count) {
  return {"control.threads", std::string(count), "--threads " + std::string(count)};
}

namespace detail {

void apply_overrides(YAML::Node& root, const std::vector<SceneOverride>& overrides, Context& ctx) {
  if (!root.IsMap()) return;  // an empty or malformed scene: the reader says what is wrong with it
  for (const auto& ov : overrides) apply_one(root, ov, ctx);
}

}  // namespace detail
}  // namespace plyimpact::config
