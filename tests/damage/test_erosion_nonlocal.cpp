// Erosion strains averaged over the reference length (erosion_nonlocal, docs/theory.md "Erosion
// strains and the element length"). An element shorter than erosion_reference_length R erodes by a
// card's strain limit when the bell-weighted mean strain of the elements within R of it (itself
// included) reaches it, and by its own strain at the limit times R / h. Independent answers: the share a straight band of one element
// carries in a bell-weighted disc, 16 h / (5 pi R) (the integral of (1 - r^2/R^2)^2 along a line
// through the centre over its integral over the disc); the kinematics of a homogeneous stretch.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../core/support.hpp"
#include "mat054_support.hpp"
#include "material/erosion_neighbourhood.hpp"
#include "model/erosion_neighbours.hpp"
#include "model/subsystems.hpp"
#include "solver/solver.hpp"

namespace plyimpact {
namespace {

constexpr double kPly = 0.25e-3, kReference = 2.5e-3, kDFAILT = 0.0156;

// A ply of n x n elements of h x h x 0.25 mm, fibres along x, the x = 0 face held in x, y = 0 in
// y, z = 0 in z and the x = n h face pulled at 1 m/s (ramped over 2e-6 s): a homogeneous stretch.
std::string pulled_ply(double h, int n, bool nonlocal) {
  const std::string L = std::to_string(n * h), N = std::to_string(n);
  return "units: SI\ncontrol: {termination_time: 1, tssfac: 0.6}\nmaterials:\n"
         "  m: {card: MAT_054, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.01895, PRCA: 0.01895,"
         " PRCB: 0.53, GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, XT: 2.2e9, XC: 1.2e9, YT: 45e6, YC: 280e6, SC: 45e6,"
         " BETA: 1, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0], DFAILT: " + std::to_string(kDFAILT) +
         ", erosion_reference_length: " + std::to_string(kReference) +
         (nonlocal ? ", erosion_nonlocal: true" : "") + "}\n"
         "sections:\n  s: {ELFORM: 1, IHQ: 4}\n"
         "parts:\n  p: {material: m, section: s}\n"
         "mesh:\n  boxes:\n    - {part: p, size: [" + L + ", " + L + ", " + std::to_string(kPly) + "], elements: [" +
         N + ", " + N + ", 1]}\n"
         "node_sets:\n  x0: {plane: {axis: x, value: 0}}\n  x1: {plane: {axis: x, value: " + L + "}}\n"
         "  y0: {plane: {axis: y, value: 0}}\n  z0: {plane: {axis: z, value: 0}}\n"
         "boundary_conditions:\n  - {node_set: x0, fix: [x]}\n  - {node_set: y0, fix: [y]}\n"
         "  - {node_set: z0, fix: [z]}\n"
         "  - {node_set: x1, velocity: {dofs: [x], curve: [[0, 0], [2.0e-6, 1.0], [1, 1.0]]}}\n";
}

TEST(ErosionNonlocal, ABandOfOneElementCarriesItsShareOfTheBellWeights) {
  // 16 x 16 elements of 0.625 mm, R = 2.5 mm: the element near the centre has neighbours out to
  // four elements; its row (itself and the row's elements) carries 16 h / (5 pi R) = 0.2546 of
  // the weights in the continuum. Tolerance 1 %: the grid sum approximates the integrals; at
  // h / R = 1/4 the two agree to 0.2 %.
  const double h = 0.625e-3;
  const model::Model model = test::model_from_yaml(pulled_ply(h, 16, true), "nonlocal.yaml");
  const auto& block = model.blocks[0];
  const auto& n = block.erosion_neighbours;
  ASSERT_FALSE(n.empty());
  ASSERT_EQ(block.erosion_scale.size(), block.size());  // the factor R / h = 4 still bounds the strains
  EXPECT_NEAR(block.erosion_scale[0], 4.0, 1e-12);
  EXPECT_EQ(n.elements_with_neighbours(), block.size());
  const auto centroid = [&](std::size_t e, int d) {
    double c = 0;
    for (int k = 0; k < 8; ++k) c += 0.125 * model.X[3 * std::size_t(block.conn[8 * e + k]) + d];
    return c;
  };
  std::size_t centre = 0;
  for (std::size_t e = 0; e < block.size(); ++e)
    if (std::abs(centroid(e, 0) - 8.5 * h) < 1e-9 && std::abs(centroid(e, 1) - 8.5 * h) < 1e-9) centre = e;
  double total = n.self_weight[centre], row = n.self_weight[centre];
  int count = 0;
  for (Index k = n.start[centre]; k < n.start[centre + 1]; ++k) {
    total += n.weight[std::size_t(k)];
    ++count;
    if (std::abs(centroid(std::size_t(n.index[std::size_t(k)]), 1) - centroid(centre, 1)) < 1e-9)
      row += n.weight[std::size_t(k)];
  }
  EXPECT_NEAR(total, 1.0, 1e-14);
  EXPECT_EQ(count, 44);  // grid points with 0 < i^2 + j^2 < 16
  const double band_share = 16 * h / (5 * M_PI * kReference);
  EXPECT_NEAR(row, band_share, 0.01 * band_share);
  EXPECT_NEAR(model::bell_weight(0.5 * kReference, kReference), 0.5625, 1e-15);
  EXPECT_EQ(model::bell_weight(kReference, kReference), 0.0);

  // An element of the reference length has no neighbour within R: the card's strains, exactly.
  EXPECT_TRUE(test::model_from_yaml(pulled_ply(2.5e-3, 2, true)).blocks[0].erosion_neighbours.empty());
}

// One material point of the seed's 0 degree card pulled along its fibres, with the factor k = 4 (an
// element a quarter of the reference length) and one neighbour of weight 1 - w0 whose strain is
// `follow` times the point's, both read one step behind (the previous pass's buffers, as in the
// solver): the strain at which the point erodes.
constexpr int kStride = material::kErosionStrainStride;

void fill_buffer(const material::CompositeDamageParams& p, const double e[6], double* out) {
  for (int i = 0; i < 6; ++i) out[i] = e[i];
  out[material::kErosionStrainPastCard] = material::composite_damage_strain_limits(p, e, 1.0) != 0;
}

double erosion_strain(double w0, double follow, bool with_neighbourhood) {
  test::PointDriver d(test::t800_card_0deg());
  const Index start[3] = {0, 1, 1}, index[1] = {1};
  const double weight[1] = {1 - w0}, self[2] = {w0, 1};
  std::vector<double> read(2 * kStride, 0.0);
  const material::ErosionNeighbourhoodView view{start, index, weight, self, read.data(), nullptr};
  d.ctx.erosion_scale = 4;
  const double step = 1e-5;
  for (int k = 0; k < 20000 && !d.result().erode; ++k) {
    double own[6], other[6];
    for (int i = 0; i < 6; ++i) own[i] = d.strain()[i], other[i] = follow * own[i];
    fill_buffer(d.params(), own, &read[0]);
    fill_buffer(d.params(), other, &read[kStride]);
    if (with_neighbourhood && view.any_past_card(0)) {
      double mean[6];
      view.mean(0, mean);
      d.ctx.mean_limits = material::composite_damage_strain_limits(d.params(), mean, 1.0);
    }
    d.uniaxial_step(0, step);
  }
  EXPECT_TRUE(d.result().erode);
  EXPECT_EQ(d.result().cause, int(material::CompositeDamageCause::DFAILT));
  return d.strain()[0];
}

TEST(ErosionNonlocal, TheMeanErodesAtTheCardsStrainsTheFactorBoundsThem) {
  const double DFAILT = test::t800_card_0deg().DFAILT, step = 1e-5;
  // Without a neighbourhood: the scaled limit 4 DFAILT, within the step that crosses it.
  EXPECT_NEAR(erosion_strain(0.5, 0, false), 4 * DFAILT, step);
  // The neighbour strained alike (a uniform field): the card's DFAILT, within two steps (the lag).
  EXPECT_NEAR(erosion_strain(0.5, 1, true), DFAILT, 2 * step);
  // The neighbour unstrained, carrying half the weights: the mean reaches DFAILT when the point's
  // own strain is 2 DFAILT. (A band of one element of h = R/4 carries a quarter, so its mean and
  // the factor agree there, as the band share test above shows.)
  EXPECT_NEAR(erosion_strain(0.5, 0, true), 2 * DFAILT, 2 * step);
  // The neighbour strained the other way (a kink): the mean stays at zero, and the factor's limit
  // erodes the point.
  EXPECT_NEAR(erosion_strain(0.5, -1, true), 4 * DFAILT, 2 * step);
}

TEST(ErosionNonlocal, APointBesideABandErodesWithIt) {
  // The neighbour, with half the weights, has opened to 2.5 DFAILT (a band that has just eroded
  // keeps that strain); the point itself is barely strained. The mean, 1.25 DFAILT, erodes it at
  // its first update, by DFAILT: the reference element holding both would have eroded too.
  test::PointDriver d(test::t800_card_0deg());
  const double DFAILT = d.params().DFAILT;
  const Index start[3] = {0, 1, 1}, index[1] = {1};
  const double weight[1] = {0.5}, self[2] = {0.5, 1};
  std::vector<double> read(2 * kStride, 0.0);
  const double band[6] = {2.5 * DFAILT, 0, 0, 0, 0, 0}, none[6] = {};
  fill_buffer(d.params(), none, &read[0]);
  fill_buffer(d.params(), band, &read[kStride]);
  const material::ErosionNeighbourhoodView view{start, index, weight, self, read.data(), nullptr};
  ASSERT_TRUE(view.any_past_card(0));
  double mean[6];
  view.mean(0, mean);
  EXPECT_DOUBLE_EQ(mean[0], 1.25 * DFAILT);
  d.ctx.erosion_scale = 4;
  d.ctx.mean_limits = material::composite_damage_strain_limits(d.params(), mean, 1.0);
  d.uniaxial_step(0, 1e-5);
  EXPECT_TRUE(d.result().erode);
  EXPECT_EQ(d.result().cause, int(material::CompositeDamageCause::DFAILT));
  // With the band at 1.5 DFAILT the mean stays below the card's limit and the point lives on.
  const double weak[6] = {1.5 * DFAILT, 0, 0, 0, 0, 0};
  fill_buffer(d.params(), weak, &read[kStride]);
  view.mean(0, mean);
  EXPECT_EQ(material::composite_damage_strain_limits(d.params(), mean, 1.0), 0);
}

// Mean elongation of the pulled face when the first element erodes, and how many have eroded ten
// cycles later.
std::pair<double, long> stretch_at_erosion(const model::Model& model, double length) {
  solver::Solver s(model);
  while (s.state().eroded_elements == 0 && s.state().time < 1e-3) s.step();
  double x = 0;
  int n = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i)
    if (model.X[3 * i] > length * (1 - 1e-9)) x += s.state().x[3 * i], ++n;
  for (int k = 0; k < 10; ++k) s.step();
  return {x / n - length, s.state().eroded_elements};
}

TEST(ErosionNonlocal, AHomogeneousStretchErodesAtTheCardsStrainWhateverTheElementSize) {
  // 4 x 4 elements of 0.625 mm pulled along the fibres: every element's strain is the same, so
  // with the neighbourhood all erode at the card's DFAILT (the opening of the 2.5 mm reference
  // element pulled alike), while the factor R / h = 4 holds them to four times that strain.
  // Tolerance 0.5 %: the last cycles overshoot by a step's stretch (under 0.1 %), the lag by one.
  const double h = 0.625e-3, L = 4 * h;
  const auto nonlocal = stretch_at_erosion(test::model_from_yaml(pulled_ply(h, 4, true)), L);
  const double expected = L * std::expm1(kDFAILT);
  EXPECT_NEAR(nonlocal.first, expected, 5e-3 * expected);
  // All within ten cycles (the stretch grows by under 1 % meanwhile): the strains are equal to
  // round-off, and each mean reads its neighbours one pass behind.
  EXPECT_EQ(nonlocal.second, 16);
  const auto scaled = stretch_at_erosion(test::model_from_yaml(pulled_ply(h, 4, false)), L);
  const double scaled_expected = L * std::expm1(4 * kDFAILT);
  EXPECT_NEAR(scaled.first, scaled_expected, 5e-3 * scaled_expected);
}

TEST(ErosionNonlocal, CheckSaysWhichElementsAverage) {
  const model::Model model = test::model_from_yaml(pulled_ply(0.625e-3, 4, true));
  for (const auto& s : model::subsystems(model))
    if (s.name == "erosion_length_scaling") {
      EXPECT_TRUE(s.active);
      EXPECT_NE(s.detail.find("16 of 16 elements"), std::string::npos) << s.detail;
      EXPECT_NE(s.detail.find("erosion_nonlocal"), std::string::npos) << s.detail;
      return;
    }
  ADD_FAILURE() << "no erosion_length_scaling subsystem";
}

}  // namespace
}  // namespace plyimpact
