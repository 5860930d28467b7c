// Element-length scaling of the *MAT_054 erosion strains (erosion_reference_length, docs/theory.md
// "Erosion strains and the element length"). The quantity kept across meshes is the elongation of
// an element at erosion, a crack opening: an element shorter than the reference length L_ref
// erodes at the card's strain times L_ref / h, so it opens by about DFAILT L_ref whatever h.
// Independent answer: the kinematics of a single element pulled along its fibres, whose total
// strain (the sum of D dt, the logarithmic strain of a homogeneous stretch) reaches the scaled
// limit when its length is h exp(k DFAILT).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../core/support.hpp"
#include "output/json_reader.hpp"
#include "run/run.hpp"
#include "model/erosion_scale.hpp"
#include "model/subsystems.hpp"

namespace plyimpact {
namespace {

constexpr double kPly = 0.25e-3, kReference = 2.5e-3, kDFAILT = 0.0156, kV = 1.0;

// One ply element h x h x 0.25 mm, fibres along x: x = 0 face held in x, y = 0 in y, z = 0 in z,
// the x = h face pulled at kV (ramped over 2e-6 s). The fibre-tension failure (XT) takes the fibre
// stress away in one cycle; the element then stretches freely until its total strain reaches the
// erosion limit. NCYRED 1 and SLIM 0: the seed's cards.
std::string pulled_ply(double h, int elform, bool regularised) {
  const std::string H = std::to_string(h);
  return "units: SI\ncontrol: {termination_time: 1, tssfac: 0.6}\nmaterials:\n"
         "  m: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895,"
         " PRCB: 0.53, GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, XT: 2.2e9, XC: 1.2e9, YT: 45e6, YC: 280e6, SC: 45e6,"
         " BETA: 1, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], DFAILT: " + std::to_string(kDFAILT) +
         (regularised ? ", erosion_reference_length: " + std::to_string(kReference) : std::string()) + "}\n"
         "sections:\n  s: {ELFORM: " + std::to_string(elform) + (elform == 1 ? ", IHQ: 4" : "") + "}\n"
         "parts:\n  p: {material: m, section: s}\n"
         "mesh:\n  boxes:\n    - {part: p, size: [" + H + ", " + H + ", " + std::to_string(kPly) +
         "], elements: [1, 1, 1]}\n"
         "node_sets:\n  x0: {plane: {axis: x, value: 0}}\n  x1: {plane: {axis: x, value: " + H + "}}\n"
         "  y0: {plane: {axis: y, value: 0}}\n  z0: {plane: {axis: z, value: 0}}\n"
         "boundary_conditions:\n  - {node_set: x0, fix: [x]}\n  - {node_set: y0, fix: [y]}\n"
         "  - {node_set: z0, fix: [z]}\n"
         "  - {node_set: x1, velocity: {dofs: [x], curve: [[0, 0], [2.0e-6, 1.0], [1, 1.0]]}}\n";
}

// Elongation of the element (mean x of its pulled face minus h) in the cycle it erodes.
double opening_at_erosion(const model::Model& model, double h) {
  solver::Solver s(model);
  while (s.state().eroded_elements == 0 && s.state().time < 1e-3) s.step();
  EXPECT_EQ(s.state().eroded_elements, 1) << "h = " << h;
  double x = 0;
  int n = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i)
    if (model.X[3 * i] > 0.5 * h) x += s.state().x[3 * i], ++n;
  return x / n - h;
}

class ErosionLength : public ::testing::TestWithParam<int> {};  // parameter: ELFORM 1 or -2

TEST_P(ErosionLength, ElementShorterThanTheReferenceOpensAsTheReferenceElement) {
  const int elform = GetParam();
  for (double h : {5e-3, 2.5e-3, 1.25e-3, 0.625e-3}) {
    const model::Model model = test::model_from_yaml(pulled_ply(h, elform, true), "pulled_ply.yaml");
    ASSERT_EQ(model.blocks[0].erosion_scale.size(), 1u);
    const double k = std::max(1.0, kReference / h);
    // The ply-plane length of an h x h x t element is h: sqrt(V / t), to round-off.
    EXPECT_NEAR(model.blocks[0].erosion_scale[0], k, 1e-12 * k) << "h = " << h;
    const double opening = opening_at_erosion(model, h);
    // Tolerance 0.5 %: the last cycle overshoots the limit by at most one step's stretch,
    // kV dt ~ 3e-8 m against openings of 3.9e-5 m and more (under 0.1 %).
    const double expected = h * std::expm1(k * kDFAILT);
    EXPECT_NEAR(opening, expected, 5e-3 * expected) << "ELFORM " << elform << ", h = " << h;
    if (h <= kReference) {
      // The opening is the reference element's, to the logarithmic strain's second order:
      // h (exp(k DFAILT) - 1) = L_ref DFAILT (1 + k DFAILT / 2 + ...), 3 % apart at k = 4.
      const double reference_opening = kReference * std::expm1(kDFAILT);
      EXPECT_NEAR(opening, reference_opening, 0.035 * reference_opening) << "h = " << h;
    }
  }
}

TEST_P(ErosionLength, WithoutAReferenceLengthTheOpeningShrinksWithTheElement) {
  // The mechanism the scaling removes: the card's strain in a quarter-size element opens a quarter.
  const int elform = GetParam();
  const double coarse = opening_at_erosion(test::model_from_yaml(pulled_ply(2.5e-3, elform, false)), 2.5e-3);
  const double fine = opening_at_erosion(test::model_from_yaml(pulled_ply(0.625e-3, elform, false)), 0.625e-3);
  EXPECT_TRUE(test::model_from_yaml(pulled_ply(0.625e-3, elform, false)).blocks[0].erosion_scale.empty());
  EXPECT_NEAR(fine / coarse, 0.25, 0.25 * 5e-3);
}

TEST(ErosionScale, CheckSaysWhichElementsAreScaled) {
  const auto find = [](const model::Model& m) {
    for (const auto& s : model::subsystems(m))
      if (s.name == "erosion_length_scaling") return s;
    ADD_FAILURE() << "no erosion_length_scaling subsystem";
    return model::Subsystem{};
  };
  const auto fine = find(test::model_from_yaml(pulled_ply(0.625e-3, 1, true)));
  EXPECT_TRUE(fine.active);
  EXPECT_NE(fine.detail.find("1 of 1 elements"), std::string::npos) << fine.detail;
  EXPECT_NE(fine.detail.find("up to 4 x"), std::string::npos) << fine.detail;
  const auto coarse = find(test::model_from_yaml(pulled_ply(5e-3, 1, true)));
  EXPECT_TRUE(coarse.active);
  EXPECT_NE(coarse.detail.find("at least their reference length"), std::string::npos) << coarse.detail;
  const auto off = find(test::model_from_yaml(pulled_ply(0.625e-3, 1, false)));
  EXPECT_FALSE(off.active);
  EXPECT_NE(off.detail.find("left out"), std::string::npos) << off.detail;
}

// The run summary's eroded volume is the reference volume of the deleted elements (here the one
// pulled element, h x h x t to round-off): the quantity a zone study compares across meshes, where
// the eroded count grows as the elements shrink. Its energy per part and cause sums to the total.
TEST(ErosionSummary, ErodedVolumeIsTheReferenceVolumeOfTheDeletedElements) {
  const double h = 1.25e-3;
  model::Model model = test::model_from_yaml(pulled_ply(h, 1, true));
  model.control.termination_time = 1e-4;  // erosion at ~4e-5 s (k DFAILT L_ref / 1 m/s)
  const auto dir = std::filesystem::temp_directory_path() / ("plyimpact_eroded_volume_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  run::RunOptions options;
  options.output_dir = dir;
  const run::RunReport report = run::run_model(model, options);
  ASSERT_TRUE(report.completed) << report.stop_reason;
  std::ifstream in(dir / "summary.json");
  std::stringstream text;
  text << in.rdbuf();
  const output::Json summary = output::parse_json(text.str(), "summary.json");
  const output::Json* erosion = summary.find("erosion");
  ASSERT_NE(erosion, nullptr);
  EXPECT_EQ(erosion->find("eroded_elements")->as_number(), 1);
  EXPECT_NEAR(erosion->find("eroded_volume")->as_number(), h * h * kPly, 1e-12 * h * h * kPly);
  // The energy per part and cause adds up to the eroded energy (here one entry holds all of it).
  const double total = erosion->find("eroded_energy")->as_number();
  double by_cause = 0;
  for (const auto& entry : erosion->find("by_part_and_cause")->as_array()) by_cause += entry.find("energy")->as_number();
  EXPECT_GT(total, 0.0);
  EXPECT_NEAR(by_cause, total, 1e-12 * total);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Elform, ErosionLength, ::testing::Values(1, -2),
                         [](const auto& info) { return info.param == 1 ? std::string("Elform1") : std::string("ElformMinus2"); });

TEST(ErosionScale, PlyPlaneLengthIgnoresTheInPlaneAxesAndTheShape) {
  // An h x 2h x t element, sheared in its plane (a parallelogram of the same area): sqrt(2) h,
  // whatever the in-plane fibre angle; only the c axis (the ply normal) enters.
  const double h = 1e-3, t = 0.25e-3, shear = 0.4e-3;
  double x[3][8];
  const double base[8][3] = {{0, 0, 0}, {h, 0, 0}, {h, 2 * h, 0}, {0, 2 * h, 0},
                             {0, 0, t}, {h, 0, t}, {h, 2 * h, t}, {0, 2 * h, t}};
  for (int k = 0; k < 8; ++k) {
    x[0][k] = base[k][0] + shear * base[k][1] / (2 * h);
    x[1][k] = base[k][1];
    x[2][k] = base[k][2];
  }
  const double volume = 2 * h * h * t;
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Mat3 rotated{c, s, 0, -s, c, 0, 0, 0, 1};
  const Mat3 plain{1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_NEAR(model::ply_plane_length(x, volume, rotated), std::sqrt(2.0) * h, 1e-15);
  EXPECT_NEAR(model::ply_plane_length(x, volume, plain), std::sqrt(2.0) * h, 1e-15);
  EXPECT_EQ(model::erosion_strain_scale(2.5e-3, 5e-3), 1.0);  // longer than the reference: the card's
  EXPECT_EQ(model::erosion_strain_scale(2.5e-3, 1.25e-3), 2.0);
}

}  // namespace
}  // namespace plyimpact
