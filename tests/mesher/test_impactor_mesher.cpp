// The impactor mesher (geo/*.geo -> hexahedra): for every shape, rigid and deformable, the element
// counts of the blocking, positive corner Jacobians, a closed outward boundary, volume and mass
// properties against the exact shape, second-order convergence of the faceting error, and a
// deformable impactor that is a separate body above the plate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "scene_cards.hpp"
#include "config/scene_loader.hpp"
#include "element/hex8.hpp"
#include "mesh/scene_mesher.hpp"

using namespace plyimpact;

namespace {

constexpr double kPi = std::numbers::pi;

// A 10 x 10 mm, 2-ply plate (2 x 2 x 2 elements, top at z = 0.5 mm) and the given impactor
// (`impactor` is the body of its mapping); steel for a deformable impactor.
config::Scene scene(const std::string& impactor) {
  return config::load_scene_from_string(R"(units: mm-t-s-MPa
control: {termination_time: 1.0e-6}
)" + std::string(test::kPlyAndSteelCards) + R"(laminate: {length: 10, width: 10, ply_thickness: 0.25, stacking: "[0/90]", material: ply, section: s,
           element_size: 5, interfaces: none}
impactor: {)" + impactor + "}\n",
                                        "impactor.yaml");
}

struct Measured {
  std::size_t plate_nodes = 0, hexes = 0;
  double volume = 0;              // m^3, sum of the trilinear hexahedra
  double min_detj = 1e300;        // smallest corner Jacobian
  Vec3 centroid{0, 0, 0};         // volume-weighted element centroids
  double surface_volume = 0;      // divergence theorem over the boundary quads (split in triangles)
  bool closed = true;             // every boundary edge shared by exactly two quads
};

Measured measure(const mesh::Mesh& m, int impactor_part) {
  Measured r;
  r.plate_nodes = m.num_nodes();
  for (std::size_t e = 0; e < m.num_elements(); ++e) {
    if (m.element_part[e] != impactor_part) continue;
    ++r.hexes;
    double x[3][8], detj[8];
    for (int k = 0; k < 8; ++k) {
      const std::size_t n = std::size_t(m.hex[8 * e + k]);
      r.plate_nodes = std::min(r.plate_nodes, n);
      for (int i = 0; i < 3; ++i) x[i][k] = m.coords[3 * n + i];
    }
    element::hex8_corner_jacobians(x, detj);
    for (double d : detj) r.min_detj = std::min(r.min_detj, d);
    const double v = element::hex8_volume(x);
    r.volume += v;
    for (int i = 0; i < 3; ++i) r.centroid[i] += v * (x[i][0] + x[i][1] + x[i][2] + x[i][3] + x[i][4] + x[i][5] + x[i][6] + x[i][7]) / 8;
  }
  for (double& c : r.centroid) c /= r.volume;
  const auto& imp = *m.impactor;
  std::map<std::pair<Index, Index>, int> edges;
  for (std::size_t q = 0; q < imp.surface_quads.size() / 4; ++q) {
    const Index* c = &imp.surface_quads[4 * q];
    for (int k = 0; k < 4; ++k) ++edges[{std::min(c[k], c[(k + 1) % 4]), std::max(c[k], c[(k + 1) % 4])}];
    for (int t = 1; t < 3; ++t) {
      const double* a = &imp.surface_coords[3 * std::size_t(c[0])];
      const double* b = &imp.surface_coords[3 * std::size_t(c[t])];
      const double* d = &imp.surface_coords[3 * std::size_t(c[t + 1])];
      r.surface_volume += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                           a[2] * (b[0] * d[1] - b[1] * d[0])) / 6;
    }
  }
  for (const auto& [edge, uses] : edges) r.closed = r.closed && uses == 2;
  return r;
}

int part_of(const config::Scene& s) { return s.impactor->part; }

}  // namespace

// Cubed sphere, D = 10 mm: N = ceil((pi/2) 5 / h) per patch edge, K = ceil(5 (1 - 1/(2 sqrt 3)) / h)
// through the shell; N^3 + 6 N^2 K hexahedra, 6 N^2 boundary quads, 6 N^2 + 2 surface nodes.
TEST(ImpactorMesher, DeformableSphereCountsJacobiansAndSeparateBody) {
  const config::Scene s = scene("shape: sphere, diameter: 10, mass: 0.1 kg, gap: 0.5, velocity: 2 m/s, rigid: false, "
                                "material: steel, section: s, element_size: 2");
  const mesh::Mesh m = mesh::mesh_scene(s);
  const int n = 4, k = 2;
  const Measured r = measure(m, part_of(s));
  EXPECT_EQ(r.hexes, std::size_t(n * n * n + 6 * n * n * k));
  EXPECT_GT(r.min_detj, 0.0);
  const auto& imp = *m.impactor;
  EXPECT_FALSE(imp.rigid);
  EXPECT_EQ(imp.part, part_of(s));
  EXPECT_EQ(imp.surface_quads.size() / 4, std::size_t(6 * n * n));
  EXPECT_EQ(imp.surface_coords.size() / 3, std::size_t(6 * n * n + 2));
  EXPECT_TRUE(r.closed);
  // Separate body: the plate has 3 x 3 x 3 nodes and the impactor's come after them, unshared.
  EXPECT_EQ(r.plate_nodes, 27u);
  for (std::size_t e = 0; e < m.num_elements(); ++e)
    if (m.element_part[e] != part_of(s)) {
      for (int c = 0; c < 8; ++c) EXPECT_LT(m.hex[8 * e + c], 27);
    }
  EXPECT_EQ(m.element_ply.size(), m.num_elements());
  // The surface maps onto mesh nodes with identical coordinates, all on the sphere (1e-9 R: gmsh
  // places them on the exact sphere up to round-off).
  ASSERT_EQ(imp.surface_nodes.size(), imp.surface_coords.size() / 3);
  double lowest = 1e300;
  for (std::size_t a = 0; a < imp.surface_nodes.size(); ++a) {
    const double* p = &m.coords[3 * std::size_t(imp.surface_nodes[a])];
    for (int i = 0; i < 3; ++i) EXPECT_EQ(p[i], imp.surface_coords[3 * a + i]);
    EXPECT_NEAR(std::hypot(p[0] - 5e-3, p[1] - 5e-3, p[2] - imp.centre_of_mass[2]), 5e-3, 5e-12);
    lowest = std::min(lowest, p[2]);
  }
  // N even: a node sits at the nose tip, exactly `gap` above the plate's top.
  EXPECT_NEAR(lowest, 0.5e-3 + 0.5e-3, 1e-12);
  EXPECT_NEAR(imp.centre_of_mass[2], 1e-3 + 5e-3, 1e-15);
}

// Faceting: a trilinear hexahedron under a sphere patch of angular size theta misses a sliver of
// relative depth ~ theta^2 / 8, and a chord of the cylinder a segment of relative area theta^2 / 6,
// so the volume error falls as h^2. Halving h (N = 4 -> 8) must divide it by 4 (3.5-4.5 allows
// the higher-order terms: measured 3.86 for the sphere).
TEST(ImpactorMesher, VolumeErrorFallsQuadratically) {
  const std::pair<const char*, double> shapes[] = {{"shape: sphere", kPi * 1000 / 6},
                                                   {"shape: hemispherical_cylinder, length: 20",
                                                    kPi * 25 * 15 + 2 * kPi * 125 / 3}};
  for (const auto& [shape, exact_mm3] : shapes) {
    const double exact = exact_mm3 * 1e-9;
    double error[2];
    for (int level = 0; level < 2; ++level) {
      const config::Scene s = scene(std::string(shape) + ", diameter: 10, mass: 0.1 kg, velocity: 1 m/s, rigid: false, "
                                    "material: steel, section: s, element_size: " + (level == 0 ? "2" : "1"));
      const Measured r = measure(mesh::mesh_scene(s), part_of(s));
      EXPECT_GT(r.min_detj, 0.0);
      error[level] = (exact - r.volume) / exact;
      std::printf("%s, h = %d mm: relative volume error %.4e\n", shape, 2 - level, error[level]);
    }
    EXPECT_GT(error[0], 0.0) << shape;  // inscribed: always smaller than the exact shape
    EXPECT_GT(error[0] / error[1], 3.5) << shape;
    EXPECT_LT(error[0] / error[1], 4.5) << shape;
  }
}

namespace {

struct ShapeCase {
  const char* name;
  const char* yaml;        // impactor mapping body without rigid/material/section
  std::size_t hexes;       // from the blocking (counts in the comments below)
  std::size_t quads;       // boundary quads
  double exact_volume;     // mm^3
  double faceted_volume;   // mm^3: exact for shapes with straight generators, else 0 (not closed form)
  double centre_z;         // mm above the nose, closed form
};

// h = 2 mm, D = 10 mm: N = ceil(7.85 / 2) = 4 per quarter circle.
// Sphere: K = ceil(3.56 / 2) = 2; N^3 + 6 N^2 K hexahedra, 6 N^2 quads.
// Hemispherical cylinder (L = 20): K = 2, M = ceil(15 / 2) = 8; N^3 + 5 N^2 K + N^2 M + 4 N M K
//   hexahedra; 5 N^2 (nose) + 4 N M (body) + N^2 + 4 N K (top: core square and ring) quads.
// Flat cylinder (L = 6): K = ceil(5 (1 - 1/(2 sqrt 2)) / 2) = 2, M = 3; N^2 M + 4 N K M hexahedra;
//   2 (N^2 + 4 N K) + 4 N M quads. Its faces are planar chords: the volume is the inscribed
//   regular 4N-gon's area x L, exactly.
// Cube (D = 10): N = 5; N^3 hexahedra, 6 N^2 quads, volume D^3 exactly.
const double kPolygon = 2 * 4 * 25 * std::sin(kPi / 8);  // 4N-gon area, N = 4, r = 5 (mm^2)
const ShapeCase kShapes[] = {
    {"sphere", "shape: sphere, diameter: 10", 64 + 6 * 16 * 2, 96, kPi * 1000 / 6, 0, 5},
    {"hemispherical_cylinder", "shape: hemispherical_cylinder, diameter: 10, length: 20",
     64 + 5 * 16 * 2 + 16 * 8 + 4 * 4 * 8 * 2, 5 * 16 + 4 * 4 * 8 + 16 + 4 * 4 * 2,
     kPi * 25 * 15 + 2 * kPi * 125 / 3, 0,
     (2 * kPi * 125 / 3 * (5 - 15.0 / 8) + kPi * 25 * 15 * (5 + 7.5)) / (kPi * 25 * 15 + 2 * kPi * 125 / 3)},
    {"flat_cylinder", "shape: flat_cylinder, diameter: 10, length: 6", 16 * 3 + 4 * 4 * 2 * 3,
     2 * (16 + 4 * 4 * 2) + 4 * 4 * 3, kPi * 25 * 6, kPolygon * 6, 3},
    {"cube", "shape: cube, diameter: 10", 125, 150, 1000, 1000, 5},
};

}  // namespace

class ImpactorShapes : public ::testing::TestWithParam<ShapeCase> {};

TEST_P(ImpactorShapes, BlockingVolumeAndMassProperties) {
  const ShapeCase& c = GetParam();
  const std::string common = std::string(c.yaml) + ", mass: 0.2 kg, gap: 0.5, velocity: 2 m/s, element_size: 2";
  const config::Scene def = scene(common + ", rigid: false, material: steel, section: s");
  const config::Scene rig = scene(common);
  const mesh::Mesh md = mesh::mesh_scene(def), mr = mesh::mesh_scene(rig);
  const Measured r = measure(md, part_of(def));
  EXPECT_EQ(r.hexes, c.hexes);
  EXPECT_GT(r.min_detj, 0.0);
  EXPECT_TRUE(r.closed);
  // The rigid impactor is the same mesh's boundary and adds no elements or nodes.
  EXPECT_EQ(mr.num_elements(), 8u);
  EXPECT_EQ(mr.num_nodes(), 27u);
  EXPECT_TRUE(mr.impactor->rigid);
  EXPECT_EQ(mr.impactor->surface_quads, md.impactor->surface_quads);
  EXPECT_EQ(mr.impactor->surface_coords, md.impactor->surface_coords);
  EXPECT_EQ(md.impactor->surface_quads.size() / 4, c.quads);
  // Outward quads: the divergence theorem over the boundary gives the (positive) volume.
  // Measured equal to the elements' volume to 10 digits; 1e-6 leaves room for round-off only.
  EXPECT_NEAR(r.surface_volume, r.volume, 1e-6 * r.volume);
  const double exact = c.exact_volume * 1e-9;
  if (c.faceted_volume > 0) {
    EXPECT_NEAR(r.volume, c.faceted_volume * 1e-9, 1e-12 * exact);
  }
  // Faceting of the curved shapes at N = 4: below 1.1 / N^2 (sphere: 0.067, see the convergence test).
  EXPECT_LE(r.volume, exact * (1 + 1e-12));
  EXPECT_GT(r.volume, exact * (1 - 1.1 / 16));
  // Mass = density x exact volume; the loader set the part's density so, and the model's FE mass
  // (density x faceted volume) is short by the faceting error only.
  const auto& imp = *md.impactor;
  EXPECT_DOUBLE_EQ(imp.mass, 0.2);
  EXPECT_NEAR(def.impactor->density * exact, 0.2, 1e-12);
  EXPECT_EQ(imp.velocity[2], -2.0);
  // Centre of mass: the closed form's, on the axis. The mesh's centroid is on the axis by symmetry;
  // along it, it agrees to the faceting error: the nose loses relatively more volume (~1.1 / N^2)
  // than the body (the 4N-gon's theta^2 / 6), which lifts the centroid 0.05 mm at N = 4; 1% of D.
  const double nose = 0.5e-3 + 0.5e-3;  // plate top + gap
  EXPECT_NEAR(imp.centre_of_mass[2], nose + c.centre_z * 1e-3, 1e-15);
  EXPECT_NEAR(r.centroid[0], 5e-3, 1e-12);
  EXPECT_NEAR(r.centroid[1], 5e-3, 1e-12);
  EXPECT_NEAR(r.centroid[2], imp.centre_of_mass[2], 0.1e-3);
}

INSTANTIATE_TEST_SUITE_P(Shapes, ImpactorShapes, ::testing::ValuesIn(kShapes),
                         [](const auto& info) { return std::string(info.param.name); });

// The nose is a node whatever the element size: the cubed sphere's nose patch has N elements per
// edge, and its centre (the pole) is a node only for even N. D = 10 mm: h = 2.2 gives
// ceil(7.85 / 2.2) = 4 and h = 1.8 gives 5, raised to 6; h = 1.3 gives 7, raised to 8. Reference:
// the exact pole, (x, y) on the axis and z = plate top (0.5 mm) + gap (0.5 mm), to gmsh round-off
// (1e-12 m); and exactly one surface node there (a face at the pole would put four nodes at the
// lowest height, none on the axis). Same for the hemispherical nose of the tup.
TEST(ImpactorMesher, PoleIsANodeForAnyElementSize) {
  for (const char* shape : {"sphere", "hemispherical_cylinder"})
    for (const char* h : {"2.2", "1.8", "1.3"}) {
      const config::Scene s = scene(std::string("shape: ") + shape + ", diameter: 10, mass: 0.1 kg, gap: 0.5, "
                                    "velocity: 2 m/s, element_size: " + h);
      const mesh::Mesh m = mesh::mesh_scene(s);
      const auto& imp = *m.impactor;
      double lowest = 1e300;
      for (std::size_t a = 2; a < imp.surface_coords.size(); a += 3) lowest = std::min(lowest, imp.surface_coords[a]);
      int at_pole = 0, lowest_level = 0;
      for (std::size_t a = 0; a < imp.surface_coords.size(); a += 3) {
        const double* p = &imp.surface_coords[a];
        if (p[2] > lowest + 1e-9) continue;
        ++lowest_level;
        if (std::hypot(p[0] - 5e-3, p[1] - 5e-3) < 1e-12) ++at_pole;
      }
      EXPECT_NEAR(lowest, 1e-3, 1e-12) << shape << " h " << h;
      EXPECT_EQ(at_pole, 1) << shape << " h " << h;
      EXPECT_EQ(lowest_level, 1) << shape << " h " << h;
    }
}

// An element size above the radius cannot be meshed as asked (at least two elements per quarter
// circumference): refused at the key with the allowed range, as the reader does for any bound.
TEST(ImpactorMesher, ElementSizeAboveTheRadiusIsRefusedAtItsKey) {
  try {
    scene("shape: sphere, diameter: 10, mass: 0.1 kg, velocity: 2 m/s, element_size: 500");
    FAIL() << "accepted an element size of 50 diameters";
  } catch (const InputError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("impactor.yaml:"), std::string::npos) << w;
    EXPECT_NE(w.find("impactor.element_size"), std::string::npos) << w;
    EXPECT_NE(w.find("at most the radius"), std::string::npos) << w;
  }
  EXPECT_NO_THROW(scene("shape: sphere, diameter: 10, mass: 0.1 kg, velocity: 2 m/s, element_size: 5"));
}
