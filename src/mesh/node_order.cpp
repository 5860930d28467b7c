#include "mesh/node_order.hpp"

#include <algorithm>
#include <numeric>

namespace plyimpact::mesh {

namespace {

void map_all(std::vector<Index>& nodes, const std::vector<Index>& new_index) {
  for (Index& n : nodes) n = new_index[std::size_t(n)];
}

}  // namespace

void number_nodes_in_element_order(Mesh& mesh) {
  const std::size_t num_nodes = mesh.num_nodes(), num_elements = mesh.num_elements();
  std::vector<std::size_t> elements(num_elements);
  std::iota(elements.begin(), elements.end(), std::size_t(0));
  std::stable_sort(elements.begin(), elements.end(),
                   [&](std::size_t a, std::size_t b) { return mesh.element_part[a] < mesh.element_part[b]; });
  constexpr Index kUnset = -1;
  std::vector<Index> new_index(num_nodes, kUnset);
  Index next = 0;
  for (std::size_t e : elements)
    for (int k = 0; k < 8; ++k) {
      Index& target = new_index[std::size_t(mesh.hex[8 * e + std::size_t(k)])];
      if (target == kUnset) target = next++;
    }
  for (Index& target : new_index)
    if (target == kUnset) target = next++;
  std::vector<double> coords(mesh.coords.size());
  for (std::size_t n = 0; n < num_nodes; ++n)
    std::copy_n(&mesh.coords[3 * n], 3, &coords[3 * std::size_t(new_index[n])]);
  mesh.coords = std::move(coords);
  map_all(mesh.hex, new_index);
  for (auto& itf : mesh.interfaces) {
    map_all(itf.lower_nodes, new_index);
    map_all(itf.upper_nodes, new_index);
    map_all(itf.lower_segments, new_index);
    map_all(itf.upper_segments, new_index);
  }
  for (auto& set : mesh.node_sets) map_all(set.nodes, new_index);
  if (mesh.impactor) map_all(mesh.impactor->surface_nodes, new_index);
}

}  // namespace plyimpact::mesh
