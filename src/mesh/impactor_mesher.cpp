#include "mesh/impactor_mesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <unistd.h>

#include "mesh/geo_scripts.hpp"
#include "mesh/gmsh_session.hpp"

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
      gmsh::model::mesh::generate(2);
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

void add_impactor(const config::Scene& scene, Mesh& mesh) {
  const auto& spec = *scene.impactor;
  if (!spec.rigid)
    throw InputError(msg() << spec.where.file << ":" << spec.where.line << ":" << spec.where.column << ": "
                           << spec.where.key_path << ": a deformable (hex) impactor is not available yet; found "
                           << "rigid: false; allowed rigid: true (surface and mass properties)");
  if (spec.shape != Shape::Sphere && spec.shape != Shape::HemisphericalCylinder)
    throw InputError(msg() << spec.where.file << ":" << spec.where.line << ":" << spec.where.column << ": "
                           << spec.where.key_path << ".shape: this impactor shape is not available yet; found "
                           << (spec.shape == Shape::Cube ? "cube" : "flat_cylinder")
                           << "; allowed sphere or hemispherical_cylinder");
  double top = 0;
  for (std::size_t i = 2; i < mesh.coords.size(); i += 3) top = std::max(top, mesh.coords[i]);
  const double r = spec.diameter / 2;
  // Elements per quarter circumference (a cubed-sphere patch edge spans 90 degrees on the equator).
  const int n = std::max(2, int(std::ceil(0.5 * std::numbers::pi * r / spec.element_size)));
  GmshModel model("impactor");
  if (spec.shape == Shape::Sphere) {
    run_script("sphere", msg() << "R = " << r << "; N = " << n << ";");
  } else {
    const int m = std::max(1, int(std::ceil((spec.length - r) / spec.element_size)));
    run_script("hemispherical_cylinder", msg() << "R = " << r << "; L = " << spec.length << "; N = " << n
                                               << "; M = " << m << ";");
  }
  ImpactorMesh imp = impactor_mass_properties(spec);
  imp.rigid = true;
  const double dx = spec.x, dy = spec.y, dz = top + spec.gap;
  gmsh_call("reading the impactor surface", [&] {
    std::vector<std::size_t> tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, true, false);
    std::size_t max_tag = 0;
    for (auto t : tags) max_tag = std::max(max_tag, t);
    std::vector<std::size_t> position(max_tag + 1, 0);
    for (std::size_t a = 0; a < tags.size(); ++a) position[tags[a]] = a;
    std::vector<std::size_t> etags, enodes;
    gmsh::model::mesh::getElementsByType(3, etags, enodes, -1);  // 4-node quadrangles
    // Only nodes of the quads: the script's construction points (the centre) are mesh nodes too.
    std::vector<Index> index(max_tag + 1, -1);
    for (std::size_t t : enodes)
      if (index[t] < 0) {
        index[t] = Index(imp.surface_coords.size() / 3);
        const double* p = &xyz[3 * position[t]];
        imp.surface_coords.insert(imp.surface_coords.end(), {p[0] + dx, p[1] + dy, p[2] + dz});
      }
    const double cx = dx, cy = dy, cz = dz + imp.centre_of_mass[2];
    for (std::size_t q = 0; q < etags.size(); ++q) {
      Index c[4];
      for (int k = 0; k < 4; ++k) c[k] = index[enodes[4 * q + k]];
      // Outward normal: the body is convex, so the normal must point away from its centroid.
      const double* p[4];
      for (int k = 0; k < 4; ++k) p[k] = &imp.surface_coords[3 * std::size_t(c[k])];
      const double d1[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
      const double d2[3] = {p[3][0] - p[1][0], p[3][1] - p[1][1], p[3][2] - p[1][2]};
      const double nrm[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
      const double mid[3] = {(p[0][0] + p[2][0]) / 2 - cx, (p[0][1] + p[2][1]) / 2 - cy, (p[0][2] + p[2][2]) / 2 - cz};
      if (nrm[0] * mid[0] + nrm[1] * mid[1] + nrm[2] * mid[2] < 0) std::swap(c[1], c[3]);
      imp.surface_quads.insert(imp.surface_quads.end(), c, c + 4);
    }
  });
  imp.centre_of_mass = {dx, dy, dz + imp.centre_of_mass[2]};
  mesh.impactor = std::move(imp);
}

}  // namespace plyimpact::mesh
