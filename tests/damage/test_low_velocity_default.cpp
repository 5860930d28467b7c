// Smoke run of the default scene (configs/low_velocity_impact.yaml, README command 1) through its
// first 0.1 ms: the tup's free flight, the first contact and the start of loading, with *MAT_054
// plies, eroding contact and the rigid tup all active. Checked against independent answers:
//  - the impact energy is the ASTM D7136 one the scene claims, E = 6.7 J/mm x h (h = 16 x 0.25 mm);
//    tolerance 0.35 %: the velocity is entered to three digits (3.12 m/s for 3.1217), so the
//    kinetic energy may differ by up to 2 x 0.005/3.12 = 0.32 %;
//  - free flight: nothing touches the plate before the tup has crossed the gap, t < gap/v (exact:
//    no gravity, plate at rest), so the contact force is zero and the tup keeps its velocity
//    exactly;
//  - conservation of energy once the contact loads the plate: the energy balance defect (total -
//    initial - external work) stays below 1 % of the energy the tup has given up (its kinetic
//    energy loss) - a contact shoot-apart or hourglass runaway would put the defect at the size of
//    the transferred energy itself, while the central-difference error is O(dt^2) (measured 1e-5
//    of the total energy in the full default run);
//  - the run's own energy check (run/energy_balance_watch) reads the same history: the ratio's
//    extremes it reports equal those of history.csv's energy_ratio column from cycle 3 on (within
//    the column's 10 printed digits), and it passes (the defect above is far inside its 1 %).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "mesh/scene_mesher.hpp"
#include "model/model.hpp"
#include "run/run.hpp"

namespace plyimpact {
namespace {

// history.csv as columns by name.
std::map<std::string, std::vector<double>> read_history(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (std::size_t c = 0; c < names.size() && std::getline(row, cell, ','); ++c) cols[names[c]].push_back(std::stod(cell));
  }
  return cols;
}

TEST(LowVelocityDefault, FreeFlightFirstContactAndEnergyBalance) {
  config::Scene scene = config::load_scene(PLYIMPACT_SOURCE_DIR "/configs/low_velocity_impact.yaml");
  scene.control.termination_time = 1.0e-4;  // the first 0.1 ms (~2,200 cycles) of the 5 ms event
  scene.output.interval = 5.0e-5;
  scene.output.history_interval = 1.0e-6;
  const model::Model model = model::build_model(scene, mesh::mesh_scene(scene));
  ASSERT_TRUE(model.impactor.has_value());
  const double mass = model.impactor->mass, v0 = -model.impactor->velocity[2];

  // D7136 energy for the meshed thickness (16 plies of 0.25 mm).
  double thickness = 0;
  for (const auto& p : scene.laminate->plies) thickness += p.thickness;
  const double e_d7136 = 6.7e3 * thickness;  // 6.7 J/mm = 6700 J/m
  EXPECT_NEAR(0.5 * mass * v0 * v0 / e_d7136, 1.0, 3.5e-3);

  const auto dir = std::filesystem::temp_directory_path() / ("plyimpact_low_velocity_default_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  run::RunOptions options;
  options.output_dir = dir;
  const run::RunReport r = run::run_model(model, options);
  ASSERT_TRUE(r.completed) << r.stop_reason;
  auto h = read_history(r.history);
  const auto& t = h["time"];
  ASSERT_GT(t.size(), 90u);

  const double gap = scene.impactor->gap, t_contact = gap / v0;
  double kinetic_loss = 0, defect = 0, peak_force = 0;
  std::size_t free_flight_rows = 0;
  const double e0 = h["total_energy"][0];
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t_contact) {
      ++free_flight_rows;
      EXPECT_EQ(h["contact_tup_plies_fz"][i], 0.0) << "t = " << t[i];
      EXPECT_EQ(h["rigid_impactor_vz"][i], -v0) << "t = " << t[i];
    }
    const double vz = h["rigid_impactor_vz"][i];
    kinetic_loss = 0.5 * mass * (v0 * v0 - vz * vz);
    defect = std::max(defect, std::abs(h["total_energy"][i] - e0 - h["external_work"][i]));
    peak_force = std::max(peak_force, h["contact_tup_plies_fz"][i]);
  }
  std::cout << "free flight to " << t_contact << " s (" << free_flight_rows << " rows); at 0.1 ms: contact force "
            << peak_force << " N, energy from the tup " << kinetic_loss << " J, largest balance defect " << defect
            << " J\n";
  EXPECT_GT(free_flight_rows, 10u);
  EXPECT_GT(peak_force, 100.0);    // the contact has started loading the plate (N)
  EXPECT_GT(kinetic_loss, 0.05);   // J: the tup has given up energy to the plate
  EXPECT_LT(defect, 0.01 * kinetic_loss) << "defect " << defect << " J, transferred " << kinetic_loss << " J";
  ASSERT_TRUE(r.energy_balance.has_value());
  double ratio_min = 1, ratio_max = 1;  // the history rows after the start-up cycles (t > 3 steps)
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] > 3 * h["dt"][i]) {
      ratio_min = std::min(ratio_min, h["energy_ratio"][i]);
      ratio_max = std::max(ratio_max, h["energy_ratio"][i]);
    }
  EXPECT_NEAR(r.energy_balance->ratio_min, ratio_min, 1e-9);
  EXPECT_NEAR(r.energy_balance->ratio_max, ratio_max, 1e-9);
  EXPECT_TRUE(r.energy_balance->passed);
  EXPECT_TRUE(r.energy_balance->negative.empty());
  // Where the hourglass energy is at the check's maximum (hourglass_check.by_part_at_max): the
  // fully integrated impact-zone parts (ELFORM -2) have no hourglass modes and hold exactly zero,
  // every one-point ply part (IHQ 6) holds some. The parts' sums are taken from the elements after
  // the sample's cycle, the total from that cycle's energy balance, which the node update records
  // before the next element pass adds its hourglass work: the two differ by that one pass.
  ASSERT_TRUE(r.hourglass.has_value());
  ASSERT_EQ(r.hourglass->by_part.size(), model.parts.size());
  double by_part_sum = 0;
  int zone_parts = 0, ply_parts = 0;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const std::string& name = model.parts[p].name;
    if (name.rfind("ply_", 0) != 0) continue;
    const bool zone = name.size() > 5 && name.compare(name.size() - 5, 5, "_zone") == 0;
    if (zone) {
      ++zone_parts;
      EXPECT_EQ(r.hourglass->by_part[p], 0.0) << name;
    } else {
      ++ply_parts;
      EXPECT_GT(r.hourglass->by_part[p], 0.0) << name;
    }
    by_part_sum += r.hourglass->by_part[p];
  }
  EXPECT_EQ(zone_parts, 16);
  EXPECT_EQ(ply_parts, 16);
  std::cout << "hourglass at the check's maximum: " << r.hourglass->hourglass << " J in the balance, " << by_part_sum
            << " J summed over the parts\n";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace plyimpact
