// The frames of a run as ParaView reads them: a small [45/0/-45/90] *MAT_054 laminate with bonded
// interfaces (which leave unused copies of the interface nodes in the model) and a rigid sphere
// flying towards it (its surface nodes are model nodes without elements), run with `plyimpact run`
// and every file read back with VTK's XML reader. Independent references:
//  - ply angles and part names: the scene's stacking and the mesher's part names ply_<i>_<angle>
//    (m for minus), as a user writes them in the contact's surface list; angles to 1e-9 degree
//    (atan2 of unit vectors built from the angle: round-off 1e-14).
//  - unused nodes: every written point is a corner of a written cell, and the bodies' bounds at
//    t = 0 are the plate's (30 x 30 x 1 mm) to 1e-12 m, although the sphere sits above it.
//  - node_id: the written points at t = 0 are the model's reference coordinates of node_id - 1.
//  - the rigid block: before contact the sphere flies freely at v = 5 m/s (no gravity), so every
//    point of its surface moves by v (t1 - t0) between two frames; central differences advance a
//    constant velocity exactly, up to the round-off of adding dt v to coordinates of 1e-2 m:
//    1e-15 m; asserted to 1e-12 m (the frame times t0, t1 are read from the files).
//  - compression: zlib by default, lz4 or none when the scene says so, and the values read back
//    identical in all three (lossless).
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "app/application.hpp"
#include "config/scene_loader.hpp"
#include "core/error.hpp"
#include "frame_reader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "scratch_dir.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

constexpr double kV = 5.0;                  // m/s, the sphere's speed towards the plate
constexpr double kPlate = 30e-3, kThickness = 1e-3;

std::string scene_yaml(const std::string& output_extra) {
  return "units: mm-t-s-MPa\ncontrol: {termination_time: 4.0e-6}\n"
         "output: {interval: 2.0e-6" + output_extra + "}\n"
         "materials:\n  ply: {card: MAT_054, RO: 1.55e-9, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.01895,"
         " PRCA: 0.01895, PRCB: 0.53, GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0],"
         " XT: 2.2 GPa, XC: 1.2 GPa, YT: 0.045 GPa, YC: 0.28 GPa, SC: 0.045 GPa}\n"
         "  steel: {card: MAT_001, RO: 7.857e-9, E: 206.7 GPa, PR: 0.3}\n"
         "sections:\n  ply: {ELFORM: 1, IHQ: 2, QM: 0.1}\n"
         "laminate:\n  length: 30\n  width: 30\n  ply_thickness: 0.25\n  stacking: \"[45/0/-45/90]\"\n"
         "  material: ply\n  section: ply\n  element_size: 3\n  interfaces: angle-change\n"
         "  supports:\n    window: {window: [24, 24]}\n"
         "impactor:\n  shape: sphere\n  diameter: 8\n  mass: 0.05 kg\n  gap: 0.5\n  velocity: 5 m/s\n"
         "  element_size: 2\n  rigid: true\n  material: steel\n"
         "contacts:\n  - {name: impact, type: automatic_surface_to_surface, surfaces: [impactor, [ply_1_45, ply_2_0,"
         " ply_3_m45, ply_4_90]], SOFT: 1}\n";
}

struct SceneRun {
  fs::path out;
  config::Scene scene;
};

SceneRun run_scene(const test::ScratchDir& dir, const std::string& name, const std::string& output_extra = "") {
  const fs::path file = dir.path() / (name + ".yaml");
  std::ofstream(file) << scene_yaml(output_extra);
  std::ostringstream o, e;
  const fs::path out = dir.path() / (name + "_out");
  EXPECT_EQ(app::run_application({"run", file.string(), "-o", out.string()}, o, e), 0) << e.str() << o.str();
  return {out, config::load_scene(file.string())};
}

struct PvdEntry {
  double time;
  int part;
  std::string name, file;
};

std::vector<PvdEntry> read_pvd(const fs::path& path) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  EXPECT_EQ(parser->Parse(), 1) << path;
  std::vector<PvdEntry> out;
  vtkXMLDataElement* c = parser->GetRootElement() ? parser->GetRootElement()->FindNestedElementWithName("Collection") : nullptr;
  if (c == nullptr) return out;
  for (int i = 0; i < c->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* d = c->GetNestedElement(i);
    const char* name = d->GetAttribute("name");
    out.push_back({std::stod(d->GetAttribute("timestep")), std::stoi(d->GetAttribute("part")), name ? name : "",
                   d->GetAttribute("file")});
  }
  return out;
}

std::vector<std::string> strings(const test::ReadFrame& f, const std::string& name) {
  auto* a = vtkStringArray::SafeDownCast(f.grid->GetFieldData()->GetAbstractArray(name.c_str()));
  std::vector<std::string> out;
  if (a == nullptr) {
    ADD_FAILURE() << "no field-data string array '" << name << "'";
    return out;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i) out.push_back(a->GetValue(i));
  return out;
}

// Every point is a corner of some cell.
void expect_no_unused_points(const test::ReadFrame& f, const char* what) {
  std::vector<char> used(f.num_points(), 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < f.grid->GetNumberOfCells(); ++c) {
    f.grid->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) used[std::size_t(ids->GetId(k))] = 1;
  }
  std::size_t unused = 0;
  for (char u : used) unused += u == 0;
  EXPECT_EQ(unused, 0u) << what << ": points of no cell";
}

// Each point and cell array of the file has its unit in the field data `units`.
std::map<std::string, std::string> expect_units(const test::ReadFrame& f, const char* what) {
  std::map<std::string, std::string> units;
  for (const auto& entry : strings(f, "units")) {
    const auto colon = entry.find(": ");
    EXPECT_NE(colon, std::string::npos) << entry;
    if (colon != std::string::npos) units[entry.substr(0, colon)] = entry.substr(colon + 2);
  }
  for (vtkFieldData* data : {static_cast<vtkFieldData*>(f.grid->GetPointData()), static_cast<vtkFieldData*>(f.grid->GetCellData())})
    for (int i = 0; i < data->GetNumberOfArrays(); ++i)
      EXPECT_TRUE(units.count(data->GetArrayName(i))) << what << ": array '" << data->GetArrayName(i) << "' has no unit";
  return units;
}

TEST(FrameBlocks, PliesPartsUnusedNodesUnitsAndTheMovingImpactor) {
  test::ScratchDir dir;
  const SceneRun run = run_scene(dir, "plate");
  const model::Model model = model::build_model(run.scene, mesh::mesh_scene(run.scene));
  ASSERT_FALSE(model.impactor_quads.empty());

  // The series: three times (0, 2 us, 4 us), each with the bodies and the rigid block.
  const auto pvd = read_pvd(run.out / "plate.pvd");
  ASSERT_EQ(pvd.size(), 6u);
  for (std::size_t i = 0; i < pvd.size(); ++i) {
    EXPECT_EQ(pvd[i].part, int(i % 2));
    EXPECT_EQ(pvd[i].name, i % 2 == 0 ? "bodies" : "rigid");
    EXPECT_EQ(pvd[i].time, pvd[i - i % 2].time);
  }
  EXPECT_EQ(pvd[0].file, "plate_0000.vtu");
  EXPECT_EQ(pvd[1].file, "plate_rigid_0000.vtu");
  const test::ReadFrame bodies = test::read_vtu(run.out / pvd[0].file);
  const test::ReadFrame rigid0 = test::read_vtu(run.out / pvd[1].file), rigid1 = test::read_vtu(run.out / pvd[3].file);

  // No unused points; the bounds are the plate's although the model's nodes reach up the sphere.
  expect_no_unused_points(bodies, "bodies");
  expect_no_unused_points(rigid0, "rigid");
  double b[6];
  bodies.grid->GetBounds(b);
  const double want[6] = {0, kPlate, 0, kPlate, 0, kThickness};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(b[k], want[k], 1e-12) << "bound " << k;
  std::size_t used_nodes = 0;
  {
    std::vector<char> used(model.num_nodes(), 0);
    for (const auto& blk : model.blocks)
      for (Index n : blk.conn) used[std::size_t(n)] = 1;
    for (char u : used) used_nodes += u;
  }
  EXPECT_EQ(bodies.num_points(), used_nodes);
  EXPECT_LT(used_nodes, model.num_nodes());  // the scene does have nodes without elements
  std::cout << "bodies frame: " << bodies.num_points() << " points of " << model.num_nodes() << " model nodes\n";

  // node_id maps each point to its model node.
  for (vtkIdType p = 0; p < vtkIdType(bodies.num_points()); ++p) {
    const auto id = std::size_t(bodies.point("node_id", p)[0]);
    ASSERT_GE(id, 1u);
    for (int d = 0; d < 3; ++d) ASSERT_EQ(bodies.points[3 * std::size_t(p) + d], model.X[3 * (id - 1) + d]) << "point " << p;
  }

  // Ply index, ply angle and part names.
  const double angles[4] = {45, 0, -45, 90};
  const std::string names[4] = {"ply_1_45", "ply_2_0", "ply_3_m45", "ply_4_90"};
  std::map<int, std::string> part_name;
  for (const auto& entry : strings(bodies, "legend_part_id")) {
    const auto colon = entry.find(": ");
    part_name[std::stoi(entry.substr(0, colon))] = entry.substr(colon + 2);
  }
  std::set<int> plies_seen;
  for (vtkIdType c = 0; c < bodies.grid->GetNumberOfCells(); ++c) {
    const int ply = int(bodies.cell("ply_index", c)[0]);
    ASSERT_GE(ply, 1);
    ASSERT_LE(ply, 4);
    plies_seen.insert(ply);
    EXPECT_NEAR(bodies.cell("ply_angle", c)[0], angles[ply - 1], 1e-9) << "cell " << c;
    EXPECT_EQ(part_name[int(bodies.cell("part_id", c)[0])], names[ply - 1]) << "cell " << c;
  }
  EXPECT_EQ(plies_seen.size(), 4u);

  // The rigid block: the sphere's surface quads, moving with the sphere.
  ASSERT_EQ(std::size_t(rigid0.grid->GetNumberOfCells()), model.impactor_quads.size() / 4);
  for (vtkIdType c = 0; c < rigid0.grid->GetNumberOfCells(); ++c) EXPECT_EQ(rigid0.grid->GetCellType(c), VTK_QUAD);
  EXPECT_EQ(strings(rigid0, "legend_rigid_body"), std::vector<std::string>{"1: impactor"});
  ASSERT_EQ(rigid0.num_points(), rigid1.num_points());
  const double t0 = pvd[1].time, t1 = pvd[3].time;
  ASSERT_GT(t1 - t0, 1e-6);
  for (std::size_t p = 0; p < rigid0.num_points(); ++p) {
    EXPECT_NEAR(rigid1.points[3 * p] - rigid0.points[3 * p], 0.0, 1e-12);
    EXPECT_NEAR(rigid1.points[3 * p + 1] - rigid0.points[3 * p + 1], 0.0, 1e-12);
    EXPECT_NEAR(rigid1.points[3 * p + 2] - rigid0.points[3 * p + 2], -kV * (t1 - t0), 1e-12) << "point " << p;
  }
  double rb[6];
  rigid0.grid->GetBounds(rb);
  EXPECT_GT(rb[4], kThickness);  // above the plate

  // Units, legends and notes as field data.
  const auto units = expect_units(bodies, "bodies");
  expect_units(rigid0, "rigid");
  EXPECT_EQ(units.at("displacement"), "m");
  EXPECT_EQ(units.at("stress"), "Pa");
  EXPECT_EQ(units.at("ply_angle"), "deg");
  EXPECT_EQ(units.at("mat054_XT"), "Pa");
  const auto causes = strings(bodies, "legend_mat054_erosion_cause");
  ASSERT_EQ(causes.size(), 9u);
  for (std::size_t c = 0; c < causes.size(); ++c) EXPECT_EQ(causes[c].rfind(std::to_string(c) + ": ", 0), 0u) << causes[c];
  EXPECT_EQ(strings(bodies, "legend_mat054_em").size(), 2u);
  EXPECT_EQ(strings(bodies, "legend_alive").size(), 2u);
  bool nan_note = false;
  for (const auto& n : strings(bodies, "notes")) nan_note = nan_note || n.find("NaN") != std::string::npos;
  EXPECT_TRUE(nan_note);
  EXPECT_EQ(strings(bodies, "unit_system").size(), 1u);
}

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(FrameBlocks, CompressedByDefaultLz4OrNoneOnRequestAndLossless) {
  test::ScratchDir dir;
  const SceneRun zlib = run_scene(dir, "zlib"), lz4 = run_scene(dir, "lz4", ", compression: lz4"),
            none = run_scene(dir, "none", ", compression: none");
  for (const char* frame : {"_0002.vtu", "_rigid_0002.vtu"}) {
    const std::string z = file_text(zlib.out / (std::string("zlib") + frame));
    const std::string l = file_text(lz4.out / (std::string("lz4") + frame));
    const std::string n = file_text(none.out / (std::string("none") + frame));
    EXPECT_NE(z.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos) << frame;
    EXPECT_NE(l.find("compressor=\"vtkLZ4DataCompressor\""), std::string::npos) << frame;
    EXPECT_EQ(n.find("compressor="), std::string::npos) << frame;
    EXPECT_LT(z.size(), n.size());
    EXPECT_LT(l.size(), n.size());
    std::cout << frame << ": none " << n.size() << " B, zlib " << z.size() << " B, lz4 " << l.size() << " B\n";
    const test::ReadFrame fz = test::read_vtu(zlib.out / (std::string("zlib") + frame)),
                          fl = test::read_vtu(lz4.out / (std::string("lz4") + frame)),
                          fn = test::read_vtu(none.out / (std::string("none") + frame));
    ASSERT_GT(fn.num_points(), 0u);
    EXPECT_EQ(fz.points, fn.points);
    EXPECT_EQ(fl.points, fn.points);
    for (vtkFieldData* data : {static_cast<vtkFieldData*>(fn.grid->GetPointData()), static_cast<vtkFieldData*>(fn.grid->GetCellData())}) {
      const bool cells = data == fn.grid->GetCellData();
      for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
        const std::string name = data->GetArrayName(i);
        const vtkIdType count = cells ? fn.grid->GetNumberOfCells() : vtkIdType(fn.num_points());
        for (vtkIdType k = 0; k < count; ++k) {
          const auto want = cells ? fn.cell(name, k) : fn.point(name, k);
          const auto got_z = cells ? fz.cell(name, k) : fz.point(name, k);
          const auto got_l = cells ? fl.cell(name, k) : fl.point(name, k);
          for (std::size_t c = 0; c < want.size(); ++c) {
            if (std::isnan(want[c])) {
              EXPECT_TRUE(std::isnan(got_z[c]) && std::isnan(got_l[c])) << name;
            } else {
              ASSERT_EQ(got_z[c], want[c]) << name << " tuple " << k;
              ASSERT_EQ(got_l[c], want[c]) << name << " tuple " << k;
            }
          }
        }
      }
    }
  }
}

TEST(FrameBlocks, UnknownCompressionIsRefusedWithItsPlace) {
  try {
    config::load_scene_from_string(scene_yaml(", compression: gzip"), "scene.yaml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("scene.yaml:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("output.compression"), std::string::npos) << what;
    EXPECT_NE(what.find("zlib"), std::string::npos) << what;
    EXPECT_NE(what.find("lz4"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace plyimpact
