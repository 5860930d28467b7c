// bench_cohesive: cost of one tiebreak pass (cohesive/tiebreak_pairs: face normals on the current
// mid-surface, frame, opening, OPTION 9 law, force scatter, energy sums) per interface pair and
// cycle, at 1e4 .. 1e6 pairs, one and two threads. The target: at most 0.3 of an element
// cycle per pair (bench_cycle gives the element cycle on the same machine).
// Model: an n x n grid of matching node pairs (0.5 mm spacing) with the seed's Table 8.6 law, the
// upper nodes opened by a field that grows every cycle on a tenth of the pairs, which soften (the
// damage branch with the pow of the B-K law every cycle); the rest stay elastic, some in compression. Only apply() is timed; the opening update between passes is not.
// Usage: bench_cohesive [max_pairs [normals | refresh K | strengths]]   ("normals": fixed given
// normals instead of faces; "refresh K": normals from the faces every K passes; "strengths": every
// pair its own NFLS and SFLS, 0.3 to 1 of the card's, as process_zone_elements gives a graded mesh).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "cohesive/tiebreak_pairs.hpp"

using namespace plyimpact;

static double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Grid {
  int n = 0;
  std::vector<double> x0, mass;
  cohesive::TiebreakPairsSpec spec;
};

static Grid make_grid(int n, bool faces) {
  Grid g;
  g.n = n;
  const std::size_t np = std::size_t(n) * n;
  const double a = 0.5e-3;
  g.x0.assign(2 * np * 3, 0.0);
  g.mass.assign(2 * np, 1550 * a * a * 0.25e-3 / 2);
  // Nodes numbered as a mesher would: the lower ply's interface nodes, then the upper ply's.
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t p = std::size_t(n) * j + i;
      g.spec.lower.push_back(Index(p));
      g.spec.upper.push_back(Index(np + p));
      g.x0[3 * p] = g.x0[3 * (np + p)] = i * a;
      g.x0[3 * p + 1] = g.x0[3 * (np + p) + 1] = j * a;
    }
  if (faces) {
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        const Index q = Index(n * j + i);
        g.spec.faces.insert(g.spec.faces.end(), {q, q + 1, q + Index(n) + 1, q + Index(n)});
      }
  } else {
    g.spec.area.assign(np, a * a);
    g.spec.normals.assign(3 * np, 0.0);
    for (std::size_t p = 0; p < np; ++p) g.spec.normals[3 * p + 2] = 1;
  }
  return g;
}

int main(int argc, char** argv) {
  const double max_pairs = argc > 1 ? std::atof(argv[1]) : 1.1e6;
  const bool faces = !(argc > 2 && std::string(argv[2]) == "normals");
  const int refresh = argc > 3 && std::string(argv[2]) == "refresh" ? std::atoi(argv[3]) : 1;
  const bool own_strengths = argc > 2 && std::string(argv[2]) == "strengths";
  cohesive::TractionLawParams law;
  law.option = cohesive::TiebreakOption::MixedMode;
  law.NFLS = 60e6;
  law.SFLS = 60e6;
  law.PARAM = -1.45;  // B-K: the damage branch calls pow
  law.ERATEN = 765;
  law.ERATES = 1250;
  law.CN = 1e14;
  law.FS = 0.3;
  std::printf("# tiebreak pass, OPTION 9 (B-K), %s (refresh every %d passes)%s\n",
              faces ? "normals from the interface faces" : "given normals", refresh,
              own_strengths ? ", every pair its own strengths" : "");
  std::printf("%10s %8s %14s %12s %14s %12s\n", "pairs", "threads", "median ns/pc", "min ns/pc", "cpu ns/pc", "damaged %");
  for (int n : {100, 316, 1000}) {
    const std::size_t np = std::size_t(n) * n;
    if (double(np) > max_pairs) break;
    Grid g = make_grid(n, faces);
    for (std::size_t p = 0; own_strengths && p < np; ++p) {
      g.spec.nfls.push_back(law.NFLS * (0.3 + 0.7 * double((p * 53) % 97) / 96.0));
      g.spec.sfls.push_back(law.SFLS * (0.3 + 0.7 * double((p * 29) % 89) / 88.0));
    }
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      cohesive::TiebreakPairs pairs(law, g.spec, g.x0.data(), g.mass.data());
      pairs.set_normal_refresh_interval(refresh);
      std::vector<double> x = g.x0, f(x.size(), 0.0);
      const int cycles = std::max(10, int(3e6 / double(np)));
      const int batches = 5;
      std::vector<double> wall(batches);
      double cpu_total = 0;
      int cycle = 0;
      for (int b = 0; b < batches; ++b) {
        double seconds = 0;
        const double cpu0 = cpu_seconds();
        double cpu_outside = 0;
        for (int c = 0; c < cycles; ++c, ++cycle) {
          const double co = cpu_seconds();
          const double s = 1 + 1e-4 * cycle;  // the opening grows slowly
          for (std::size_t p = 0; p < np; ++p) {
            const double phase = 7e-3 * double(p % 9973);
            double* xu = &x[3 * (np + p)];
            const bool zone = p % 10 == 0;  // a tenth in the process zone, the rest elastic
            xu[0] = g.x0[3 * (np + p)] + (zone ? s * 1e-6 : 0.2e-6) * std::sin(phase);
            xu[2] = zone ? s * 2e-6 : 0.3e-6 * std::cos(2 * phase);  // some elastic pairs compressed
          }
          std::fill(f.begin(), f.end(), 0.0);
          cpu_outside += cpu_seconds() - co;
          const auto t0 = std::chrono::steady_clock::now();
          pairs.apply(x.data(), nullptr, f.data(), 1e-8);
          seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
        cpu_total += cpu_seconds() - cpu0 - cpu_outside;
        wall[b] = 1e9 * seconds / (double(cycles) * double(np));
      }
      std::sort(wall.begin(), wall.end());
      const auto& d = pairs.damage();
      const double damaged = 100.0 * double(std::count_if(d.begin(), d.end(), [](double v) { return v > 0; })) / double(np);
      std::printf("%10zu %8d %14.1f %12.1f %14.1f %12.1f\n", np, threads, wall[batches / 2], wall[0],
                  1e9 * cpu_total / (double(batches) * cycles * double(np)), damaged);
    }
  }
  return 0;
}
