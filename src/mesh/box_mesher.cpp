#include <algorithm>

#include "core/error.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::mesh {

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
  for (const auto& box : scene.boxes) {
    const auto part = std::find_if(scene.parts.begin(), scene.parts.end(),
                                   [&](const config::PartSpec& p) { return p.name == box.part; });
    if (part == scene.parts.end())
      throw InputError(msg() << box.where.file << ":" << box.where.line << ":" << box.where.column << ": "
                             << box.where.key_path << ": unknown part '" << box.part << "'");
    const int part_index = int(part - scene.parts.begin());
    const int nx = box.elements[0], ny = box.elements[1], nz = box.elements[2];
    const Index base = Index(m.coords.size() / 3);
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
  return m;
}

}  // namespace plyimpact::mesh
