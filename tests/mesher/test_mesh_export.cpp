// `plyimpact mesh` output for the impactor: a rigid impactor's surface goes to <scene>_impactor.vtu
// as VTK_QUAD cells that VTK reads back exactly (17-digit ASCII); a deformable impactor is a part
// of <scene>_mesh.vtu and writes no separate file.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>

#include "scene_cards.hpp"
#include "app/mesh_export.hpp"
#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"

using namespace plyimpact;
namespace fs = std::filesystem;

namespace {

config::Scene scene(const std::string& impactor) {
  return config::load_scene_from_string(R"(units: mm-t-s-MPa
control: {termination_time: 1.0e-6}
)" + std::string(test::kPlyAndSteelCards) + R"(laminate: {length: 10, width: 10, ply_thickness: 0.25, stacking: "[0/90]", material: ply, section: s,
           element_size: 5, interfaces: none}
impactor: {shape: hemispherical_cylinder, diameter: 10, length: 12, mass: 0.1 kg, gap: 0.5, velocity: 2 m/s,
           element_size: 2)" + impactor + "}\n",
                                        "export.yaml");
}

vtkNew<vtkUnstructuredGrid> read(const fs::path& p) {
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(p.c_str());
  r->Update();
  vtkNew<vtkUnstructuredGrid> g;
  g->ShallowCopy(r->GetOutput());
  return g;
}

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("plyimpact_export_" + std::to_string(::getpid()));
  ~TempDir() { fs::remove_all(path); }
};

}  // namespace

TEST(MeshExport, RigidImpactorSurfaceIsAQuadGridReadBackExactly) {
  const config::Scene s = scene("");
  const mesh::Mesh m = mesh::mesh_scene(s);
  const model::Model model = model::build_model(s, m);
  TempDir dir;
  const auto written = app::export_mesh(s, m, model, dir.path);
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(written[2].filename(), "export_impactor.vtu");
  const auto g = read(written[2]);
  const auto& imp = *m.impactor;
  ASSERT_EQ(std::size_t(g->GetNumberOfPoints()), imp.surface_coords.size() / 3);
  ASSERT_EQ(std::size_t(g->GetNumberOfCells()), imp.surface_quads.size() / 4);
  for (vtkIdType a = 0; a < g->GetNumberOfPoints(); ++a) {
    double p[3];
    g->GetPoint(a, p);
    for (int i = 0; i < 3; ++i) ASSERT_EQ(p[i], imp.surface_coords[3 * std::size_t(a) + i]);
  }
  vtkDataArray* normal = g->GetCellData()->GetArray("outward_normal");
  ASSERT_NE(normal, nullptr);
  vtkNew<vtkIdList> ids;
  for (vtkIdType q = 0; q < g->GetNumberOfCells(); ++q) {
    ASSERT_EQ(g->GetCellType(q), VTK_QUAD);
    g->GetCellPoints(q, ids);
    for (int k = 0; k < 4; ++k) ASSERT_EQ(ids->GetId(k), imp.surface_quads[4 * std::size_t(q) + k]);
    const double* n = normal->GetTuple3(q);
    EXPECT_NEAR(std::hypot(n[0], n[1], n[2]), 1.0, 1e-8);  // unit, printed to 9 digits
  }
}

TEST(MeshExport, DeformableImpactorIsPartOfTheMeshFile) {
  const config::Scene s = scene(", rigid: false, material: steel, section: s");
  const mesh::Mesh m = mesh::mesh_scene(s);
  const model::Model model = model::build_model(s, m);
  TempDir dir;
  const auto written = app::export_mesh(s, m, model, dir.path);
  ASSERT_EQ(written.size(), 2u);
  EXPECT_FALSE(fs::exists(dir.path / "export_impactor.vtu"));
  const auto g = read(written[0]);
  EXPECT_EQ(std::size_t(g->GetNumberOfCells()), m.num_elements());
  EXPECT_GT(m.num_elements(), 8u);  // the plate's 8 and the impactor's
}
