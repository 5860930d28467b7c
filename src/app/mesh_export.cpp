#include "app/mesh_export.hpp"

#include <numbers>

#include "core/error.hpp"
#include "mesh/scene_mesher.hpp"
#include "output/vtu_writer.hpp"

namespace plyimpact::app {

std::vector<std::filesystem::path> export_mesh(const config::Scene& scene, const mesh::Mesh& mesh,
                                               const model::Model& model, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw RunError(msg() << dir.string() << ": cannot create the output directory: " << ec.message());
  const std::size_t ne = mesh.num_elements();
  output::Frame f;
  f.points = mesh.coords;
  f.hex_connectivity.assign(mesh.hex.begin(), mesh.hex.end());
  output::IntField part{"part_id", std::vector<std::int32_t>(ne)}, ply{"ply_index", std::vector<std::int32_t>(ne, -1)};
  output::Field angle{"ply_angle", 1, std::vector<double>(ne, 0.0), {}};
  output::Field axes[3] = {{"material_a_axis", 3, std::vector<double>(3 * ne, 0.0), {}},
                           {"material_b_axis", 3, std::vector<double>(3 * ne, 0.0), {}},
                           {"material_c_axis", 3, std::vector<double>(3 * ne, 0.0), {}}};
  for (std::size_t e = 0; e < ne; ++e) {
    const auto& ps = scene.parts[std::size_t(mesh.element_part[e])];
    part.values[e] = ps.id;
    angle.values[e] = ps.beta * 180 / std::numbers::pi;
    if (!mesh.element_ply.empty()) ply.values[e] = mesh.element_ply[e] + 1;  // 1-based like part ids; 0 = none
  }
  for (const auto& b : model.blocks)
    for (std::size_t k = 0; k < b.orientation.size(); ++k) {
      const auto& a = model.orientations[std::size_t(b.orientation[k])].axes;
      const std::size_t e = std::size_t(b.element_id[k] - 1);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) axes[r].values[3 * e + c] = a[3 * r + c];
    }
  for (auto& v : ply.values) v = v < 0 ? 0 : v;
  output::IntField itf{"interface_id", std::vector<std::int32_t>(mesh.num_nodes(), 0)};
  for (const auto& i : mesh.interfaces) {
    for (Index n : i.lower_nodes) itf.values[std::size_t(n)] = i.id;
    for (Index n : i.upper_nodes) itf.values[std::size_t(n)] = i.id;
  }
  f.cell_int_fields = {part, ply};
  f.cell_fields = {angle, axes[0], axes[1], axes[2]};
  f.point_int_fields = {itf};
  const auto vtu = dir / (scene.name + "_mesh.vtu");
  const auto msh = dir / (scene.name + ".msh");
  output::write_vtu(f, vtu);
  mesh::write_msh(scene, mesh, msh.string());
  return {vtu, msh};
}

}  // namespace plyimpact::app
