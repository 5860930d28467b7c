// Mesh size before meshing; see size_estimate.hpp.
#include "mesh/size_estimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/axis_grid.hpp"
#include "mesh/laminate_mesher.hpp"

namespace plyimpact::mesh {
namespace {

// Elements along one axis of the plate: exact (the mesher's own bands) when the count is small
// enough to be formed in int arithmetic, else an upper bound, which is then far beyond any limit.
double axis_elements(const AxisSpec& a) {
  const double finest = a.zone_size > 0 ? std::min(a.size, a.zone_size) : a.size;
  const double bound = ((a.hi - a.lo) / finest + double(a.breaks.size()) + 3) * std::ldexp(1.0, a.level);
  if (!(bound <= 1e8)) return bound;
  double n = 0;
  for (const Band& b : axis_bands(a)) n += b.elements;
  return n;
}

std::string count_text(double n) {
  return n < 1e9 ? std::string(msg() << std::llround(n)) : std::string(msg() << n);
}

struct Factor {
  double ratio;  // count over a typical count: the largest ratio names the key
  std::string key;
};

MeshSizeEstimate laminate_estimate(const config::LaminateSpec& lam) {
  const double nx = axis_elements(laminate_axis(lam, 0)), ny = axis_elements(laminate_axis(lam, 1));
  const double plies = double(lam.plies.size()), layers = plies * lam.elements_per_ply;
  const double delaminating = double(std::count(lam.delaminating.begin(), lam.delaminating.end(), true));
  MeshSizeEstimate e;
  e.elements = nx * ny * layers;
  e.nodes = (nx + 1) * (ny + 1) * (layers + 1 + delaminating);
  e.account = msg() << count_text(nx) << " x " << count_text(ny) << " in-plane x " << count_text(layers)
                    << " layers (" << lam.plies.size() << " plies x " << lam.elements_per_ply << " per ply)";
  const double level_factor = std::ldexp(1.0, 2 * lam.refinement_level);
  std::string in_plane_key = "laminate.element_size";
  if (lam.zone_element_size > 0 && lam.zone_element_size < lam.element_size) {
    const double zone_cells = (lam.zone_x / lam.zone_element_size) * (lam.zone_y / lam.zone_element_size);
    if (zone_cells * level_factor > 0.5 * nx * ny) in_plane_key = "laminate.refined_zone.element_size";
  }
  if (lam.refinement_level > 0 && nx * ny / level_factor <= 1e5) in_plane_key = "laminate.refinement_level";
  const Factor factors[] = {
      {nx * ny / 1e5, in_plane_key},
      {plies / 64, "laminate.stacking"},
      {double(lam.elements_per_ply) / 4, "laminate.elements_per_ply"},
  };
  e.key = std::max_element(std::begin(factors), std::end(factors),
                           [](const Factor& a, const Factor& b) { return a.ratio < b.ratio; })->key;
  return e;
}

// Element counts of the impactor scripts (see geo/*.geo and impactor_mesher's script_for): N per
// quarter circumference, K through the shell or ring, M along the body. Rigid or not, gmsh meshes
// the solid.
MeshSizeEstimate impactor_estimate(const config::ImpactorSpec& s) {
  using Shape = config::ImpactorSpec::Shape;
  const double r = s.diameter / 2, h = s.element_size, pi = std::numbers::pi;
  const auto count = [&](double length) { return std::max(1.0, std::ceil(length / h - 1e-9)); };
  // N rounded up to even, as the mesher does (the pole is then a node).
  const double n_quarter = std::max(2.0, std::ceil(0.5 * pi * r / h - 1e-9));
  const double n = n_quarter + std::fmod(n_quarter, 2.0), k_sphere = count(r * (1 - 0.5 / std::sqrt(3.0))),
               k_ring = count(r * (1 - 0.5 / std::sqrt(2.0)));
  MeshSizeEstimate e;
  switch (s.shape) {
    case Shape::Sphere: e.elements = n * n * n + 6 * n * n * k_sphere; break;
    case Shape::HemisphericalCylinder:
      // Nose: a core N x N x N (its meridians have N elements too) under five N x N x K shells.
      e.elements = n * n * n + 5 * n * n * k_sphere + (n * n + 4 * n * k_sphere) * count(s.length - r);
      break;
    case Shape::FlatCylinder: e.elements = (n * n + 4 * n * k_ring) * count(s.length); break;
    case Shape::Cube: {
      const double c = std::max(2.0, std::ceil(s.diameter / h - 1e-9));
      e.elements = c * c * c;
      break;
    }
  }
  e.nodes = e.elements + 8 * n * n;  // the surface layer's extra nodes, roughly
  e.key = "impactor.element_size";
  e.account = msg() << "impactor: " << count_text(n) << " elements per quarter circumference";
  return e;
}

MeshSizeEstimate boxes_estimate(const std::vector<config::BoxSpec>& boxes) {
  MeshSizeEstimate e;
  double largest = -1;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const auto& n = boxes[i].elements;
    const double elements = double(n[0]) * n[1] * n[2];
    e.elements += elements;
    e.nodes += (n[0] + 1.0) * (n[1] + 1.0) * (n[2] + 1.0);
    if (elements > largest) {
      largest = elements;
      e.key = msg() << "mesh.boxes[" << i << "].elements";
      e.account = msg() << "box " << i << ": " << n[0] << " x " << n[1] << " x " << n[2];
    }
  }
  return e;
}

std::string gib(double bytes) { return msg() << std::round(bytes / 1073741824.0 * 10) / 10 << " GiB"; }

}  // namespace

MeshSizeEstimate estimate_mesh_size(const config::Scene& scene) {
  MeshSizeEstimate e;
  if (scene.laminate) e = laminate_estimate(*scene.laminate);
  else if (!scene.mesh_file) e = boxes_estimate(scene.boxes);
  if (scene.impactor) {
    const MeshSizeEstimate imp = impactor_estimate(*scene.impactor);
    if (imp.elements > e.elements) {
      e.key = imp.key;
      e.account = imp.account + (e.account.empty() ? "" : "; " + e.account);
    } else {
      e.account += "; " + imp.account;
    }
    e.elements += imp.elements;
    e.nodes += imp.nodes;
  }
  e.bytes = e.elements * kBytesPerElement + e.nodes * kBytesPerNode;
  return e;
}

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0.0;
}

void require_mesh_fits(const config::Scene& scene, const MeshSizeEstimate& e, double memory_bytes) {
  const bool limit_given = scene.control.max_elements > 0;
  const double max_elements = limit_given ? double(scene.control.max_elements) : kDefaultMaxElements;
  const bool too_many = e.elements > max_elements;
  const bool too_big = !limit_given && memory_bytes > 0 && e.bytes > 0.8 * memory_bytes;
  if (!too_many && !too_big) return;
  throw InputError(config::at(scene.where_of(e.key))
                   << "the mesh would have about " << count_text(e.elements) << " elements and "
                   << count_text(e.nodes) << " nodes (" << e.account << "), needing about " << gib(e.bytes)
                   << " of memory; found " << (too_many ? "more elements than the limit" : "more than this machine holds")
                   << "; allowed at most " << count_text(max_elements) << " elements (control.max_elements"
                   << (limit_given ? ")" : ", default)")
                   << (limit_given || memory_bytes <= 0 ? "" : " and 80 % of the machine's " + gib(memory_bytes))
                   << ": coarsen " << e.key << " (or the other sizes named), or raise control.max_elements");
}

}  // namespace plyimpact::mesh
