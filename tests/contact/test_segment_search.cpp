// The contact toolkit without a penalty contact (contact/segment_set, contact/segment_search): what a
// tie between two surfaces (tiebreak, bonded interface) needs is a segment set over the two sides
// and, per node of one side, the segment of the other side it lies on and its projection there.
// Scene: two plates of n x n x 1 cubic elements (h = 1 mm) stacked on the plane z = h with
// duplicated nodes (merge_nodes: false), an interface without a law; once with matching meshes and
// once with the upper plate shifted in plane by (0.3 h, 0.2 h).
// References (geometry, independent of the search):
//  - matching: every interface node of either side lies on a node of the other side (its
//    duplicate); its partner segment holds that duplicate, the projection is that point (shape
//    weight 1 on the duplicate) at gap 0;
//  - shifted: a node of the upper plate over the lower plate's top face projects onto the lower
//    segment whose square contains (x, y), at the natural coordinates xi = 2 (x - x_c) / h,
//    eta = 2 (y - y_c) / h (x_c, y_c: the square's centre), at gap 0; a node over the overhang
//    (x > L or y > L, by 0.2 h at least, far beyond the MAXPAR tolerance of 0.025 h) finds none.
//  - nodes a plate thickness away from the interface find nothing within the tie distance;
//  - deleting the corner element of the upper plate (rebuild) removes its four exterior faces and
//    its two nodes no other element holds, exposes the two faces of its neighbours, and maps every
//    other segment and node to one with the same side and nodes (their identity).
// Tolerances: coordinates are sums of a few multiples of h, exact to ~1e-19 m; 1e-12 h on points
// and gaps and 1e-12 on natural coordinates and weights leave room for the Newton projection's
// round-off (its last step is below 1e-12 in natural coordinates).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "contact/segment_search.hpp"
#include "contact/segment_set.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kH = 1e-3;  // element edge, m
constexpr int kN = 4;        // elements per plate edge
constexpr double kL = kN * kH;

model::Model stacked_plates(double dx, double dy) {
  const std::string size = "[" + std::to_string(kL) + ", " + std::to_string(kL) + ", 0.001]";
  const std::string elems = "[" + std::to_string(kN) + ", " + std::to_string(kN) + ", 1]";
  const std::string yaml =
      std::string("units: SI\ncontrol: {termination_time: 1}\n") +
      "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1}\n"
      "parts:\n  lower: {material: steel, section: s}\n  upper: {material: steel, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: lower, size: " + size + ", elements: " + elems + "}\n"
      "    - {part: upper, origin: [" + std::to_string(dx) + ", " + std::to_string(dy) + ", 0.001], size: " + size +
      ", elements: " + elems + "}\n";
  return test::model_from_yaml(yaml, "stacked.yaml");
}

// The segment set of the two plates: side A the lower, B the upper.
contact::SegmentSet plates_set(const model::Model& model) {
  contact::SegmentSetSpec spec;
  spec.blocks[0] = {model.parts[0].block};
  spec.blocks[1] = {model.parts[1].block};
  return contact::SegmentSet(model, spec, model.X);
}

// That set and a search sorted for ties at x.
struct Tie {
  contact::SegmentSet set;
  contact::SegmentSearch search;
};

Tie make_tie(const model::Model& model) {
  Tie t{plates_set(model), contact::SegmentSearch(contact::SearchOptions{})};
  t.search.reset(t.set, model.X.data());
  t.search.sort(t.set, model.X.data(), 0.0, /*full_depth=*/true);
  return t;
}

const double* node_x(const model::Model& m, Index n) { return &m.X[3 * std::size_t(n)]; }

TEST(SegmentSearch, MatchingInterfaceNodesFindTheirDuplicateOnTheOtherSide) {
  const model::Model model = stacked_plates(0, 0);
  Tie tie = make_tie(model);
  const contact::SegmentSet& set = tie.set;
  // Each plate: 2 n^2 faces top and bottom + 4 n side faces.
  ASSERT_EQ(set.num_segments(), std::size_t(2 * (2 * kN * kN + 4 * kN)));
  const double tie_distance = 0.01 * kH;
  std::size_t interface_nodes = 0;
  for (std::size_t i = 0; i < set.num_nodes(); ++i) {
    const Index node = set.node_id(i);
    const double* p = node_x(model, node);
    contact::Projection pr;
    const long s = tie.search.nearest_segment(set, i, model.X.data(), tie_distance, pr);
    const bool on_interface = std::abs(p[2] - kH) < 1e-12 * kH;
    if (!on_interface) {
      EXPECT_LT(s, 0) << "node " << node << " a thickness away found segment " << s;
      continue;
    }
    ++interface_nodes;
    ASSERT_GE(s, 0) << "interface node " << node << " found no partner";
    EXPECT_EQ(set.segment_side(std::size_t(s)), 1 - set.node_side(i));
    // The partner segment holds the node's duplicate, with shape weight 1 at the projection.
    const Index* q = set.segment_nodes(std::size_t(s));
    int duplicate = -1;
    for (int a = 0; a < 4; ++a) {
      const double* qa = node_x(model, q[a]);
      if (q[a] != node && std::abs(qa[0] - p[0]) + std::abs(qa[1] - p[1]) + std::abs(qa[2] - p[2]) < 1e-12 * kH)
        duplicate = a;
    }
    ASSERT_GE(duplicate, 0) << "segment " << s << " does not hold node " << node << "'s duplicate";
    EXPECT_NEAR(pr.N[duplicate], 1.0, 1e-12);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(pr.point[d], p[d], 1e-12 * kH);
    EXPECT_NEAR(pr.gap, 0.0, 1e-12 * kH);
  }
  // (n + 1)^2 interface nodes per side.
  EXPECT_EQ(interface_nodes, std::size_t(2 * (kN + 1) * (kN + 1)));
}

TEST(SegmentSearch, ShiftedInterfaceNodesProjectAtTheirBilinearCoordinates) {
  const double dx = 0.3 * kH, dy = 0.2 * kH;
  const model::Model model = stacked_plates(dx, dy);
  Tie tie = make_tie(model);
  const contact::SegmentSet& set = tie.set;
  const double tie_distance = 0.01 * kH;
  std::size_t over = 0, overhang = 0;
  for (std::size_t i = 0; i < set.num_nodes(); ++i) {
    if (set.node_side(i) != 1) continue;  // the upper plate's nodes on the lower plate
    const Index node = set.node_id(i);
    const double* p = node_x(model, node);
    if (std::abs(p[2] - kH) > 1e-12 * kH) continue;  // not on the interface plane
    contact::Projection pr;
    const long s = tie.search.nearest_segment(set, i, model.X.data(), tie_distance, pr);
    if (p[0] > kL + 1e-12 * kH || p[1] > kL + 1e-12 * kH) {
      ++overhang;
      EXPECT_LT(s, 0) << "node " << node << " over the overhang found segment " << s;
      continue;
    }
    ++over;
    ASSERT_GE(s, 0) << "node " << node << " over the lower plate found no segment";
    // The lower top-face square that contains (x, y); its centre from the grid.
    const double xc = (std::floor(p[0] / kH) + 0.5) * kH, yc = (std::floor(p[1] / kH) + 0.5) * kH;
    const Index* q = set.segment_nodes(std::size_t(s));
    double cx = 0, cy = 0, cz = 0;
    for (int a = 0; a < 4; ++a) {
      cx += 0.25 * node_x(model, q[a])[0];
      cy += 0.25 * node_x(model, q[a])[1];
      cz += 0.25 * node_x(model, q[a])[2];
    }
    EXPECT_NEAR(cx, xc, 1e-12 * kH);
    EXPECT_NEAR(cy, yc, 1e-12 * kH);
    EXPECT_NEAR(cz, kH, 1e-12 * kH);
    // Natural coordinates up to the face's orientation (a top face's xi, eta axes may be any of
    // the in-plane directions): compare |xi|, |eta| as a set.
    const double u = std::abs(2 * (p[0] - xc) / kH), w = std::abs(2 * (p[1] - yc) / kH);
    const double a = std::abs(pr.xi), b = std::abs(pr.eta);
    EXPECT_TRUE((std::abs(a - u) < 1e-12 && std::abs(b - w) < 1e-12) ||
                (std::abs(a - w) < 1e-12 && std::abs(b - u) < 1e-12))
        << "node " << node << ": (xi, eta) = (" << pr.xi << ", " << pr.eta << "), expected |.| = " << u << ", " << w;
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(pr.point[d], p[d], 1e-12 * kH);
    EXPECT_NEAR(pr.gap, 0.0, 1e-12 * kH);
  }
  // Upper interface nodes: (n + 1)^2; over the overhang: those with x or y beyond L (the last
  // column and row of the shifted grid).
  EXPECT_EQ(over + overhang, std::size_t((kN + 1) * (kN + 1)));
  EXPECT_EQ(overhang, std::size_t(2 * (kN + 1) - 1));
}

TEST(SegmentSet, RebuildKeepsTheIdentityOfWhatSurvives) {
  const model::Model model = stacked_plates(0, 0);
  contact::SegmentSet set = plates_set(model);
  const contact::SegmentSet before = set;
  const std::size_t upper = std::size_t(model.parts[1].block);
  contact::AliveMask alive(model.blocks.size());
  alive[upper].assign(model.blocks[upper].size(), 1);
  alive[upper][0] = 0;  // the corner element (x, y fastest)
  const contact::SegmentSetRemap r = set.rebuild(alive, model.X);
  ASSERT_EQ(set.num_segments(), before.num_segments() - 4 + 2);
  std::size_t gone = 0, added = 0;
  for (std::size_t s = 0; s < before.num_segments(); ++s) {
    if (r.segment[s] < 0) {
      ++gone;
      const Index* o = before.segment_owner(s);
      EXPECT_TRUE(std::equal(o, o + 8, &model.blocks[upper].conn[0])) << "segment " << s << " lost";
      continue;
    }
    EXPECT_EQ(set.segment_key(r.segment[s]), before.segment_key(long(s)));
  }
  for (char c : r.new_segment) added += c != 0;
  EXPECT_EQ(gone, 4u);
  EXPECT_EQ(added, 2u);
  std::size_t nodes_gone = 0;
  for (std::size_t i = 0; i < before.num_nodes(); ++i) {
    if (r.node[i] < 0) {
      ++nodes_gone;
      continue;
    }
    EXPECT_EQ(set.node_id(std::size_t(r.node[i])), before.node_id(i));
    EXPECT_EQ(set.node_side(std::size_t(r.node[i])), before.node_side(i));
  }
  EXPECT_EQ(nodes_gone, 2u);
  for (char c : r.new_node) EXPECT_EQ(c, 0);
}

// A rebuild carries a segment's neighbours over (renumbered) when none of its nodes lost or gained
// a segment, and searches the others. Reference: by definition, the segments of the same side
// sharing a node with s, ascending, found by comparing every pair of segments. Four rebuilds
// erode elements of both plates, one and several at a time, including neighbours of earlier holes.
TEST(SegmentSet, RebuiltNeighboursAreTheSegmentsOfTheSameSideSharingANode) {
  const model::Model model = stacked_plates(0, 0);
  contact::SegmentSet set = plates_set(model);
  contact::AliveMask alive(model.blocks.size());
  for (std::size_t b = 0; b < model.blocks.size(); ++b) alive[b].assign(model.blocks[b].size(), 1);
  const std::size_t lower = std::size_t(model.parts[0].block), upper = std::size_t(model.parts[1].block);
  const std::vector<std::vector<std::pair<std::size_t, Index>>> rounds = {
      {{upper, 0}}, {{upper, 5}, {lower, 10}}, {{upper, 6}, {upper, 1}}, {{lower, 11}, {lower, 15}, {upper, 9}}};
  for (std::size_t round = 0; round < rounds.size(); ++round) {
    for (const auto& [block, element] : rounds[round]) alive[block][std::size_t(element)] = 0;
    set.rebuild(alive, model.X);
    const std::size_t S = set.num_segments();
    for (std::size_t s = 0; s < S; ++s) {
      std::vector<Index> expected;
      const Index* q = set.segment_nodes(s);
      for (std::size_t t = 0; t < S; ++t) {
        if (t == s || set.segment_side(t) != set.segment_side(s)) continue;
        const Index* p = set.segment_nodes(t);
        bool shares = false;
        for (int a = 0; a < 4; ++a) shares = shares || std::find(p, p + 4, q[a]) != p + 4;
        if (shares) expected.push_back(Index(t));
      }
      const std::vector<Index> listed(set.neighbours_begin(s), set.neighbours_end(s));
      EXPECT_EQ(listed, expected) << "round " << round << ", segment " << s;
    }
  }
}

// The sort lists in its buckets only the segments some node of the other side can reach before
// the next sort (the plate faces far from a small body are left out). Whatever it leaves out, a
// node's list must still hold every segment of the other side whose centre is within the list
// test's reach of it and within 5 % of its extent plus the bucket allowance (a sixteenth of the
// median segment extent): part of the margin of the segment's box, so the node lies inside the box
// and the bucket test cannot exclude it either.
// Scene: a 2 x 2 x 1 block of 1 mm elements 0.1 mm over a 16 x 16 x 1 plate, shifted by half an
// element, so each block node lies 0.1 mm over a plate face centre and four plate nodes lie 0.1 mm
// under the block's face centres.
// The default release depth is LS-DYNA's 0.4 x the segment thickness: for a solid, the element's
// depth behind the face, V/A. Reference: the box's geometry. A plate of 2 x 2 x 0.25 mm elements:
// its top and bottom faces are 0.25 mm deep (0.1 mm), its side faces 2 mm deep (0.8 mm). PENMAX
// replaces it on every face. Tolerance 1e-12 relative: V/A of an undistorted box is exact to
// round-off.
TEST(SegmentSet, DefaultReleaseDepthIsFourTenthsOfTheElementDepthBehindTheFace) {
  const std::string yaml =
      std::string("units: SI\ncontrol: {termination_time: 1}\n") +
      "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1}\n"
      "parts:\n  ply: {material: steel, section: s}\n"
      "mesh:\n  boxes:\n    - {part: ply, size: [0.004, 0.004, 0.00025], elements: [2, 2, 1]}\n";
  const model::Model model = test::model_from_yaml(yaml, "ply.yaml");
  for (const double penmax : {0.0, 5e-5}) {
    contact::SegmentSetSpec spec;
    spec.single = true;
    spec.blocks[0] = {model.parts[0].block};
    spec.PENMAX = penmax;
    const contact::SegmentSet set(model, spec, model.X);
    ASSERT_EQ(set.num_segments(), 2u * 4 + 4 * 2);  // top and bottom 2 x 2, four sides of 2
    std::size_t flat = 0, side = 0;
    for (std::size_t s = 0; s < set.num_segments(); ++s) {
      const Index* q = set.segment_nodes(s);
      bool level = true;
      for (int k = 1; k < 4; ++k) level = level && model.X[3 * std::size_t(q[k]) + 2] == model.X[3 * std::size_t(q[0]) + 2];
      const double expected = penmax > 0 ? penmax : 0.4 * (level ? 0.25e-3 : 2e-3);
      EXPECT_NEAR(set.release_depth(s), expected, 1e-12 * expected) << "segment " << s << (level ? " (top/bottom)" : " (side)");
      ++(level ? flat : side);
    }
    EXPECT_EQ(flat, 8u);
    EXPECT_EQ(side, 8u);
  }
}

TEST(SegmentSearch, ListsHoldEverySegmentWithinReachOfANode) {
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1}\n"
      "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1}\n"
      "parts:\n  plate: {material: steel, section: s}\n  block: {material: steel, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: plate, size: [0.016, 0.016, 0.001], elements: [16, 16, 1]}\n"
      "    - {part: block, origin: [0.0075, 0.0075, 0.0011], size: [0.002, 0.002, 0.001], elements: [2, 2, 1]}\n";
  const model::Model model = test::model_from_yaml(yaml, "block_over_plate.yaml");
  const double* x = model.X.data();
  for (bool full_depth : {true, false}) {
    SCOPED_TRACE(full_depth ? "full depth" : "new-contact depth");
    contact::SegmentSetSpec spec;
    spec.blocks[0] = {model.parts[0].block};
    spec.blocks[1] = {model.parts[1].block};
    contact::SegmentSet set(model, spec, model.X);
    contact::SegmentSearch search{contact::SearchOptions{}};
    search.reset(set, x);
    search.sort(set, x, 0.0, full_depth);
    const double cap = search.new_depth_cap();
    const double half_a = 4 * cap;  // with step_depth 0 the sort sets cap = list allowance / 8
    const double extent = std::sqrt(2.0) * 1e-3;  // every extent, and the median: a 1 mm face's diagonal
    const double in_box = 0.05 * extent + extent / 16;
    const double r_factor = 1 + 2 * (search.options().MAXPAR - 1);
    int expected = 0;
    for (std::size_t i = 0; i < set.num_nodes(); ++i) {
      const double* p = &x[3 * std::size_t(set.node_id(i))];
      const auto list = search.candidates(i);
      for (std::size_t s = 0; s < set.num_segments(); ++s) {
        if (set.segment_side(s) != set.other_side(i)) continue;
        const double* g = search.record(set, s, x);
        const double depth = full_depth ? g[7] : std::min(g[7], cap + 0.02 * g[7]);
        const double reach = r_factor * (double(contact::SegmentSearch::radius(g)) + half_a) + depth + half_a;
        const double d = std::sqrt((p[0] - g[0]) * (p[0] - g[0]) + (p[1] - g[1]) * (p[1] - g[1]) + (p[2] - g[2]) * (p[2] - g[2]));
        if (d > std::min(reach, in_box)) continue;
        ++expected;
        EXPECT_NE(std::find(list.begin(), list.end(), Index(s)), list.end())
            << "node " << set.node_id(i) << " lacks segment " << s << " at " << d << " m";
      }
    }
    // The 9 block nodes, each over a plate face centre, and the 4 plate nodes under the block's
    // 4 bottom face centres; every other centre is at least 0.5 mm away.
    EXPECT_EQ(expected, 13);
  }
}

}  // namespace
}  // namespace plyimpact
