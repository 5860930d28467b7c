// bench: nanoseconds per element-cycle of the whole explicit cycle (node update + element pass)
// for ELFORM 1 + IHQ 4 + *MAT_002 hexahedra, on 1e4, 1e5 and 1e6 elements, with 1 and 2 OpenMP
// threads (ns per element-cycle: median and minimum of five batches, wall clock, and the median
// process CPU time). Usage: bench [max_elements [max_threads]]   (defaults 1e6, 2). Figures go to
// BENCHMARKS.md. `bench --scene FILE ...` profiles a scene per subsystem instead (bench_scene.cpp).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "config/scene_loader.hpp"
#include "mesh/mesh.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

using namespace plyimpact;

// Process CPU time (all threads): unaffected by preemption from other processes, so it gives a
// stable per-thread cost on a busy machine; wall time is what counts on an idle one.
static double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

static model::Model make_model(int nx, int ny, int nz) {
  const std::string yaml =
      "units: SI\ncontrol: {termination_time: 1}\nmaterials:\n"
      "  ply: {card: MAT_002, RO: 1550, EA: 157e9, EB: 8.5e9, EC: 8.5e9, PRBA: 0.019, PRCA: 0.019, PRCB: 0.53,"
      " GAB: 4.2e9, GBC: 2.2e9, GCA: 4.2e9, AOPT: 2, A: [1,0,0], D: [0,1,0]}\n"
      "sections:\n  s: {ELFORM: 1, IHQ: 4, QM: 0.1}\nparts:\n  p: {material: ply, section: s, beta: 30}\n"
      "mesh:\n  boxes:\n    - {part: p, size: [" + std::to_string(nx * 1e-3) + ", " + std::to_string(ny * 1e-3) + ", " +
      std::to_string(nz * 1e-3) + "], elements: [" + std::to_string(nx) + ", " + std::to_string(ny) + ", " +
      std::to_string(nz) + "]}\n";
  const config::Scene scene = config::load_scene_from_string(yaml, "bench.yaml");
  model::Model m = model::build_model(scene, mesh::mesh_boxes(scene));
  for (std::size_t n = 0; n < m.num_nodes(); ++n) {  // a smooth non-rigid velocity field
    const double* X = &m.X[3 * n];
    m.v0[3 * n + 0] = std::sin(300 * X[1]);
    m.v0[3 * n + 1] = std::cos(200 * X[2]);
    m.v0[3 * n + 2] = std::sin(250 * X[0]) * 2;
  }
  return m;
}

int bench_scene(int argc, char** argv);  // bench_scene.cpp

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--scene") {
    try {
      return bench_scene(argc, argv);
    } catch (const std::exception& e) {  // a scene or override error: its message, not an abort
      std::fprintf(stderr, "bench: %s\n", e.what());
      return 1;
    }
  }
  const double max_elements = argc > 1 ? std::atof(argv[1]) : 1e6;
  const int max_threads = argc > 2 ? std::atoi(argv[2]) : 2;
  struct Size { int nx, ny, nz, cycles; };
  const Size sizes[] = {{25, 20, 20, 300}, {50, 50, 40, 40}, {100, 100, 100, 6}};
  std::printf("%12s %8s %8s %18s %18s %18s %10s\n", "elements", "threads", "cycles/batch", "median wall ns",
              "min wall ns", "median cpu ns", "speed-up");
  for (const Size& s : sizes) {
    const double ne = double(s.nx) * s.ny * s.nz;
    if (ne > max_elements) break;
    const model::Model model = make_model(s.nx, s.ny, s.nz);
    double ns_one_thread = 0;
    for (int threads = 1; threads <= max_threads; ++threads) {
      omp_set_num_threads(threads);
      solver::Solver solver(model);
      for (int i = 0; i < 2; ++i) solver.step();  // warm up (page faults, caches)
      // Five batches of s.cycles: the median is robust to the virtual machine's interrupt bursts,
      // the minimum shows the undisturbed cost.
      constexpr int kBatches = 5;
      double wall[kBatches], cpu[kBatches];
      for (int b = 0; b < kBatches; ++b) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_seconds();
        for (int i = 0; i < s.cycles; ++i) solver.step();
        wall[b] = 1e9 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / (ne * s.cycles);
        cpu[b] = 1e9 * (cpu_seconds() - c0) / (ne * s.cycles);
      }
      std::sort(wall, wall + kBatches);
      std::sort(cpu, cpu + kBatches);
      const double ns = wall[kBatches / 2], ns_min = wall[0], ns_cpu = cpu[kBatches / 2];
      if (threads == 1) ns_one_thread = ns;
      std::printf("%12.0f %8d %8d %18.1f %18.1f %18.1f %10.2f\n", ne, threads, s.cycles, ns, ns_min, ns_cpu,
                  ns_one_thread / ns);
      std::fflush(stdout);
    }
  }
  return 0;
}
