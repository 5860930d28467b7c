// Meshing time and peak memory (not a test): `bench_mesher N` meshes a 150 x 100 mm [0/45/-45/90]2s
// plate (16 plies, one element per ply, delaminating interfaces at every angle change) with about
// N elements and prints elements, nodes, wall time and the process's peak resident memory. Run one
// size per process so the peak belongs to that size.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "config/scene_loader.hpp"
#include "mesh/laminate_mesher.hpp"

int main(int argc, char** argv) {
  const double n = argc > 1 ? std::stod(argv[1]) : 1e5;
  const double h = std::sqrt(16 * 150.0 * 100.0 / n);  // mm
  const std::string text = R"(units: mm-t-s-MPa
control: {termination_time: 1.0e-6}
materials:
  ply: {card: MAT_002, RO: 1.55e-9, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.019, PRCA: 0.019,
        PRCB: 0.53, GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0]}
sections: {s: {}}
laminate: {length: 150, width: 100, ply_thickness: 0.25, stacking: "[0/45/-45/90]2s", material: ply, section: s,
           interfaces: angle-change, element_size: )" + std::to_string(h) + "}\n";
  const auto t0 = std::chrono::steady_clock::now();
  const auto scene = plyimpact::config::load_scene_from_string(text, "bench.yaml");
  const auto mesh = plyimpact::mesh::mesh_laminate(scene);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("elements %zu nodes %zu interfaces %zu h %.3f mm: %.2f s, peak RSS %.0f MiB\n", mesh.num_elements(),
              mesh.num_nodes(), mesh.interfaces.size(), h, s, ru.ru_maxrss / 1024.0);
}
