// ComponentIntegrator (reduced/component_integrator.hpp) on a component
// whose answer is known (issue 12 items 1 and 4):
//
// Two 3D nodes, per direction the same chain: ground -- k -- interior node I
// (mass m) -- k_c -- boundary node B (mass eps m). B is the contact node, at
// (R, 0, 0): e_n = -x, e_t1 = z, e_t2 = +y (rigid_casing.hpp). The rigid
// casing approaches at speed v: g(t) = g_0 - v t, contact from t_c = g_0/v;
// it slides at -R Omega along e_t2, fast enough that B always slips, so
// lambda_t2 = -mu lambda_n, lambda_t1 = 0.
//
// Exact solution for eps -> 0 (massless B; tau = t - t_c >= 0, before t_c
// nothing moves): B follows the casing, u_Bx = -v tau, and with
// omega^2 = (k + k_c)/m, c = k_c v/(k + k_c),
//   q_x(tau) = -c (tau - sin(omega tau)/omega),
//   lambda_n(tau) = k_c (q_x - u_Bx) = (k_c v/(k + k_c)) (k tau + k_c sin(omega tau)/omega)
// (>= 0 for k >= k_c: contact persists); tangentially B is in static
// balance k_c (u_By - q_y) = lambda_t2, so m q_y'' + k q_y = -mu lambda_n:
// with omega_t^2 = k/m, a = k_c k v/(k + k_c), b = k_c^2 v/((k + k_c) omega),
//   q_y = -(mu/m) [a (tau/omega_t^2 - sin(omega_t tau)/omega_t^3)
//                  + b (sin(omega tau) - (omega/omega_t) sin(omega_t tau))/(omega_t^2 - omega^2)].
//
// MacNeal keeps all 3 free modes (n - n_B) of the eps = 1e-8 model: up to
// O(eps) it is the massless model, integrated by the partitioned scheme.
// CB keeps all 3 fixed-interface modes of the eps = 1e-4 model (CB-all is
// that model exactly), integrated by the mass-carrying scheme at its own
// stable step (omega_B ~ sqrt(k_c/(eps m)) = 71 rad/s).
//
// Central differences on the normal direction (the linear part c tau is
// exact; the homogeneous part starts from q = 0 at two grid points, so its
// amplitude is c dt/sin(omega_d dt) instead of c/omega, a relative
// 1/cos(omega_d dt/2) - 1 <= (omega dt)^2/8 (1 + (omega dt)^2/4), and its
// frequency omega_d = (2/dt) asin(omega dt/2) = omega (1 + (omega dt)^2/24 +
// 3 (omega dt)^4/640 + ...)):
//   |q_x^n - q_x(tau_n)| <= (c/omega) [(omega dt)^2/8 + omega tau (omega dt)^2/24] (1 + (omega
//   dt)^2)
// (the last factor bounds the neglected higher orders for omega dt <= 0.1).

#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>
#include <gtest/gtest.h>

#include "characteristic_constraint.hpp"
#include "component_integrator.hpp"
#include "component_run.hpp"
#include "modal_damping.hpp"
#include "reduction.hpp"
#include "rigid_casing.hpp"

namespace rsi {
namespace {

constexpr double kM = 1.0, kK = 1.0, kKc = 0.5; // omega_t = 1, omega = sqrt(1.5)
constexpr double kV = 1e-3, kTc = 1.0, kR = 1.0, kOmega = 1.0, kMu = 0.15;
constexpr double kEnd = 20.0;

struct Model {
  Eigen::SparseMatrix<double> k, m;
  std::vector<int> boundary{0, 1, 2};
};

/// dofs 0..2: B (ux, uy, uz); 3..5: I.
Model chain(double eps) {
  Model model;
  std::vector<Eigen::Triplet<double>> kt, mt;
  for (int a = 0; a < 3; ++a) {
    const int b = a, i = 3 + a;
    kt.emplace_back(b, b, kKc);
    kt.emplace_back(b, i, -kKc);
    kt.emplace_back(i, b, -kKc);
    kt.emplace_back(i, i, kKc + kK);
    mt.emplace_back(b, b, eps * kM);
    mt.emplace_back(i, i, kM);
  }
  model.k.resize(6, 6);
  model.m.resize(6, 6);
  model.k.setFromTriplets(kt.begin(), kt.end());
  model.m.setFromTriplets(mt.begin(), mt.end());
  return model;
}

/// omega: the gap phase's speed (no effect on the linear gap); sliding:
/// Omega_s, the casing moving at -R Omega_s e_t2 (rigid_casing.hpp).
RigidCasing plane(double omega = kOmega, double sliding = kOmega) {
  return RigidCasing({Eigen::Vector3d(kR, 0.0, 0.0)}, {{0, 1, 2}},
                     {CasingGapKind::linear, kV * kTc, kV, 0.15}, omega, sliding);
}

double omega_n() {
  return std::sqrt((kK + kKc) / kM);
}

double exact_x(double t) {
  const double tau = t - kTc;
  if (tau <= 0.0) return 0.0;
  const double w = omega_n(), c = kKc * kV / (kK + kKc);
  return -c * (tau - std::sin(w * tau) / w);
}

double exact_y(double t) {
  const double tau = t - kTc;
  if (tau <= 0.0) return 0.0;
  const double w = omega_n(), wt = std::sqrt(kK / kM);
  const double a = kKc * kK * kV / (kK + kKc), b = kKc * kKc * kV / ((kK + kKc) * w);
  return -(kMu / kM) *
         (a * (tau / (wt * wt) - std::sin(wt * tau) / (wt * wt * wt)) +
          b * (std::sin(w * tau) - (w / wt) * std::sin(wt * tau)) / (wt * wt - w * w));
}

struct Errors {
  double x = 0.0, y = 0.0, x_scale = 0.0, y_scale = 0.0;
  ComponentRunSummary summary;
  ComponentHistory hx, hy;
};

/// Runs the basis over [0, kEnd] at dt and measures the interior x, y
/// against the exact solution at every step.
Errors run(const ReducedBasis& basis, double dt, double zeta = 0.0,
           const RigidCasing& casing = plane()) {
  ComponentIntegratorOptions o;
  o.dt = dt;
  o.mu = kMu;
  if (zeta > 0.0) o.damping = modal_damping(basis, zeta);
  ComponentIntegrator integrator(basis, casing, o);
  ComponentRunOptions ro;
  ro.steps = static_cast<int>(std::lround(kEnd / dt));
  ro.balance_tolerance = 1e-6; // a monitor only; the balance is asserted below
  Errors e;
  const Eigen::RowVectorXd row_x = basis.transformation.row(3);
  const Eigen::RowVectorXd row_y = basis.transformation.row(4);
  e.summary = run_component(integrator, row_x, ro, e.hx);
  integrator.start();
  // Second pass for y with the same integrator: identical steps.
  ComponentRunSummary sy = run_component(integrator, row_y, ro, e.hy, true);
  (void)sy;
  for (int n = 0; n < e.hx.n_rows(); ++n) {
    const double t = e.hx.time[n];
    e.x = std::max(e.x, std::abs(e.hx.response[n] - exact_x(t)));
    e.y = std::max(e.y, std::abs(e.hy.response[n] - exact_y(t)));
    e.x_scale = std::max(e.x_scale, std::abs(exact_x(t)));
    e.y_scale = std::max(e.y_scale, std::abs(exact_y(t)));
  }
  return e;
}

/// The normal-direction bound of the header at dt, over tau <= kEnd - kTc.
double normal_bound(double dt) {
  const double w = omega_n(), c = kKc * kV / (kK + kKc), wdt = w * dt;
  return (c / w) * (wdt * wdt / 8.0 + w * (kEnd - kTc) * wdt * wdt / 24.0) * (1.0 + wdt * wdt);
}

TEST(ComponentIntegrator, MacNealAllModesMatchesExactMasslessSolution) {
  const Model model = chain(1e-8);
  const ReducedBasis basis = reduce(model.k, model.m, model.boundary, "macneal", 3);
  ASSERT_TRUE(basis.massless_boundary);
  const double dt = 0.04; // t_c = 25 dt, end = 500 dt
  const Errors e = run(basis, dt);
  const Errors h = run(basis, dt / 2);
  std::printf("MacNeal-3: omega_max %.6f rad/s (critical %.4f s), dt %.3f: |x err| %.3e (bound "
              "%.3e, scale %.3e), |y err| %.3e (scale %.3e); dt/2: %.3e, %.3e; status %s\n",
              e.summary.omega_max, e.summary.critical_dt, dt, e.x, normal_bound(dt), e.x_scale, e.y,
              e.y_scale, h.x, h.y, e.summary.status.c_str());
  ASSERT_TRUE(e.summary.completed) << e.summary.status;
  ASSERT_TRUE(h.summary.completed) << h.summary.status;
  // Stable step of the massless model: the kept free modes, omega_t = 1 rad/s
  // (k/m; B free and massless carries no force): 2/omega_t = 2 s, to O(eps) = 1e-8.
  EXPECT_NEAR(e.summary.omega_max, 1.0, 1e-7);
  // Header bound, plus the eps = 1e-8 model difference (relative O(eps) of
  // the scale, grown by omega tau <= 24: 1e-6 of the scale covers it).
  EXPECT_LE(e.x, normal_bound(dt) + 1e-6 * e.x_scale);
  EXPECT_LE(h.x, normal_bound(dt / 2) + 1e-6 * h.x_scale);
  // Second order (central differences): halving dt divides the error by
  // 4 (1 +- 0.15: the dt^4 terms at omega dt = 0.049 and the O(eps) floor
  // 1e-6 of the scale are below 0.15 of the error).
  EXPECT_NEAR(e.x / h.x, 4.0, 0.6);
  EXPECT_NEAR(e.y / h.y, 4.0, 0.6);
  // The contact: closed from t_c on, always slipping (casing speed R Omega = 1
  // against the node's own tangential speed <= 1e-3).
  EXPECT_EQ(e.summary.stick_contact_steps, 0);
  long closing = 0; // steps whose imposed gap g(t_n) is negative (the node free before)
  for (int n = 1; n <= std::lround(kEnd / dt); ++n)
    closing += kV * kTc - kV * (n * dt) < 0.0;
  EXPECT_EQ(e.summary.slip_contact_steps, closing);
  // Certificate (reduced_coulomb_certificate): round-off of a 3 x 3 solve on
  // W ~ 1/k_c: gaps 1e-15 of v t ~ 1e-2, forces 1e-15 of lambda ~ 1e-2.
  EXPECT_LE(e.summary.max_penetration, 1e-15);
  EXPECT_LE(e.summary.max_cone_violation, 1e-15);
  EXPECT_LE(e.summary.max_stick_slip_residual, 1e-12);
}

// The rotation direction (rigid_casing.hpp, Omega_s): reversing the
// sliding (Omega_s = -Omega: NLstep's PLAUSIBLE set-up, or a clockwise rotor
// Omega < 0 sliding with it) mirrors the problem through the plane y = 0
// (the node at (R, 0, 0), e_t2 = +y): the friction force lambda_t2 e_t2
// changes sign, so q_y -> -q_y and q_x is unchanged. IEEE arithmetic is
// symmetric under negation and every operation of the step is odd or even
// in the t2 components (the slip norm squares them), so the mirrored
// histories are the original ones negated bit for bit: tolerance 0.
TEST(ComponentIntegrator, ReversedSlidingMirrorsTheTangentialResponse) {
  const Model model = chain(1e-8);
  const ReducedBasis basis = reduce(model.k, model.m, model.boundary, "macneal", 3);
  const double dt = 0.04;
  const Errors with = run(basis, dt);
  const Errors against = run(basis, dt, 0.0, plane(kOmega, -kOmega));
  const Errors clockwise = run(basis, dt, 0.0, plane(-kOmega, -kOmega));
  ASSERT_TRUE(against.summary.completed) << against.summary.status;
  ASSERT_TRUE(clockwise.summary.completed) << clockwise.summary.status;
  ASSERT_EQ(against.hy.n_rows(), with.hy.n_rows());
  double worst_x = 0.0, worst_y = 0.0, worst_cw = 0.0, y_exact = 0.0;
  for (int n = 0; n < with.hy.n_rows(); ++n) {
    worst_x = std::max(worst_x, std::abs(against.hx.response[n] - with.hx.response[n]));
    worst_y = std::max(worst_y, std::abs(against.hy.response[n] + with.hy.response[n]));
    worst_cw = std::max({worst_cw, std::abs(clockwise.hy.response[n] - against.hy.response[n]),
                         std::abs(clockwise.hx.response[n] - against.hx.response[n])});
    y_exact = std::max(y_exact, std::abs(against.hy.response[n] + exact_y(with.hy.time[n])));
  }
  std::printf("against the rotation: |q_x - q_x(with)| %.3e, |q_y + q_y(with)| %.3e, "
              "|q_y - (-exact)| %.3e (with: %.3e, scale %.3e); clockwise with = counter-clockwise "
              "against: %.3e\n",
              worst_x, worst_y, y_exact, with.y, with.y_scale, worst_cw);
  EXPECT_EQ(worst_x, 0.0);
  EXPECT_EQ(worst_y, 0.0);
  // The linear gap has no phase: Omega's sign acts only through Omega_s.
  EXPECT_EQ(worst_cw, 0.0);
  // Against the exact solution mirrored: the same error as the original run.
  EXPECT_EQ(y_exact, with.y);
  // The friction force now pushes the node along +e_t2: q_y > 0 once it slides.
  EXPECT_GT(against.hy.response.back(), 0.0);
  EXPECT_LT(with.hy.response.back(), 0.0);
}

TEST(ComponentIntegrator, CraigBamptonAllModesMatchesExactSolutionAndMacNeal) {
  const double eps = 1e-4;
  const Model model = chain(eps);
  const ReducedBasis cb = reduce(model.k, model.m, model.boundary, "cb", 3);
  const ReducedBasis mn = reduce(chain(1e-8).k, chain(1e-8).m, model.boundary, "macneal", 3);
  // CB's own stable step: omega_max ~ sqrt(k_c (1 + eps)/(eps m)) = 70.7 rad/s.
  const double dt_cb = 0.002; // omega_B dt = 0.14; t_c = 500 steps
  const Errors c = run(cb, dt_cb);
  const Errors m = run(mn, 0.04);
  double diff_x = 0.0, diff_y = 0.0;
  for (int n = 0; n < m.hx.n_rows(); ++n) {
    const int j = 20 * n; // dt_cb = 0.04 / 20
    diff_x = std::max(diff_x, std::abs(c.hx.response[j] - m.hx.response[n]));
    diff_y = std::max(diff_y, std::abs(c.hy.response[j] - m.hy.response[n]));
  }
  std::printf("CB-3 (eps %.0e): omega_max %.3f rad/s (critical %.5f s), dt %.4f: |x err| %.3e "
              "(bound %.3e), |y err| %.3e (scale %.3e); CB vs MacNeal(dt 0.04): x %.3e, y %.3e\n",
              eps, c.summary.omega_max, c.summary.critical_dt, dt_cb, c.x, normal_bound(dt_cb), c.y,
              c.y_scale, diff_x, diff_y);
  ASSERT_TRUE(c.summary.completed) << c.summary.status;
  // In contact B's normal motion is prescribed, so the normal equation of I
  // is the massless one: only the central-difference bound at dt_cb, plus the
  // impulse at t_c (B, mass eps m, taking the casing's speed v in one step:
  // a spring displacement <= v dt_cb, force error k_c v dt_cb for one step,
  // I moved by dt_cb^2 k_c v dt_cb / m = 4e-12).
  EXPECT_LE(c.x, normal_bound(dt_cb) + 1e-11);
  // Tangentially B's mass adds eps m u_By'' to the interior's forcing:
  // relative eps m omega^2/k_c = 3 eps, grown by omega tau <= 24: below
  // 100 eps of the scale.
  EXPECT_LE(c.y, 100.0 * eps * c.y_scale + normal_bound(dt_cb));
  // The two reductions agree within the sum of their bounds.
  EXPECT_LE(diff_x, normal_bound(0.04) + normal_bound(dt_cb) + 1e-6 * m.x_scale + 1e-11);
}

// Characteristic constraint modes (reduced/bases/characteristic_constraint.hpp)
// with every boundary mode: T_cc = T_cb S, S = diag(I, Psi_c) invertible, and
// central differences with the contact rows B_q = B_B U (u_B = Psi_c q_c) are
// invariant under the change of coordinates q_cb = S q_cc (W = dt^2 B_q A^-1
// B_q^T is the same matrix): the two runs differ by rounding only. Each step
// rounds r-term products in coordinates scaled by S (relative r eps cond(S),
// cond(S) = cond(Psi_c) = sqrt(cond(M^_BB)) for M^_BB-orthonormal Psi_c), and
// central differences carry an error at most linearly over the N steps:
// |x_cc - x_cb| <= N r eps sqrt(cond(M^_BB)) max|x| while the contact makes the
// same decisions (the contact work compared with the same bound).
TEST(ComponentIntegrator, CharacteristicConstraintAllBoundaryModesIsCraigBampton) {
  const Model model = chain(1e-4);
  const ReducedBasis cb = reduce(model.k, model.m, model.boundary, "cb", 3);
  const ReducedBasis cc =
      characteristic_constraint(model.k, model.m, make_partition(6, model.boundary), 3, 3);
  ASSERT_EQ(cc.n_boundary(), 3);
  ASSERT_TRUE(cc.boundary_position.empty());
  const double dt = 0.002; // CB's step in the test above
  const Errors a = run(cb, dt);
  const Errors b = run(cc, dt);
  ASSERT_TRUE(a.summary.completed) << a.summary.status;
  ASSERT_TRUE(b.summary.completed) << b.summary.status;
  const Eigen::VectorXd m_bb = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
                                   cb.mass.bottomRightCorner(3, 3), Eigen::EigenvaluesOnly)
                                   .eigenvalues();
  const double cond_s = std::sqrt(m_bb(2) / m_bb(0));
  const int steps = a.summary.steps;
  const double relative = steps * cb.n_reduced() * 2.2e-16 * cond_s;
  ASSERT_EQ(a.hx.n_rows(), b.hx.n_rows());
  double dx = 0.0, dy = 0.0;
  for (int n = 0; n < a.hx.n_rows(); ++n) {
    dx = std::max(dx, std::abs(a.hx.response[n] - b.hx.response[n]));
    dy = std::max(dy, std::abs(a.hy.response[n] - b.hy.response[n]));
  }
  std::printf("CC-3 with n_c = n_B = 3 against CB-3, %d steps: |x| difference %.3e (%.2e of "
              "bound), |y| %.3e (%.2e of bound); cond(S) = %.3f; CB's contact work %.6e, CC's "
              "%.6e\n",
              steps, dx, dx / (relative * a.x_scale), dy, dy / (relative * a.y_scale), cond_s,
              a.summary.final_contact_work, b.summary.final_contact_work);
  EXPECT_LE(dx, relative * a.x_scale);
  EXPECT_LE(dy, relative * a.y_scale);
  EXPECT_NEAR(b.summary.final_contact_work, a.summary.final_contact_work,
              relative * std::abs(a.summary.final_contact_work));
}

TEST(ComponentIntegrator, EnergyBalanceClosesToRoundOffWithDampingAndFriction) {
  for (const char* method : {"macneal", "cb"}) {
    const double eps = std::string(method) == "cb" ? 1e-2 : 1e-8;
    const Model model = chain(eps);
    const ReducedBasis basis = reduce(model.k, model.m, model.boundary, method, 3);
    const double dt = std::string(method) == "cb" ? 0.01 : 0.04;
    const Errors e = run(basis, dt, 0.05);
    const int n = e.summary.steps;
    // Each step's identity holds to the round-off of r-term products (r = 6)
    // on terms of the energy's size: accumulated over n steps, n r eps.
    const double bound = n * 6 * 2.2e-16 * e.summary.energy_scale;
    std::printf("%s: %d steps, W_contact %.6e, W_damp %.6e, E_end %.6e, balance error %.3e "
                "(bound %.3e)\n",
                method, n, e.summary.final_contact_work, e.summary.final_damping_work,
                e.hx.energy.back(), e.summary.energy_balance_error, bound);
    ASSERT_TRUE(e.summary.completed) << e.summary.status;
    EXPECT_GT(e.summary.final_damping_work, 0.0);
    EXPECT_GT(std::abs(e.summary.final_contact_work), 1e3 * bound);
    EXPECT_LE(e.summary.energy_balance_error, bound);
  }
}

// Stick with a massless boundary. The casing does not slide (Omega = 0)
// and is pressed into B by delta (constant gap g_0 = -delta); the interior
// starts at rest displaced by y_0 along e_t2 = +y (B with it: free and
// massless, B follows I). From t = 0, B is held at (-delta, y_0) (normal
// closed, tangent stuck), so with omega^2 = (k + k_c)/m, s = k_c/(k + k_c):
//   q_x(t) = -s delta (1 - cos(omega t)),
//   q_y(t) = y_0 (s + (1 - s) cos(omega t)),
//   lambda_n = k_c (q_x + delta) >= k_c delta (1 - 2 s),
//   |lambda_t2| = k_c |y_0 - q_y| <= 2 k_c (1 - s) y_0,
// and stick holds throughout while 2 k_c (1 - s) y_0 <= mu k_c delta (1 - 2 s),
// i.e. y_0 <= mu delta (k - k_c)/(2 k) = 3.75e-5 delta/1e-3 here: y_0 = 2e-5.
// Central differences from rest (q_{-1} = q_1) reproduce A cos(omega_d t_n)
// exactly, with omega_d = (2/dt) asin(omega dt/2): the error is the phase
// alone, |A| omega t (omega dt)^2/24 (1 + (omega dt)^2) for omega dt <= 0.1.
TEST(ComponentIntegrator, MacNealStickOnAPressedPlaneMatchesExactSolution) {
  const double delta = 1e-3, y0 = 2e-5, dt = 0.04, end = 20.0;
  const Model model = chain(1e-8);
  const ReducedBasis basis = reduce(model.k, model.m, model.boundary, "macneal", 3);
  const RigidCasing casing({Eigen::Vector3d(kR, 0.0, 0.0)}, {{0, 1, 2}},
                           {CasingGapKind::constant, -delta, 0.0, 0.15}, 0.0);
  ComponentIntegratorOptions o;
  o.dt = dt;
  o.mu = kMu;
  ComponentIntegrator integrator(basis, casing, o);
  // T is square (n = 6 = 3 boundary + 3 modes): q0 = T^-1 u0 exactly.
  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(6);
  u0(1) = y0; // B, uy
  u0(4) = y0; // I, uy
  const Eigen::VectorXd q0 = basis.transformation.fullPivLu().solve(u0);
  integrator.start(q0);
  ComponentRunOptions ro;
  ro.steps = static_cast<int>(std::lround(end / dt));
  ComponentHistory hx;
  const ComponentRunSummary sx =
      run_component(integrator, basis.transformation.row(3), ro, hx, true);
  integrator.start(q0);
  ComponentHistory hy;
  const ComponentRunSummary sy =
      run_component(integrator, basis.transformation.row(4), ro, hy, true);
  ASSERT_TRUE(sx.completed) << sx.status;
  ASSERT_TRUE(sy.completed) << sy.status;
  const double w = omega_n(), sr = kKc / (kK + kKc), wdt = w * dt;
  double ex = 0.0, ey = 0.0;
  for (int n = 0; n < hx.n_rows(); ++n) {
    const double t = hx.time[n];
    ex = std::max(ex, std::abs(hx.response[n] + sr * delta * (1.0 - std::cos(w * t))));
    ey = std::max(ey, std::abs(hy.response[n] - y0 * (sr + (1.0 - sr) * std::cos(w * t))));
  }
  const double phase = w * end * wdt * wdt / 24.0 * (1.0 + wdt * wdt);
  std::printf("MacNeal-3 stick: |x err| %.3e (bound %.3e), |y err| %.3e (bound %.3e); stick %ld, "
              "slip %ld contact-steps, transitions %ld, cone %.2e, stick residual %.2e, balance "
              "%.2e of %.2e\n",
              ex, sr * delta * phase, ey, (1.0 - sr) * y0 * phase, sx.stick_contact_steps,
              sx.slip_contact_steps, sx.stick_slip_transitions, sx.max_cone_violation,
              sx.max_stick_slip_residual, sx.energy_balance_error, sx.energy_scale);
  // Exact solution above, phase bound; plus the eps = 1e-8 model difference
  // (1e-6 of the amplitude, as in the slip test).
  EXPECT_LE(ex, sr * delta * (phase + 1e-6));
  EXPECT_LE(ey, (1.0 - sr) * y0 * (phase + 1e-6));
  // Sticks at every step (the closed contact of t = 0 counts in start()).
  EXPECT_EQ(sx.stick_contact_steps, ro.steps);
  EXPECT_EQ(sx.slip_contact_steps, 0);
  // Certificate: the stick residual (|s| per the largest predicted slip) at
  // round-off of a 3 x 3 solve; the cone not reached at all (|lambda_t| stays
  // below mu lambda_n by (3.75 - 2)/3.75 of it, far above round-off).
  EXPECT_LE(sx.max_stick_slip_residual, 1e-12);
  EXPECT_LE(sx.max_cone_violation, 0.0);
  EXPECT_LE(sx.energy_balance_error, ro.steps * 6 * 2.2e-16 * sx.energy_scale);
}

TEST(ComponentIntegrator, RefusesStepAboveCriticalAndBadArguments) {
  const Model model = chain(1e-4);
  const ReducedBasis cb = reduce(model.k, model.m, model.boundary, "cb", 3);
  ComponentIntegratorOptions o;
  o.dt = 0.04; // > 2/70.7 = 0.028
  try {
    ComponentIntegrator bad(cb, plane(), o);
    FAIL() << "dt above the critical step accepted";
  } catch (const ComponentIntegrationError& e) {
    std::printf("refused: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("critical step"), std::string::npos);
  }
  // MacNeal: the massless boundary condensed, omega_max = omega_t = 1 rad/s
  // (k/m): 2.1 s is above 2/omega_t = 2 s, 1.9 s below it.
  const ReducedBasis mn = reduce(chain(1e-8).k, chain(1e-8).m, model.boundary, "macneal", 3);
  o.dt = 2.1;
  EXPECT_THROW(ComponentIntegrator(mn, plane(), o), ComponentIntegrationError);
  o.dt = 1.9;
  EXPECT_NO_THROW(ComponentIntegrator(mn, plane(), o));
  o.dt = -1.0;
  EXPECT_THROW(ComponentIntegrator(cb, plane(), o), std::invalid_argument);
  EXPECT_THROW(RigidCasing({Eigen::Vector3d(0, 0, 1)}, {{0, 1, 2}}, {}, 1.0),
               std::invalid_argument);
}

TEST(RigidCasing, FrameAndOvalGap) {
  const double phi = 0.3;
  const RigidCasing casing({Eigen::Vector3d(2 * std::cos(phi), 2 * std::sin(phi), 5)}, {{0, 1, 2}},
                           oval_casing_gap(0.356), 1344.0);
  const Eigen::Matrix3d f = casing.frame(0);
  // e_n = -(cos, sin, 0), e_t1 = z, e_t2 = e_n x e_t1 = (-sin, cos, 0): exact up to 1 ulp.
  EXPECT_NEAR((f.row(0) - Eigen::RowVector3d(-std::cos(phi), -std::sin(phi), 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((f.row(2) - Eigen::RowVector3d(-std::sin(phi), std::cos(phi), 0)).norm(), 0, 1e-15);
  // Oval: g = -g_m where mod(theta, pi) = pi/2 (t = (pi/2 - phi)/Omega), g -> g_m(1 -
  // 2e^{-1/(4*0.0225)}) at theta = 0.
  const double t = (M_PI / 2 - phi) / 1344.0;
  EXPECT_NEAR(casing.imposed_gap(0, t), -0.356, 1e-12);
  EXPECT_NEAR(casing.imposed_gap(0, t + M_PI / 1344.0), -0.356, 1e-12);
  EXPECT_NEAR(casing.imposed_gap(0, -phi / 1344.0), 0.356 * (1 - 2 * std::exp(-1 / 0.09)), 1e-12);
  EXPECT_DOUBLE_EQ(casing.casing_slip(0, 1e-6), 2 * 1344.0 * 1e-6);
}

} // namespace
} // namespace rsi
