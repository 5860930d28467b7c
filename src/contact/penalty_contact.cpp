#include "contact/penalty_contact.hpp"

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "contact/catch_rules.hpp"

namespace plyimpact::contact {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

SearchOptions search_options(const config::ContactSpec& spec) { return {spec.MAXPAR, spec.BSORT}; }

}  // namespace

PenaltyContact::PenaltyContact(const model::Model& model, const model::Contact& def, const std::vector<double>& x,
                               double dt_initial)
    : model_(model),
      def_(def),
      law_(def.spec, def.spec.DTSTIF > 0 ? def.spec.DTSTIF : dt_initial),
      set_(model, segment_set_spec(def), x),
      search_(search_options(def.spec)) {
  springs_.reset(set_.num_nodes(), set_.num_segments());
  fc_prev_.assign(3 * set_.num_force_nodes(), 0.0);
  start(x);
}

void PenaltyContact::rebuild(const AliveMask& alive, const std::vector<double>& x) {
  // Each surviving node keeps its spring history and the force nodes their last forces (the
  // trapezoid of the next pass); the pass after the rebuild looks at any depth (catch_rules).
  const SegmentSetRemap remap = set_.rebuild(alive, x);
  eroded_spring_energy_ += springs_.remap(remap);  // energy_ still holds them until the next pass
  std::vector<double> old_forces = std::move(fc_prev_);
  fc_prev_.assign(3 * set_.num_force_nodes(), 0.0);
  for (std::size_t u = 0; u < remap.force_node.size(); ++u)
    if (const Index w = remap.force_node[u]; w >= 0)
      for (int d = 0; d < 3; ++d) fc_prev_[3 * std::size_t(w) + d] = old_forces[3 * u + d];
  start(x);
  list_previous_forces();
}

void PenaltyContact::size_pass_scratch() {
  // A restart reads a surface that erosion may have rebuilt since construction: the scratch sized
  // by start() must follow it, or the nodes beyond the constructed outcome chunks would never be
  // evaluated. Allocates only then.
  const std::size_t U = set_.num_force_nodes(), N = set_.num_nodes();
  if (marked_.size() != U) {
    marked_.assign(U, 0);
    touched_.reserve(U);  // no allocation in the passes
    touched_prev_.reserve(U);
  }
  if (outcomes_.size() != N) {
    outcomes_.resize(N);
    outcome_count_.assign((N + kNodeChunk - 1) / kNodeChunk, 0);
  }
}

void PenaltyContact::list_previous_forces() {
  touched_prev_.clear();
  for (std::size_t u = 0; u < set_.num_force_nodes(); ++u)
    if (fc_prev_[3 * u] != 0 || fc_prev_[3 * u + 1] != 0 || fc_prev_[3 * u + 2] != 0) touched_prev_.push_back(Index(u));
}

void PenaltyContact::start(const std::vector<double>& x) {
  const std::size_t U = set_.num_force_nodes();
  fc_.assign(3 * U, 0.0);
  rows_.assign(U, 0.0);
  touched_.clear();
  size_pass_scratch();
  search_.reset(set_, x.data());
  bounds_ = stiffness_bounds(set_, law_, model_.mass);
  search_.sort(set_, x.data(), 0.0, springs_.exposed_pass);
}

InitialPenetrations PenaltyContact::resolve_initial_penetrations(std::vector<double>& x) {
  InitialPenetrations r;
  r.moved = def_.spec.initial_penetration == config::ContactSpec::InitialPenetration::Move;
  search_.refresh_all(set_, x.data());
  search_.build_candidates(set_, x.data(), true);  // any depth counts here, so lists sized for the full depth
  for (std::size_t i = 0; i < set_.num_nodes(); ++i) {
    Projection pr;
    const long s = catch_segment(set_, search_, springs_, i, x.data(), pr, kInf);
    if (s < 0) continue;
    const double g = pr.gap - springs_.offset[i];
    ++r.count;
    r.max_depth = std::max(r.max_depth, -g);
    const Index node = set_.node_id(i);
    if (r.moved && !set_.node_rigid(node)) {
      for (int d = 0; d < 3; ++d) x[3 * std::size_t(node) + d] -= g * pr.normal[d];
    } else {
      springs_.offset[i] += g;
    }
  }
  search_.build_candidates(set_, x.data(), false);
  return r;
}

[[gnu::always_inline]] inline bool PenaltyContact::update_exposure(std::size_t i, long s, long last,
                                                                   const Projection& pr) {  // per active node
  // Erosion exposed a face already behind this node, within the face proper (or made it a surface
  // node already behind a face): nothing crossed anything, so a spring of that depth would be
  // energy from nowhere. Kept as an offset instead, like an initial penetration, but on that face
  // only (a node beside a hole's edge "behind" the new side face is not offset against the top face
  // it then lands on): the force starts from zero and grows with further penetration; the offset
  // relaxes as the node backs out and ends when it leaves the face.
  SpringHistory& h = springs_;
  bool booked = false;
  if (h.exposed_pass && last < 0 && (h.new_node[i] || h.new_segment[std::size_t(s)]) && std::abs(pr.xi) <= 1 &&
      std::abs(pr.eta) <= 1) {
    h.exposure_segment[i] = s;
    h.exposure_offset[i] = pr.gap - h.offset[i];
    booked = true;
  } else if (s != h.exposure_segment[i]) {  // the offset belongs to the face it was found on
    h.exposure_segment[i] = -1;
    h.exposure_offset[i] = 0;
  }
  if (s == h.exposure_segment[i]) h.exposure_offset[i] = std::max(h.exposure_offset[i], pr.gap - h.offset[i]);  // relaxes
  return booked;
}

double PenaltyContact::release_depth(std::size_t i, long last, const double* x) {
  if (last < 0) return 0;  // its segment did not survive an eroding rebuild: nothing to compare with
  const Index node = set_.node_id(i);
  // Behind the face and over it, with a margin of four times the MAXPAR tolerance: a node pressed
  // into a corner of the surface (an impactor's pole over a node of the plate) is released when
  // its projection leaves every segment's MAXPAR range, still deep behind them.
  const double margin = 1 + 4 * std::max(search_.options().MAXPAR - 1, 0.0);
  const Projection pr = project_to_bilinear(&x[3 * std::size_t(node)], search_.record(set_, std::size_t(last), x), margin);
  const double g = pr.gap - springs_.offset_on(i, last);
  if (!pr.inside || !(g < 0)) return 0;  // left the face (lifted off or slid past its edge)
  return -g;
}

bool PenaltyContact::evaluate_node(std::size_t i, const double* x, const double* v, double dt, double v_max,
                                   bool friction, NodeOutcome& out) {
  SpringHistory& h = springs_;
  Projection pr;
  const double* vi = &v[3 * std::size_t(set_.node_id(i))];
  const long s = catch_segment(set_, search_, h, i, x, pr, 2.0 * dt * (std::sqrt(dot3(vi, vi)) + v_max), v, dt);
  double* ft = &h.ft[3 * i];
  const bool entering = !h.engaged[i];
  const long last = h.segment[i];
  h.segment[i] = s;
  h.engaged[i] = s >= 0;
  if (s < 0) {  // released: the spring and its potential end here
    if (entering) return false;  // (a node that was not in contact has all of this at zero already)
    const double depth = release_depth(i, last, x);
    const double held = 0.5 * h.k[i] * h.gap[i] * h.gap[i];
    h.release(i);
    if (!(depth > 0)) return false;
    out.i = i;
    out.s = -1;
    out.depth = depth;
    out.potential = held;
    return true;
  }
  out.i = i;
  out.s = s;
  out.exposure = update_exposure(i, s, last, pr);
  const Index node = set_.node_id(i);
  const Index* q = set_.segment_nodes(std::size_t(s));
  const double* n = pr.normal;
  double vrel[3];
  for (int d = 0; d < 3; ++d) {
    vrel[d] = v[3 * std::size_t(node) + d];
    for (int a = 0; a < 4; ++a) vrel[d] -= pr.N[a] * v[3 * std::size_t(q[a]) + d];
  }
  const double vn = dot3(vrel, n);
  // A new spring (the node engages, or moves on to another segment) whose node was already behind
  // that face before this step's motion, deeper than its old spring (none: 0), did not cross the
  // face in this step (within the face proper; beside it catch_segment does not take it). Taken
  // at its whole depth it would be a spring nobody compressed (0.5 k g^2 from nothing, up to the
  // catch depth); offset like an exposure, it continues from the old spring's depth and grows
  // with this step's motion.
  if (s != last && s != h.exposure_segment[i]) {
    const double start = last < 0 ? 0.0 : std::min(h.gap[i], 0.0), g0 = pr.gap - h.offset[i] - vn * dt;
    if (g0 < start) {
      h.exposure_segment[i] = s;
      h.exposure_offset[i] = g0 - start;
    }
  }
  const double g = pr.gap - h.offset_on(i, s);
  const double k = law_.stiffness(set_, i, std::size_t(s));
  const double fn = law_.normal_force(set_, i, std::size_t(s), k, g, vn);
  for (int d = 0; d < 3; ++d) out.F[d] = fn * n[d];
  out.friction_work = out.tangential = 0;
  if (friction) {
    double vt[3];
    law_.friction_update(ft, n, vrel, vn, k, fn, dt, vt);
    for (int d = 0; d < 3; ++d) out.F[d] += ft[d];
    out.friction_work = dot3(ft, vt) * dt;
    out.tangential = std::sqrt(dot3(ft, ft));
  }
  // Damping (VDC) dissipates -(f_n - f_spring) v_n dt: the normal force beyond the spring's k |g|
  // against the normal relative velocity.
  out.damping_work = (fn + k * g) * vn * dt;
  h.gap[i] = g;
  h.k[i] = k;
  for (int d = 0; d < 3; ++d) h.fn[3 * i + d] = fn * n[d];
  out.fn = fn;
  out.potential = 0.5 * k * g * g;
  out.k = k;
  for (int a = 0; a < 4; ++a) out.N[a] = pr.N[a];
  // Stability: the spring is k b b^T (x) D, b = (1, -N_1..-N_4) over the node and the segment
  // nodes, D <= k I (normal spring; the friction return map never exceeds the same k
  // tangentially). Gershgorin on M^-1 K: row j gets k |b_j| sum_l |b_l| over deformable nodes
  // (rigid nodes move with their body, whose mass is far larger; their rows and columns drop out).
  const Index ui = set_.force_node_of_node(i);
  const Index* ql = set_.force_nodes_of_segment(std::size_t(s));
  double sum_b = set_.force_node_inv_mass(std::size_t(ui)) > 0 ? 1.0 : 0.0;
  for (int a = 0; a < 4; ++a)
    if (set_.force_node_inv_mass(std::size_t(ql[a])) > 0) sum_b += pr.N[a];
  out.sum_b = sum_b;
  return true;
}

void PenaltyContact::apply(const double* x, const double* v, double* f, double dt, double time) {
  const std::size_t N = set_.num_nodes(), U = set_.num_force_nodes();
  // One pass over the force nodes: the fastest (it bounds the relative motion in one step) and the
  // re-sort test.
  const PassMotion motion = search_.begin_pass(set_, x, v);
  const double v_max2 = motion.v_max2;
  // Largest new-contact depth of this pass (catch_segment's new_contact_depth below).
  const double step_depth = 4 * dt * std::sqrt(v_max2);
  if (search_.sort_due(motion, step_depth)) search_.sort(set_, x, step_depth, springs_.exposed_pass);
  for (const Index u : touched_)
    for (int d = 0; d < 3; ++d) fc_[3 * std::size_t(u) + d] = 0;
  touched_.clear();
  size_pass_scratch();
  forces_ = ContactForces{};
  const bool friction = law_.friction();
  const double v_max = std::sqrt(v_max2);
  // Search and law per node, in parallel: each node writes its own history and outcome slot.
  // Dynamic: the nodes near the other surface (few chunks) cost far more than the rest.
  const long chunks = long(outcome_count_.size());
#pragma omp parallel for schedule(dynamic) if (N >= 2 * kNodeChunk && omp_get_max_threads() > 1)
  for (long c = 0; c < chunks; ++c) {
    const std::size_t begin = std::size_t(c) * kNodeChunk, end = std::min(N, begin + kNodeChunk);
    std::size_t count = 0;
    for (std::size_t i = begin; i < end; ++i) {
      // Most of a surface has nothing within reach and no spring (catch_segment would find no
      // segment, and the node stays out of contact): skipped before the node's speed and the call.
      if (!springs_.engaged[i] && springs_.segment[i] < 0 && search_.candidates(i).empty()) continue;
      if (evaluate_node(i, x, v, dt, v_max, friction, outcomes_[begin + count])) ++count;
    }
    outcome_count_[std::size_t(c)] = count;
  }
  // In node order, as one thread would: forces on the force nodes, stability rows, sums, records.
  double friction_work = 0, damping_work = 0;
  for (long c = 0; c < chunks; ++c) {
    const NodeOutcome* o = &outcomes_[std::size_t(c) * kNodeChunk];
    for (const NodeOutcome* end = o + outcome_count_[std::size_t(c)]; o != end; ++o) {
      if (o->s < 0) {
        Penetrations& p = penetrations_;
        p.released_potential += o->potential;
        const PenetrationEvent e{time, o->depth, set_.node_id(o->i)};
        if (p.count == 0) p.first = e;
        if (e.depth > p.deepest.depth) p.deepest = e;
        p.last = e;
        ++p.count;
        continue;
      }
      if (o->exposure) ++exposures_;
      if (friction) {
        friction_work -= o->friction_work;
        forces_.tangential += o->tangential;
      }
      damping_work -= o->damping_work;
      forces_.normal += o->fn;
      forces_.potential += o->potential;
      ++forces_.active;
      const Index ui = set_.force_node_of_node(o->i);
      touch(ui);
      double* fs = &fc_[3 * std::size_t(ui)];
      for (int d = 0; d < 3; ++d) fs[d] += o->F[d];
      const Index* ql = set_.force_nodes_of_segment(std::size_t(o->s));
      for (int a = 0; a < 4; ++a) {
        touch(ql[a]);
        double* fm = &fc_[3 * std::size_t(ql[a])];
        for (int d = 0; d < 3; ++d) fm[d] -= o->N[a] * o->F[d];
      }
      rows_[std::size_t(ui)] += o->k * o->sum_b;
      for (int a = 0; a < 4; ++a) rows_[std::size_t(ql[a])] += o->k * o->N[a] * o->sum_b;
    }
  }
  // Scatter, side-A resultant and the work of the contact forces on the bodies (book_work).
  // Over the touched force nodes in ascending order: the sums of a loop over all of them.
  const std::vector<Index>& nodes = set_.force_nodes();
  std::sort(touched_.begin(), touched_.end());
  double power_old = 0, power_new = 0, omega2 = 0;
  for (const Index ui : touched_) {
    const std::size_t u = std::size_t(ui), node = std::size_t(nodes[u]);
    marked_[u] = 0;
    omega2 = std::max(omega2, rows_[u] * set_.force_node_inv_mass(u));
    rows_[u] = 0;
    for (int d = 0; d < 3; ++d) {
      const double fu = fc_[3 * u + d];
      f[3 * node + d] += fu;
      power_new += fu * v[3 * node + d];
      if (set_.force_node_side_a(u)) forces_.resultant[d] += fu;
    }
  }
  for (const Index ui : touched_prev_) {
    const std::size_t u = std::size_t(ui), node = std::size_t(nodes[u]);
    for (int d = 0; d < 3; ++d) power_old += fc_prev_[3 * u + d] * v[3 * node + d];
  }
  book_work(power_old, power_new, dt);
  friction_energy_ += friction_work;
  damping_energy_ += damping_work;
  energy_ = forces_.potential + friction_energy_ + damping_energy_ + eroded_spring_energy_;
  dt_springs_ = omega2 > 0 ? 2 / std::sqrt(omega2) : kInf;
  springs_.exposed_pass = false;
  // fc_prev_ becomes this pass's forces; fc_ keeps them for output until the next pass.
  for (const Index u : touched_prev_)
    for (int d = 0; d < 3; ++d) fc_prev_[3 * std::size_t(u) + d] = 0;
  for (const Index u : touched_)
    for (int d = 0; d < 3; ++d) fc_prev_[3 * std::size_t(u) + d] = fc_[3 * std::size_t(u) + d];
  touched_prev_ = touched_;
}

void PenaltyContact::book_work(double power_old, double power_new, double dt) {
  // The integrator applies the force f^p of the pass at t^p over dt_p = (dt^{p-1/2} + dt^{p+1/2}) / 2
  // and evaluates the kinetic energy at t^p with v_p = (v^{p-1/2} + v^{p+1/2}) / 2, so the work that
  // changes the bodies' kinetic energy as the balance measures it is dt_p f^p . v_p. Its first half,
  // 0.5 dt_p f^p . v^{p-1/2}, is due at the pass itself, before dt^{p+1/2} is known: booked with
  // dt^{p-1/2} and corrected at the next pass, which also books the second half with v^{p+1/2}.
  // (A plain trapezoid 0.5 (f^p + f^{p+1}) . v^{p+1/2} dt^{p+1/2} weights a force with a step it was
  // not applied over, which the combined contact step changes from pass to pass.)
  const double dt_p = 0.5 * (work_dt_ + dt);
  const double work = 0.5 * (dt_p - work_dt_) * work_power_ + 0.5 * dt_p * power_old + 0.5 * dt * power_new;
  taken_ -= work;
  work_power_ = power_new;
  work_dt_ = dt;
}

void PenaltyContact::visit_state(StateVisitor& v) {
  StateGroup group(v, "penalty contact " + def_.spec.name);
  // The SOFT 1/2 step is fixed at construction from the initial step; a reader built at another
  // geometry must still use the run's.
  v.scalar("SOFT 1/2 step", law_.dt_c);
  set_.visit_state(v);
  search_.visit_state(v);
  springs_.visit_state(v);
  v.array("forces", fc_);
  v.array("forces of the last pass", fc_prev_);
  v.array("force nodes of this pass", touched_);
  v.array("force nodes of the last pass", touched_prev_);
  v.array("stability rows", rows_);  // zero between passes; visited for its size
  v.scalar("exposures", exposures_);
  v.scalar("energy", energy_);
  v.scalar("friction energy", friction_energy_);
  v.scalar("damping energy", damping_energy_);
  v.scalar("eroded spring energy", eroded_spring_energy_);
  v.scalar("energy taken from the bodies", taken_);
  v.scalar("power of the last pass", work_power_);
  v.scalar("step of the last pass", work_dt_);
  v.scalar("pass forces", forces_);
  v.scalar("penetrations", penetrations_);
  v.scalar("stiffness bounds", bounds_);
  v.scalar("spring stable step", dt_springs_);
}

}  // namespace plyimpact::contact
