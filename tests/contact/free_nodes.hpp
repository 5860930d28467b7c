// Nodes moving as free lumped masses under a penalty contact's forces alone (no element forces:
// the contact is what is under test), by the solver's central-difference update, with an optional
// body acceleration along z per node: the driver of the contact tests that compare runs cycle by cycle.
#pragma once

#include <algorithm>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "model/model.hpp"

namespace plyimpact::test {

struct FreeNodes {
  std::vector<double> x, v, f;
  std::vector<double> push;  // (num_nodes) body acceleration along z, m/s^2
  double dt = 0;
};

// Every figure a contact reports after a cycle, as bytes: the nodal forces, energies and stable
// step, resultant and force sums, active springs, exposure offsets, segment count and the contact's
// own node forces; with_sorts adds its sort count (which only the sort interval changes).
inline std::vector<char> contact_figures(const contact::PenaltyContact& pc, const FreeNodes& r, bool with_sorts) {
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
  const long counts[4] = {long(cf.active), with_sorts ? pc.sorts() : 0L, pc.exposed_offsets(), long(pc.num_segments())};
  put(counts, sizeof counts);
  put(pc.node_forces().data(), pc.node_forces().size() * sizeof(double));
  return out;
}

// One cycle: x^{n+1} = x^n + dt v^{n+1/2}, contact forces at x^{n+1}, v^{n+3/2} = v^{n+1/2} +
// dt (f / m + push).
inline void contact_cycle(const model::Model& model, contact::PenaltyContact& pc, FreeNodes& r) {
  for (std::size_t k = 0; k < r.x.size(); ++k) r.x[k] += r.dt * r.v[k];
  std::fill(r.f.begin(), r.f.end(), 0.0);
  pc.apply(r.x.data(), r.v.data(), r.f.data(), r.dt);
  for (std::size_t n = 0; n < model.num_nodes(); ++n) {
    for (int d = 0; d < 3; ++d) r.v[3 * n + d] += r.dt * r.f[3 * n + d] / model.mass[n];
    r.v[3 * n + 2] += r.dt * r.push[n];
  }
}

// head_on_blocks' block b, started 0.2 mm above block a, brought to 10 um of it, sliding along x
// at 1 m/s (friction) while the blocks are pushed together (1e8 m/s^2 each), so that the contact
// forms (~200 cycles) and stays; dt is left to the caller.
inline FreeNodes pressed_sliding_blocks(const model::Model& model) {
  FreeNodes r;
  r.x = model.X;
  r.v.assign(model.X.size(), 0.0);
  r.f.assign(model.X.size(), 0.0);
  r.push.assign(model.num_nodes(), 0.0);
  const model::ElementBlock& b = model.blocks[std::size_t(model.parts[1].block)];
  std::vector<char> in_b(model.num_nodes(), 0);
  for (Index n : b.conn) in_b[std::size_t(n)] = 1;
  for (std::size_t n = 0; n < model.num_nodes(); ++n) {
    r.push[n] = in_b[n] ? -1e8 : 1e8;
    if (!in_b[n]) continue;
    r.x[3 * n + 2] -= 0.199e-3;
    r.v[3 * n] = 1.0;
  }
  return r;
}

// The eroding rebuild: two top elements of block a under block b (6 and 7: x, y fastest) deleted.
inline void erode_under_block_b(const model::Model& model, contact::PenaltyContact& pc, const std::vector<double>& x) {
  const std::size_t a = std::size_t(model.parts[0].block);
  contact::AliveMask alive(model.blocks.size());
  alive[a].assign(model.blocks[a].size(), 1);
  alive[a][6] = alive[a][7] = 0;
  pc.rebuild(alive, x);
}

}  // namespace plyimpact::test
