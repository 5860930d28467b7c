#include "mesh/impactor_mesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <unistd.h>

#include "mesh/geo_scripts.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/hex_boundary.hpp"

namespace plyimpact::mesh {
namespace {

using Shape = config::ImpactorSpec::Shape;

// Runs geo/<name>.geo with the given parameter definitions prepended; gmsh reads scripts from
// files only, so a private temporary file is used (and removed).
void run_script(const std::string& name, const std::string& parameters) {
  const std::string_view body = geo_script(name);
  if (body.empty()) throw InputError(msg() << "internal: no gmsh script geo/" << name << ".geo compiled in");
  const auto dir = std::filesystem::temp_directory_path();
  const auto path = dir / ("plyimpact_" + name + "_" + std::to_string(::getpid()) + ".geo");
  {
    std::ofstream f(path);
    f << parameters << "\n" << body;
    if (!f) throw RunError(msg() << path.string() << ": cannot write a temporary gmsh script");
  }
  try {
    gmsh_call("running geo/" + name + ".geo", [&] {
      gmsh::merge(path.string());
      gmsh::model::geo::synchronize();
      gmsh::model::mesh::generate(3);
    });
  } catch (...) {
    std::filesystem::remove(path);
    throw;
  }
  std::filesystem::remove(path);
}

}  // namespace

ImpactorMesh impactor_mass_properties(const config::ImpactorSpec& s) {
  ImpactorMesh out;
  const double pi = std::numbers::pi, r = s.diameter / 2, m = s.mass;
  double izz = 0, ixx = 0, zc = 0;  // about the centre of mass; axisymmetric (cube: isotropic)
  switch (s.shape) {
    case Shape::Sphere:
      zc = r;
      ixx = izz = 0.4 * m * r * r;
      break;
    case Shape::Cube:
      zc = s.diameter / 2;
      ixx = izz = m * s.diameter * s.diameter / 6;
      break;
    case Shape::FlatCylinder:
      zc = s.length / 2;
      izz = 0.5 * m * r * r;
      ixx = m * (3 * r * r + s.length * s.length) / 12;
      break;
    case Shape::HemisphericalCylinder: {
      // Hemisphere (flat face at z = r, centroid 3r/8 below it) + cylinder from z = r to z = length.
      const double lc = s.length - r, vh = 2 * pi * r * r * r / 3, vc = pi * r * r * lc;
      const double mh = m * vh / (vh + vc), mc = m - mh;
      const double zh = r - 3 * r / 8, zcyl = r + lc / 2;
      zc = (mh * zh + mc * zcyl) / m;
      izz = 0.4 * mh * r * r + 0.5 * mc * r * r;
      ixx = 83.0 / 320.0 * mh * r * r + mh * (zh - zc) * (zh - zc) + mc * (3 * r * r + lc * lc) / 12 +
            mc * (zcyl - zc) * (zcyl - zc);
      break;
    }
  }
  out.mass = m;
  out.centre_of_mass = {0, 0, zc};
  out.inertia = {ixx, 0, 0, 0, ixx, 0, 0, 0, izz};
  out.velocity = s.velocity;
  return out;
}

namespace {

// Script parameters: the element counts follow spec.element_size (N per quarter circumference, even, K
// through the O-grid's shell or ring, M along a cylinder's body).
struct Script {
  std::string name, parameters;
};

// Exact text of a double (the default 6 digits would move the geometry off the exact shape).
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

Script script_for(const config::ImpactorSpec& spec) {
  const double r = spec.diameter / 2, h = spec.element_size, pi = std::numbers::pi;
  const auto count = [&](double length) { return std::to_string(std::max(1, int(std::ceil(length / h - 1e-9)))); };
  // N even: the nose patch of the cubed sphere then has a node at its centre, the pole, whatever
  // the element size (an odd N puts a face there, and first contact then depends on the size's
  // parity: a flat face meets the plate later and all at once).
  const int n_quarter = std::max(2, int(std::ceil(0.5 * pi * r / h - 1e-9)));
  const std::string n = std::to_string(n_quarter + n_quarter % 2);
  // Core half-widths r / (2 sqrt 3) (cubed sphere) and r / (2 sqrt 2) (cylinder): the shell or ring
  // is r (1 - 0.289) or r (1 - 0.354) thick on the axes.
  const std::string k_sphere = count(r * (1 - 0.5 / std::sqrt(3.0))), k_ring = count(r * (1 - 0.5 / std::sqrt(2.0)));
  switch (spec.shape) {
    case Shape::Sphere:
      return {"sphere", "R = " + num(r) + "; N = " + n + "; K = " + k_sphere + ";"};
    case Shape::HemisphericalCylinder:
      return {"hemispherical_cylinder", "R = " + num(r) + "; L = " + num(spec.length) + "; N = " + n +
                                            "; M = " + count(spec.length - r) + "; K = " + k_sphere + ";"};
    case Shape::FlatCylinder:
      return {"flat_cylinder", "R = " + num(r) + "; L = " + num(spec.length) + "; N = " + n + "; M = " +
                                   count(spec.length) + "; K = " + k_ring + ";"};
    case Shape::Cube:
      return {"cube", "D = " + num(spec.diameter) + "; N = " +
                          std::to_string(std::max(2, int(std::ceil(spec.diameter / h - 1e-9)))) + ";"};
  }
  return {};
}

// The hexahedra of the current gmsh model, right-handed, over the nodes they use (the scripts'
// construction points, such as a sphere's centre, are mesh nodes too and are left out).
void read_hexes(std::vector<double>& coords, std::vector<Index>& hex) {
  gmsh_call("reading the impactor mesh", [&] {
    std::vector<std::size_t> tags, etags, enodes;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, true, false);
    std::size_t max_tag = 0;
    for (auto t : tags) max_tag = std::max(max_tag, t);
    std::vector<std::size_t> position(max_tag + 1, 0);
    for (std::size_t a = 0; a < tags.size(); ++a) position[tags[a]] = a;
    gmsh::model::mesh::getElementsByType(5, etags, enodes, -1);  // 8-node hexahedra
    std::vector<Index> index(max_tag + 1, -1);
    for (std::size_t t : enodes) {
      if (index[t] < 0) {
        index[t] = Index(coords.size() / 3);
        coords.insert(coords.end(), &xyz[3 * position[t]], &xyz[3 * position[t]] + 3);
      }
      hex.push_back(index[t]);
    }
  });
  orient_hexes(coords, hex);
}

}  // namespace

void add_impactor(const config::Scene& scene, Mesh& mesh) {
  const auto& spec = *scene.impactor;
  double top = 0;
  for (std::size_t i = 2; i < mesh.coords.size(); i += 3) top = std::max(top, mesh.coords[i]);
  // Both kinds mesh the solid; a rigid impactor keeps only its boundary, so the two share a surface.
  std::vector<double> coords;
  std::vector<Index> hex;
  {
    GmshModel model("impactor");
    const Script script = script_for(spec);
    run_script(script.name, script.parameters);
    read_hexes(coords, hex);
  }
  const double shift[3] = {spec.x, spec.y, top + spec.gap};  // nose (local origin) `gap` above the plate
  for (std::size_t i = 0; i < coords.size(); ++i) coords[i] += shift[i % 3];

  ImpactorMesh imp = impactor_mass_properties(spec);
  imp.rigid = spec.rigid;
  imp.centre_of_mass = {shift[0], shift[1], shift[2] + imp.centre_of_mass[2]};
  const std::vector<Index> quads = boundary_quads(hex);
  // Surface nodes numbered in order of first use by the quads.
  std::vector<Index> surface_index(coords.size() / 3, -1);
  for (Index n : quads) {
    if (surface_index[std::size_t(n)] < 0) {
      surface_index[std::size_t(n)] = Index(imp.surface_coords.size() / 3);
      imp.surface_coords.insert(imp.surface_coords.end(), &coords[3 * std::size_t(n)], &coords[3 * std::size_t(n)] + 3);
      imp.surface_nodes.push_back(n);  // made global below for a deformable impactor
    }
    imp.surface_quads.push_back(surface_index[std::size_t(n)]);
  }
  if (spec.rigid) {
    imp.surface_nodes.clear();
  } else {
    // A separate body: its own nodes after the plate's, never merged with them.
    const Index offset = Index(mesh.num_nodes());
    mesh.coords.insert(mesh.coords.end(), coords.begin(), coords.end());
    for (Index n : hex) mesh.hex.push_back(n + offset);
    mesh.element_part.insert(mesh.element_part.end(), hex.size() / 8, spec.part);
    if (!mesh.element_ply.empty()) mesh.element_ply.insert(mesh.element_ply.end(), hex.size() / 8, -1);
    for (Index& n : imp.surface_nodes) n += offset;
    imp.part = spec.part;
  }
  mesh.impactor = std::move(imp);
}

}  // namespace plyimpact::mesh
