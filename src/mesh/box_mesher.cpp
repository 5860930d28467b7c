#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

namespace {

// Merges coincident nodes of different boxes: nodes are hashed on a grid of cell `tol`, and a node
// takes the index of an earlier node within `tol` in its cell or a neighbouring one.
void merge_coincident_nodes(Mesh& m, const std::vector<int>& node_box, double tol) {
  struct Key {
    long long i, j, k;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k.i * 73856093LL ^ k.j * 19349663LL ^ k.k * 83492791LL);
    }
  };
  std::unordered_map<Key, std::vector<Index>, Hash> grid;
  const std::size_t n = m.num_nodes();
  std::vector<Index> target(n);
  std::vector<double> coords;
  coords.reserve(m.coords.size());
  std::vector<int> kept_box;
  for (std::size_t a = 0; a < n; ++a) {
    const double* p = &m.coords[3 * a];
    const Key key{std::llround(p[0] / tol), std::llround(p[1] / tol), std::llround(p[2] / tol)};
    Index found = -1;
    for (long long di = -1; di <= 1 && found < 0; ++di)
      for (long long dj = -1; dj <= 1 && found < 0; ++dj)
        for (long long dk = -1; dk <= 1 && found < 0; ++dk) {
          const auto it = grid.find(Key{key.i + di, key.j + dj, key.k + dk});
          if (it == grid.end()) continue;
          for (Index c : it->second) {
            const double* q = &coords[3 * std::size_t(c)];
            if (kept_box[c] != node_box[a] && std::abs(p[0] - q[0]) <= tol && std::abs(p[1] - q[1]) <= tol &&
                std::abs(p[2] - q[2]) <= tol) {
              found = c;
              break;
            }
          }
        }
    if (found < 0) {
      found = Index(coords.size() / 3);
      coords.insert(coords.end(), p, p + 3);
      kept_box.push_back(node_box[a]);
      grid[key].push_back(found);
    }
    target[a] = found;
  }
  for (Index& node : m.hex) node = target[node];
  m.coords = std::move(coords);
}

}  // namespace

Mesh mesh_boxes(const config::Scene& scene) {
  Mesh m;
  std::size_t nodes = 0, elems = 0;
  for (const auto& box : scene.boxes) {
    const auto& n = box.elements;
    nodes += std::size_t(n[0] + 1) * (n[1] + 1) * (n[2] + 1);
    elems += std::size_t(n[0]) * n[1] * n[2];
  }
  m.coords.reserve(3 * nodes);
  m.hex.reserve(8 * elems);
  m.element_part.reserve(elems);
  std::vector<int> node_box;
  for (const auto& box : scene.boxes) {
    const auto part = std::find_if(scene.parts.begin(), scene.parts.end(),
                                   [&](const config::PartSpec& p) { return p.name == box.part; });
    if (part == scene.parts.end())
      throw InputError(msg() << box.where.file << ":" << box.where.line << ":" << box.where.column << ": "
                             << box.where.key_path << ": unknown part '" << box.part << "'");
    const int part_index = int(part - scene.parts.begin());
    const int nx = box.elements[0], ny = box.elements[1], nz = box.elements[2];
    const Index base = Index(m.coords.size() / 3);
    node_box.resize(std::size_t(base) + std::size_t(nx + 1) * (ny + 1) * (nz + 1), int(&box - scene.boxes.data()));
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
          // Exact end coordinates (origin + size) so plane selections and box faces match.
          m.coords.push_back(box.origin[0] + (i == nx ? box.size[0] : box.size[0] * i / nx));
          m.coords.push_back(box.origin[1] + (j == ny ? box.size[1] : box.size[1] * j / ny));
          m.coords.push_back(box.origin[2] + (k == nz ? box.size[2] : box.size[2] * k / nz));
        }
    auto id = [&](int i, int j, int k) { return base + Index((k * (ny + 1) + j) * (nx + 1) + i); };
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const Index c[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                              id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                              id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
          m.hex.insert(m.hex.end(), c, c + 8);
          m.element_part.push_back(part_index);
        }
  }
  if (scene.merge_coincident_nodes && scene.boxes.size() > 1) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < m.num_nodes(); ++i)
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], m.coords[3 * i + d]);
        hi[d] = std::max(hi[d], m.coords[3 * i + d]);
      }
    const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    merge_coincident_nodes(m, node_box, 1e-9 * size);
  }
  return m;
}

}  // namespace plyimpact::mesh
