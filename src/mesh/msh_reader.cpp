#include "mesh/msh_reader.hpp"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "mesh/gmsh_session.hpp"

namespace plyimpact::mesh {
namespace {

constexpr int kHex8 = 5;  // gmsh element type numbers (gmsh reference manual, MSH file format)
constexpr int kQuad4 = 3;

struct HexRecord {
  std::size_t tag = 0;
  int part = -1;
  std::size_t nodes[8] = {};
};

std::string type_name(int type) {
  std::string name;
  int dim = 0, order = 0, num_nodes = 0, primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, num_nodes, local, primary);
  return name;
}

// Volume element types other than the 8-node hexahedron, with their counts.
void refuse_other_volume_elements(const std::string& file) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3);
  msg problem;
  bool any = false;
  for (int t : types) {
    if (t == kHex8) continue;
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(t, tags, nodes);
    problem << (any ? ", " : "") << tags.size() << " elements of type '" << type_name(t) << "' (gmsh type " << t << ")";
    any = true;
  }
  if (any)
    throw InputError(msg() << file << ": the mesh has " << std::string(problem)
                           << "; allowed: 8-node hexahedra only (gmsh type 5)");
}

int part_of_group(const config::Scene& scene, const std::string& file, int tag, const std::string& name) {
  for (std::size_t p = 0; p < scene.parts.size(); ++p)
    if (name.empty() ? scene.parts[p].id == tag : scene.parts[p].name == name) return int(p);
  msg parts;
  for (const auto& p : scene.parts) parts << " '" << p.name << "' (id " << p.id << ")";
  throw InputError(msg() << file << ": physical volume " << tag << (name.empty() ? "" : " '" + name + "'")
                         << " matches no part of the scene; allowed: a part name (or, unnamed, a part id):"
                         << std::string(parts));
}

std::vector<HexRecord> read_hexahedra(const config::Scene& scene, const std::string& file) {
  std::map<std::size_t, HexRecord> by_tag;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 3);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    const int part = part_of_group(scene, file, tag, name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (int entity : entities) {
      std::vector<std::size_t> tags, nodes;
      gmsh::model::mesh::getElementsByType(kHex8, tags, nodes, entity);
      for (std::size_t e = 0; e < tags.size(); ++e) {
        HexRecord h;
        h.tag = tags[e];
        h.part = part;
        std::copy(&nodes[8 * e], &nodes[8 * e] + 8, h.nodes);
        const auto [it, fresh] = by_tag.emplace(h.tag, h);
        if (!fresh && it->second.part != part)
          throw InputError(msg() << file << ": hexahedron " << h.tag << " is in the physical volumes of parts '"
                                 << scene.parts[std::size_t(it->second.part)].name << "' and '"
                                 << scene.parts[std::size_t(part)].name << "'; allowed: one part per element");
      }
    }
  }
  std::vector<std::size_t> all_tags, all_nodes;
  gmsh::model::mesh::getElementsByType(kHex8, all_tags, all_nodes);
  if (all_tags.empty()) throw InputError(msg() << file << ": the mesh has no hexahedra; allowed: a volume mesh of 8-node hexahedra");
  std::size_t loose = 0, example = 0;
  for (std::size_t t : all_tags)
    if (!by_tag.count(t)) ++loose, example = t;
  if (loose)
    throw InputError(msg() << file << ": " << loose << " hexahedra (e.g. element " << example
                           << ") belong to no physical volume; allowed: every hexahedron in the physical volume of a part");
  std::vector<HexRecord> out;
  out.reserve(by_tag.size());
  for (auto& [tag, h] : by_tag) out.push_back(h);
  return out;
}

// Quadrangles of a physical surface, in element-tag order, as node tags.
std::vector<std::size_t> group_quads(int tag) {
  std::map<std::size_t, std::array<std::size_t, 4>> quads;
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(2, tag, entities);
  for (int entity : entities) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(kQuad4, tags, nodes, entity);
    for (std::size_t e = 0; e < tags.size(); ++e) quads[tags[e]] = {nodes[4 * e], nodes[4 * e + 1], nodes[4 * e + 2], nodes[4 * e + 3]};
  }
  std::vector<std::size_t> out;
  for (const auto& [t, q] : quads) out.insert(out.end(), q.begin(), q.end());
  return out;
}

// "interface_<id>_lower" -> (id, false); "interface_<id>_upper" -> (id, true); else id 0.
std::pair<int, bool> interface_side(const std::string& name) {
  const std::string prefix = "interface_";
  for (const char* side : {"_lower", "_upper"}) {
    const std::string s = side;
    if (name.size() <= prefix.size() + s.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - s.size(), s.size(), s) != 0)
      continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - s.size());
    if (digits.empty() || digits.size() > 6 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) continue;
    return {std::stoi(digits), s == "_upper"};
  }
  return {0, false};
}

class NodeIndex {
 public:
  explicit NodeIndex(const std::vector<HexRecord>& hexes) {
    for (const auto& h : hexes) used_.insert(h.nodes, h.nodes + 8);
    std::size_t i = 0;
    for (std::size_t t : used_) index_[t] = Index(i++);
  }
  std::size_t size() const { return index_.size(); }
  const std::map<std::size_t, Index>& map() const { return index_; }
  // -1 for a node no hexahedron uses.
  Index operator()(std::size_t tag) const {
    const auto it = index_.find(tag);
    return it == index_.end() ? Index(-1) : it->second;
  }

 private:
  std::set<std::size_t> used_;
  std::map<std::size_t, Index> index_;
};

void read_interfaces(Mesh& m, const NodeIndex& index, const std::map<std::pair<int, bool>, int>& sides,
                     const std::string& file) {
  for (const auto& [key, tag] : sides) {
    if (key.second) continue;
    const auto upper = sides.find({key.first, true});
    if (upper == sides.end())
      throw InputError(msg() << file << ": interface_" << key.first << "_lower has no interface_" << key.first
                             << "_upper; allowed: both sides of a delaminating interface");
    const auto lo = group_quads(tag), up = group_quads(upper->second);
    if (lo.size() != up.size() || lo.empty())
      throw InputError(msg() << file << ": interface " << key.first << " has " << lo.size() / 4 << " lower and "
                             << up.size() / 4 << " upper quadrangles; allowed: the same non-zero number");
    Interface itf;
    itf.id = key.first;
    itf.lower_ply = key.first - 1;
    itf.upper_ply = key.first;
    std::map<Index, Index> partner;
    for (std::size_t q = 0; q < lo.size() / 4; ++q)
      for (int k = 0; k < 4; ++k) {
        // The upper side is the same face seen from above: its corners in reverse order.
        const Index a = index(lo[4 * q + k]), b = index(up[4 * q + (4 - k) % 4]);
        if (a < 0 || b < 0)
          throw InputError(msg() << file << ": interface " << key.first << " uses a node of no hexahedron");
        for (int d = 0; d < 3; ++d)
          if (m.coords[3 * std::size_t(a) + d] != m.coords[3 * std::size_t(b) + d])
            throw InputError(msg() << file << ": interface " << key.first << ": nodes " << lo[4 * q + k] << " and "
                                   << up[4 * q + (4 - k) % 4] << " of a face pair do not coincide");
        if (partner.emplace(a, b).second) {
          itf.lower_nodes.push_back(a);
          itf.upper_nodes.push_back(b);
        }
        itf.lower_segments.push_back(a);
        itf.upper_segments.push_back(index(up[4 * q + k]));
      }
    itf.z = m.coords[3 * std::size_t(itf.lower_nodes.front()) + 2];
    m.interfaces.push_back(std::move(itf));
  }
}

}  // namespace

Mesh read_msh(const config::Scene& scene) {
  const auto& spec = *scene.mesh_file;
  const std::string& file = spec.path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(at(spec.where) << "no mesh file at " << file
                           << "; allowed: a gmsh .msh file (path relative to the scene file)");
  GmshModel model("msh_reader");
  Mesh m;
  std::map<std::string, std::string> unusable;  // node set name -> why
  gmsh_call("reading " + file, [&] {
    gmsh::merge(file);
    refuse_other_volume_elements(file);
    const auto hexes = read_hexahedra(scene, file);
    const NodeIndex index(hexes);
    std::vector<std::size_t> tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, true, false);
    m.coords.assign(3 * index.size(), 0.0);
    for (std::size_t k = 0; k < tags.size(); ++k)
      if (const Index i = index(tags[k]); i >= 0)
        for (int d = 0; d < 3; ++d) m.coords[3 * std::size_t(i) + d] = xyz[3 * k + d] * spec.length_scale;
    for (const auto& h : hexes) {
      for (std::size_t n : h.nodes) m.hex.push_back(index(n));
      m.element_part.push_back(h.part);
    }
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    std::map<std::pair<int, bool>, int> interface_sides;
    for (const auto& [dim, tag] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(dim, tag, name);
      if (name.empty()) continue;
      if (dim == 2)
        if (const auto side = interface_side(name); side.first > 0) interface_sides[side] = tag;
      std::vector<std::size_t> nodes;
      std::vector<double> c;
      gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, nodes, c);
      NodeList list{name, {}};
      std::size_t outside = 0;
      for (std::size_t n : nodes)
        if (const Index i = index(n); i >= 0) list.nodes.push_back(i);
        else ++outside;
      std::sort(list.nodes.begin(), list.nodes.end());
      list.nodes.erase(std::unique(list.nodes.begin(), list.nodes.end()), list.nodes.end());
      if (outside) unusable[name] = msg() << outside << " of its nodes belong to no hexahedron";
      else m.node_sets.push_back(std::move(list));
    }
    read_interfaces(m, index, interface_sides, file);
  });
  for (const auto& set : scene.node_sets) {
    if (set.kind != config::NodeSetSpec::Kind::Generated) continue;
    if (std::any_of(m.node_sets.begin(), m.node_sets.end(), [&](const NodeList& l) { return l.name == set.name; }))
      continue;
    if (const auto it = unusable.find(set.name); it != unusable.end())
      throw InputError(at(set.where) << "the physical group '" << set.name << "' of " << file
                             << " cannot be a node set: " << it->second);
    msg names;
    for (const auto& l : m.node_sets) names << (names.str().empty() ? "" : ", ") << l.name;
    throw InputError(at(set.where) << file << " has no physical group '" << set.name
                           << "'; allowed: one of its named groups: " << std::string(names));
  }
  return m;
}

}  // namespace plyimpact::mesh
