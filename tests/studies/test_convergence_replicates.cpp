// Replicates in a mesh-convergence study: a perturbation parameter beside the mesh (combined as a
// grid) makes each mesh's cases replicates of it. Reference: the arithmetic done by hand on a table
// of made-up values: each mesh's value is the replicates' mean, its spread their range, its wall
// time the mean of one run; Richardson runs on the means; a change between the two finest meshes
// no larger than their spread is flagged, a larger one is not.
#include <gtest/gtest.h>

#include <string>

#include "study/convergence.hpp"
#include "study/study_spec.hpp"
#include "study/study_table.hpp"

namespace plyimpact::study {
namespace {

StudySpec zone_study() {
  StudySpec spec;
  spec.parameters = {{"laminate.refined_zone.element_size", {{"2.5", ""}, {"1.25", ""}, {"0.625", ""}}},
                     {"impactor.gap", {{"0.05", ""}, {"0.15", ""}}}};
  ConvergenceSpec c;
  c.parameter = "laminate.refined_zone.element_size";
  c.h_from = HFrom::value;
  spec.convergence = c;
  return spec;
}

// absorbed_energy of (zone, gap) and the wall time of each run.
StudyTable table(double fine_a, double fine_b) {
  StudyTable t;
  t.parameter_keys = {"laminate.refined_zone.element_size", "impactor.gap"};
  t.quantity_columns = {"absorbed_energy", "wall_time"};
  const auto row = [&](const char* zone, const char* gap, double energy, double wall) {
    t.rows.push_back({std::string("z") + zone + "_g" + gap, "finished", {zone, gap},
                      {{"absorbed_energy", energy}, {"wall_time", wall}}, {}});
  };
  row("2.5", "0.05", 8.0, 240);
  row("2.5", "0.15", 7.8, 250);
  row("1.25", "0.05", 9.7, 700);
  row("1.25", "0.15", 9.3, 720);
  row("0.625", "0.05", fine_a, 2700);
  row("0.625", "0.15", fine_b, 2800);
  return t;
}

TEST(ConvergenceReplicates, MeansSpreadsAndTheUnresolvedFlag) {
  const ConvergenceReport rep = analyse_convergence(zone_study(), table(10.9, 10.1));
  ASSERT_EQ(rep.h.size(), 3u);
  EXPECT_EQ(rep.h[0], 2.5);
  EXPECT_EQ(rep.cases[0], "z2.5_g0.05+z2.5_g0.15");
  EXPECT_EQ(rep.case_names[2].size(), 2u);
  EXPECT_DOUBLE_EQ(rep.wall_time[1], 710);
  ASSERT_EQ(rep.quantities.size(), 1u);
  const QuantityConvergence& q = rep.quantities[0];
  EXPECT_DOUBLE_EQ(q.values[0], 7.9);
  EXPECT_DOUBLE_EQ(q.values[1], 9.5);
  EXPECT_DOUBLE_EQ(q.values[2], 10.5);
  EXPECT_NEAR(q.spread[0], 0.2, 1e-12);
  EXPECT_NEAR(q.spread[1], 0.4, 1e-12);
  EXPECT_NEAR(q.spread[2], 0.8, 1e-12);
  // 1.0 apart, spread 0.8: resolved.
  EXPECT_TRUE(q.flags.empty());
  ASSERT_TRUE(q.richardson);
  // Richardson on the means: differences 1.6 and 1.0 at a refinement ratio of 2.
  EXPECT_NEAR(q.richardson->order, std::log(1.6 / 1.0) / std::log(2.0), 1e-9);

  const ConvergenceReport close = analyse_convergence(zone_study(), table(10.3, 9.3));  // mean 9.8, spread 1.0
  ASSERT_EQ(close.quantities[0].flags.size(), 1u);
  EXPECT_NE(close.quantities[0].flags[0].find("not resolved"), std::string::npos) << close.quantities[0].flags[0];
  const std::string csv = convergence_csv(close);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "case,h,wall_time,replicates,absorbed_energy,absorbed_energy_spread,absorbed_energy_error_finest,"
            "absorbed_energy_error_richardson,absorbed_energy_error_reference");
}

TEST(ConvergenceReplicates, OneRunPerMeshHasNoSpreadAndNoFlag) {
  StudySpec spec = zone_study();
  spec.parameters.pop_back();
  StudyTable t = table(10.9, 10.1);
  t.parameter_keys.pop_back();
  std::vector<CaseRow> one;
  for (auto& r : t.rows)
    if (r.values[1] == "0.05") {
      r.values.pop_back();
      one.push_back(r);
    }
  t.rows = one;
  const ConvergenceReport rep = analyse_convergence(spec, t);
  ASSERT_EQ(rep.quantities.size(), 1u);
  EXPECT_EQ(rep.quantities[0].values, (std::vector<double>{8.0, 9.7, 10.9}));
  EXPECT_EQ(rep.quantities[0].spread, (std::vector<double>{0, 0, 0}));
  EXPECT_TRUE(rep.quantities[0].flags.empty());
  EXPECT_EQ(rep.cases[1], "z1.25_g0.05");
}

}  // namespace
}  // namespace plyimpact::study
