// Quantities of interest on a synthetic run record with a closed-form answer: a 2 kg rigid tup
// moving at -3 m/s along z decelerated by a constant 100 N contact force (a = 50 m/s^2), sampled
// every 10 ms for 0.1 s: v(t) = -3 + 50 t (rebound at 0.06 s, +2 m/s at the end), travel
// s(t) = 3 t - 25 t^2 (0.09 m at the rebound, 0.05 m at the end). Expected: mass 2 kg from F = m a,
// absorbed energy 0.5 x 2 x (9 - 4) = 5 J, residual velocity -2 m/s (rebound), largest travel
// 0.09 m, permanent indentation 0.05 m. Tolerances 1e-12 relative: the values are exact in binary
// up to the products above.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "output/json.hpp"
#include "study/quantities.hpp"

namespace plyimpact::study {
namespace {

RunRecord tup_record() {
  RunRecord r;
  r.history = output::HistoryTable({"time", "kinetic_energy", "internal_energy", "hourglass_energy", "energy_ratio",
                                    "contact_impact_fx", "contact_impact_fy", "contact_impact_fz",
                                    "contact_impact_normal", "contact_impact_tangential", "rigid_tup_x", "rigid_tup_y",
                                    "rigid_tup_z", "rigid_tup_vx", "rigid_tup_vy", "rigid_tup_vz", "rigid_tup_ax",
                                    "rigid_tup_ay", "rigid_tup_az", "rigid_tup_contact_fx", "rigid_tup_contact_fy",
                                    "rigid_tup_contact_fz", "eroded_elements"});
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.01 * i, v = -3 + 50 * t, z = 0.5 - 3 * t + 25 * t * t;
    const double plate_force = i == 4 ? 150.0 : 100.0;  // the contact columns' own peak at 0.04 s
    const double internal = i < 5 ? 10.0 * i : 40.0, hourglass = 0.5 * i;
    r.history.add_row(std::vector<double>{t, 0.5 * 2 * v * v, internal, hourglass, 1.0 + 0.001 * i * (i % 2 ? 1 : -1),
                                          0, 0, plate_force, plate_force, 0, 0.1, 0.2, z, 0, 0, v, 0, 0, 50, 0, 0, 100,
                                          i >= 7 ? 3.0 : 0.0});
  }
  r.summary = output::Json::object();
  r.summary["wall_seconds"] = 12.5;
  r.summary["elements"] = 7488;
  r.summary["erosion"]["eroded_elements"] = 3;
  r.summary["erosion"]["eroded_volume"] = 4.5e-9;
  r.summary["erosion"]["eroded_energy"] = 0.25;
  output::Json by = output::Json::array();
  for (auto [cause, count] : {std::pair{"fibre_tension", 2}, std::pair{"matrix", 1}}) {
    output::Json e = output::Json::object();
    e["part"] = "ply_1";
    e["cause"] = cause;
    e["count"] = count;
    by.push_back(e);
  }
  r.summary["erosion"]["by_part_and_cause"] = by;
  return r;
}

double value(const RunRecord& r, const std::string& quantity, const std::string& name = "") {
  for (const auto& v : find_quantity(quantity)->compute(r))
    if (v.name == (name.empty() ? quantity : name)) return v.value;
  ADD_FAILURE() << "no value " << name;
  return std::nan("");
}

TEST(Quantities, RigidImpactorClosedForm) {
  const RunRecord r = tup_record();
  EXPECT_NEAR(value(r, "absorbed_energy"), 5.0, 5e-12);
  EXPECT_NEAR(value(r, "residual_velocity"), -2.0, 2e-12);
  EXPECT_NEAR(value(r, "max_impactor_displacement"), 0.09, 1e-12);
  EXPECT_NEAR(value(r, "permanent_indentation"), 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(value(r, "peak_contact_force"), 150.0);
  EXPECT_DOUBLE_EQ(value(r, "peak_contact_force_time"), 0.04);
  EXPECT_DOUBLE_EQ(value(r, "first_damage_time"), 0.07);
  EXPECT_NEAR(value(r, "energy_ratio_deviation"), 0.010, 1e-15);  // the last sample, 1 - 0.010
  // No summary check and no energy columns: hourglass over the same sample's internal energy, largest
  // at the last sample (5 over 40; the first samples' 0.5 i / 10 i is 0.05).
  EXPECT_NEAR(value(r, "hourglass_ratio"), 5.0 / 40.0, 1e-15);
  EXPECT_DOUBLE_EQ(value(r, "wall_time"), 12.5);
  EXPECT_DOUBLE_EQ(value(r, "elements"), 7488);
  EXPECT_DOUBLE_EQ(value(r, "eroded_elements"), 3);
  EXPECT_DOUBLE_EQ(value(r, "eroded_elements", "eroded_elements_fibre_tension"), 2);
  EXPECT_DOUBLE_EQ(value(r, "eroded_elements", "eroded_elements_matrix"), 1);
  EXPECT_DOUBLE_EQ(value(r, "eroded_volume"), 4.5e-9);
  EXPECT_DOUBLE_EQ(value(r, "eroded_energy"), 0.25);
}

// The impactor force on a closed form: a 2 kg tup at -3 m/s along z under the force
// F(t) = F0 (1 - cos 2 pi f t) / 2 along +z, rows every T = 5 us. The tup's momentum change per row
// over the row's interval is the force's mean over it, F0/2 (1 - sinc(pi f T) cos 2 pi f t_mid)
// at the interval's middle t_mid (tolerance 1e-9 F0: the velocities' round-off over a 5 us
// difference). The contact columns carry a one-row spike of 10 F0, which the instantaneous
// peak_contact_force reports and the momentum does not see.
RunRecord sine_force_record(double f0, double f, double t_end) {
  RunRecord r;
  r.history = output::HistoryTable({"time", "contact_impact_fx", "contact_impact_fy", "contact_impact_fz", "rigid_tup_x",
                                    "rigid_tup_y", "rigid_tup_z", "rigid_tup_vx", "rigid_tup_vy", "rigid_tup_vz",
                                    "rigid_tup_ax", "rigid_tup_ay", "rigid_tup_az", "rigid_tup_contact_fx",
                                    "rigid_tup_contact_fy", "rigid_tup_contact_fz"});
  const double m = 2, w = 2 * std::numbers::pi * f, T = 5e-6;
  const auto rows = int(std::lround(t_end / T));
  for (int i = 0; i <= rows; ++i) {
    const double t = i * T, force = 0.5 * f0 * (1 - std::cos(w * t));
    const double v = -3 + 0.5 * f0 / m * (t - std::sin(w * t) / w);
    const double spike = i == rows / 3 ? 10 * f0 : force;
    r.history.add_row(std::vector<double>{t, 0, 0, spike, 0, 0, 0.5 - 3 * t, 0, 0, v, 0, 0, force / m, 0, 0, force});
  }
  r.summary = output::Json::object();
  return r;
}

TEST(Quantities, ImpactorForceIsTheIntervalMeanOfTheForce) {
  const double f0 = 1000, f = 1000, T = 5e-6;
  const RunRecord r = sine_force_record(f0, f, 0.01);
  const ImpactorForce force = impactor_force(r);
  EXPECT_NEAR(force.interval, T, 1e-15);
  ASSERT_EQ(force.time.size(), 2000u);
  const double sinc = std::sin(std::numbers::pi * f * T) / (std::numbers::pi * f * T);
  for (std::size_t i = 0; i < force.time.size(); ++i) {
    EXPECT_NEAR(force.time[i], (double(i) + 0.5) * T, 1e-15);
    EXPECT_NEAR(force.force[i], 0.5 * f0 * (1 - sinc * std::cos(2 * std::numbers::pi * f * force.time[i])), 1e-9 * f0) << i;
  }
  EXPECT_DOUBLE_EQ(value(r, "peak_contact_force"), 10 * f0);  // the instantaneous column's spike
  EXPECT_LT(value(r, "peak_impactor_force_cfc1000"), 1.001 * f0);
}

TEST(Quantities, FilteredImpactorForcePeaksAtTheMiddleOfASymmetricPulse) {
  // One period of the force above, 4 ms long (125 Hz), inside 10 ms of rows: the phaseless filter
  // keeps its crest at 2 ms, within one row, and its height within 1 % (125 Hz is far below the
  // corner of either class).
  RunRecord r = sine_force_record(2000, 250, 0.004);
  const double t_last = r.history.at(r.history.rows() - 1, 0);
  for (int i = 1; i <= 1200; ++i) {
    std::vector<double> row(r.history.columns().size(), 0.0);
    for (std::size_t c = 0; c < row.size(); ++c) row[c] = r.history.at(r.history.rows() - 1, c);
    row[0] = t_last + i * 5e-6;
    row[6] += row[9] * i * 5e-6;  // the tup flies on at its last speed, no force
    row[3] = row[12] = row[15] = 0;
    r.history.add_row(row);
  }
  EXPECT_NEAR(value(r, "peak_impactor_force_cfc600_time"), 0.002, 5e-6);
  EXPECT_NEAR(value(r, "peak_impactor_force_cfc600"), 2000, 20);
}

// A run's summary carries its own hourglass check (the same-sample rule with the 1 % floor at every
// history sample): the quantity is that verdict, not a recomputation.
TEST(Quantities, HourglassRatioIsTheRunsOwnCheck) {
  RunRecord r = tup_record();
  r.summary["hourglass_check"]["max_ratio"] = 0.3;
  EXPECT_DOUBLE_EQ(value(r, "hourglass_ratio"), 0.3);
}

TEST(Quantities, MissingDataSaysWhy) {
  const RunRecord r = tup_record();
  try {
    find_quantity("delaminated_area")->compute(r);
    FAIL();
  } catch (const NotAvailable& e) {
    EXPECT_NE(std::string(e.what()).find("not available in this scene"), std::string::npos) << e.what();
  }
  RunRecord plain;
  plain.history = output::HistoryTable({"time", "kinetic_energy"});
  plain.history.add_row(std::vector<double>{0, 1});
  EXPECT_THROW(find_quantity("residual_velocity")->compute(plain), NotAvailable);
  EXPECT_THROW(find_quantity("eroded_elements")->compute(plain), NotAvailable);
}

TEST(Quantities, DelaminatedAreaPerInterface) {
  RunRecord r;
  r.history = output::HistoryTable({"time", "delaminated_area", "delaminated_area_1", "delaminated_area_2"});
  r.history.add_row(std::vector<double>{0, 0, 0, 0});
  r.history.add_row(std::vector<double>{1, 3e-6, 1e-6, 2e-6});
  const auto v = find_quantity("delaminated_area")->compute(r);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[2].name, "delaminated_area_2");
  EXPECT_DOUBLE_EQ(v[0].value, 3e-6);
}

// A deformable impactor (centre-of-mass columns impactor_*): the same motion as the rigid tup, its
// kinetic energy column 0.5 x 2 x v^2 plus 1 J of vibration at the end. Residual velocity and
// travel come from the centre of mass, the absorbed energy from the kinetic-energy column: 9 - 5 = 4 J.
TEST(Quantities, DeformableImpactorFromItsCentreOfMass) {
  RunRecord r;
  r.history = output::HistoryTable({"time", "kinetic_energy", "impactor_x", "impactor_y", "impactor_z", "impactor_vx",
                                    "impactor_vy", "impactor_vz", "impactor_kinetic_energy"});
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.01 * i, v = -3 + 50 * t, z = 0.5 - 3 * t + 25 * t * t;
    r.history.add_row(std::vector<double>{t, 0, 0.1, 0.2, z, 0, 0, v, 0.5 * 2 * v * v + (i == 10 ? 1.0 : 0.0)});
  }
  EXPECT_NEAR(value(r, "residual_velocity"), -2.0, 2e-12);
  EXPECT_NEAR(value(r, "max_impactor_displacement"), 0.09, 1e-12);
  EXPECT_NEAR(value(r, "permanent_indentation"), 0.05, 1e-12);
  EXPECT_NEAR(value(r, "absorbed_energy"), 4.0, 4e-12);
}

}  // namespace
}  // namespace plyimpact::study
