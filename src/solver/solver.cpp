#include "solver/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <omp.h>
#include <sched.h>

#include "core/error.hpp"
#include "material/composite_damage.hpp"
#include "solver/contributors.hpp"

namespace plyimpact::solver {

namespace {
// Node-update chunk: fixed (not per thread) so the kinetic-energy sums do not depend on the thread
// count; small enough that a static schedule shares a small model's nodes evenly (the default
// scene's 19,209 nodes: 19 chunks, 10 and 9 per thread; with 4096, 3 and 2 chunks, 12,288 against
// 6,921 nodes), large enough that a chunk's loop dwarfs its scheduling.
constexpr std::size_t kNodeChunk = 1024;
// Below this many elements the cycle runs on one thread. Chosen from measurement (BENCHMARKS.md,
// "Threads"): with the element pass ordered by chunk dependencies instead of a barrier per colour,
// and contact and interfaces parallel too, two threads pay off on the 7,488-element default scene;
// at a few hundred elements the few synchronisation points per cycle outweigh the work. The
// arithmetic and the summation order are the same either way.
constexpr std::size_t kParallelMinElements = 1024;
// The chunk plan is reviewed every this many parallel element passes, from the chunks' wall times
// over them (a few seconds of a run like the default scene: enough passes that a host's hiccup is
// a small part of a chunk's sum, few enough to follow the erosion), and replaced when its
// simulation gives the new plan a pass at least this much shorter (a new split moves nodes between
// the cores' caches once).
constexpr long kReplanPasses = 1000;
constexpr double kReplanGain = 0.02;

// Indices into phase_times_ (the contributors follow).
constexpr std::size_t kNodeUpdate = 0, kElementPass = 1, kElementChecks = 2, kFirstContributor = 3;

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point from, Clock::time_point to) { return std::chrono::duration<double>(to - from).count(); }

// Waits until a chunk's done flag reaches `pass`: spins briefly (the usual wait is a fraction of
// a chunk), then yields the core (on an oversubscribed machine the owner may need it).
void wait_for_pass(const std::uint64_t& flag, std::uint64_t pass) {
  for (int spins = 0; __atomic_load_n(&flag, __ATOMIC_ACQUIRE) < pass; ++spins) {
    if (spins < 4096) {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    } else {
      sched_yield();
    }
  }
}

void merge(ChunkResult& total, const ChunkResult& r) {
  total.internal_energy += r.internal_energy;
  total.hourglass_energy += r.hourglass_energy;
  total.bulk_viscous_energy += r.bulk_viscous_energy;
  if (r.dt_element >= 0 && (total.dt_element < 0 || r.dt_min < total.dt_min)) {
    total.dt_min = r.dt_min;
    total.dt_element = r.dt_element;
  }
  if (r.bad_element >= 0 && total.bad_element < 0) {
    total.bad_element = r.bad_element;
    total.bad_volume = r.bad_volume;
    total.bad_is_nan = r.bad_is_nan;
  }
  total.eroded.insert(total.eroded.end(), r.eroded.begin(), r.eroded.end());
  total.eroded_energy += r.eroded_energy;
  total.eroded_hourglass_energy += r.eroded_hourglass_energy;
}
}

Solver::Solver(const model::Model& model)
    : model_(model), chunk_plan_(model), replan_passes_(kReplanPasses), replan_gain_(kReplanGain),
      node_owners_(model, kNodeChunk) {
  if (model.control.dt2ms != 0 && !model.mass_scaling.applied)
    throw RunError("control.dt2ms is set but the model's mass was not scaled (solver::apply_mass_scaling)");
  warnings_ = model.mass_scaling.warnings;
  const std::size_t n = model.num_nodes();
  if (3 * n > std::size_t(std::numeric_limits<std::int32_t>::max()))
    throw RunError(msg() << n << " nodes in one run; allowed at most " << std::numeric_limits<std::int32_t>::max() / 3
                         << " (the element pass gathers the nodal dofs with 32-bit indices)");
  state_.x = model.X;
  state_.v = model.v0;
  state_.f.assign(3 * n, 0.0);
  // Rigid-body nodes move with their body: zero mass and inverse mass in the nodal update.
  node_mass_ = model.mass;
  node_body_.assign(n, -1);
  for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b)
    for (Index node : model.rigid_bodies[b].nodes) {
      node_body_[node] = int(b);
      node_mass_[node] = 0.0;
      rigid_nodes_.push_back(node);
    }
  if (!model.rigid_bodies.empty()) rigid_ = std::make_unique<RigidBodies>(model);
  inverse_mass_.resize(n);
  for (std::size_t i = 0; i < n; ++i) inverse_mass_[i] = node_mass_[i] > 0 ? 1.0 / node_mass_[i] : 0.0;
  parallel_ = model.num_elements() >= kParallelMinElements;
  if (rigid_) rigid_->set_parallel(parallel_);
  chunk_seconds_.assign(model.schedule.chunks.size(), 0.0);
  chunk_done_.assign(model.schedule.chunks.size(), 0);
  alive_.resize(model.blocks.size());
  chunk_ranges_.resize(model.schedule.chunks.size());
  state_.blocks.resize(model.blocks.size());
  for (std::size_t b = 0; b < model.blocks.size(); ++b) state_.blocks[b] = initial_block_state(model, b);
  dof_constraint_.assign(3 * n, -1);
  for (std::size_t c = 0; c < model.constraints.size(); ++c) dof_constraint_[model.constraints[c].dof] = int(c);
  constraint_force_.assign(model.constraints.size(), 0.0);
  constraint_work_.assign(model.constraints.size(), 0.0);
  curve_value_.assign(model.curves.size(), 0.0);
  chunk_results_.resize(model.schedule.chunks.size());
  node_chunk_ke_.assign((n + kNodeChunk - 1) / kNodeChunk, 0.0);
  for (int set : model.constrained_sets) {
    std::vector<int> list;
    for (Index node : model.node_sets[set].nodes)
      for (int d = 0; d < 3; ++d)
        if (dof_constraint_[3 * std::size_t(node) + d] >= 0) list.push_back(dof_constraint_[3 * std::size_t(node) + d]);
    set_constraints_.push_back(std::move(list));
  }
  state_.reaction.assign(3 * model.constrained_sets.size(), 0.0);

  // Initial velocities obey the boundary conditions at t = 0.
  for (std::size_t c = 0; c < model.constraints.size(); ++c) {
    const auto& con = model.constraints[c];
    state_.v[con.dof] = con.curve < 0 ? 0.0 : model.curves[con.curve](0.0);
  }
  element_pass(0.0);
  check_after_pass(0.0);
  state_.dt_initial = state_.dt_next_half;

  build_contributors();
  contributor_forces(0.0);

  double ke = rigid_ ? rigid_->kinetic_energy() : 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) ke += 0.5 * node_mass_[i] * state_.v[3 * i + d] * state_.v[3 * i + d];
  for (auto& t : state_.last_balance.terms) t.value = 0.0;
  state_.last_balance.terms[Energies::kKinetic].value = ke;
  state_.initial_total_energy = ke;
}

void Solver::build_contributors() {
  ContributorSetup setup{model_, state_.x, state_.dt_initial, dt_element_crit_, rigid_.get(), node_body_, contributors_};
  for (const auto& type : contributor_types())
    if (type.describe(model_).active) contributors_.push_back(type.make(setup));
  std::size_t most = 0;
  for (std::size_t c = 0; c < contributors_.size(); ++c) {
    const auto& con = contributors_[c];
    if (const auto* p = dynamic_cast<const PenaltyContacts*>(con.get())) contacts_ = p;
    if (const auto* p = dynamic_cast<const RigidWalls*>(con.get())) walls_ = p;
    for (const auto& w : con->warnings()) warnings_.push_back(w);
    const auto names = con->energy_names();
    energy_counts_.push_back(names.size());
    most = std::max(most, names.size());
    for (const auto& e : names) state_.last_balance.terms.push_back({e.key, e.column, e.in_total, 0.0, int(c)});
  }
  energy_scratch_.assign(most, 0.0);
  // Always in the balance: delete_elements may be called on any model (tests, a future element kill).
  eroded_kinetic_term_ = state_.last_balance.terms.size();
  state_.last_balance.terms.push_back({"eroded_kinetic", "eroded_kinetic_energy", true, 0.0, Energies::kErosion});
  contributors_built_ = true;
  phase_times_ = {{"node update", 0}, {"element pass", 0}, {"element checks", 0}};
  for (const auto& c : contributors_) phase_times_.push_back({c->name(), 0});
}

const std::vector<contact::PenaltyContact>& Solver::contacts() const {
  static const std::vector<contact::PenaltyContact> none;
  return contacts_ ? contacts_->contacts() : none;
}

const std::vector<contact::RigidWallConstraint>& Solver::rigid_walls() const {
  static const std::vector<contact::RigidWallConstraint> none;
  return walls_ ? walls_->walls() : none;
}

std::string Solver::moved_nodes_note() const {
  // An element that inverts in the first cycles after contact set-up moved nodes onto surfaces is
  // most often one of those nodes' elements: the release depth (PENMAX) reached the faces of other
  // parts stacked within it, as in plies under a single surface contact with a PENMAX deeper than
  // a ply (docs/theory.md, "Inter-ply contact", "Release depth").
  if (!contacts_ || state_.cycle > 2) return "";
  std::string note;
  for (std::size_t c = 0; c < contacts_->contacts().size(); ++c) {
    const auto& ip = contacts_->initial_penetrations()[c];
    if (!ip.moved || ip.count == 0) continue;
    note += msg() << "; contact '" << contacts_->contacts()[c].name() << "' moved " << ip.count
                  << " nodes onto its surface at t = 0, up to " << ip.max_depth
                  << " m: if they are not real overlaps, leave its PENMAX at the default (0.4 x the thickness of "
                     "the face's element) or set it below that thickness, or initial_penetration: offset";
  }
  return note;
}

const std::vector<contact::InitialPenetrations>& Solver::initial_penetrations() const {
  static const std::vector<contact::InitialPenetrations> none;
  return contacts_ ? contacts_->initial_penetrations() : none;
}

const std::vector<RigidBodyState>& Solver::rigid_bodies() const {
  static const std::vector<RigidBodyState> none;
  return rigid_ ? rigid_->states() : none;
}

void Solver::contributor_forces(double dt) {
  State& s = state_;
  ForceContext context;
  context.x = s.x.data();
  context.v = s.v.data();
  context.f = s.f.data();
  context.mass = model_.mass.data();
  context.time = s.time;
  context.dt = dt;
  using Phase = ForceContributor::Phase;
  auto apply = [&](std::size_t c) {
    const auto t0 = Clock::now();
    contributors_[c]->apply(context);
    if (kFirstContributor + c < phase_times_.size()) phase_times_[kFirstContributor + c].seconds += seconds(t0, Clock::now());
  };
  for (std::size_t c = 0; c < contributors_.size(); ++c)
    if (contributors_[c]->phase() == Phase::Forces) apply(c);
  update_step_bounds();
  context.dt_n1 = 0.5 * (s.dt_prev_half + s.dt_next_half);
  context.dt_next = s.dt_next_half;
  for (const Phase phase : {Phase::Constraints, Phase::Bookkeeping})
    for (std::size_t c = 0; c < contributors_.size(); ++c)
      if (contributors_[c]->phase() == phase) apply(c);
}

void Solver::delete_elements(const std::vector<Index>& ids) {
  std::vector<std::pair<int, Index>> deleted;
  for (Index id : ids) {
    bool found = false;
    for (std::size_t b = 0; b < model_.blocks.size() && !found; ++b) {
      const auto& ids_b = model_.blocks[b].element_id;
      const auto it = std::lower_bound(ids_b.begin(), ids_b.end(), id);
      if (it == ids_b.end() || *it != id) continue;
      if (alive_[b].empty()) alive_[b].assign(ids_b.size(), 1);
      const Index e = Index(it - ids_b.begin());
      alive_[b][std::size_t(e)] = 0;
      deleted.push_back({int(b), e});
      found = true;
    }
    if (!found) throw RunError(msg() << "cannot delete element " << id << ": no such element");
  }
  update_chunk_ranges();
  for (auto& c : contributors_) c->on_erosion(alive_, state_.x);
  remove_freed_nodes(deleted);
}

void Solver::update_chunk_ranges() {
  for (std::size_t c = 0; c < model_.schedule.chunks.size(); ++c) {
    const auto& chunk = model_.schedule.chunks[c];
    const auto& alive = alive_[chunk.block];
    auto& ranges = chunk_ranges_[c];
    ranges.clear();
    if (alive.empty()) continue;
    for (Index e = chunk.begin; e < chunk.end;) {
      while (e < chunk.end && !alive[e]) ++e;
      const Index start = e;
      while (e < chunk.end && alive[e]) ++e;
      if (e > start) ranges.push_back({start, e});
    }
  }
}

void Solver::visit_state(StateVisitor& visitor) {
  StateGroup group(visitor, "solver");
  state_.visit_state(visitor);
  apply_removed_nodes();  // derived from state_.removed_nodes (a reader has just replaced it)
  visitor.fixed_array("constraint_force", constraint_force_);
  visitor.fixed_array("constraint_work", constraint_work_);
  visitor.scalar("dt_element_crit", dt_element_crit_);
  for (std::size_t b = 0; b < alive_.size(); ++b) visitor.array("alive " + std::to_string(b), alive_[b]);
  update_chunk_ranges();  // derived from alive_ (a reader has just replaced it)
  if (rigid_) rigid_->visit_state(visitor);
  StateGroup forces(visitor, "contributors");
  for (auto& c : contributors_) c->visit_state(visitor);
}

double combined_step(double dt_element, double dt_contact) {
  // The element and contact stiffnesses add: K = K_e + K_c. The highest frequency of the
  // mass-normalised sum is at most the sum of the highest of each (Weyl's inequality for symmetric
  // matrices, lambda_max(A + B) <= lambda_max(A) + lambda_max(B)), so with omega_e = 2 / dt_e and
  // omega_c = 2 / dt_c the central-difference limit dt = 2 / omega becomes
  //   dt = 1 / sqrt(1 / dt_e^2 + 1 / dt_c^2).
  // This is Radioss's nodal-step idea (the contact stiffness added to the equivalent nodal
  // stiffness, Altair Radioss help "Nodal Time Step") applied to the two global bounds; LS-DYNA
  // instead leaves the contact springs out of the step and only prints the step they would need
  // ("The LS-DYNA time step size should not exceed ... to avoid contact instabilities", see
  // blog.d3view.com/?p=2183). Taking min(dt_e, dt_c) is not enough: with dt_c = dt_e the combined
  // frequency is sqrt(2) omega_e, unstable at TSSFAC 0.9. The bound is global (stiffest spring with
  // the smallest element) and so conservative when they are in different places.
  if (!(dt_contact > 0) || !std::isfinite(dt_contact)) return dt_element;
  const double r = dt_element / dt_contact;
  return dt_element / std::sqrt(1.0 + r * r);
}

void Solver::update_step_bounds() {
  // After the Forces phase at x^{n+1}: the springs now active enter dt^{n+3/2}. Per cycle, as the
  // nodal step of Radioss does with the contact stiffness, so the approach phase (no spring) keeps
  // the element step and a stiff contact lowers it only while it acts.
  State& s = state_;
  double dt_contact = std::numeric_limits<double>::infinity();
  for (const auto& c : contributors_) dt_contact = std::min(dt_contact, c->stable_step());
  s.dt_contact = std::isfinite(dt_contact) ? dt_contact : 0.0;
  if (!(dt_element_crit_ > 0)) return;  // no element step (all eroded): keep the last step
  s.dt_contact_controls = s.dt_contact > 0 && s.dt_contact < dt_element_crit_;
  s.dt_next_half = model_.control.tssfac * combined_step(dt_element_crit_, s.dt_contact);
}

void Solver::step() {
  thread_choice_.before_cycle(state_.cycle);
  const auto t_start = Clock::now();
  State& s = state_;
  const double dt_half = s.dt_next_half;
  const double dt_n = 0.5 * (s.dt_prev_half + dt_half);
  const bool first = s.cycle == 0;
  for (std::size_t c = 0; c < model_.curves.size(); ++c) curve_value_[c] = model_.curves[c](s.time + 0.5 * dt_half);

  // Node update: v^{n+1/2}, constraints, kinetic energy at t^n, x^{n+1}.
  const std::size_t n = model_.num_nodes();
  double* __restrict x = s.x.data();
  double* __restrict v = s.v.data();
  double* __restrict f = s.f.data();
  const double* __restrict mass = node_mass_.data();
  const double* __restrict inv_mass = inverse_mass_.data();
  const int threads = parallel_ ? omp_get_max_threads() : 1;
  const auto& owned = threads > 1 && chunk_plan_.threads() == threads ? node_owners_.for_bounds(chunk_plan_.bounds())
                                                                     : node_owners_.for_threads(threads);
#pragma omp parallel num_threads(threads) if (threads > 1)
  for (long chunk : owned[std::size_t(omp_get_thread_num())]) {
    const std::size_t begin = std::size_t(chunk) * kNodeChunk, end = std::min(n, begin + kNodeChunk);
    double ke = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const double m = mass[i], im = inv_mass[i];
      const bool keep_force = node_body_[i] >= 0;  // read by the rigid-body update below
      for (int d = 0; d < 3; ++d) {
        const std::size_t dof = 3 * i + d;
        const double vo = v[dof];
        double vn = vo + dt_n * f[dof] * im;
        // The force is consumed here: clearing it now saves element_pass a serial sweep of f.
        if (!keep_force) f[dof] = 0;
        const int c = dof_constraint_[dof];
        if (c >= 0) {
          const int curve = model_.constraints[c].curve;
          const double vb = curve < 0 ? 0.0 : curve_value_[curve];
          const double reaction = m * (vb - vn) / dt_n;
          constraint_force_[c] = reaction;
          constraint_work_[c] = dt_n * reaction * 0.5 * (vo + vb);
          vn = vb;
        }
        const double vm = first ? vo : 0.5 * (vo + vn);
        ke += 0.5 * m * vm * vm;
        v[dof] = vn;
        x[dof] += dt_half * vn;
      }
    }
    node_chunk_ke_[chunk] = ke;
  }
  double ke = 0;
  for (double k : node_chunk_ke_) ke += k;
  double rigid_work = 0;
  if (rigid_) ke += rigid_->step(f, x, v, dt_n, dt_half, first, curve_value_, rigid_work);
  // The constraint work of this step spans t^{n-1/2}..t^{n+1/2}; half of it belongs before t^n,
  // where the kinetic energy is evaluated (average of the half-step velocities).
  double work = rigid_work;
  for (double w : constraint_work_) work += w;
  // Contributors' work (gravity) is that of their last apply, i.e. up to t^n.
  double external_work_at_n = s.external_work + 0.5 * work;
  for (const auto& c : contributors_) external_work_at_n += c->external_work();
  s.external_work += work;
  for (std::size_t set = 0; set < set_constraints_.size(); ++set) {
    double r[3] = {0, 0, 0};
    for (int c : set_constraints_[set]) r[model_.constraints[c].dof % 3] += constraint_force_[c];
    for (int d = 0; d < 3; ++d) s.reaction[3 * set + d] = r[d];
  }
  record_balance(ke, external_work_at_n);
  if (!std::isfinite(ke))
    throw RunError(msg() << "non-finite kinetic energy at cycle " << s.cycle << ", time " << s.time
                         << " s: a nodal velocity became NaN or infinite (unstable run; check the time step, "
                            "hourglass coefficient and boundary conditions)");
  // Energy creation is the signature of a numerical instability (it grows geometrically once it
  // starts). The first cycles are skipped: with the start-up half step their ratio is noise.
  const double limit = model_.control.energy_ratio_limit;
  if (limit > 0 && s.cycle >= 3 && energy_ratio() > limit)
    throw RunError(msg() << "energy ratio " << energy_ratio() << " exceeds " << limit << " at cycle " << s.cycle
                         << ", time " << s.time << " s: the run is creating energy, i.e. it is numerically "
                         << "unstable; the step is controlled by element " << s.dt_element << " (part '"
                         << part_of_element(s.dt_element) << "'). Lower control.tssfac (a free corner or a lone "
                         << "element can exceed the Courant limit at 0.9), the hourglass QM or the contact stiffness");

  s.time += dt_half;
  const auto t_nodes = Clock::now();
  element_pass(dt_half);
  const auto t_elements = Clock::now();
  s.dt_prev_half = dt_half;
  ++s.cycle;
  check_after_pass(dt_half);
  const auto t_checks = Clock::now();
  contributor_forces(dt_half);
  phase_times_[kNodeUpdate].seconds += seconds(t_start, t_nodes);
  phase_times_[kElementPass].seconds += seconds(t_nodes, t_elements);
  phase_times_[kElementChecks].seconds += seconds(t_elements, t_checks);
  thread_choice_.after_cycle(s.cycle, seconds(t_start, Clock::now()));
}

void Solver::record_balance(double kinetic, double external_work) {
  // Values only: the list of terms is fixed at construction, so a cycle allocates nothing.
  State& s = state_;
  Energies& e = s.last_balance;
  e.time = s.time;
  e.terms[Energies::kKinetic].value = kinetic;
  e.terms[Energies::kInternal].value = s.internal_energy;
  e.terms[Energies::kHourglass].value = s.hourglass_energy;
  e.terms[Energies::kBulkViscous].value = s.bulk_viscous_energy;
  e.terms[Energies::kExternalWork].value = external_work;
  std::size_t t = Energies::kNumOwn;
  for (std::size_t c = 0; c < contributors_.size(); ++c) {
    const std::size_t k = energy_counts_[c];
    if (k == 0) continue;
    contributors_[c]->energies(std::span<double>(energy_scratch_.data(), k));
    for (std::size_t i = 0; i < k; ++i) e.terms[t++].value = energy_scratch_[i];
  }
  e.terms[eroded_kinetic_term_].value = s.eroded_kinetic_energy;
}

void Solver::element_pass(double dt) {
  State& s = state_;
  // f is zero here except at rigid-body nodes: the node update clears what it consumes (and the
  // constructor starts from zero).
  for (Index node : rigid_nodes_)
    for (int d = 0; d < 3; ++d) s.f[3 * std::size_t(node) + d] = 0;
  const auto& schedule = model_.schedule;
  const double* x = s.x.data();
  const double* v = s.v.data();
  double* f = s.f.data();
  const std::uint64_t pass = ++element_passes_;
  // Erosion neighbourhoods read what the previous pass wrote: the buffer follows the cycle's parity,
  // so a restored state needs no more than the two buffers.
  for (auto& st : s.blocks)
    if (!st.erosion_strain[0].empty()) st.erosion_strain_read = int(s.cycle & 1);
  auto run_chunk = [&](int c) {
    const auto& chunk = schedule.chunks[std::size_t(c)];
    ChunkResult& result = chunk_results_[std::size_t(c)];
    result = ChunkResult{};
    if (alive_[chunk.block].empty()) {
      update_elements(model_, model_.blocks[chunk.block], s.blocks[chunk.block], chunk.begin, chunk.end, x, v, f, dt,
                      result);
    } else {  // elements deleted: the alive ranges of this chunk, in order
      for (const auto& [begin, end] : chunk_ranges_[std::size_t(c)]) {
        ChunkResult r;
        update_elements(model_, model_.blocks[chunk.block], s.blocks[chunk.block], begin, end, x, v, f, dt, r);
        merge(result, r);
      }
    }
  };
  const int threads = parallel_ ? omp_get_max_threads() : 1;
  if (threads == 1) {  // colour by colour: the order the parallel pass reproduces at every node
    for (const auto& color : schedule.colors)
      for (int c : color) run_chunk(c);
    return;
  }
  // Each thread runs the chunks the plan gives it, in the plan's order (solver/chunk_plan.hpp); before
  // a chunk it waits until the chunks of lower colour that share a node with it are done. Every node
  // then receives its forces in colour order, as in the one-thread pass, without a barrier per colour.
  keep_chunk_plan(threads);
#pragma omp parallel num_threads(threads)
  {
    for (int c : chunk_plan_.order(omp_get_thread_num())) {
      for (int p : chunk_plan_.predecessors(c)) wait_for_pass(chunk_done_[std::size_t(p)], pass);
      const auto t0 = Clock::now();
      run_chunk(c);
      chunk_seconds_[std::size_t(c)] += seconds(t0, Clock::now());
      __atomic_store_n(&chunk_done_[std::size_t(c)], pass, __ATOMIC_RELEASE);
    }
  }
}

void Solver::keep_chunk_plan(int threads) {
  if (chunk_plan_.threads() != threads) {  // the first parallel pass, or another thread count
    chunk_plan_.plan(threads, passes_since_plan_ > 0 ? std::span<const double>(chunk_seconds_)
                                                      : std::span<const double>(chunk_plan_.element_count_costs()));
    std::fill(chunk_seconds_.begin(), chunk_seconds_.end(), 0.0);
    passes_since_plan_ = 0;
    return;
  }
  if (++passes_since_plan_ < replan_passes_) return;
  chunk_plan_.plan(threads, chunk_seconds_, replan_gain_);
  std::fill(chunk_seconds_.begin(), chunk_seconds_.end(), 0.0);
  passes_since_plan_ = 0;
}

void Solver::check_after_pass(double dt_used) {
  State& s = state_;
  ChunkResult total;
  for (const auto& r : chunk_results_) {  // chunk order: deterministic whatever the thread count
    total.internal_energy += r.internal_energy;
    total.hourglass_energy += r.hourglass_energy;
    total.bulk_viscous_energy += r.bulk_viscous_energy;
    if (r.dt_element >= 0 && (r.dt_min < total.dt_min || (r.dt_min == total.dt_min && r.dt_element < total.dt_element))) {
      total.dt_min = r.dt_min;
      total.dt_element = r.dt_element;
    }
    if (r.bad_element >= 0 && (total.bad_element < 0 || r.bad_element < total.bad_element)) {
      total.bad_element = r.bad_element;
      total.bad_volume = r.bad_volume;
      total.bad_is_nan = r.bad_is_nan;
    }
  }
  std::vector<Index> eroded;
  for (const auto& r : chunk_results_) {  // chunk order: deterministic
    for (const ErodedElement& el : r.eroded) {
      eroded.push_back(el.id);
      count_erosion(el);
    }
    s.eroded_energy += r.eroded_energy;
    s.eroded_hourglass_energy += r.eroded_hourglass_energy;
  }
  s.internal_energy += total.internal_energy;
  s.hourglass_energy += total.hourglass_energy;
  s.bulk_viscous_energy += total.bad_element >= 0 ? 0.0 : total.bulk_viscous_energy;
  if (total.bad_element >= 0) {
    if (total.bad_is_nan)
      throw RunError(msg() << "element " << total.bad_element << " (part '" << part_of_element(total.bad_element)
                           << "') produced a non-finite stress or time step at cycle " << s.cycle << ", time "
                           << s.time << " s (unstable run)");
    throw RunError(msg() << "element " << total.bad_element << " (part '" << part_of_element(total.bad_element)
                         << "') has zero or negative volume (" << total.bad_volume << " m^3) at cycle " << s.cycle
                         << ", time " << s.time << " s after a step of " << dt_used
                         << " s: the element inverted (excessive distortion, hourglassing or a too large step)"
                         << moved_nodes_note());
  }
  if (!eroded.empty()) {
    delete_elements(eroded);
    mark_crashfront(eroded);
  }
  if (total.dt_element < 0) {
    // Every deformable element is gone (eroded): the nodes fly on as free masses with the last step.
    if (s.eroded_elements > 0 && s.dt_next_half > 0) return;
    throw RunError("the model has no deformable element, so no stable time step exists");
  }
  // Element step; the contact springs are added after the contact pass (update_contact_step).
  dt_element_crit_ = total.dt_min;
  s.dt_next_half = model_.control.tssfac * total.dt_min;
  s.dt_element = total.dt_element;
  if (s.dt_initial > 0 && s.dt_next_half < model_.control.dt_min_ratio * s.dt_initial)
    throw RunError(msg() << "time step collapsed to " << s.dt_next_half << " s, below " << model_.control.dt_min_ratio
                         << " x the initial " << s.dt_initial << " s, at cycle " << s.cycle << ", time " << s.time
                         << " s; controlling element " << s.dt_element << " (part '" << part_of_element(s.dt_element)
                         << "') is severely distorted");
}

double Solver::energy_ratio() const {
  const Energies& e = state_.last_balance;
  const double reference = state_.initial_total_energy + e.external_work();
  // No initial energy and no work done: the ratio is undefined (what remains is round-off), report 1.
  if (!(reference > 0.0)) return 1.0;
  return e.total() / reference;
}

std::vector<double> Solver::acceleration() const {
  std::vector<double> a(state_.f.size());
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = state_.f[i] * inverse_mass_[i / 3];
  for (const auto& con : model_.constraints) a[con.dof] = 0.0;  // constrained dofs follow their curve
  return a;
}

void Solver::count_erosion(const ErodedElement& el) {
  ++state_.eroded_elements;
  int part = 0;
  for (const auto& blk : model_.blocks)
    if (!blk.element_id.empty() && std::binary_search(blk.element_id.begin(), blk.element_id.end(), el.id))
      part = blk.part;
  for (auto& c : state_.erosion)
    if (c.part == part && c.cause == el.cause) {
      ++c.count;
      c.energy += el.energy;
      return;
    }
  state_.erosion.push_back({part, el.cause, 1, el.energy});
}

void Solver::mark_crashfront(const std::vector<Index>& eroded) {
  // Elements that share a node with an eroded element become crashfront elements (MAT_054 SOFT).
  bool any_damage = false;
  for (const auto& blk : model_.blocks)
    any_damage = any_damage || model_.materials[blk.material].kind == model::MaterialKind::CompositeDamage;
  if (!any_damage) return;
  build_node_adjacency();
  for (Index id : eroded)
    for (std::size_t b = 0; b < model_.blocks.size(); ++b) {
      const auto& blk = model_.blocks[b];
      const auto it = std::lower_bound(blk.element_id.begin(), blk.element_id.end(), id);
      if (it == blk.element_id.end() || *it != id) continue;
      const std::size_t e = std::size_t(it - blk.element_id.begin());
      for (int k = 0; k < 8; ++k) {
        const Index node = blk.conn[8 * e + k];
        for (Index p = node_elements_start_[node]; p < node_elements_start_[node + 1]; ++p) {
          const auto [nb, ne] = node_elements_[p];
          if (model_.materials[model_.blocks[nb].material].kind != model::MaterialKind::CompositeDamage) continue;
          const std::size_t points = std::size_t(model_.blocks[nb].points());
          for (std::size_t g = 0; g < points; ++g)  // every integration point of the neighbour
            state_.blocks[nb].history[(std::size_t(ne) * points + g) * material::kCompositeDamageHistory +
                                      material::composite_history::kCrashfront] = 1.0;
        }
      }
    }
}

int Solver::threads_used() const {
  if (thread_choice_.enabled()) return thread_choice_.chosen();
  return parallel_ ? omp_get_max_threads() : 1;
}

std::string Solver::part_of_element(Index id) const {
  for (const auto& blk : model_.blocks)
    if (!blk.element_id.empty() && std::binary_search(blk.element_id.begin(), blk.element_id.end(), id))
      return model_.parts[blk.part].name;
  return "?";
}

}  // namespace plyimpact::solver
