// Free vibration of a cantilever: MAT_001 with PR = 0 (no Poisson coupling, so the solid matches
// beam theory), length L, square section h x h, L/h = 20, every dof fixed at x = 0. The initial
// velocity is the first Euler-Bernoulli mode shape phi(x) (tiny amplitude: linear, elastic); the tip
// deflection is recorded every cycle and the period measured from zero crossings (linear
// interpolation between cycles). Four meshes of cubes (n = 1, 2, 3, 4 elements through the depth,
// 20 n along), ELFORM 2. Reference: Euler-Bernoulli f1 = (kL)^2 / (2 pi L^2) sqrt(E I / (rho A))
// with the first-order Timoshenko correction (rotary inertia and shear, computed here from the mode
// shape). Asserted: monotone error decrease, the finest error below an a-priori bound, and the
// observed order of convergence on the meshes with at least two elements through the depth (one
// element through the depth is outside the asymptotic range, see below; its order is reported).
// Bulk viscosity stays at its defaults: its linear term damps this mode at a ratio of about
// omega l Q2 / (2 c) ~ 2e-8, no effect on the period. The initial field is the beam mode, not the
// discrete one, so higher modes are excited slightly; the period from t = 0 (an upward crossing)
// to the next upward crossing and twice the time between the downward and that upward crossing
// differ by ~1 % of the finest-mesh error (both printed), far below what the order estimates can
// resolve.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "support.hpp"

namespace plyimpact {
namespace {

constexpr double kE = 210e9, kRho = 7850;        // PR = 0
constexpr double kH = 0.01, kLength = 20 * kH;   // m
constexpr double kBeta1 = 1.875104068711961;     // k L of the first cantilever mode
constexpr double kTipVelocity = 0.1;             // m/s: tip amplitude V/omega ~ 8e-5 m = 4e-4 L

// First Euler-Bernoulli cantilever mode and its derivatives, x in [0, L].
struct Mode {
  double k = kBeta1 / kLength;
  double s = (std::cosh(kBeta1) + std::cos(kBeta1)) / (std::sinh(kBeta1) + std::sin(kBeta1));
  double phi(double x) const {
    const double a = k * x;
    return std::cosh(a) - std::cos(a) - s * (std::sinh(a) - std::sin(a));
  }
  double d1(double x) const {
    const double a = k * x;
    return k * (std::sinh(a) + std::sin(a) - s * (std::cosh(a) - std::cos(a)));
  }
  double d2(double x) const {
    const double a = k * x;
    return k * k * (std::cosh(a) + std::cos(a) - s * (std::sinh(a) + std::sin(a)));
  }
  double d3(double x) const {
    const double a = k * x;
    return k * k * k * (std::sinh(a) - std::sin(a) - s * (std::cosh(a) + std::cos(a)));
  }
};

// Simpson integral of f over [0, L].
template <class F>
double integrate(F f) {
  const int n = 2000;
  const double dx = kLength / n;
  double sum = f(0.0) + f(kLength);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * dx);
  return sum * dx / 3;
}

struct Reference {
  double f_eb = 0;          // Euler-Bernoulli
  double timoshenko = 0;    // relative first-order correction (negative)
  double rotary = 0;        // its rotary-inertia part (negative)
  double f = 0;             // f_eb (1 + timoshenko)
};

Reference reference_frequency() {
  const double A = kH * kH, I = kH * kH * kH * kH / 12, r2 = I / A;
  Reference ref;
  ref.f_eb = kBeta1 * kBeta1 / (2 * M_PI * kLength * kLength) * std::sqrt(kE * I / (kRho * A));
  // Rayleigh-quotient perturbation of omega^2 with the EB mode (first order in (h/L)^2):
  //   rotary inertia adds rho I int phi'^2 to the kinetic term: d(omega^2)/omega^2 = -r^2 int phi'^2 / int phi^2;
  //   shear adds the complementary energy of V = E I phi''': d(omega^2)/omega^2 =
  //   -(E I / (kappa G A)) int phi'''^2 / int phi''^2, with G = E/2 (nu = 0) and Cowper's kappa =
  //   10 (1 + nu) / (12 + 11 nu) = 5/6 for a rectangle. The frequency changes by half of that.
  // Beyond Timoshenko, the clamped face restrains shear warping over a length ~h at the root: a
  // fraction of the shear term times h/L, below 1e-4. Cross-check (outside this test): a 400-element
  // Timoshenko beam FE eigen-solution with consistent mass gives -0.16404 % against -0.16461 % here.
  const Mode m;
  const double rotary = r2 * integrate([&](double x) { return m.d1(x) * m.d1(x); }) /
                        integrate([&](double x) { return m.phi(x) * m.phi(x); });
  const double shear = r2 * (2.0 / (5.0 / 6.0)) * integrate([&](double x) { return m.d3(x) * m.d3(x); }) /
                       integrate([&](double x) { return m.d2(x) * m.d2(x); });
  ref.timoshenko = -0.5 * (rotary + shear);
  ref.rotary = -0.5 * rotary;
  ref.f = ref.f_eb * (1 + ref.timoshenko);
  return ref;
}

// Cantilever scene: `section` is the YAML flow mapping of the section, nx elements along, nd
// through the width and the depth; TSSFAC tssfac.
std::string scene_yaml(const std::string& section, int nx, int nd, double tssfac) {
  std::ostringstream y;
  y << "units: SI\ncontrol: {termination_time: 1.0, tssfac: " << tssfac << "}\n"
    << "materials:\n  steel: {card: MAT_001, RO: 7850, E: 210e9, PR: 0}\n"
    << "sections:\n  s: " << section << "\n"
    << "parts:\n  beam: {material: steel, section: s}\n"
    << "mesh:\n  boxes:\n    - {part: beam, size: [" << kLength << ", " << kH << ", " << kH << "], elements: ["
    << nx << ", " << nd << ", " << nd << "]}\n"
    << "node_sets:\n  root: {plane: {axis: x, value: 0}}\n"
    << "boundary_conditions:\n  - {node_set: root, fix: [x, y, z]}\n";
  return y.str();
}

struct Measured {
  double period = 0;        // t = 0 (upward zero crossing, exact) to the next upward crossing
  double period_half = 0;   // 2 x (upward - downward crossing): a second estimate
  double wall = 0;
  long cycles = 0;
  int elements = 0;
};

Measured run_mesh(const std::string& section, int nx, int nd, double period_guess, double tssfac = 0.9) {
  model::Model model = test::model_from_yaml(scene_yaml(section, nx, nd, tssfac),
                                             "cantilever_" + std::to_string(nx) + "x" + std::to_string(nd) + ".yaml");
  const Mode mode;
  const double tip_phi = mode.phi(kLength);  // = 2 for this normalisation
  std::vector<int> tip;
  for (std::size_t i = 0; i < model.num_nodes(); ++i) {
    const double x = model.X[3 * i];
    model.v0[3 * i + 2] = kTipVelocity * mode.phi(x) / tip_phi;  // transverse (z) velocity, mode shape
    if (std::abs(x - kLength) < 1e-9 * kLength) tip.push_back(int(i));
  }
  solver::Solver s(model);
  // Tip deflection: mean z displacement of the tip face.
  auto tip_w = [&] {
    double w = 0;
    for (int i : tip) w += s.state().x[3 * std::size_t(i) + 2] - model.X[3 * std::size_t(i) + 2];
    return w / double(tip.size());
  };
  Measured m;
  m.elements = int(model.num_elements());
  double t_down = -1, t_up = -1, w_prev = 0, t_prev = 0;
  const auto wall0 = std::chrono::steady_clock::now();
  while (t_up < 0 && s.state().time < 1.5 * period_guess) {
    s.step();
    const double t = s.state().time, w = tip_w();
    if (t_down < 0 && w_prev > 0 && w <= 0) t_down = t_prev + (t - t_prev) * w_prev / (w_prev - w);
    if (t_down > 0 && w_prev < 0 && w >= 0) t_up = t_prev + (t - t_prev) * w_prev / (w_prev - w);
    w_prev = w, t_prev = t;
  }
  m.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  m.cycles = s.state().cycle;
  EXPECT_GT(t_up, 0) << "no full period within 1.5 reference periods on mesh " << nx << " x " << nd;
  m.period = t_up;
  m.period_half = 2 * (t_up - t_down);
  return m;
}

TEST(CantileverFrequency, ConvergesAtSecondOrderToBeamTheory) {
  const Reference ref = reference_frequency();
  std::cout << std::setprecision(7) << "reference: Euler-Bernoulli f1 = " << ref.f_eb
            << " Hz, Timoshenko correction " << ref.timoshenko << " -> f1 = " << ref.f << " Hz\n";
  RecordProperty("f_reference_hz", std::to_string(ref.f));

  constexpr int kMeshes = 4;
  const int meshes[kMeshes] = {1, 2, 3, 4};
  double err[kMeshes], freq[kMeshes], wall_total = 0;
  for (int i = 0; i < kMeshes; ++i) {
    const Measured m = run_mesh("{ELFORM: 2}", 20 * meshes[i], meshes[i], 1.0 / ref.f);
    freq[i] = 1.0 / m.period;
    err[i] = (freq[i] - ref.f) / ref.f;
    wall_total += m.wall;
    const double err_half = (1.0 / m.period_half - ref.f) / ref.f;
    std::cout << "mesh n = " << meshes[i] << " (" << m.elements << " elements): f1 = " << freq[i]
              << " Hz, error " << err[i] << " (from the half period: " << err_half << "), " << m.cycles
              << " cycles, wall " << m.wall << " s\n";
    std::string err_key = "error_n", wall_key = "wall_s_n";  // (appending: avoids a GCC 12 -Wrestrict false positive)
    err_key += std::to_string(meshes[i]);
    wall_key += std::to_string(meshes[i]);
    RecordProperty(err_key, std::to_string(err[i]));
    RecordProperty(wall_key, std::to_string(m.wall));
  }
  // Observed order between consecutive meshes: p = ln(e_a / e_b) / ln(n_b / n_a).
  double p[kMeshes - 1];
  for (int i = 0; i + 1 < kMeshes; ++i) {
    p[i] = std::log(std::abs(err[i] / err[i + 1])) / std::log(double(meshes[i + 1]) / meshes[i]);
    std::cout << "observed order n = " << meshes[i] << " -> " << meshes[i + 1] << ": " << p[i] << "\n";
    std::string key = "order_";
    key += std::to_string(meshes[i]);
    key += std::to_string(meshes[i + 1]);
    RecordProperty(key, std::to_string(p[i]));
  }
  // Brief's halving pairs: log2(e1/e2), log2(e2/e4).
  std::cout << "log2(e1/e2) = " << std::log2(err[0] / err[1]) << ", log2(e2/e4) = " << std::log2(err[1] / err[3])
            << ", reference-free log2((f1-f2)/(f2-f4)) = " << std::log2((freq[0] - freq[1]) / (freq[1] - freq[3]))
            << "; total wall " << wall_total << " s\n";

  for (int i = 0; i + 1 < kMeshes; ++i) EXPECT_GT(std::abs(err[i]), std::abs(err[i + 1])) << "mesh " << meshes[i + 1];
  // A-priori bound for the finest mesh (n = 4), a Rayleigh-quotient argument with the interpolated
  // Euler-Bernoulli mode as trial field: the fully integrated trilinear hex samples a parasitic
  // shear strain kappa (x - x_c) in bending, adding (G/E)(a/h)^2 = 1/(2 n^2) to the bending
  // energy; ELFORM 2's B-bar replaces the volumetric strain, which varies by kappa (z - z_c) across
  // an element, by its element mean and so removes (K/E)(a/h)^2 = 1/(3 n^2) (K = E/3 at nu = 0).
  // The lumped mass and the field's own relaxation only lower the quotient. Hence
  // f_FE <= f_EB (1 + 1/(12 n^2)) and, against the Timoshenko reference,
  // error <= 1/(12 n^2) + |Timoshenko correction| = 0.52 % + 0.16 % at n = 4.
  EXPECT_LT(err[kMeshes - 1], 1.0 / (12.0 * 16.0) - ref.timoshenko);
  // Order: every term of the estimate above scales with (a/h)^2, so the asymptotic order is 2.
  // With one element through the depth (n = 1) the next terms, (a/h)^4, are as large as the
  // leading ones (B-bar's volumetric averaging then spans the whole section), so log2(e1/e2) is not
  // an order estimate: it is printed, and only the error decrease is asserted for it. From n = 2
  // on, the (a/h)^4 terms are at most ~1/4 of the leading term and shift the local order by up to
  // ~0.5: range [1.5, 2.5].
  for (int i = 1; i + 1 < kMeshes; ++i) {
    EXPECT_GT(p[i], 1.5) << "order between n = " << meshes[i] << " and " << meshes[i + 1];
    EXPECT_LT(p[i], 2.5) << "order between n = " << meshes[i] << " and " << meshes[i + 1];
  }
}

// IHQ 6 (assumed-strain hourglass control, QM 1) with ONE element through the depth and the width,
// the thin-ply case of docs/theory.md section 6: 4, 8, 16 elements along (aspect 5:1, 2.5:1, 1.25:1), where IHQ 4/5
// give f/f_ref = 5.3 at 5:1 and ELFORM 2 3.5. The hourglass strains of a rectangular element bend
// it exactly (hourglass/assumed_strain.hpp, uniaxial modulus, PR = 0 here anyway), so the
// element behaves like a linear Timoshenko beam element with exact bending and one-point shear, and
// two errors remain: (1) the lumped mass sits at the section's corners, so the section's rotary
// inertia is rho A h^2/4 instead of rho A h^2/12: three times the rotary-inertia term of the
// Timoshenko correction (computed in reference_frequency), i.e. an extra 2 x that term (-0.08 %),
// independent of the mesh; (2) the discretisation of the mode by linear elements, O((l/L)^2).
// Asserted: after removing (1), the error converges at order 2 (observed 2.02 and 2.10; range
// [1.7, 2.4], as the (l/L)^4 terms are still ~ 1/4 of the leading ones at 5:1) and the 5:1 error
// is within 2.5 % (measured -1.76 %, i.e. -0.27 (l/L)^2 with l/L = 1/4, plus the -0.08 %).
// TSSFAC 0.9 (LS-DYNA's default), which needs the element step to hold its bulk-viscosity Q
// (solver/element_step.hpp, step_q): with Q taken afresh every cycle the step would oscillate with
// the vibration and pump it. Measured at 0.9 over 20000 cycles: the discrete energy within 2e-4
// (IHQ 6) and 6e-4 (IHQ 4) of its start (test_step_modulation.cpp has the focused case).
TEST(CantileverFrequency, AssumedStrainIHQ6OneElementThroughDepth) {
  const Reference ref = reference_frequency();
  constexpr int kMeshes = 3;
  const int along[kMeshes] = {4, 8, 16};  // 5:1, 2.5:1, 1.25:1 elements, one through the depth
  double err[kMeshes], disc[kMeshes];
  for (int i = 0; i < kMeshes; ++i) {
    const Measured m = run_mesh("{ELFORM: 1, IHQ: 6, QM: 1}", along[i], 1, 1.0 / ref.f, 0.9);
    err[i] = (1.0 / m.period - ref.f) / ref.f;
    disc[i] = err[i] - 2 * ref.rotary;
    std::cout << "IHQ 6, " << along[i] << " x 1 x 1 elements (aspect " << 20.0 / along[i] << "): f1/f_ref = " << 1 + err[i]
              << " (from the half period: " << 1.0 / (ref.f * m.period_half) << "), without the lumped rotary inertia "
              << disc[i] << ", " << m.cycles << " cycles, wall " << m.wall << " s\n";
  }
  for (int i = 0; i + 1 < kMeshes; ++i) {
    const double p = std::log2(disc[i] / disc[i + 1]);
    std::cout << "order " << along[i] << " -> " << along[i + 1] << ": " << p << "\n";
    EXPECT_GT(p, 1.7) << along[i] << " -> " << along[i + 1];
    EXPECT_LT(p, 2.4) << along[i] << " -> " << along[i + 1];
  }
  EXPECT_LT(std::abs(err[0]), 0.025) << "5:1 elements, one through the depth";
}

// ELFORM -2 (tied transverse shear, element/hex8_ans.hpp) with one element through the depth, 5:1,
// where ELFORM 2 gives f/f_ref = 3.5. Its tied shear leaves no parasitic shear in bending, its
// 2x2x2 points integrate the bending strain exactly, and its volume rate is averaged only over each
// layer of points, so a linear-through-the-depth volume rate (bending at nu = 0) is kept. On these
// rectangular elements it is then the same linear Timoshenko element as IHQ 6's above (exact
// bending, the shear of the element's mid-line), with the same lumped mass: the two must give the
// same frequency. Tolerance 1e-4: the period is read from zero crossings interpolated between
// cycles, and the two runs take different steps (measured: equal to 1e-6).
TEST(CantileverFrequency, AssumedShearOneElementThroughDepthEqualsIHQ6) {
  const Reference ref = reference_frequency();
  const Measured ihq6 = run_mesh("{ELFORM: 1, IHQ: 6, QM: 1}", 4, 1, 1.0 / ref.f, 0.9);
  const Measured ans = run_mesh("{ELFORM: -2}", 4, 1, 1.0 / ref.f, 0.9);
  const double ratio = ihq6.period / ans.period;
  std::cout << "ELFORM -2, 4 x 1 x 1 elements: f1/f_ref = " << 1.0 / (ref.f * ans.period)
            << "; against IHQ 6 on the same mesh, ratio - 1 = " << ratio - 1 << " (" << ans.cycles << " cycles)\n";
  EXPECT_NEAR(ratio, 1.0, 1e-4);
}

}  // namespace
}  // namespace plyimpact
