// The delamination outputs as a ParaView user and an inspector read them back: the interface series
// (interfaces.pvd -> .vtm with one named block per interface -> .vtu), the C-scan (cscan.vtu,
// cscan.png) and the areas for summary.json, on a small laminate with pre-cracks whose areas are
// known in closed form.
//
// Scene: 4 x 2 mm plate, 0.5 mm elements, plies 0/90/0/90 of 0.2/0.3/0.25/0.25 mm (bottom first), so
// interfaces 1, 2, 3 lie 0.8, 0.5 and 0.25 mm below the top (impacted) face. Pre-cracks:
//   interface 1: x in [0, 1.75], y in [0, 1.25] mm;  interface 3: x in [1.25, 3.25], y in [0.75, 2] mm.
// Their bounds lie on element mid-lines (or the plate edge), so the pairs inside own tributary
// areas that tile each rectangle exactly: A1 = 1.75 x 1.25, A3 = 2 x 1.25, overlap 0.5 x 0.5 mm^2,
// union A1 + A3 - overlap. The C-scan raster (pitch half the element, aligned with the mesh) has its
// cell edges on those mid-lines, so its union area and depths are exact too. Tolerances are
// round-off (1e-12 relative on sums of ~100 areas of 1e-7 m^2; 1e-9 on openings of 1e-7 m taken as
// differences of millimetre coordinates).
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkFieldData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "output/json_reader.hpp"
#include "run/interface_frame_writer.hpp"
#include "run/run.hpp"
#include "scratch_dir.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

const std::string kScene =
    "units: mm-t-s-MPa\n"
    "control: {termination_time: 1.0e-5}\n"
    "materials:\n"
    "  ply: {card: MAT_002, RO: 1600 kg/m^3, EA: 120 GPa, EB: 10 GPa, EC: 10 GPa, PRBA: 0.025, PRCA: 0.025,\n"
    "        PRCB: 0.45, GAB: 5 GPa, GBC: 3.5 GPa, GCA: 5 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
    "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
    "laminate:\n"
    "  length: 4\n  width: 2\n  ply_thickness: [0.2, 0.3, 0.25, 0.25]\n  stacking: [0, 90, 0, 90]\n"
    "  material: ply\n  section: s\n  element_size: 0.5\n"
    "  interfaces: {select: angle-change, model: tiebreak, OPTION: 9, NFLS: 60 MPa, SFLS: 50 MPa,\n"
    "               ERATEN: 765 J/m^2, ERATES: 1250 J/m^2, PARAM: 1, CN: 100 kN/mm^3, CT2CN: 1,\n"
    "               per_interface: {1: {precrack: {x: [0, 1.75], y: [0, 1.25]}},\n"
    "                               3: {precrack: {x: [1.25, 3.25], y: [0.75, 2]}}}}\n";

struct Rect {
  double x0, x1, y0, y1;  // m
  bool holds(double x, double y) const { return x > x0 && x < x1 && y > y0 && y < y1; }
  double area() const { return (x1 - x0) * (y1 - y0); }
};
const Rect kCrack1{0, 1.75e-3, 0, 1.25e-3}, kCrack3{1.25e-3, 3.25e-3, 0.75e-3, 2e-3};
const double kOverlap = 0.5e-3 * 0.5e-3;
const double kDepth[4] = {0, 0.8e-3, 0.5e-3, 0.25e-3};  // by interface number

model::Model build() {
  const config::Scene s = config::load_scene_from_string(kScene, "itf.yaml");
  return model::build_model(s, mesh::mesh_scene(s));
}

vtkSmartPointer<vtkMultiBlockDataSet> read_vtm(const fs::path& p) {
  vtkNew<vtkXMLMultiBlockDataReader> r;
  r->SetFileName(p.c_str());
  r->Update();
  return vtkMultiBlockDataSet::SafeDownCast(r->GetOutputDataObject(0));
}

// Area of the delaminated part of a quad surface from its point data alone: a point owns a quarter
// of each quad around it (the tributary rule), so a quad contributes its area times the share of
// its delaminated corners. Quads here are planar rectangles: area from the diagonals' cross product.
double delaminated_area_of(vtkUnstructuredGrid* g) {
  vtkDataArray* flag = g->GetPointData()->GetArray("delaminated");
  double sum = 0;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) {
    vtkIdType n;
    const vtkIdType* ids;
    g->GetCellPoints(c, n, ids);
    double p[4][3];
    for (int k = 0; k < 4; ++k) g->GetPoint(ids[k], p[k]);
    const double d1[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double d2[3] = {p[3][0] - p[1][0], p[3][1] - p[1][1], p[3][2] - p[1][2]};
    const double cx = d1[1] * d2[2] - d1[2] * d2[1], cy = d1[2] * d2[0] - d1[0] * d2[2], cz = d1[0] * d2[1] - d1[1] * d2[0];
    const double area = 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
    int on = 0;
    for (int k = 0; k < 4; ++k) on += flag->GetTuple1(ids[k]) != 0;
    sum += area * on / 4.0;
  }
  return sum;
}

TEST(InterfaceOutput, SeriesHasOneNamedBlockPerInterfaceWithThePrecrackExactly) {
  test::ScratchDir dir;
  const model::Model model = build();
  solver::Solver solver(model);
  run::InterfaceFrameWriter writer(model, dir.path(), 1e-5);
  writer.start(solver);
  run::RunReport report;
  writer.stop(&solver, report);

  const std::string pvd = test::slurp(dir.path() / "interfaces.pvd");
  EXPECT_NE(pvd.find("file=\"interfaces/interfaces_0000.vtm\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0\""), std::string::npos) << pvd;
  auto mb = read_vtm(dir.path() / "interfaces" / "interfaces_0000.vtm");
  ASSERT_TRUE(mb);
  ASSERT_EQ(mb->GetNumberOfBlocks(), 3u);
  const char* names[3] = {"interface_1 (plies 1/2, 0/90)", "interface_2 (plies 2/3, 90/0)",
                          "interface_3 (plies 3/4, 0/90)"};
  for (unsigned b = 0; b < 3; ++b) {
    const int id = int(b) + 1;
    EXPECT_STREQ(mb->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()), names[b]);
    auto* g = vtkUnstructuredGrid::SafeDownCast(mb->GetBlock(b));
    ASSERT_TRUE(g) << names[b];
    EXPECT_EQ(g->GetNumberOfPoints(), 9 * 5) << "a pair per node of the 8 x 4 interface grid";
    EXPECT_EQ(g->GetNumberOfCells(), 8 * 4);
    for (const char* f : {"damage", "mode_mixity", "opening_normal", "opening_shear", "traction_normal",
                          "traction_shear", "displacement", "delaminated"})
      EXPECT_TRUE(g->GetPointData()->GetArray(f)) << f;
    EXPECT_TRUE(vtkStringArray::SafeDownCast(g->GetFieldData()->GetAbstractArray("units")));
    // Damage 1 exactly on the pre-crack (closed region), 0 elsewhere; points at the reference
    // mid-surface of the interface, 1e-12 m tolerance for the rounding of the coordinates.
    vtkDataArray* damage = g->GetPointData()->GetArray("damage");
    const Rect* crack = id == 1 ? &kCrack1 : id == 3 ? &kCrack3 : nullptr;
    for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p) {
      double x[3];
      g->GetPoint(p, x);
      const bool in = crack && x[0] >= crack->x0 - 1e-12 && x[0] <= crack->x1 + 1e-12 && x[1] >= crack->y0 - 1e-12 &&
                      x[1] <= crack->y1 + 1e-12;
      EXPECT_EQ(damage->GetTuple1(p), in ? 1.0 : 0.0) << names[b] << " at " << x[0] << ", " << x[1];
      EXPECT_NEAR(x[2], 1e-3 - kDepth[id], 1e-12) << "on the interface plane";
    }
    const double expected = crack ? crack->area() : 0.0;
    EXPECT_NEAR(delaminated_area_of(g), expected, 1e-12 * 8e-6) << names[b];
    ASSERT_TRUE(report.delamination);
    EXPECT_NEAR(report.delamination->interfaces[b].area, expected, 1e-12 * 8e-6);
    EXPECT_DOUBLE_EQ(report.delamination->interfaces[b].depth, kDepth[id]);
  }
  EXPECT_NEAR(report.delamination->total_area, kCrack1.area() + kCrack3.area(), 1e-12 * 8e-6);
  EXPECT_NEAR(report.delamination->projected_area, kCrack1.area() + kCrack3.area() - kOverlap, 1e-12 * 8e-6);
}

TEST(InterfaceOutput, CscanShowsTheShallowestDelaminationAndTheUnion) {
  test::ScratchDir dir;
  const model::Model model = build();
  solver::Solver solver(model);
  run::InterfaceFrameWriter writer(model, dir.path(), 1e-5);
  writer.start(solver);
  run::RunReport report;
  writer.stop(&solver, report);
  ASSERT_TRUE(report.warnings.empty()) << report.warnings.front();

  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName((dir.path() / "cscan.vtu").c_str());
  r->Update();
  vtkUnstructuredGrid* g = r->GetOutput();
  ASSERT_GT(g->GetNumberOfCells(), 0);
  vtkDataArray* shallow = g->GetCellData()->GetArray("depth_shallowest");
  vtkDataArray* deep = g->GetCellData()->GetArray("depth_deepest");
  vtkDataArray* count = g->GetCellData()->GetArray("interfaces_delaminated");
  vtkDataArray* first = g->GetCellData()->GetArray("shallowest_interface");
  ASSERT_TRUE(shallow && deep && count && first);
  double union_area = 0;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) {
    double b[6];
    g->GetCell(c)->GetBounds(b);
    const double x = 0.5 * (b[0] + b[1]), y = 0.5 * (b[2] + b[3]);
    EXPECT_NEAR(b[4], 1e-3, 1e-15) << "the plane of the impacted face";
    const bool in1 = kCrack1.holds(x, y), in3 = kCrack3.holds(x, y);
    EXPECT_EQ(count->GetTuple1(c), double(in1) + double(in3)) << x << ", " << y;
    if (in3) {  // interface 3 is nearer the impacted face and hides interface 1 where they overlap
      EXPECT_DOUBLE_EQ(shallow->GetTuple1(c), 0.25);
      EXPECT_EQ(first->GetTuple1(c), 3);
    } else if (in1) {
      EXPECT_DOUBLE_EQ(shallow->GetTuple1(c), 0.8);
      EXPECT_EQ(first->GetTuple1(c), 1);
    } else {
      EXPECT_TRUE(std::isnan(shallow->GetTuple1(c)));
      EXPECT_EQ(first->GetTuple1(c), 0);
    }
    if (in1) {
      EXPECT_DOUBLE_EQ(deep->GetTuple1(c), 0.8);
    } else if (in3) {
      EXPECT_DOUBLE_EQ(deep->GetTuple1(c), 0.25);
    }
    if (count->GetTuple1(c) > 0) union_area += (b[1] - b[0]) * (b[3] - b[2]);
  }
  EXPECT_NEAR(union_area, kCrack1.area() + kCrack3.area() - kOverlap, 1e-12 * 8e-6);

  // The PNG: a real image of the requested size (PNG signature, IHDR width and height big-endian).
  const std::string png = test::slurp(dir.path() / "cscan.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const auto be32 = [&](std::size_t at) {
    return (unsigned(std::uint8_t(png[at])) << 24) | (unsigned(std::uint8_t(png[at + 1])) << 16) |
           (unsigned(std::uint8_t(png[at + 2])) << 8) | unsigned(std::uint8_t(png[at + 3]));
  };
  EXPECT_EQ(be32(16), 1000u);
  EXPECT_EQ(be32(20), 750u);
  EXPECT_GT(png.size(), 5000u) << "axes, legend and map, not a blank image";
}

// Openings, tractions and the mid-surface's displacement as written: the upper side of interface 2
// moved rigidly by 0.1 um along x (shear) and z (opening). Below onset ((10/60)^2 + (10/50)^2 < 1) the law is linear:
// t = CN delta in both directions (CT2CN = 1), and G_II/G_T = Kt ds^2 / (Kn dn^2 + Kt ds^2) = 1/2.
TEST(InterfaceOutput, OpeningTractionAndMixityOfAKnownSeparation) {
  test::ScratchDir dir;
  const model::Model model = build();
  solver::Solver solver(model);
  const double delta = 1e-7;
  for (Index n : model.interfaces[1].upper_nodes) {
    solver.state().x[3 * std::size_t(n)] += delta;
    solver.state().x[3 * std::size_t(n) + 2] += delta;
  }
  run::InterfaceFrameWriter writer(model, dir.path(), 1e-5);
  writer.start(solver);
  auto mb = read_vtm(dir.path() / "interfaces" / "interfaces_0000.vtm");
  ASSERT_TRUE(mb);
  for (unsigned b = 0; b < 3; ++b) {
    auto* g = vtkUnstructuredGrid::SafeDownCast(mb->GetBlock(b));
    const bool moved = b == 1;
    const auto value = [&](const char* f, vtkIdType p) { return g->GetPointData()->GetArray(f)->GetTuple1(p); };
    vtkDataArray* u = g->GetPointData()->GetArray("displacement");
    ASSERT_TRUE(u);
    for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p) {
      // The mid-surface moved by half the upper side's motion (the lower side stayed).
      const double* up = u->GetTuple3(p);
      EXPECT_NEAR(up[0], moved ? 0.5 * delta : 0.0, 1e-15);
      EXPECT_EQ(up[1], 0.0);
      EXPECT_NEAR(up[2], moved ? 0.5 * delta : 0.0, 1e-15);
      if (!moved) {
        EXPECT_EQ(value("opening_normal", p), 0.0);
        continue;
      }
      EXPECT_NEAR(value("opening_normal", p), delta, 1e-9 * delta);
      EXPECT_NEAR(value("opening_shear", p), delta, 1e-9 * delta);
      EXPECT_NEAR(value("traction_normal", p), 1e14 * delta, 1e-9 * 1e7);
      EXPECT_NEAR(value("traction_shear", p), 1e14 * delta, 1e-9 * 1e7);
      EXPECT_NEAR(value("mode_mixity", p), 0.5, 1e-9);
      EXPECT_EQ(value("damage", p), 0.0);
      double x[3];
      g->GetPoint(p, x);
      EXPECT_NEAR(x[2], 1e-3 - kDepth[2] + 0.5 * delta, 1e-15) << "the mid-surface of the pair";
    }
  }
}

std::vector<std::string> timesteps(const fs::path& pvd) {
  const std::string text = test::slurp(pvd);
  const std::regex attr("timestep=\"([^\"]*)\"");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), attr); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

// Through the run: the interface series has the ply frames' times, and summary.json carries the
// areas with their units and names the files.
TEST(InterfaceOutput, RunWritesTheSeriesAtTheFrameTimesAndTheAreasInTheSummary) {
  test::ScratchDir dir;
  model::Model model = build();
  model.control.termination_time = 2e-7;
  model.output.interval = 5e-8;
  run::RunOptions options;
  options.output_dir = dir.path();
  const run::RunReport report = run::run_model(model, options);
  ASSERT_TRUE(report.completed) << report.stop_reason;
  const auto plies = timesteps(dir.path() / (model.name + ".pvd")), interfaces = timesteps(dir.path() / "interfaces.pvd");
  EXPECT_GE(plies.size(), 5u);
  EXPECT_EQ(interfaces, plies);
  const output::Json summary = output::read_json_file(dir.path() / "summary.json");
  const output::Json* d = summary.find("delamination");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->find("units")->find("area")->as_string(), "m^2");
  EXPECT_NEAR(d->find("delaminated_area")->as_number(), kCrack1.area() + kCrack3.area(), 1e-12 * 8e-6);
  EXPECT_NEAR(d->find("projected_delaminated_area")->as_number(), kCrack1.area() + kCrack3.area() - kOverlap,
              1e-12 * 8e-6);
  const auto& per = d->find("interfaces")->as_array();
  ASSERT_EQ(per.size(), 3u);
  EXPECT_EQ(per[2].find("name")->as_string(), "interface_3 (plies 3/4, 0/90)");
  EXPECT_NEAR(per[2].find("delaminated_area")->as_number(), kCrack3.area(), 1e-12 * 8e-6);
  const output::Json* files = summary.find("files");
  EXPECT_EQ(files->find("interfaces")->as_string(), "interfaces.pvd");
  EXPECT_EQ(files->find("cscan_png")->as_string(), "cscan.png");
  EXPECT_TRUE(fs::exists(dir.path() / "cscan.vtu"));
}

}  // namespace
}  // namespace plyimpact
