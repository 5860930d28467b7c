#include "model/mesh_conversion.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <unordered_map>

namespace plyimpact::model {

Interface make_interface(const mesh::Interface& meshed, const std::vector<double>& X) {
  Interface itf;
  itf.id = meshed.id;
  itf.lower_ply = meshed.lower_ply;
  itf.upper_ply = meshed.upper_ply;
  itf.z = meshed.z;
  itf.lower_nodes = meshed.lower_nodes;
  itf.upper_nodes = meshed.upper_nodes;
  itf.lower_segments = meshed.lower_segments;
  itf.upper_segments = meshed.upper_segments;
  const std::size_t np = itf.num_pairs();
  itf.area.assign(np, 0.0);
  itf.normal.assign(3 * np, 0.0);
  std::unordered_map<Index, std::size_t> pair_of;
  for (std::size_t k = 0; k < np; ++k) pair_of[itf.lower_nodes[k]] = k;
  auto point = [&](Index n) { return Eigen::Vector3d(&X[3 * std::size_t(n)]); };
  // A bilinear quad's consistent nodal areas are a quarter each for a parallelogram (the mesher's
  // interfaces are planar grids); the area vector of a quad is half the cross product of its
  // diagonals, whatever its shape.
  std::vector<Eigen::Vector3d> sum(np, Eigen::Vector3d::Zero());
  for (std::size_t q = 0; 4 * q < itf.lower_segments.size(); ++q) {
    const Index* s = &itf.lower_segments[4 * q];
    const Eigen::Vector3d a = 0.5 * (point(s[2]) - point(s[0])).cross(point(s[3]) - point(s[1]));
    const double quarter = 0.25 * a.norm();
    for (int c = 0; c < 4; ++c) {
      const auto it = pair_of.find(s[c]);
      if (it == pair_of.end()) continue;
      itf.area[it->second] += quarter;
      sum[it->second] += a;
    }
  }
  for (std::size_t k = 0; k < np; ++k) {
    const double len = sum[k].norm();
    const Eigen::Vector3d n = len > 0 ? Eigen::Vector3d(sum[k] / len) : Eigen::Vector3d::UnitZ();
    for (int d = 0; d < 3; ++d) itf.normal[3 * k + d] = n[d];
  }
  return itf;
}

Impactor make_impactor(const mesh::ImpactorMesh& meshed) {
  Impactor imp;
  imp.rigid = meshed.rigid;
  imp.surface_coords = meshed.surface_coords;
  imp.surface_quads = meshed.surface_quads;
  imp.surface_nodes = meshed.surface_nodes;
  imp.mass = meshed.mass;
  imp.centre_of_mass = meshed.centre_of_mass;
  imp.inertia = meshed.inertia;
  imp.velocity = meshed.velocity;
  return imp;
}

}  // namespace plyimpact::model
