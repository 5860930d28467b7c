// Contact in the stable time step (solver.cpp combined_step, penalty_contact spring_stable_step):
// a stiff case, the "penalty far above the element stiffness". Two steel blocks in head-on
// impact (as test_penalty_contact's HeadOn), SOFT 0 with SFS = SFM = 100: the penalty springs are
// 100x the default, k = 100 SLSFAC K A^2 / V = 10 K h, against an element stiffness of order
// (K + 4 G / 3) h, so the contact frequency is several times the element one.
// Checked against independent answers:
//  - set-up: the a priori check warns, naming the factor by which the contact frequency exceeds the
//    element step (the diagnosis), and the factor is > 1;
//  - stability, by the conservation laws: total momentum stays at its initial value to round-off
//    (1e-12 of one block's momentum, as HeadOn), the energy ratio does not trend once the blocks
//    have separated, and the energy balance stays within the one error
//    a stiff penalty cannot avoid: a node that crosses the surface during a step lands up to
//    g = v_rel dt deep in a spring that did not exist a step before, which creates 0.5 k g^2. The
//    bound sum over the nodes that engage of 0.5 k_max (v_rel dt)^2, relative to the initial
//    kinetic energy, is computed below (v_rel = 10 m/s closing, dt the step before contact, the
//    largest number of nodes in contact at once); |ratio - 1| must stay below it over the whole
//    impact and rebound. An instability would grow geometrically past it (the solver's own guard
//    stops at a ratio of 1.5). Because the a priori check found the contact stiffer than the
//    elements, the solver applies the contact step from the start (not only once springs act), so
//    dt before contact is already the combined step and g small;
//  - while the springs act, the step never exceeds TSSFAC x the contact step the solver reports:
//    dt = TSSFAC / sqrt(1 / dt_e^2 + 1 / dt_c^2) < TSSFAC dt_c (the combination, not the element
//    step alone).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "head_on_blocks.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

// Stability is checked after the blocks separate: the energy ratio oscillates with the blocks'
// free vibration (the kinetic energy at t^n is the product of the two half-step velocities) but may
// not trend, as an instability grows geometrically. Means over the first and the last 500 cycles
// after separation (each window spans many periods of the blocks) differ by less than a tenth of
// the oscillation's swing (measured 3 %). The energy balance itself is the test below.
TEST(ContactStep, StiffPenaltyRunsStableWithTheCombinedStep) {
  const model::Model model = test::model_from_yaml(test::head_on_blocks("SOFT: 0, SFS: 100, SFM: 100"), "stiff_contact.yaml");
  solver::Solver solver(model);
  bool warned = false;
  for (const auto& w : solver.warnings())
    if (w.find("contact frequency exceeds the element step by") != std::string::npos) {
      warned = true;
      std::cout << "warning: " << w << "\n";
    }
  EXPECT_TRUE(warned);
  const auto& c = solver.contacts()[0];
  const double dt_approach = solver.state().dt_next_half;  // no spring active yet: element step
  const double tssfac = model.control.tssfac;
  EXPECT_LT(dt_approach, tssfac * c.stable_step() * (1 + 1e-12)) << "the contact step applies from the start";

  double mass = 0;
  for (std::size_t i = 0; i < model.num_nodes(); ++i) mass += model.mass[i];
  const double p_scale = 0.5 * mass * 5.0;
  double p0[3] = {0, 0, 0};
  for (std::size_t i = 0; i < model.num_nodes(); ++i)
    for (int d = 0; d < 3; ++d) p0[d] += model.mass[i] * solver.state().v[3 * i + d];
  const double ke0 = solver.balance().total();
  double max_dp = 0, max_ratio_err = 0, dt_min = dt_approach, peak_force = 0;
  long contact_cycles = 0;
  std::size_t max_active = 0;
  bool step_within_contact_bound = true;
  std::vector<double> ratios;      // per cycle
  std::size_t last_contact = 0;    // index of the last cycle with an active spring
  while (solver.state().time < 3 * 43e-6) {
    solver.step();
    ratios.push_back(solver.energy_ratio());
    if (c.forces().active > 0) last_contact = ratios.size() - 1;
    double p[3] = {0, 0, 0};
    for (std::size_t i = 0; i < model.num_nodes(); ++i)
      for (int d = 0; d < 3; ++d) p[d] += model.mass[i] * solver.state().v[3 * i + d];
    for (int d = 0; d < 3; ++d) max_dp = std::max(max_dp, std::abs(p[d] - p0[d]));
    max_active = std::max(max_active, c.forces().active);
    max_ratio_err = std::max(max_ratio_err, std::abs(solver.energy_ratio() - 1));
    peak_force = std::max(peak_force, c.forces().normal);
    if (c.forces().active > 0) {
      ++contact_cycles;
      dt_min = std::min(dt_min, solver.state().dt_next_half);
      // dt = TSSFAC / sqrt(1/dt_e^2 + 1/dt_c^2) < TSSFAC dt_c (round-off allowance 1e-12).
      if (solver.state().dt_next_half > tssfac * solver.state().dt_contact * (1 + 1e-12))
        step_within_contact_bound = false;
    }
  }
  const double g = 10.0 * dt_approach;
  const double entry_bound = double(max_active) * 0.5 * c.stiffness_max() * g * g / ke0;
  std::cout << "stiff contact: a priori contact step " << c.stable_step() << " s; smallest step in contact " << dt_min << " s (approach "
            << dt_approach << " s), " << contact_cycles << " cycles in contact, peak normal force " << peak_force
            << " N, max |dp| / p " << max_dp / p_scale << ", max |ratio - 1| " << max_ratio_err << " (entry-energy bound " << entry_bound << ")\n";
  EXPECT_GT(contact_cycles, 10);
  EXPECT_TRUE(step_within_contact_bound);
  EXPECT_LT(max_dp / p_scale, 1e-12);
  ASSERT_LT(last_contact + 100, ratios.size()) << "the blocks did not separate for good";
  // The ratio oscillates with the free vibration of the blocks (the kinetic energy at t^n is the
  // product of the two half-step velocities); what must not happen is a trend. Means over the
  // first and the last 500 cycles after separation.
  auto mean = [&](std::size_t a, std::size_t b) {
    double m = 0;
    for (std::size_t i = a; i < b; ++i) m += ratios[i];
    return m / double(b - a);
  };
  const std::size_t a = last_contact + 1, n = ratios.size();
  ASSERT_GT(n - a, 1000u);
  const double early = mean(a, a + 500), late = mean(n - 500, n);
  double swing = 0;
  for (std::size_t i = a; i < n; ++i) swing = std::max(swing, std::abs(ratios[i] - early));
  std::cout << "after separation (" << n - a << " cycles): mean ratio " << early << " then " << late << ", swing " << swing
            << "\n";
  EXPECT_LT(std::abs(late - early), 0.1 * swing);
}

// The energy of the same impact. Reference: conservation, except for the one error a stiff
// penalty cannot avoid: a node crossing the surface part way through a step lands up to
// g = v_rel dt deep in a spring that did not exist a step before. Against the bodies' work that
// is 0.5 k g^2 created, or (the spring starting late) up to as much lost, returned at release:
// while the springs act |ratio - 1| stays below the entry-energy bound of the header (22.8 %
// here). After separation the contact energy (its springs' potential) is 0 and what remains is
// the net of those entries and releases, asserted at no less than the head-on blocks' 1 % below 1
// (the booking used to keep 14 % of the initial energy in the contact after separation, a ratio
// of 0.857; measured now 1.009) and within the bound above. Means over the cycles after the last
// spring let go (the ratio oscillates with the blocks' free vibration).
TEST(ContactStep, StiffPenaltyLosesNoEnergy) {
  const model::Model model = test::model_from_yaml(test::head_on_blocks("SOFT: 0, SFS: 100, SFM: 100"), "stiff_contact.yaml");
  solver::Solver solver(model);
  const auto& c = solver.contacts()[0];
  const double dt_approach = solver.state().dt_next_half, ke0 = solver.balance().total();
  double ratio_min = 1, ratio_max = 1;
  std::size_t max_active = 0, last_contact = 0;
  std::vector<double> ratios;
  while (solver.state().time < 3 * 43e-6) {
    solver.step();
    ratios.push_back(solver.energy_ratio());
    ratio_min = std::min(ratio_min, solver.energy_ratio());
    ratio_max = std::max(ratio_max, solver.energy_ratio());
    max_active = std::max(max_active, c.forces().active);
    if (c.forces().active > 0) last_contact = ratios.size();
  }
  const double g = 10.0 * dt_approach;
  const double entry_bound = double(max_active) * 0.5 * c.stiffness_max() * g * g / ke0;
  ASSERT_LT(last_contact + 100, ratios.size());
  double after = 0;
  for (std::size_t i = last_contact + 1; i < ratios.size(); ++i) after += ratios[i];
  after /= double(ratios.size() - last_contact - 1);
  std::cout << "stiff contact energy: ratio " << ratio_min << " .. " << ratio_max << " in the run, " << after
            << " after separation (entry bound " << entry_bound << "), contact energy at the end "
            << solver.balance().value("contact") << " J\n";
  EXPECT_GT(ratio_min, 1 - entry_bound);
  EXPECT_LT(ratio_max, 1 + entry_bound);
  EXPECT_EQ(solver.balance().value("contact"), 0.0);
  EXPECT_GT(after, 0.99);
  EXPECT_LT(after, 1 + entry_bound);
}

}  // namespace
}  // namespace plyimpact
