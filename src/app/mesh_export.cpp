#include "app/mesh_export.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "mesh/scene_mesher.hpp"
#include "output/atomic_file.hpp"
#include "output/vtu_writer.hpp"

namespace plyimpact::app {
namespace {

// The rigid impactor's surface as its own small .vtu (VTK_QUAD cells, cell field outward_normal):
// output::Frame and its writer hold hexahedra only, and a separate file keeps them untouched. A few
// thousand quads, so plain ASCII XML written here is enough; doubles at 17 digits are exact.
void write_impactor_vtu(const mesh::ImpactorMesh& imp, const std::filesystem::path& path) {
  const std::size_t np = imp.surface_coords.size() / 3, nq = imp.surface_quads.size() / 4;
  std::string x;
  char buf[96];
  x += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt64\">\n<UnstructuredGrid>\n";
  std::snprintf(buf, sizeof buf, "<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n", np, nq);
  x += buf;
  x += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t a = 0; a < np; ++a) {
    const double* p = &imp.surface_coords[3 * a];
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    x += buf;
  }
  x += "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t q = 0; q < nq; ++q) {
    const Index* c = &imp.surface_quads[4 * q];
    x += std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + " " + std::to_string(c[3]) + "\n";
  }
  x += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t q = 1; q <= nq; ++q) x += std::to_string(4 * q) + "\n";
  x += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t q = 0; q < nq; ++q) x += "9\n";  // VTK_QUAD
  x += "</DataArray>\n</Cells>\n<CellData>\n"
       "<DataArray type=\"Float64\" Name=\"outward_normal\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t q = 0; q < nq; ++q) {
    const Index* c = &imp.surface_quads[4 * q];
    const auto p = [&](int k, int i) { return imp.surface_coords[3 * std::size_t(c[k]) + i]; };
    double d1[3], d2[3];
    for (int i = 0; i < 3; ++i) {
      d1[i] = p(2, i) - p(0, i);
      d2[i] = p(3, i) - p(1, i);
    }
    double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
    const double len = std::hypot(n[0], n[1], n[2]);
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", n[0] / len, n[1] / len, n[2] / len);
    x += buf;
  }
  x += "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  output::write_text_atomically(path, x);
}

}  // namespace

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
  if (mesh.impactor && mesh.impactor->rigid) {  // a deformable impactor's hexahedra are in the _mesh.vtu
    const auto imp = dir / (scene.name + "_impactor.vtu");
    write_impactor_vtu(*mesh.impactor, imp);
    return {vtu, msh, imp};
  }
  return {vtu, msh};
}

}  // namespace plyimpact::app
