// bench --scene: where the cycle of a real scene goes, per subsystem, with 1 and 2 threads.
//   bench --scene FILE [--set key=value ...] [--warmup N] [--cycles N] [--batches N]
// Loads and meshes the scene as `plyimpact run` does (without its output), runs `warmup` cycles on
// all threads (to reach contact: shorten impactor.gap), then alternates batches of `cycles` cycles
// on 1 and on 2 threads over the same evolving state (A B A B ...: both see the same load and
// nearly the same physics). Per thread count it prints the median over the batches of the wall ns
// per element-cycle of the whole cycle and of each phase the solver times (node update, element
// pass, element checks, each force contributor), the median process CPU ns of the whole cycle, the
// range of the whole-cycle wall figure, and the load average before and after.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "solver/solver.hpp"

using namespace plyimpact;

namespace {

double cpu_now() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

void print_load(const char* when) {
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) == 3) std::printf("load average %s: %.2f %.2f %.2f\n", when, load[0], load[1], load[2]);
}

struct Batch {
  double wall = 0, cpu = 0;      // ns per element-cycle
  std::vector<double> phases;    // ns per element-cycle, as Solver::phase_times()
};

}  // namespace

int bench_scene(int argc, char** argv) {
  std::string file;
  std::vector<config::SceneOverride> overrides;
  int warmup = 200, cycles = 100, batches = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--scene" && has_value) file = argv[++i];
    else if (a == "--set" && has_value) overrides.push_back(config::parse_set_argument(argv[++i]));
    else if (a == "--warmup" && has_value) warmup = std::atoi(argv[++i]);
    else if (a == "--cycles" && has_value) cycles = std::atoi(argv[++i]);
    else if (a == "--batches" && has_value) batches = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "bench --scene FILE [--set key=value ...] [--warmup N] [--cycles N] [--batches N]\n");
      return 64;
    }
  }
  const config::Scene scene = config::load_scene(file, overrides);
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  std::size_t elements = 0;
  for (const auto& blk : model.blocks)
    if (!blk.rigid) elements += blk.size();
  const int max_threads = omp_get_max_threads();
  solver::Solver solver(model);
  for (int i = 0; i < warmup; ++i) solver.step();
  std::printf("%s: %zu deformable elements, %zu nodes; after %d warm-up cycles t = %.4g s\n", file.c_str(), elements,
              model.num_nodes(), warmup, solver.state().time);
  std::printf("element schedule: %zu chunks in %zu colours (chunks per colour:", model.schedule.chunks.size(),
              model.schedule.colors.size());
  for (const auto& c : model.schedule.colors) std::printf(" %zu", c.size());
  std::printf(")\n");
  print_load("before");
  std::vector<std::vector<Batch>> runs(std::size_t(std::min(max_threads, 2)));
  const double per = 1e9 / (double(elements) * cycles);
  for (int b = 0; b < batches; ++b)
    for (int t = 1; t <= int(runs.size()); ++t) {
      omp_set_num_threads(t);
      std::vector<double> before;
      for (const auto& p : solver.phase_times()) before.push_back(p.seconds);
      const auto w0 = std::chrono::steady_clock::now();
      const double c0 = cpu_now();
      for (int i = 0; i < cycles; ++i) solver.step();
      Batch r;
      r.wall = per * std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
      r.cpu = per * (cpu_now() - c0);
      for (std::size_t k = 0; k < before.size(); ++k) r.phases.push_back(per * (solver.phase_times()[k].seconds - before[k]));
      runs[std::size_t(t - 1)].push_back(r);
    }
  print_load("after");
  std::printf("t = %.4g s, cycle %ld, %ld eroded elements; solver threads used %d\n", solver.state().time,
              solver.state().cycle, solver.state().eroded_elements, solver.threads_used());
  std::printf("%-22s", "ns / element-cycle");
  for (std::size_t t = 0; t < runs.size(); ++t) std::printf("  %9s %-2zu", "threads", t + 1);
  std::printf("\n");
  auto row = [&](const char* name, auto get) {
    std::printf("%-22s", name);
    for (const auto& batches_t : runs) {
      std::vector<double> v;
      for (const auto& r : batches_t) v.push_back(get(r));
      std::printf("  %12.1f", median(v));
    }
    std::printf("\n");
  };
  row("cycle (wall)", [](const Batch& r) { return r.wall; });
  row("cycle (cpu)", [](const Batch& r) { return r.cpu; });
  for (std::size_t k = 0; k < solver.phase_times().size(); ++k)
    row(solver.phase_times()[k].name.c_str(), [k](const Batch& r) { return r.phases[k]; });
  for (std::size_t t = 0; t < runs.size(); ++t) {
    double lo = 1e300, hi = 0;
    for (const auto& r : runs[t]) {
      lo = std::min(lo, r.wall);
      hi = std::max(hi, r.wall);
    }
    std::printf("threads %zu: whole-cycle wall range %.1f - %.1f ns over %d batches of %d cycles\n", t + 1, lo, hi,
                batches, cycles);
  }
  if (runs.size() == 2) {
    std::vector<double> w1, w2;
    for (const auto& r : runs[0]) w1.push_back(r.wall);
    for (const auto& r : runs[1]) w2.push_back(r.wall);
    std::printf("2-thread speed-up (medians): %.2f\n", median(w1) / median(w2));
  }
  return 0;
}
