// bench_contact: cost of one penalty-contact pass (contact/penalty_contact: bucket sort every BSORT
// = 10 cycles or on motion, bounding spheres, node normals, search of every contact node in its
// bucket, projection, penalty force and scatter) per contact segment and cycle, against the
// surface size (about 1e3 .. 1e6 segments), and the element update of the same model for the
// comparison the issue asks ("a contact cycle should cost no more than the element update of the
// same number of surface elements").
// Model: two steel plates of n x n x 1 cubic elements (h = 1 mm), automatic surface to surface,
// SOFT 0, frictionless (LS-DYNA defaults); every exterior face of both plates is a segment
// (4 n^2 + 8 n). The upper plate is pressed 1e-3 h into the lower one (and shifted in plane by
// (0.3 h, 0.2 h), so the meshes do not match), so nearly every node of the two facing surfaces
// (half of all contact nodes) is in contact and gets a force each cycle; the nodes
// move by a small smooth velocity field so the re-sort triggers behave as in a run.
// Usage: bench_contact [max_segments [matching]]   (default 1.1e6, offset grids). Figures go to
// BENCHMARKS.md.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "contact/penalty_contact.hpp"
#include "mesh/mesh.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

using namespace plyimpact;

static double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

static model::Model make_model(int n) {
  const std::string size = std::to_string(n * 1e-3);
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      "  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0.3}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4, QM: 0.1}\n"
      "parts:\n  lower: {material: steel, section: s}\n  upper: {material: steel, section: s}\n"
      "mesh:\n  merge_nodes: false\n  boxes:\n"
      "    - {part: lower, size: [" + size + ", " + size + ", 0.001], elements: [" + std::to_string(n) + ", " +
      std::to_string(n) + ", 1]}\n"
      "    - {part: upper, origin: [0, 0, 0.001], size: [" + size + ", " + size + ", 0.001], elements: [" +
      std::to_string(n) + ", " + std::to_string(n) + ", 1]}\n"
      "contacts:\n  - {name: c, type: automatic_surface_to_surface, surfaces: [lower, upper]}\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "bench_contact.yaml");
  return model::build_model(scene, mesh::mesh_boxes(scene));
}

int main(int argc, char** argv) {
  const double max_segments = argc > 1 ? std::atof(argv[1]) : 1.1e6;
  // Non-matching meshes (the usual case: impactor on plate) unless "matching" is given: the upper
  // plate is shifted by (0.3 h, 0.2 h) in plane. Matching grids put every node on a corner shared
  // by four opposing segments, the worst case of the search (four projections per node).
  const bool matching = argc > 2 && std::string(argv[2]) == "matching";
  const double offset[2] = {matching ? 0.0 : 0.3, matching ? 0.0 : 0.2};
  omp_set_num_threads(1);
  const int sizes[] = {16, 50, 158, 500};
  // cpu: process CPU time (1 thread), which a shared machine inflates far less than wall time.
  std::printf("%10s %9s %9s %7s %6s %15s %12s %16s %13s %7s %9s\n", "segments", "nodes", "active", "cycles", "sorts",
              "contact ns/seg", "(cpu ns/seg)", "element ns/elem", "(cpu ns/elem)", "ratio", "cpu ratio");
  for (int n : sizes) {
    const double segs_expected = 4.0 * n * n + 8.0 * n;
    if (segs_expected > max_segments) break;
    model::Model model = make_model(n);
    const std::size_t nn = model.num_nodes();
    std::vector<double> x = model.X, v(3 * nn, 0.0), f(3 * nn, 0.0);
    const double h = 1e-3, dt = 1e-7;
    // Upper plate pressed 1e-3 h into the lower one; a smooth velocity field
    // of ~0.1 m/s (1e-8 m per cycle, far below the re-sort allowance of h / 4).
    std::vector<char> upper(nn, 0);  // the plates' nodes at z = h coincide: go by element
    for (Index nd : model.blocks[model.parts[1].block].conn) upper[std::size_t(nd)] = 1;
    for (std::size_t i = 0; i < nn; ++i) {
      if (upper[i]) {
        x[3 * i + 0] += offset[0] * h;
        x[3 * i + 1] += offset[1] * h;
        x[3 * i + 2] -= 1e-3 * h;
      }
      v[3 * i + 0] = 0.1 * std::sin(300 * model.X[3 * i + 1]);
      v[3 * i + 1] = 0.1 * std::cos(200 * model.X[3 * i]);
    }
    contact::PenaltyContact pc(model, model.contacts[0], x, dt);
    const std::size_t S = pc.num_segments();
    const int cycles = int(std::max(10.0, 3e7 / double(S)));
    for (int i = 0; i < 2; ++i) pc.apply(x.data(), v.data(), f.data(), dt);  // warm up
    const long sorts0 = pc.sorts();
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    for (int c = 0; c < cycles; ++c) {
      for (std::size_t i = 0; i < 3 * nn; ++i) x[i] += dt * v[i];
      pc.apply(x.data(), v.data(), f.data(), dt);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_seconds() - c0;
    // The x update above is part of the loop; time it alone and take it out.
    const auto t1 = std::chrono::steady_clock::now();
    for (int c = 0; c < cycles; ++c)
      for (std::size_t i = 0; i < 3 * nn; ++i) x[i] += dt * v[i];
    const double update = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    const double ns_seg = 1e9 * (seconds - update) / (double(S) * cycles);
    const double ns_seg_cpu = 1e9 * (cpu - update) / (double(S) * cycles);
    const std::size_t active = pc.forces().active;
    const long sorts = pc.sorts() - sorts0;

    // Element update of the same model (contact removed), 1 thread: the whole cycle per element.
    model.contacts.clear();
    double ns_elem = 0, ns_elem_cpu = 0;
    {
      solver::Solver solver(model);
      for (int i = 0; i < 2; ++i) solver.step();
      const double ne = double(model.num_elements());
      const int ecycles = int(std::max(5.0, 1e7 / ne));
      const auto e0 = std::chrono::steady_clock::now();
      const double ec0 = cpu_seconds();
      for (int i = 0; i < ecycles; ++i) solver.step();
      ns_elem = 1e9 * std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count() / (ne * ecycles);
      ns_elem_cpu = 1e9 * (cpu_seconds() - ec0) / (ne * ecycles);
    }
    std::printf("%10zu %9zu %9zu %7d %6ld %15.1f %12.1f %16.1f %13.1f %7.2f %9.2f\n", S, pc.num_slave_nodes(), active,
                cycles, sorts, ns_seg, ns_seg_cpu, ns_elem, ns_elem_cpu, ns_seg / ns_elem, ns_seg_cpu / ns_elem_cpu);
    std::fflush(stdout);
  }
  return 0;
}
