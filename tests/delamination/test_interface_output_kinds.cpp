// The delamination outputs (interface series, C-scan, summary areas, a coupon's crack length) are
// the same whichever representation holds the plies together: tiebreak node pairs, *MAT_138
// cohesive elements with corner (Newton-Cotes) or 2 x 2 Gauss points, or the segment ties of a
// tiebreak contact between two parts.
//
// Plate of test_interface_output.cpp: 4 x 2 mm, 0.5 mm elements, plies 0/90/0/90 of
// 0.2/0.3/0.25/0.25 mm; pre-cracks on interface 1 (x in [0, 1.75], y in [0, 1.25] mm) and interface 3
// (x in [1.25, 3.25], y in [0.75, 2] mm). Their bounds lie on element mid-lines or the plate edge,
// which are also the bounds of what each sample point owns: a pair's tributary quarter-faces, a
// corner point's quadrant of its element, and a Gauss point's quadrant (the Gauss points of an
// element lie at 0.106 and 0.394 mm from its edge, on either side of the mid-line). So every
// representation separates exactly the rectangles, and the areas are known in closed form:
// A1 = 1.75 x 1.25, A3 = 2 x 1.25, overlap 0.5 x 0.5 mm^2. Tolerances are round-off (1e-12 relative
// on sums of about 100 areas).
// The tiebreak contact has no pre-crack key: its ties in the rectangle are separated through the run
// state (as a restart would set them), on a two-part plate meshed as the two-ply laminate.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkCellData.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "config/overrides.hpp"
#include "config/scene_loader.hpp"
#include "interface/surface_tiebreaks.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "output/json_reader.hpp"
#include "run/coupon_probe.hpp"
#include "run/interface_frame_writer.hpp"
#include "run/run.hpp"
#include "scratch_dir.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

const char* const kPrecracks =
    "per_interface: {1: {precrack: {x: [0, 1.75], y: [0, 1.25]}}, 3: {precrack: {x: [1.25, 3.25], y: [0.75, 2]}}}";

struct Representation {
  const char* name;
  std::string interfaces;
};

std::vector<Representation> representations() {
  const std::string cohesive =
      "{select: angle-change, model: cohesive, T: 60 MPa, S: 50 MPa, GIC: 765 J/m^2, GIIC: 1250 J/m^2, XMU: 1,\n"
      "               EN: 100 kN/mm^3, ET: 100 kN/mm^3, ";
  return {{"tiebreak pairs",
           "{select: angle-change, model: tiebreak, OPTION: 9, NFLS: 60 MPa, SFLS: 50 MPa, ERATEN: 765 J/m^2,\n"
           "               ERATES: 1250 J/m^2, PARAM: 1, CN: 100 kN/mm^3, CT2CN: 1, " + std::string(kPrecracks) + "}"},
          {"cohesive, corner points", cohesive + kPrecracks + "}"},
          {"cohesive, Gauss points", cohesive + "INTFAIL: 1, " + kPrecracks + "}"}};
}

std::string plate(const std::string& interfaces) {
  return "units: mm-t-s-MPa\n"
         "control: {termination_time: 2.0e-7}\n"
         "output: {interval: 5.0e-8}\n"
         "materials:\n"
         "  ply: {card: MAT_002, RO: 1600 kg/m^3, EA: 120 GPa, EB: 10 GPa, EC: 10 GPa, PRBA: 0.025, PRCA: 0.025,\n"
         "        PRCB: 0.45, GAB: 5 GPa, GBC: 3.5 GPa, GCA: 5 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
         "laminate:\n"
         "  length: 4\n  width: 2\n  ply_thickness: [0.2, 0.3, 0.25, 0.25]\n  stacking: [0, 90, 0, 90]\n"
         "  material: ply\n  section: s\n  element_size: 0.5\n"
         "  interfaces: " + interfaces + "\n";
}

struct Rect {
  double x0, x1, y0, y1;  // m
  bool holds(double x, double y) const { return x > x0 && x < x1 && y > y0 && y < y1; }
  double area() const { return (x1 - x0) * (y1 - y0); }
};
const Rect kCrack1{0, 1.75e-3, 0, 1.25e-3}, kCrack3{1.25e-3, 3.25e-3, 0.75e-3, 2e-3};
const double kOverlap = 0.5e-3 * 0.5e-3;
constexpr double kTol = 1e-12 * 8e-6;  // m^2

model::Model build(const std::string& yaml) {
  const config::Scene s = config::load_scene_from_string(yaml, "plate.yaml");
  return model::build_model(s, mesh::mesh_scene(s));
}

vtkSmartPointer<vtkMultiBlockDataSet> read_vtm(const fs::path& p) {
  vtkNew<vtkXMLMultiBlockDataReader> r;
  r->SetFileName(p.c_str());
  r->Update();
  return vtkMultiBlockDataSet::SafeDownCast(r->GetOutputDataObject(0));
}

// A quad's area (planar here) from its diagonals, and its centroid.
double quad_area(vtkUnstructuredGrid* g, vtkIdType c, double centroid[3]) {
  vtkIdType n;
  const vtkIdType* ids;
  g->GetCellPoints(c, n, ids);
  double p[4][3];
  for (int k = 0; k < 4; ++k) g->GetPoint(ids[k], p[k]);
  for (int i = 0; i < 3; ++i) centroid[i] = 0.25 * (p[0][i] + p[1][i] + p[2][i] + p[3][i]);
  const double d1[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
  const double d2[3] = {p[3][0] - p[1][0], p[3][1] - p[1][1], p[3][2] - p[1][2]};
  const double cx = d1[1] * d2[2] - d1[2] * d2[1], cy = d1[2] * d2[0] - d1[0] * d2[2], cz = d1[0] * d2[1] - d1[1] * d2[0];
  return 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
}

// The delaminated area of a block from its point data alone (a vertex owns a quarter of each of its
// quads), and a check that no quad straddles the rectangle's edge in a way the flags contradict: a
// quad whose centroid lies inside `crack` has its quarters there flagged, one outside has none.
double delaminated_area_of(vtkUnstructuredGrid* g, const Rect* crack, int* contradictions) {
  vtkDataArray* flag = g->GetPointData()->GetArray("delaminated");
  double sum = 0;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) {
    double centroid[3];
    const double area = quad_area(g, c, centroid);
    vtkIdType n;
    const vtkIdType* ids;
    g->GetCellPoints(c, n, ids);
    int on = 0;
    for (int k = 0; k < 4; ++k) on += flag->GetTuple1(ids[k]) != 0;
    sum += area * on / 4.0;
    const bool inside = crack && crack->holds(centroid[0], centroid[1]);
    if ((inside && on == 0) || (!inside && on == 4)) ++*contradictions;
  }
  return sum;
}

TEST(InterfaceOutputKinds, EveryLaminateRepresentationShowsThePrecracksExactly) {
  for (const Representation& rep : representations()) {
    SCOPED_TRACE(rep.name);
    test::ScratchDir dir;
    const model::Model model = build(plate(rep.interfaces));
    solver::Solver solver(model);
    run::InterfaceFrameWriter writer(model, dir.path(), 1e-5);
    writer.start(solver);
    run::RunReport report;
    writer.stop(&solver, report);
    ASSERT_TRUE(report.delamination);
    ASSERT_TRUE(report.warnings.empty()) << report.warnings.front();
    auto mb = read_vtm(dir.path() / "interfaces" / "interfaces_0000.vtm");
    ASSERT_TRUE(mb);
    ASSERT_EQ(mb->GetNumberOfBlocks(), 3u);
    const double depth[4] = {0, 0.8e-3, 0.5e-3, 0.25e-3};
    for (unsigned b = 0; b < 3; ++b) {
      const int id = int(b) + 1;
      auto* g = vtkUnstructuredGrid::SafeDownCast(mb->GetBlock(b));
      ASSERT_TRUE(g);
      const Rect* crack = id == 1 ? &kCrack1 : id == 3 ? &kCrack3 : nullptr;
      int contradictions = 0;
      const double expected = crack ? crack->area() : 0.0;
      EXPECT_NEAR(delaminated_area_of(g, crack, &contradictions), expected, kTol) << "interface " << id;
      EXPECT_EQ(contradictions, 0) << "interface " << id;
      for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p) {
        double x[3];
        g->GetPoint(p, x);
        EXPECT_NEAR(x[2], 1e-3 - depth[id], 1e-12) << "on the interface plane";
      }
      EXPECT_NEAR(report.delamination->interfaces[b].area, expected, kTol);
      EXPECT_DOUBLE_EQ(report.delamination->interfaces[b].depth, depth[id]);
    }
    EXPECT_NEAR(report.delamination->total_area, kCrack1.area() + kCrack3.area(), kTol);
    EXPECT_NEAR(report.delamination->projected_area, kCrack1.area() + kCrack3.area() - kOverlap, kTol);
    // The C-scan read back: the union, cell by cell.
    vtkNew<vtkXMLUnstructuredGridReader> r;
    r->SetFileName((dir.path() / "cscan.vtu").c_str());
    r->Update();
    vtkUnstructuredGrid* scan = r->GetOutput();
    vtkDataArray* count = scan->GetCellData()->GetArray("interfaces_delaminated");
    ASSERT_TRUE(count);
    double union_area = 0;
    for (vtkIdType c = 0; c < scan->GetNumberOfCells(); ++c) {
      double bounds[6];
      scan->GetCell(c)->GetBounds(bounds);
      const double x = 0.5 * (bounds[0] + bounds[1]), y = 0.5 * (bounds[2] + bounds[3]);
      EXPECT_EQ(count->GetTuple1(c), double(kCrack1.holds(x, y)) + double(kCrack3.holds(x, y)));
      if (count->GetTuple1(c) > 0) union_area += (bounds[1] - bounds[0]) * (bounds[3] - bounds[2]);
    }
    EXPECT_NEAR(union_area, kCrack1.area() + kCrack3.area() - kOverlap, kTol);
  }
}

// Through run_model: summary.json and history.csv give the same areas for every representation.
TEST(InterfaceOutputKinds, SummaryAreasAgreeAcrossRepresentations) {
  std::vector<double> totals, projected, third;
  for (const Representation& rep : representations()) {
    SCOPED_TRACE(rep.name);
    test::ScratchDir dir;
    const model::Model model = build(plate(rep.interfaces));
    run::RunOptions options;
    options.output_dir = dir.path();
    const run::RunReport report = run::run_model(model, options);
    ASSERT_TRUE(report.completed) << report.stop_reason;
    const output::Json summary = output::read_json_file(dir.path() / "summary.json");
    const output::Json* d = summary.find("delamination");
    ASSERT_TRUE(d);
    totals.push_back(d->find("delaminated_area")->as_number());
    projected.push_back(d->find("projected_delaminated_area")->as_number());
    third.push_back(d->find("interfaces")->as_array()[2].find("delaminated_area")->as_number());
    EXPECT_TRUE(fs::exists(dir.path() / "interfaces.pvd"));
    EXPECT_TRUE(fs::exists(dir.path() / "cscan.png"));
  }
  for (std::size_t k = 0; k < totals.size(); ++k) {
    EXPECT_NEAR(totals[k], kCrack1.area() + kCrack3.area(), kTol) << representations()[k].name;
    EXPECT_NEAR(projected[k], kCrack1.area() + kCrack3.area() - kOverlap, kTol) << representations()[k].name;
    EXPECT_NEAR(third[k], kCrack3.area(), kTol) << representations()[k].name;
  }
}

// Separates, through the run state, the ties of a tiebreak contact whose slave node lies in `crack`
// (the contact has no pre-crack key; this is what a restart dump holding such a state sets).
class SeparateTies : public StateVisitor {
 public:
  SeparateTies(const std::vector<char>& separate) : separate_(separate) {}
  void enter(std::string_view group) override { path_.emplace_back(group); }
  void leave() override { path_.pop_back(); }
  void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize, void*) override {
    if (path_.empty() || path_.back() != "segment tiebreaks" || name != "damage") return;
    ASSERT_EQ(elem_size, sizeof(double));
    ASSERT_EQ(count, separate_.size());
    for (std::size_t k = 0; k < count; ++k)
      if (separate_[k]) static_cast<double*>(data)[k] = 1.0;
  }

 private:
  const std::vector<char>& separate_;
  std::vector<std::string> path_;
};

TEST(InterfaceOutputKinds, TiebreakContactTiesShowTheSameAreaAsTheLaminate) {
  // Two parts of 0.5 mm meshed 8 x 4 x 1 (the upper the slave), and the two-ply laminate of the
  // same size and mesh with interface 1 pre-cracked on the same rectangle.
  const std::string boxes =
      "units: mm-t-s-MPa\n"
      "control: {termination_time: 2.0e-7}\n"
      "materials:\n  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
      "parts:\n  lower: {material: steel, section: s}\n  upper: {material: steel, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: lower, origin: [0, 0, 0], size: [4, 2, 0.5], elements: [8, 4, 1]}\n"
      "    - {part: upper, origin: [0, 0, 0.5], size: [4, 2, 0.5], elements: [8, 4, 1]}\n"
      "contacts:\n"
      "  - {name: glue, type: tiebreak_surface_to_surface, surfaces: [upper, lower], OPTION: 9, NFLS: 20 MPa,\n"
      "     SFLS: 20 MPa, ERATEN: 200 J/m^2, ERATES: 400 J/m^2, PARAM: 1, CN: 10 kN/mm^3, CT2CN: 1}\n";
  const model::Model model = build(boxes);
  ASSERT_EQ(model.tiebreak_contacts.size(), 1u);
  const interface::ContactTying tying = interface::tie_contact(model, model.tiebreak_contacts[0]);
  ASSERT_EQ(tying.result.ties.size(), 45u) << "every node of the 8 x 4 slave face";
  std::vector<char> in(tying.result.ties.size(), 0);
  const double tol = 1e-12;
  for (std::size_t k = 0; k < in.size(); ++k) {
    const double* X = &model.X[3 * std::size_t(tying.result.ties[k].slave)];
    in[k] = X[0] <= kCrack1.x1 + tol && X[1] <= kCrack1.y1 + tol;
  }
  test::ScratchDir dir;
  solver::Solver solver(model);
  SeparateTies visitor(in);
  solver.visit_state(visitor);
  solver.step();  // the reported area is the ties' own count of their last force pass, as history.csv's
  run::InterfaceFrameWriter writer(model, dir.path(), 1e-5);
  writer.start(solver);
  run::RunReport report;
  writer.stop(&solver, report);
  ASSERT_TRUE(report.delamination);
  ASSERT_EQ(report.delamination->interfaces.size(), 1u);
  const auto& contact = report.delamination->interfaces[0];
  EXPECT_EQ(contact.label, "tiebreak contact glue");
  EXPECT_EQ(contact.id, 1) << "numbered after the laminate's interfaces (none here)";
  EXPECT_NEAR(contact.depth, 0.5e-3, 1e-15) << "below the top of the tied parts";
  EXPECT_NEAR(contact.area, kCrack1.area(), kTol);
  EXPECT_NEAR(report.delamination->projected_area, kCrack1.area(), kTol);
  auto mb = read_vtm(dir.path() / "interfaces" / "interfaces_0000.vtm");
  ASSERT_TRUE(mb);
  auto* g = vtkUnstructuredGrid::SafeDownCast(mb->GetBlock(0));
  ASSERT_TRUE(g);
  EXPECT_EQ(g->GetNumberOfCells(), 32) << "the fully tied slave faces";
  int contradictions = 0;
  EXPECT_NEAR(delaminated_area_of(g, &kCrack1, &contradictions), kCrack1.area(), kTol);
  EXPECT_EQ(contradictions, 0);

  const std::string laminate =
      "units: mm-t-s-MPa\n"
      "control: {termination_time: 2.0e-7}\n"
      "materials:\n  steel: {card: MAT_001, RO: 7.85e-9, E: 210 GPa, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
      "laminate:\n  length: 4\n  width: 2\n  ply_thickness: 0.5\n  stacking: [0, 90]\n"
      "  material: steel\n  section: s\n  element_size: 0.5\n"
      "  interfaces: {select: all, model: tiebreak, OPTION: 9, NFLS: 20 MPa, SFLS: 20 MPa, ERATEN: 200 J/m^2,\n"
      "               ERATES: 400 J/m^2, PARAM: 1, CN: 10 kN/mm^3, CT2CN: 1, precrack: {x: [0, 1.75], y: [0, 1.25]}}\n";
  const model::Model lam = build(laminate);
  solver::Solver lam_solver(lam);
  test::ScratchDir lam_dir;
  run::InterfaceFrameWriter lam_writer(lam, lam_dir.path(), 1e-5);
  lam_writer.start(lam_solver);
  run::RunReport lam_report;
  lam_writer.stop(&lam_solver, lam_report);
  ASSERT_TRUE(lam_report.delamination);
  EXPECT_NEAR(lam_report.delamination->total_area, contact.area, kTol);
  EXPECT_NEAR(lam_report.delamination->interfaces[0].depth, contact.depth, 1e-15);
}

// A coupon's crack length from the damage front: the pre-crack x <= 25 mm of the shipped DCB at CI
// width gives a traction-free length of 25.5 mm with pairs and with corner points (the separated
// row at 25 mm owns half a segment beyond it), and 26 mm with Gauss points and a region x <= 25.8 mm
// (the segment [25, 26] mm's two points separated, its quadrants reach its far node).
TEST(InterfaceOutputKinds, CouponCrackLengthFromEveryRepresentation) {
  std::ifstream in(std::string(PLYIMPACT_SOURCE_DIR) + "/configs/dcb_t800s_m21.yaml");
  std::stringstream text;
  text << in.rdbuf();
  const std::string yaml = text.str();
  const std::size_t from = yaml.find("  interfaces: {"), to = yaml.find("node_sets:");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  const std::string cohesive =
      "  interfaces: {select: [1], model: cohesive, T: 60 MPa, S: 60 MPa, GIC: 765 J/m^2, GIIC: 1250 J/m^2, XMU: 1,\n"
      "               EN: 100 kN/mm^3, ET: 100 kN/mm^3, ";
  const struct {
    const char* name;
    std::string interfaces;
    double crack;
  } cases[] = {{"pairs", yaml.substr(from, to - from), 25.5e-3},
               {"corner points", cohesive + "precrack: {x: [0, 25]}}\n", 25.5e-3},
               {"Gauss points", cohesive + "INTFAIL: 1, precrack: {x: [0, 25.8]}}\n", 26e-3}};
  std::vector<config::SceneOverride> o;
  for (const char* s : {"laminate.width=2", "laminate.length=60", "node_sets.block_top.box.max=[0.01, 3, 3.1]",
                        "node_sets.block_bottom.box.max=[0.01, 3, 1.49]"})
    o.push_back(config::parse_set_argument(s));
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::string scene = yaml;
    scene.replace(from, to - from, c.interfaces);
    std::vector<config::SceneOverride> overrides = o;
    if (std::string(c.name) == "pairs")  // the shipped card, its pre-crack at the CI length
      overrides.push_back(config::parse_set_argument("laminate.interfaces.precrack.x=[0, 25]"));
    const config::Scene s = config::load_scene_from_string(scene, "dcb.yaml", overrides);
    const model::Model model = model::build_model(s, mesh::mesh_scene(s));
    solver::Solver solver(model);
    const run::CouponProbe probe(model);
    EXPECT_NEAR(probe.crack_length(solver), c.crack, 1e-12);
  }
}

}  // namespace
}  // namespace plyimpact
