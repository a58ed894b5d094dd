// Coulomb friction with stick and slip through the REDUCED component
// integrator (ComponentIntegrator, reduced/component_integrator.hpp, with its
// external force; issue 12 item 5, "through both the full and the reduced
// integrators"): the single-dof oscillator of verification/support/coulomb_oscillator.hpp,
// free decay and Den Hartog forced with stops, against the exact solutions, at
// w0 dt = 0.02, 0.01, 0.005. test_coulomb_integrator.cpp does the same through
// the reference integrator; this file shares nothing with it but the oracle.
//
// The reduced model IS the oscillator: one node (3 dofs, M = m I, K = k along
// one tangent only), Craig-Bampton with the node as the boundary and 0 modes,
// T = I (asserted), so K^ = K, M^ = M. Rigid casing with constant gap 0 and
// Omega = 0 (rigid_casing.hpp). Node at X = (0.25, 0, 0) m: e_n = (-1, 0, 0)
// (a load +N along x presses it on the plane), e_t1 = (0, 0, 1) (dof 2),
// e_t2 = (0, 1, 0) (dof 1). K^ is singular (no stiffness along e_n and the
// other tangent): the mass-carrying scheme needs only M^ + dt/2 C^ positive
// definite, and omega_max = w0 (the other eigenvalues are 0).
//
// Loads (ComponentIntegratorOptions' force, in reduced = physical
// coordinates): f0 = (N, 0, 0) + (-k x0) on the tangent dof, f1 = P on the
// tangent dof, cos(w t - pi/2) = sin(w t). The integrator starts at rest at
// q = 0 under f(0) (x_{-1} = x_0 + dt^2/2 M^-1 f(0)); the oscillator's
// y = x_t + x0 starts at x0 since the spring's rest point is at -x0. As in
// the reference, the start from rest is consistent to second order with the
// contact: step 0's normal multiplier is N/2 (the normal prediction is
// -dt^2/2 N/m, W_nn = dt^2/m), so its friction bound is mu N/2 and
// x_1 = dt^2/(2m) (F_t - mu N s), the Taylor expansion of the exact start;
// from step 1 on lambda_n = N (the normal motion is static).
//
// In exact arithmetic the mass-carrying scheme (*) of the header is, on this
// model, the reference's scheme (central differences, forward-increment
// multipliers, the contact of x_{n+1} determining lambda_n, the slip
// increment x_{n+1} - x_n): the error budget of test_coulomb_integrator.cpp
// applies unchanged and is restated at each assertion.
//
// MacNeal (massless boundary). Not done here: the massless-boundary scheme
// needs interior modes, so the single node is not a MacNeal model; with an
// interior mass (a second node joined to the contact node by a spring) the
// contact node is a massless Jenkins element in series with a spring-mass,
// whose exact stick/slip solution is not the single-dof one and is not in
// verification/support/coulomb_oscillator. The force's entry into the static
// balance (B) is checked here only by the energy identity and by the
// static load of a MacNeal model (MacNealLoadEntersTheStaticBalance).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>
#include <gtest/gtest.h>

#include "component_integrator.hpp"
#include "component_run.hpp"
#include "coulomb_oscillator.hpp"
#include "reduction.hpp"
#include "rigid_casing.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double kR = 0.25;

RigidCasing pressed_plane() {
  return RigidCasing({Eigen::Vector3d(kR, 0.0, 0.0)}, {{0, 1, 2}},
                     {CasingGapKind::constant, 0.0, 0.0, 0.15}, 0.0);
}

/// The oscillator's node as a reduced model, its spring on `dof`:
/// reduce(..., "cb", 0) with every dof on the boundary (no interior: the
/// constraint modes are empty, T = I, K^ = K, M^ = M, asserted here).
ReducedBasis node_model(const coulomb::Oscillator& o, int dof) {
  Eigen::SparseMatrix<double> k(3, 3), m(3, 3);
  k.insert(dof, dof) = o.stiffness;
  for (int i = 0; i < 3; ++i)
    m.insert(i, i) = o.mass;
  const ReducedBasis b = reduce(k, m, {0, 1, 2}, "cb", 0);
  EXPECT_EQ(b.transformation, Eigen::MatrixXd::Identity(3, 3));
  EXPECT_EQ(b.stiffness, Eigen::MatrixXd(k));
  EXPECT_EQ(b.mass, Eigen::MatrixXd(m));
  EXPECT_EQ(b.boundary_position, (std::vector<int>{0, 1, 2}));
  return b;
}

/// The integrator's history of the oscillator coordinate y = x_t + x0.
struct PlaneRun {
  std::vector<double> time;
  std::vector<double> y;
  std::vector<int> direction;    ///< +1/-1 slip direction, 0 stick/open, per step (index n: t_n)
  double worst_cone = 0.0;       ///< max over steps of max_cone_violation [N]
  double worst_stick_slip = 0.0; ///< max over steps of max_stick_slip_residual (scaled)
  /// max over steps of max_stick_slip_residual / its round-off bound (expect_certificate)
  double worst_stick_slip_ratio = 0.0;
  double max_normal_error = 0.0; ///< max |lambda_n - N| over steps n >= 1
  double lambda_t_max = 0.0;     ///< max |lambda_t| over steps
  double energy_error = 0.0;     ///< max |E - E0 - W_ext - W_contact| over steps
  double energy_scale = 0.0;     ///< max of |E|, |W_ext|, |W_contact| over steps
};

/// Runs `o` along tangent 1 (dof 2) or 2 (dof 1) for `steps` steps of dt.
PlaneRun run_plane(const coulomb::Oscillator& o, int tangent, double dt, int steps) {
  const int dof = tangent == 1 ? 2 : 1;
  const ReducedBasis basis = node_model(o, dof);
  ComponentIntegratorOptions options;
  options.dt = dt;
  options.mu = o.friction_coefficient;
  options.force_constant = Eigen::VectorXd::Zero(3);
  options.force_constant(0) = o.normal_force;
  options.force_constant(dof) = -o.stiffness * o.x0;
  options.force_harmonic = Eigen::VectorXd::Zero(3);
  options.force_harmonic(dof) = o.force_amplitude;
  options.force_frequency = o.forcing_frequency;
  options.force_phase = o.forcing_phase - M_PI / 2.0; // cos(w t + phi - pi/2) = sin(w t + phi)
  ComponentIntegrator integrator(basis, pressed_plane(), options);
  integrator.start();
  PlaneRun run;
  run.time.push_back(0.0);
  run.y.push_back(o.x0);
  run.direction.push_back(0);
  const double e0 = integrator.initial_energy();
  for (int n = 0; n < steps; ++n) {
    const StepReport r = integrator.step();
    const ReducedContactState c = integrator.states()[0];
    // lambda_t = -mu lambda_n s^: the slip direction along the tangent is -sign(lambda_t).
    const double lt = integrator.lambda()(tangent);
    run.direction.push_back(c == ReducedContactState::slip ? (lt < 0.0 ? 1 : -1) : 0);
    run.worst_cone = std::max(run.worst_cone, r.max_cone_violation);
    run.worst_stick_slip = std::max(run.worst_stick_slip, r.max_stick_slip_residual);
    // The residual's round-off bound (expect_certificate): slip s = the step's
    // increment, s~ = s - W_tt lambda_t (W_tt = dt^2/m, the other tangent and
    // W_tn zero), the local law's size |s~| + W_tt |lambda_t|.
    if (c != ReducedContactState::open) {
      const double s_now = integrator.q()(dof) - (run.y.back() - o.x0);
      const double lt_size = dt * dt / o.mass * integrator.lambda().tail(2).norm();
      const double s_pred = std::abs(s_now - dt * dt / o.mass * lt);
      const double conditioning =
          c == ReducedContactState::stick ? 2.0 : (s_pred + lt_size) / std::abs(s_now);
      run.worst_stick_slip_ratio =
          std::max(run.worst_stick_slip_ratio,
                   r.max_stick_slip_residual / ((8.0 + 64.0 * conditioning) * eps));
    }
    run.time.push_back(integrator.time());
    run.y.push_back(integrator.q()(dof) + o.x0);
    run.lambda_t_max = std::max(run.lambda_t_max, integrator.lambda().tail(2).norm());
    if (n >= 1)
      run.max_normal_error =
          std::max(run.max_normal_error, std::abs(integrator.lambda()(0) - o.normal_force));
    const double e = integrator.energy();
    const double we = integrator.external_work(), wc = integrator.contact_work();
    run.energy_scale = std::max({run.energy_scale, std::abs(e), std::abs(we), std::abs(wc)});
    run.energy_error = std::max(run.energy_error, std::abs(e - e0 - we - wc));
  }
  return run;
}

/// Runs of one motion (stick 0, slip +1, -1) in the discrete history,
/// dropping stick runs of a single step (a discrete turning point, where the
/// exact stick has zero length): (motion, first step).
std::vector<std::pair<int, int>> motion_runs(const PlaneRun& run) {
  std::vector<std::pair<int, int>> runs;
  for (size_t n = 1; n < run.direction.size(); ++n) {
    const int d = run.direction[n];
    const bool single_stick = d == 0 && n + 1 < run.direction.size() && run.direction[n + 1] != 0 &&
                              run.direction[n - 1] != 0;
    if (single_stick) continue;
    if (runs.empty() || runs.back().first != d) runs.emplace_back(d, static_cast<int>(n));
  }
  return runs;
}

/// The certificate of every step and the normal multiplier (shared by both
/// tests). One contact, W = dt^2/m I (M^ = m I, the frame rows are the unit
/// vectors up to sign), so the Gauss-Seidel's local solution is the whole
/// solution, and its residuals are those of forming y = [g~; s~] + W lambda
/// and of the local law (local_coulomb_solution.hpp). The local slip solution
/// is accepted at a relative violation <= 64 eps of its size |s~| +
/// W_tt |lambda_t|; the integrator scales the slip residual by mu lambda_n,
/// mu lambda_n |e - s/|s||, which the direction's error divides by |s|:
/// <= 64 eps size/|s| (ill-conditioned where a slip starts, |s| << |s~|:
/// local_coulomb_solution.hpp says so), plus 8 eps for forming y and the
/// scaling. Stick: |s| per |s~| from the LU solve, size/|s~| = 2 (W lambda_t
/// = -s~). Cone: |lambda_t| = mu lambda_n e rounded, 8 eps of mu N.
void expect_certificate(const PlaneRun& run, const coulomb::Oscillator& o) {
  const double mu_n = coulomb::friction_limit(o);
  // Cone: |lambda_t| - mu lambda_n after the local law's rounding (above).
  EXPECT_LE(run.worst_cone, 8.0 * eps * mu_n);
  // Scaled stick/slip residual <= (8 + 64 size/|s|) eps per step (above).
  EXPECT_LE(run.worst_stick_slip_ratio, 1.0) << "worst residual " << run.worst_stick_slip;
  // lambda_n = N from step 1 on: -g~/W_nn, g~ = the sum of four terms of
  // size <= dt^2 N/m (2 x_n, x_{n-1} at round-off of 0, dt^2 A^-1 f0), so
  // |lambda_n - N| <= (4 + 1) eps N, doubled: 10 eps N.
  EXPECT_LE(run.max_normal_error, 10.0 * eps * o.normal_force);
  // The friction force stays in the cone and reaches it: |lambda_t| = mu N in slip.
  EXPECT_LE(run.lambda_t_max, mu_n * (1.0 + 8.0 * eps));
  // E = E0 + W_ext + W_contact (header, energy identity; no damping): its
  // round-off, a few eps of the energy scale per step, accumulated.
  EXPECT_LE(run.energy_error, 8.0 * eps * run.time.size() * run.energy_scale);
}

// ------------------------------------------------------------------ the model

// CB with the node as the boundary and 0 modes is T = I: the reduced model
// is the oscillator (so the runs below test the integrator, not a
// reduction). The integrator sees it as the mass-carrying scheme with
// omega_max = w0 (critical_step.hpp: the eigenvalues of (K^, M^) are 0, 0,
// k/m), to the dense eigensolver's round-off (a few eps of w0^2).
TEST(ComponentCoulombOscillator, NodeModelIsTheOscillator) {
  coulomb::Oscillator o;
  o.mass = 2.0;
  o.stiffness = 50.0;
  ComponentIntegratorOptions options;
  options.dt = 1e-3;
  const ComponentIntegrator integrator(node_model(o, 2), pressed_plane(), options);
  const double w0 = coulomb::natural_frequency(o);
  std::printf("omega_max %.17g, w0 %.17g\n", integrator.omega_max(), w0);
  EXPECT_FALSE(integrator.massless_boundary());
  EXPECT_LE(std::abs(integrator.omega_max() - w0), 8.0 * eps * w0); // critical_step.hpp, above
  // W = dt^2 B M^-1 B^T = dt^2/m I: the frame rows are +-unit vectors.
  EXPECT_LE((integrator.contact_matrix() -
             options.dt * options.dt / o.mass * Eigen::MatrixXd::Identity(3, 3))
                .cwiseAbs()
                .maxCoeff(),
            eps * options.dt * options.dt / o.mass);
}

// ------------------------------------------------------------------ free decay

// Exact (coulomb_oscillator.hpp, FreeVibration): with d = mu N / k,
// half-cycle j about the centre +-d lasts pi/w0, turning points |x_j| =
// |x0| - 2 j d, final stick at the first turning point with k|x_j| <= mu N.
// x0 = 10.3 d: five half-cycles, rest at x_5 = -0.3 d at t = 5 pi/w0.
TEST(ComponentCoulombOscillator, FreeDecayMatchesTheExactSolution) {
  coulomb::Oscillator o;
  o.mass = 2.0;
  o.stiffness = 50.0; // w0 = 5 rad/s
  o.friction_coefficient = 0.15;
  o.normal_force = 10.0;
  const double d = coulomb::friction_limit(o) / o.stiffness;
  o.x0 = 10.3 * d;
  const coulomb::FreeVibration exact(o);
  const double w0 = coulomb::natural_frequency(o);
  ASSERT_EQ(exact.turning_points().size(), 6u);              // x0 at t = 0, then x_1 .. x_5
  const double window = exact.rest_time() + 2.0 * M_PI / w0; // and one period at rest
  for (int tangent : {1, 2}) {
    double first_error = 0.0;
    for (double omega_dt : {0.02, 0.01, 0.005}) {
      const double dt = omega_dt / w0;
      const int steps = static_cast<int>(std::ceil(window / dt));
      const PlaneRun run = run_plane(o, tangent, dt, steps);
      double error = 0.0;
      for (size_t n = 0; n < run.time.size(); ++n)
        error = std::max(error, std::abs(run.y[n] - exact.x(run.time[n])));
      const std::vector<std::pair<int, int>> runs = motion_runs(run);
      // History error budget (test_coulomb_integrator.cpp): each of the 5
      // events may be held one step by the forward-increment law (a zero
      // increment over [t_n, t_n+1]) and shifts the motion that follows by
      // at most dt, an error <= x0 w0 dt (speed <= x0 w0): first order,
      // constant 5 x0 (one x0 per event). Between events: the sampled
      // sinusoid's phase error 2 w0 t (w0 dt)^2/24 on amplitude <= x0, and
      // per switch an amplitude offset <= 5/8 x0 (w0 dt)^2.
      const double bound =
          o.x0 *
          (5.0 * omega_dt + omega_dt * omega_dt * (2.0 * w0 * window / 24.0 + 5.0 * 5.0 / 8.0));
      std::printf("free decay, tangent %d, w0 dt = %.3f: max |y_n - x(t_n)| = %.3e m (bound "
                  "%.3e, x0 = %.3e), %zu motion runs, final y %.12e (exact %.12e), "
                  "|lambda_n - N| %.2e N, cone %.2e N, stick/slip residual %.2e (%.2f of its "
                  "bound), energy %.2e of %.2e J\n",
                  tangent, omega_dt, error, bound, o.x0, runs.size(), run.y.back(),
                  exact.rest_position(), run.max_normal_error, run.worst_cone, run.worst_stick_slip,
                  run.worst_stick_slip_ratio, run.energy_error, run.energy_scale);
      EXPECT_LE(error, bound) << "tangent " << tangent << ", w0 dt " << omega_dt;
      // The motions in order: slip -, +, -, +, - then stick for good (x0 > 0:
      // the spring pulls back first); the one-step turning-point sticks dropped.
      ASSERT_EQ(runs.size(), exact.segments().size())
          << "tangent " << tangent << ", w0 dt " << omega_dt;
      for (size_t i = 0; i < runs.size(); ++i) {
        EXPECT_EQ(runs[i].first, coulomb::direction(exact.segments()[i].motion)) << "run " << i;
        // Event times: within 2 dt (its step and the step that shows it) plus
        // the phase drift 2 t (w0 dt)^2/24.
        const double t_exact = exact.segments()[i].start;
        const double t_run = run.time[runs[i].second - 1];
        EXPECT_LE(std::abs(t_run - t_exact), 2.0 * dt + 2.0 * t_exact * omega_dt * omega_dt / 24.0)
            << "run " << i << ": t = " << t_run << ", exact " << t_exact;
      }
      // The final stick: the last run sticks (exact: for good from t = 5 pi/w0)
      // and holds the node: each stuck step's increment is the stick residual,
      // <= (8 + 128) eps |s~| (expect_certificate), |s~| = dt^2/m |f - k x|
      // <= (w0 dt)^2 2 x0 (|x| <= x0, |f| = k x0 + 0).
      EXPECT_EQ(runs.back().first, 0);
      const int rest = runs.back().second;
      for (size_t n = rest; n < run.y.size(); ++n)
        ASSERT_LE(std::abs(run.y[n] - run.y[rest]),
                  (n - rest) * 136.0 * eps * omega_dt * omega_dt * 2.0 * o.x0)
            << "step " << n << " moved while stuck";
      // The rest position is a turning point, not shifted by the event timing
      // (the speed is zero there): the second-order budget of 5 switches,
      // 5 x 5/8 x0 (w0 dt)^2 (test_coulomb_integrator.cpp).
      const double rest_error = std::abs(run.y.back() - exact.rest_position());
      EXPECT_LE(rest_error, 5.0 * 5.0 / 8.0 * o.x0 * omega_dt * omega_dt)
          << "tangent " << tangent << ", w0 dt " << omega_dt;
      expect_certificate(run, o);
      // The error falls as dt halves: first order in its leading term (event
      // shifts), but each shift is the distance from the event to the next
      // step, which does not shrink monotonically with dt: over two halvings
      // (dt -> dt/4, a factor 4 at first order) we ask at least a factor 2.
      if (omega_dt == 0.02) first_error = error;
      if (omega_dt == 0.005) {
        std::printf("  e(dt) / e(dt/4) = %.2f\n", first_error / error);
        EXPECT_GE(first_error / error, 2.0) << "tangent " << tangent;
      }
    }
  }
}

// ----------------------------------------------------- Den Hartog, forced

// Forced with stops (Den Hartog 1931; ForcedResponse, event by event): from
// rest at x = 0 under P sin(w t), P = 2 mu N, w = 0.6 w0: sticks until
// P sin(w t) = mu N, then slips; stops and sticks again while |F - k x_s|
// <= mu N. Over three forcing periods.
TEST(ComponentCoulombOscillator, DenHartogForcedWithStopsMatchesTheExactSolution) {
  coulomb::Oscillator o;
  o.mass = 2.0;
  o.stiffness = 50.0;
  o.friction_coefficient = 0.15;
  o.normal_force = 10.0;
  o.force_amplitude = 2.0 * coulomb::friction_limit(o);
  const double w0 = coulomb::natural_frequency(o);
  o.forcing_frequency = 0.6 * w0;
  const double window = 3.0 * 2.0 * M_PI / o.forcing_frequency;
  const coulomb::ForcedResponse exact(o, window);
  ASSERT_TRUE(exact.ok()) << exact.failure();
  const coulomb::Transitions tr = exact.transitions();
  int exact_sticks = 0;
  for (const coulomb::Segment& s : exact.segments())
    exact_sticks += s.motion == coulomb::Motion::stick;
  std::printf("exact: %zu segments (%d sticks), %d stick/slip, %d reversals\n",
              exact.segments().size(), exact_sticks, tr.stick_slip, tr.reversals);
  ASSERT_GE(exact_sticks, 2); // the stops the test is about
  double amplitude = 0.0;
  for (double t = 0.0; t <= window; t += 1e-3)
    amplitude = std::max(amplitude, std::abs(exact.x(t)));
  for (int tangent : {2, 1}) {
    double first_error = 0.0;
    for (double omega_dt : {0.02, 0.01, 0.005}) {
      const double dt = omega_dt / w0;
      const int steps = static_cast<int>(std::floor(window / dt));
      const PlaneRun run = run_plane(o, tangent, dt, steps);
      double error = 0.0;
      for (size_t n = 0; n < run.time.size(); ++n)
        error = std::max(error,
                         std::abs(run.y[n] - exact.x(std::min(run.time[n], exact.solved_until()))));
      const std::vector<std::pair<int, int>> runs = motion_runs(run);
      // Budget as the free decay (test_coulomb_integrator.cpp), with the
      // amplitude A = max |x| + P/k + d (homogeneous, forced and friction
      // parts), the frequency w0 >= w, and per exact segment boundary one
      // event shift <= dt (A w0 dt: first order, constant n_events A) and one
      // switch offset 5/8 A (w0 dt)^2.
      const double big_a =
          amplitude + o.force_amplitude / o.stiffness + coulomb::friction_limit(o) / o.stiffness;
      const double n_events = static_cast<double>(exact.segments().size());
      const double bound =
          big_a * (n_events * omega_dt +
                   omega_dt * omega_dt * (2.0 * w0 * window / 24.0 + 5.0 / 8.0 * n_events));
      std::printf("forced, tangent %d, w0 dt = %.3f: max |y_n - x(t_n)| = %.3e m (bound %.3e, "
                  "max |x| %.3e), %zu motion runs (exact %zu), |lambda_n - N| %.2e N, cone "
                  "%.2e N, stick/slip residual %.2e (%.2f of its bound), energy %.2e of %.2e J\n",
                  tangent, omega_dt, error, bound, amplitude, runs.size(), exact.segments().size(),
                  run.max_normal_error, run.worst_cone, run.worst_stick_slip,
                  run.worst_stick_slip_ratio, run.energy_error, run.energy_scale);
      EXPECT_LE(error, bound) << "tangent " << tangent << ", w0 dt " << omega_dt;
      ASSERT_EQ(runs.size(), exact.segments().size())
          << "tangent " << tangent << ", w0 dt " << omega_dt;
      for (size_t i = 0; i < runs.size(); ++i) {
        const coulomb::Segment& s = exact.segments()[i];
        EXPECT_EQ(runs[i].first, coulomb::direction(s.motion)) << "run " << i;
        // Event times: each earlier event shifts by <= dt, this one is seen
        // within 2 dt, plus the phase drift (test_coulomb_integrator.cpp).
        const double slack = (2.0 + i) * dt + 2.0 * s.start * omega_dt * omega_dt / 24.0;
        const double t_run = run.time[runs[i].second - 1];
        EXPECT_LE(std::abs(t_run - s.start), slack)
            << "run " << i << ": t = " << t_run << ", exact " << s.start;
        if (s.motion != coulomb::Motion::stick) continue;
        // A stick interval [start, end]: its end within the same slack (the
        // next event's), the node held over it (each step's increment the
        // stick residual, <= 136 eps |s~|, |s~| = dt^2/m |F - k x| <=
        // (w0 dt)^2 A: free decay), at the exact stick position x_s to the
        // history budget.
        const int first = runs[i].second;
        const int last = i + 1 < runs.size() ? runs[i + 1].second - 1 : steps;
        const double t_end = run.time[last];
        const double end_slack = (3.0 + i) * dt + 2.0 * s.end * omega_dt * omega_dt / 24.0;
        if (i + 1 < runs.size()) {
          EXPECT_LE(std::abs(t_end - s.end), end_slack)
              << "stick " << i << " ends at " << t_end << ", exact " << s.end;
        }
        for (int n = first; n <= last; ++n)
          ASSERT_LE(std::abs(run.y[n] - run.y[first]),
                    (n - first) * 136.0 * eps * omega_dt * omega_dt * big_a)
              << "stick " << i << ": step " << n << " moved";
        EXPECT_LE(std::abs(run.y[first] - s.x_start), bound)
            << "stick " << i << " at " << run.y[first] << ", exact " << s.x_start;
      }
      expect_certificate(run, o);
      // Falls as dt halves (free decay: a factor 2 over dt -> dt/4).
      if (omega_dt == 0.02) first_error = error;
      if (omega_dt == 0.005) {
        std::printf("  e(dt) / e(dt/4) = %.2f\n", first_error / error);
        EXPECT_GE(first_error / error, 2.0) << "tangent " << tangent;
      }
    }
  }
}

// ------------------------------------------------------------------ the force

// Without a force every history is the one of before (the header: the force
// terms are skipped); with a force of zeros the same arithmetic gives the same
// numbers up to the added zeros, which change nothing (x + 0 = x exactly):
// the two runs are bitwise equal.
TEST(ComponentCoulombOscillator, ZeroForceIsNoForce) {
  coulomb::Oscillator o;
  o.mass = 2.0;
  o.stiffness = 50.0;
  const ReducedBasis basis = node_model(o, 2);
  const RigidCasing casing({Eigen::Vector3d(kR, 0.0, 0.0)}, {{0, 1, 2}},
                           {CasingGapKind::linear, 1e-3, 1e-2, 0.15}, 3.0);
  ComponentIntegratorOptions a;
  a.dt = 1e-3;
  a.mu = 0.15;
  ComponentIntegratorOptions b = a;
  b.force_constant = Eigen::VectorXd::Zero(3);
  b.force_harmonic = Eigen::VectorXd::Zero(3);
  b.force_frequency = 3.0;
  ComponentIntegrator ia(basis, casing, a), ib(basis, casing, b);
  EXPECT_FALSE(ia.has_external_force());
  EXPECT_TRUE(ib.has_external_force());
  Eigen::VectorXd q0(3);
  q0 << 0.0, 1e-3, -2e-3;
  ia.start(q0);
  ib.start(q0);
  long contact_steps = 0;
  for (int n = 0; n < 400; ++n) {
    contact_steps += ia.step().n_active;
    ib.step();
    ASSERT_EQ(ia.q(), ib.q()) << "step " << n;
    ASSERT_EQ(ia.lambda(), ib.lambda()) << "step " << n;
  }
  EXPECT_GT(contact_steps, 0); // the casing closes within the run (g0/v = 0.1 s)
  EXPECT_EQ(ib.external_work(), 0.0);
}

// A constant load on a MacNeal model enters the static balance (B): with the
// contact open, the structure under a load f applied at t = 0 oscillates
// about the static solution K^-1 f (condensed), and the energy identity
// with W_ext closes. Model: ground -- k -- I (mass m) -- k_c -- B (mass
// eps m), per direction (test_component_integrator.cpp's chain), MacNeal-3
// of eps = 1e-8; a load F along +y on B (the gap, g0 = 1 m, stays open).
// Exact (massless B): B's balance k_c (u_B - q) = F, and m q'' + k q = F
// from rest at 0: q = (F/k)(1 - cos(w t)), w = sqrt(k/m); u_B = q + F/k_c.
// Central differences from rest reproduce (F/k)(1 - cos(w_d t_n)),
// w_d = w (1 + (w dt)^2/24 + ...): error <= (F/k) w t (w dt)^2/24 (1 + (w dt)^2),
// plus the eps = 1e-8 model's O(eps) difference (1e-6 of F/k, generous).
TEST(ComponentCoulombOscillator, MacNealLoadEntersTheStaticBalance) {
  const double m = 1.0, k = 1.0, kc = 0.5, f = 2.0, dt = 0.05, end = 20.0;
  std::vector<Eigen::Triplet<double>> kt, mt;
  for (int a = 0; a < 3; ++a) {
    kt.emplace_back(a, a, kc);
    kt.emplace_back(a, 3 + a, -kc);
    kt.emplace_back(3 + a, a, -kc);
    kt.emplace_back(3 + a, 3 + a, kc + k);
    mt.emplace_back(a, a, 1e-8 * m);
    mt.emplace_back(3 + a, 3 + a, m);
  }
  Eigen::SparseMatrix<double> ks(6, 6), ms(6, 6);
  ks.setFromTriplets(kt.begin(), kt.end());
  ms.setFromTriplets(mt.begin(), mt.end());
  const ReducedBasis basis = reduce(ks, ms, {0, 1, 2}, "macneal", 3);
  ASSERT_TRUE(basis.massless_boundary);
  const RigidCasing casing({Eigen::Vector3d(1.0, 0.0, 0.0)}, {{0, 1, 2}},
                           {CasingGapKind::constant, 1.0, 0.0, 0.15}, 0.0);
  ComponentIntegratorOptions o;
  o.dt = dt;
  o.mu = 0.15;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(6);
  load(1) = f; // B, uy
  o.force_constant = basis.transformation.transpose() * load;
  ComponentIntegrator integrator(basis, casing, o);
  ComponentRunOptions ro;
  ro.steps = static_cast<int>(std::lround(end / dt));
  ComponentHistory hq, hb;
  const ComponentRunSummary s = run_component(integrator, basis.transformation.row(4), ro, hq);
  integrator.start();
  run_component(integrator, basis.transformation.row(1), ro, hb, true);
  ASSERT_TRUE(s.completed) << s.status;
  const double w = std::sqrt(k / m), wdt = w * dt;
  double eq = 0.0, eb = 0.0;
  for (int n = 0; n < hq.n_rows(); ++n) {
    const double t = hq.time[n], q = f / k * (1.0 - std::cos(w * t));
    eq = std::max(eq, std::abs(hq.response[n] - q));
    eb = std::max(eb, std::abs(hb.response[n] - (q + f / kc)));
  }
  const double bound = f / k * (w * end * wdt * wdt / 24.0 * (1.0 + wdt * wdt) + 1e-6);
  std::printf("MacNeal-3 under a load: |q err| %.3e, |u_B err| %.3e (bound %.3e); W_ext %.6e, "
              "balance %.2e of %.2e, contact-steps %ld\n",
              eq, eb, bound, s.final_external_work, s.energy_balance_error, s.energy_scale,
              s.stick_contact_steps + s.slip_contact_steps);
  EXPECT_LE(eq, bound); // the exact solution above
  EXPECT_LE(eb, bound); // u_B = q + F/k_c: the load in (B)
  EXPECT_EQ(s.stick_contact_steps + s.slip_contact_steps, 0);
  // W_ext > 0 (the load does work); the identity's round-off: steps r eps of the scale.
  EXPECT_GT(s.final_external_work, 0.0);
  EXPECT_LE(s.energy_balance_error, ro.steps * 6 * eps * s.energy_scale);
  EXPECT_EQ(hq.external_work.size(), hq.time.size());
}

TEST(ComponentCoulombOscillator, RefusesABadForce) {
  coulomb::Oscillator o;
  const ReducedBasis basis = node_model(o, 2);
  ComponentIntegratorOptions options;
  options.dt = 1e-3;
  options.force_constant = Eigen::VectorXd::Zero(2);
  try {
    ComponentIntegrator bad(basis, pressed_plane(), options);
    ADD_FAILURE() << "a force of 2 entries on a 3-coordinate basis was taken";
  } catch (const std::invalid_argument& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("force_constant"), std::string::npos) << e.what();
  }
  options.force_constant = Eigen::VectorXd::Zero(3);
  options.force_harmonic = Eigen::VectorXd::Constant(3, std::nan(""));
  EXPECT_THROW(ComponentIntegrator(basis, pressed_plane(), options), std::invalid_argument);
  options.force_harmonic = Eigen::VectorXd::Zero(3);
  options.force_frequency = std::numeric_limits<double>::infinity();
  EXPECT_THROW(ComponentIntegrator(basis, pressed_plane(), options), std::invalid_argument);
}

} // namespace
} // namespace rsi
