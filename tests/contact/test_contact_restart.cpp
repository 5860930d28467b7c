// Restart of a penalty contact (PenaltyContact::visit_state): a contact run for N cycles, its state
// copied through a visitor into a second contact freshly built from the same model and definition,
// continues exactly like the first for the next M cycles. Reference: the uninterrupted run itself;
// the comparison is exact (bit-identical forces, energies, pass figures), since the restart is
// meant to be invisible. The scene exercises every piece of run state: two blocks pressed together
// with SOFT 1, friction (FS, FD, DC) and viscous damping (VDC), so springs, friction forces and
// both energies build up; an element of the lower block deleted half-way (the eroding rebuild: a
// segment set of another size, remapped springs, exposure offsets); sorts by interval and motion.
// Nodes move as free lumped masses under the contact forces alone (no element forces: the contact
// is what is under test), by the central-difference update of the solver.
// A control run (no state copied) must differ, so that the test cannot pass by the second contact
// simply repeating the first from the same arrays.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "head_on_blocks.hpp"
#include "state_copy.hpp"
#include "support.hpp"

namespace plyimpact {
namespace {

struct Kinematics {
  std::vector<double> x, v, f;
  std::vector<double> push;  // (num_nodes) body acceleration along z, m/s^2
  double dt = 0;
};

// One cycle: x^{n+1} = x^n + dt v^{n+1/2}, contact forces at x^{n+1}, v^{n+3/2} = v^{n+1/2} +
// dt (f / m + push).
void cycle(const model::Model& model, contact::PenaltyContact& pc, Kinematics& r) {
  for (std::size_t k = 0; k < r.x.size(); ++k) r.x[k] += r.dt * r.v[k];
  std::fill(r.f.begin(), r.f.end(), 0.0);
  pc.apply(r.x.data(), r.v.data(), r.f.data(), r.dt);
  for (std::size_t n = 0; n < model.num_nodes(); ++n) {
    for (int d = 0; d < 3; ++d) r.v[3 * n + d] += r.dt * r.f[3 * n + d] / model.mass[n];
    r.v[3 * n + 2] += r.dt * r.push[n];
  }
}

// Every figure a contact reports, as bytes.
std::vector<char> figures(const contact::PenaltyContact& pc, const Kinematics& r) {
  std::vector<char> out;
  auto put = [&](const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    out.insert(out.end(), c, c + n);
  };
  put(r.f.data(), r.f.size() * sizeof(double));
  const double e[3] = {pc.energy(), pc.friction_energy(), pc.spring_stable_step()};
  put(e, sizeof e);
  const contact::ContactForces& cf = pc.forces();
  put(cf.resultant.data(), sizeof(double) * 3);
  const double cfs[3] = {cf.normal, cf.tangential, cf.potential};
  put(cfs, sizeof cfs);
  const long counts[4] = {long(cf.active), pc.sorts(), pc.exposed_offsets(), long(pc.num_segments())};
  put(counts, sizeof counts);
  put(pc.node_forces().data(), pc.node_forces().size() * sizeof(double));
  return out;
}

TEST(ContactRestart, StateCopiedThroughAVisitorContinuesBitIdentically) {
  const model::Model model =
      test::model_from_yaml(test::head_on_blocks("SOFT: 1, FS: 0.3, FD: 0.2, DC: 10, VDC: 20"), "restart.yaml");
  const model::Contact& def = model.contacts[0];
  Kinematics run;
  run.x = model.X;
  run.v.assign(model.X.size(), 0.0);
  run.f.assign(model.X.size(), 0.0);
  run.push.assign(model.num_nodes(), 0.0);
  // Block b starts 0.2 mm above block a: bring it to 10 um, slide it along x at 1 m/s (friction)
  // and push the blocks together (1e6 m/s^2 each) so that the contact forms (~200 cycles) and stays.
  const model::ElementBlock& b = model.blocks[std::size_t(model.parts[1].block)];
  std::vector<char> in_b(model.num_nodes(), 0);
  for (Index n : b.conn) in_b[std::size_t(n)] = 1;
  for (std::size_t n = 0; n < model.num_nodes(); ++n) {
    run.push[n] = in_b[n] ? -1e8 : 1e8;
    if (!in_b[n]) continue;
    run.x[3 * n + 2] -= 0.199e-3;
    run.v[3 * n] = 1.0;
  }
  const std::vector<double> x_start = run.x;

  contact::PenaltyContact first(model, def, x_start, 1e-8);
  run.dt = 0.3 * first.stable_step();
  const int kBefore = 450, kErode = 300, kAfter = 300;
  long active_max = 0;
  for (int c = 0; c < kBefore; ++c) {
    if (c == kErode) {  // delete two top elements of block a under block b (6 and 7: x, y fastest)
      const std::size_t a = std::size_t(model.parts[0].block);
      contact::AliveMask alive(model.blocks.size());
      alive[a].assign(model.blocks[a].size(), 1);
      alive[a][6] = alive[a][7] = 0;
      first.rebuild(alive, run.x);
    }
    cycle(model, first, run);
    active_max = std::max(active_max, long(first.forces().active));
  }
  // The scene did what it is for.
  ASSERT_GT(active_max, 0) << "no contact formed";
  ASSERT_GT(first.friction_energy(), 0.0);
  contact::PenaltyContact fresh(model, def, x_start, 1e-8);
  ASSERT_NE(fresh.num_segments(), first.num_segments()) << "the rebuild did not change the segment set";

  test::StateRecorder recorder;
  first.visit_state(recorder);
  test::StateReplayer replayer(recorder.blocks);
  fresh.visit_state(replayer);
  ASSERT_EQ(replayer.replayed(), recorder.blocks.size());
  contact::PenaltyContact control(model, def, x_start, 1e-8);  // same arrays, no state

  Kinematics second = run, third = run;
  long active = 0;
  for (int c = 0; c < kAfter; ++c) {
    cycle(model, first, run);
    cycle(model, fresh, second);
    ASSERT_EQ(figures(first, run), figures(fresh, second)) << "cycle " << kBefore + c << " after the restart";
    active += long(first.forces().active);
    if (c == 0) {
      cycle(model, control, third);
      EXPECT_NE(figures(first, run), figures(control, third)) << "the control run without state agrees";
    }
  }
  EXPECT_GT(active, 0) << "no spring active after the restart";
  EXPECT_EQ(run.x, second.x);
  EXPECT_EQ(run.v, second.v);
}

}  // namespace
}  // namespace plyimpact
