// Damping (issue 12 item 3, SPEC §8): Rayleigh damping in the reference
// integrator, modal damping in the reduced one, both with the centred
// velocity (central_difference.hpp, reduced_integrator.hpp).
//
// Single-mode tests. For a mode of circular frequency omega and ratio zeta,
// y'' + 2 zeta omega y' + omega^2 y = 0 from y = 1 at rest has the exact
// solution y(t) = e^{-sigma t} (cos omega_d t + b sin omega_d t),
// sigma = zeta omega, omega_d = omega sqrt(1 - zeta^2), b = zeta / sqrt(1 - zeta^2).
// The scheme advances (1 + zeta w) y_{n+1} = (2 - w^2) y_n - (1 - zeta w) y_{n-1},
// w = omega dt, from y_0 = 1, y_{-1} = 1 - w^2/2 (the start at rest of both
// integrators): y_n = c1 z1^n + c2 z2^n with z1, z2 the roots of
// (1 + zeta w) z^2 - (2 - w^2) z + (1 - zeta w) = 0. Each test checks the
// integrator against that closed form (round-off bound below) and against
// the exact solution (the closed form's distance to it, bounded from the
// roots: the scheme's amplitude and phase errors, plus the round-off).
//
// Round-off bound: each step rounds the few operations that form a
// coordinate (2 u_n - u_{n-1} + dt^2 A^-1 r), at most c eps |y|max with
// c = 8 in the mode's M-norm; an error injected at step k reaches step n
// multiplied by the recursion's Green function g_{n-k},
// g_j = (z1^{j+1} - z2^{j+1}) / (z1 - z2), so after n steps the error is
// at most c eps |y|max sum_{j<=n} |g_j| (computed below).

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "central_difference.hpp"
#include "critical_step.hpp"
#include "modal_analysis.hpp"
#include "modal_damping.hpp"
#include "reduced_contact.hpp"
#include "reduced_integrator.hpp"
#include "reduced_run.hpp"
#include "reduction.hpp"
#include "reference_run.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double roundoff_per_step = 8.0; // c of the file comment

Case default_case() {
  return load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
}

/// The free structure: no constraint.
class NoContact : public ContactLaw {
public:
  int n_constraints() const override { return 0; }
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>&, const Eigen::Ref<const Eigen::VectorXd>&,
                double, ContactState& state) const override {
    state.gap.resize(0);
    state.sliding_velocity.resize(0);
    state.friction_sign.resize(0);
    state.gradient.clear();
    state.direction.clear();
  }
  double friction_coefficient() const override { return 0.0; }
  std::vector<int> dofs_read(int) const override { return {}; }
};

/// e^{-sigma t} (cos omega t + b sin omega t).
struct Oscillation {
  double sigma, omega, b;
};

/// |p(t) - q(t)| <= this for two oscillations, by the mean value theorem:
///   |e^{-s1 t} - e^{-s2 t}| <= |s1 - s2| t e^{-min(s1, s2) t},
///   |cos w1 t - cos w2 t|, |sin w1 t - sin w2 t| <= |w1 - w2| t, so
///   |p - q| <= |s1 - s2| t e^{-min t} (1 + |b1|) + e^{-s2 t} ((1 + |b2|) |w1 - w2| t + |b1 - b2|).
double distance_bound(const Oscillation& p, const Oscillation& q, double t) {
  return std::abs(p.sigma - q.sigma) * t * std::exp(-std::min(p.sigma, q.sigma) * t) *
             (1.0 + std::abs(p.b)) +
         std::exp(-q.sigma * t) *
             ((1.0 + std::abs(q.b)) * std::abs(p.omega - q.omega) * t + std::abs(p.b - q.b));
}

/// One damped mode: the exact solution and the scheme's closed form (file comment).
struct DampedMode {
  double omega, zeta, dt;
  std::complex<double> z1, z2, c1, c2;

  DampedMode(double omega_, double zeta_, double dt_)
      : omega(omega_)
      , zeta(zeta_)
      , dt(dt_) {
    const double w = omega * dt;
    const double a2 = 1.0 + zeta * w, a1 = -(2.0 - w * w), a0 = 1.0 - zeta * w;
    const std::complex<double> root = std::sqrt(std::complex<double>(a1 * a1 - 4.0 * a2 * a0));
    z1 = (-a1 + root) / (2.0 * a2); // Im z1 >= 0 for a complex pair
    z2 = (-a1 - root) / (2.0 * a2);
    // c1 + c2 = y_0 = 1, c1 / z1 + c2 / z2 = y_{-1} = 1 - w^2/2.
    const double y_minus = 1.0 - 0.5 * w * w;
    c2 = (y_minus - 1.0 / z1) / (1.0 / z2 - 1.0 / z1);
    c1 = 1.0 - c2;
  }
  double sigma() const { return zeta * omega; }
  double omega_d() const { return omega * std::sqrt(1.0 - zeta * zeta); }
  double b() const { return zeta / std::sqrt(1.0 - zeta * zeta); }
  double exact(double t) const {
    return std::exp(-sigma() * t) * (std::cos(omega_d() * t) + b() * std::sin(omega_d() * t));
  }
  double discrete(int n) const { return (c1 * std::pow(z1, n) + c2 * std::pow(z2, n)).real(); }
  /// |discrete(n)| <= |c1| + |c2| (both roots in the unit disc).
  double y_max() const { return std::abs(c1) + std::abs(c2); }
  /// sum_{j=0}^{n} |g_j|, the Green function of the recursion.
  double green_sum(int n) const {
    double sum = 0.0;
    for (int j = 0; j <= n; ++j)
      sum += std::abs((std::pow(z1, j + 1) - std::pow(z2, j + 1)) / (z1 - z2));
    return sum;
  }
  /// The closed form as e^{-sigma_h t} (cos omega_h t + b_h sin omega_h t)
  /// for a complex pair z1 = r e^{i theta}: sigma_h = -ln r / dt,
  /// omega_h = theta / dt, b_h = -2 Im c1 (Re c1 = 1/2).
  Oscillation scheme() const {
    return {-std::log(std::abs(z1)) / dt, std::arg(z1) / dt, -2.0 * c1.imag()};
  }
  Oscillation continuous() const { return {sigma(), omega_d(), b()}; }
  /// |discrete(n) - exact(n dt)| <= this: the scheme's amplitude and phase errors.
  double discretization_bound(int n) const {
    return distance_bound(scheme(), continuous(), n * dt);
  }
};

/// |phi|^T |M| |u|: the scale of the rounding of phi^T M u (Higham eq. 3.5:
/// a dot product of m terms errs by at most m eps times the sum of |terms|).
double abs_product(const Eigen::VectorXd& phi, const Eigen::SparseMatrix<double>& m,
                   const Eigen::VectorXd& u) {
  const Eigen::SparseMatrix<double> abs_m = m.cwiseAbs();
  return phi.cwiseAbs().dot(abs_m * u.cwiseAbs());
}

/// A step response of one mode: under F = M phi held from t = 0 (phi
/// mass-normalised: modal force 1, no other mode forced since
/// phi_j^T M phi = delta_j) the modal coordinate is x = x_s (1 - y) with
/// x_s = 1 / omega^2 and y the single-mode solution. `advance` takes one
/// step and returns the displacement u of the part; x = phi^T M u is checked
/// against the closed form and (when `exact`: a complex pair of roots) the
/// exact solution every `every` steps.
void check_step_response(const DampedMode& mode, const Eigen::VectorXd& phi,
                         const Eigen::SparseMatrix<double>& mass, int steps, int every, bool exact,
                         const std::function<const Eigen::VectorXd&()>& advance) {
  const double x_s = 1.0 / (mode.omega * mode.omega);
  const int n_terms = static_cast<int>(mass.rows()) + 64; // a dot product and a row of M
  double worst_scheme = 0.0, worst_exact = 0.0, worst_scheme_bound = 0.0, worst_exact_bound = 0.0;
  for (int n = 1; n <= steps; ++n) {
    const Eigen::VectorXd& u = advance();
    if (n % every != 0 && n != steps) continue;
    const double x = phi.dot(mass * u);
    // |x| / x_s = |1 - y| <= 1 + y_max; the projection phi^T M u rounds
    // within n_terms eps |phi|^T |M| |u| (Higham eq. 3.5).
    const double roundoff = roundoff_per_step * eps * (1.0 + mode.y_max()) * mode.green_sum(n) +
                            n_terms * eps * abs_product(phi, mass, u) / x_s;
    const double scheme_error = std::abs(x / x_s - (1.0 - mode.discrete(n)));
    const double exact_error = std::abs(x / x_s - (1.0 - mode.exact(n * mode.dt)));
    const double exact_bound = mode.discretization_bound(n) + roundoff;
    worst_scheme = std::max(worst_scheme, scheme_error);
    worst_exact = std::max(worst_exact, exact_error);
    worst_scheme_bound = std::max(worst_scheme_bound, roundoff);
    worst_exact_bound = std::max(worst_exact_bound, exact_bound);
    // The scheme's closed form: round-off only (file comment).
    EXPECT_LE(scheme_error, roundoff) << "step " << n;
    // The exact exp(-zeta omega t) solution: the scheme's amplitude and phase
    // errors (DampedMode::discretization_bound) plus the round-off.
    if (exact) {
      EXPECT_LE(exact_error, exact_bound) << "step " << n;
    }
  }
  std::printf("omega %.6g rad/s, zeta %.4g, omega dt %.3g, %d steps: |x - scheme| / x_s max %.3e "
              "(bound %.3e), |x - exact| / x_s max %.3e (bound %.3e)%s; envelope at the end "
              "%.4f\n",
              mode.omega, mode.zeta, mode.omega * mode.dt, steps, worst_scheme, worst_scheme_bound,
              worst_exact, worst_exact_bound, exact ? "" : " (exact not asserted)",
              std::exp(-mode.sigma() * steps * mode.dt));
}

/// The reference integrator on the bladed disk alone (no contact), Rayleigh
/// damped, under F = M phi: check_step_response.
void reference_step_response(const BladedDisk& bd, const Eigen::VectorXd& phi, double omega,
                             const RayleighDamping& damping, double dt, int steps, int every,
                             bool exact) {
  const double zeta = damping.alpha / (2.0 * omega) + damping.beta * omega / 2.0;
  const NoContact law;
  CentralDifference cd(bd.stiffness, bd.mass, dt, law, damping);
  cd.start(bd.mass * phi);
  check_step_response(DampedMode(omega, zeta, dt), phi, bd.mass, steps, every, exact,
                      [&]() -> const Eigen::VectorXd& {
                        cd.step();
                        return cd.displacement();
                      });
}

TEST(Damping, ReferenceRayleighDecayOfTheFirstMode) {
  const Case c = default_case();
  const BladedDisk bd = assemble_bladed_disk(c);
  const Modes modes = lowest_modes(bd.stiffness, bd.mass, 1);
  const double omega = std::sqrt(modes.omega_squared(0));
  // zeta_1 = 2 %, half from alpha (alpha / (2 omega)), half from beta (beta omega / 2).
  const double zeta = 0.02;
  const RayleighDamping damping{zeta * omega, zeta / omega};
  // The largest stable step of the bladed disk (0.9 of 2 / omega_max): the
  // highest modes get zeta = beta omega_max / 2 >> 1 there, stable with the
  // centred damping, not with a lagged one.
  const double dt = 0.9 * 2.0 / modes.omega_max;
  const int steps = static_cast<int>(3.0 * 2.0 * M_PI / omega / dt); // three periods
  reference_step_response(bd, modes.shapes.col(0), omega, damping, dt, steps, 97, true);
}

TEST(Damping, ReferenceCentredDampingIsStableAtTheUndampedLimit) {
  // The highest mode at omega_max dt = 1.9, zeta = 0.5 (beta = 1 / omega_max):
  // the centred scheme's roots (central_difference.hpp) are inside the unit
  // circle for every omega dt < 2; a lagged velocity would need
  // omega dt < 2 (sqrt(1 + zeta^2) - zeta) = 1.236 and grow here.
  const Case c = default_case();
  const BladedDisk bd = assemble_bladed_disk(c);
  const Modes modes = lowest_modes(bd.stiffness, bd.mass, bd.n_dofs(), ModalSolver::dense);
  const int top = modes.n_modes() - 1;
  const double omega = std::sqrt(modes.omega_squared(top));
  const double dt = 1.9 / omega;
  const RayleighDamping damping{0.0, 1.0 / omega};
  const DampedMode mode(omega, 0.5, dt);
  std::printf("roots of the centred scheme: |z1| = %.4f, |z2| = %.4f\n", std::abs(mode.z1),
              std::abs(mode.z2));
  // Both roots inside the unit circle (the claim of central_difference.hpp).
  ASSERT_LT(std::max(std::abs(mode.z1), std::abs(mode.z2)), 1.0);
  // Real roots here (overdamped in the scheme): the closed form only.
  reference_step_response(bd, modes.shapes.col(top), omega, damping, dt, 400, 1, false);
}

TEST(Damping, ReducedModalDecayOfAFreeInterfaceMode) {
  // CCM-10: the kept free mode i lies in the basis at q_i = M^-1 e_j, j = n_B + i
  // (modal_damping.hpp: M^ q_i = e_j), a mode of (K^, M^, C^) with ratio zeta,
  // exact up to the basis' own accuracy (residual rho below). From q_0 = a q_i
  // at rest, y = q_i^T M^ q / (a q_i^T M^ q_i) follows the single mode with
  // the Rayleigh quotients omega_q^2 = q_i^T K^ q_i / q_i^T M^ q_i and
  // 2 zeta_q omega_q = q_i^T C^ q_i / q_i^T M^ q_i; the parts of q_i off the
  // exact mode (relative size rho) are M^-orthogonal to it up to rho and
  // enter y at O(rho^2).
  const Case c = default_case();
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  const ReducedBasis basis = reduce_bladed_disk(bd, "ccm", 10);
  const int nb = static_cast<int>(basis.boundary_position.size());
  const int i = 0;
  const int j = nb + i; // CCM's q = (q_B, u_1)
  const Eigen::VectorXd q_i = basis.mass.llt().solve(Eigen::VectorXd::Unit(basis.n_reduced(), j));
  const double omega = basis.mode_omega(i);
  const double zeta = 0.02;
  ReducedDamping damping;
  damping.bladed_disk = modal_damping(basis, zeta);
  // C^ = 2 zeta omega_i on mode i's coordinate j = n_B + i (modal_damping.hpp).
  EXPECT_EQ(damping.bladed_disk(j), 2.0 * zeta * omega);
  const double mass = q_i.dot(basis.mass * q_i);
  const double omega_q = std::sqrt(q_i.dot(basis.stiffness * q_i) / mass);
  const double zeta_q = q_i.dot(damping.bladed_disk.cwiseProduct(q_i)) / mass / (2.0 * omega_q);
  const double rho = (basis.stiffness * q_i - omega_q * omega_q * basis.mass * q_i).norm() /
                     (omega_q * omega_q * (basis.mass * q_i).norm());
  std::printf("CCM-10 mode 1: omega %.9g rad/s, residual rho %.3e, omega_q / omega - 1 = %.3e, "
              "zeta_q / zeta - 1 = %.3e\n",
              omega, rho, omega_q / omega - 1.0, zeta_q / zeta - 1.0);

  const ReducedTipContact contact(basis, casing, c);
  // The reduced model's own largest stable step, 0.9 of 2 / omega_max: omega dt = 0.05 on mode 1.
  const double dt = 0.9 * 2.0 / reduced_omega_max(basis);
  ReducedIntegrator integrator(basis, casing, dt, contact, damping);
  // a: 1e-6 m of physical displacement at most keeps every tip far from the
  // 1 mm clearance (checked: no contact below).
  const double a = 1e-6 / basis.transformation.cwiseAbs().maxCoeff() / q_i.cwiseAbs().maxCoeff();
  integrator.start(Eigen::VectorXd::Zero(casing.n_dofs()), a * q_i);
  const DampedMode mode(omega_q, zeta_q, dt); // the reduced model's mode
  const DampedMode nominal(omega, zeta, dt);  // what the case file asks for
  const int steps = static_cast<int>(3.0 * 2.0 * M_PI / omega / dt);
  double worst_scheme = 0.0, worst_exact = 0.0, bound_scheme = 0.0, bound_exact = 0.0;
  for (int n = 1; n <= steps; ++n) {
    const StepReport r = integrator.step();
    ASSERT_EQ(r.n_active, 0) << "step " << n;
    const double y = q_i.dot(basis.mass * integrator.q()) / (a * mass);
    // Round-off of the recursion and of the projection (r terms), the O(rho^2) rest.
    const double roundoff = roundoff_per_step * eps * mode.y_max() * mode.green_sum(n) +
                            basis.n_reduced() * eps * mode.y_max() + rho * rho;
    // exp(-zeta omega t) as asked: the scheme's amplitude and phase errors, the
    // distance from the reduced mode to the nominal one, and the above.
    const double exact_bound = mode.discretization_bound(n) +
                               distance_bound(mode.continuous(), nominal.continuous(), n * dt) +
                               roundoff;
    const double scheme_error = std::abs(y - mode.discrete(n));
    const double exact_error = std::abs(y - nominal.exact(n * dt));
    worst_scheme = std::max(worst_scheme, scheme_error);
    worst_exact = std::max(worst_exact, exact_error);
    bound_scheme = std::max(bound_scheme, roundoff);
    bound_exact = std::max(bound_exact, exact_bound);
    EXPECT_LE(scheme_error, roundoff) << "step " << n;
    EXPECT_LE(exact_error, exact_bound) << "step " << n;
  }
  std::printf("omega dt %.3g, %d steps: |y - scheme| max %.3e (bound %.3e), |y - exact| max %.3e "
              "(bound %.3e); envelope at the end %.4f\n",
              omega * dt, steps, worst_scheme, bound_scheme, worst_exact, bound_exact,
              std::exp(-zeta * omega * steps * dt));
  // The damping took out the energy lost: E_0 - E = W_damp (balance, no
  // force, no contact), to round-off: each step carries eps |q| / |q_{n+1} - q_n|
  // = eps / (omega dt) of the energy, over `steps` steps.
  const double e0 = integrator.initial_energy();
  const double balance = std::abs(e0 - integrator.energy() - integrator.damping_work());
  std::printf("E_0 %.6e J, E %.6e J, W_damp %.6e J, |E_0 - E - W_damp| = %.3e J (bound %.3e J)\n",
              e0, integrator.energy(), integrator.damping_work(), balance,
              steps * eps / (omega * dt) * e0);
  EXPECT_LE(balance, steps * eps / (omega * dt) * e0);
}

TEST(Damping, ReducedCasingRayleighStepResponse) {
  // The reduced integrator's casing (full, Rayleigh damped): a step force
  // M_c phi on one casing mode, the bladed disk (Guyan) at rest, no contact.
  const Case c = default_case();
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  const ReducedBasis basis = reduce_bladed_disk(bd, "guyan", 0);
  const Modes modes =
      lowest_modes(casing.stiffness, casing.mass, casing.n_dofs(), ModalSolver::dense);
  const double dt = 0.9 * 2.0 / std::max(modes.omega_max, reduced_omega_max(basis));
  // The casing mode nearest omega dt = 0.2: the scheme's errors are visible.
  int k = 0;
  for (int i = 0; i < modes.n_modes(); ++i)
    if (std::abs(std::sqrt(modes.omega_squared(i)) * dt - 0.2) <
        std::abs(std::sqrt(modes.omega_squared(k)) * dt - 0.2))
      k = i;
  const double omega = std::sqrt(modes.omega_squared(k));
  const double zeta = 0.02; // half from alpha, half from beta
  ReducedDamping damping;
  damping.casing = {zeta * omega, zeta / omega};
  const ReducedTipContact contact(basis, casing, c);
  ReducedIntegrator integrator(basis, casing, dt, contact, damping);
  // F = s M_c phi: static deflection s / omega^2 |phi|max = 1e-6 m, far
  // inside the 1 mm clearance (checked: no contact).
  const Eigen::VectorXd phi = modes.shapes.col(k);
  const double s = 1e-6 * omega * omega / phi.cwiseAbs().maxCoeff();
  integrator.start(s * (casing.mass * phi));
  Eigen::VectorXd u;
  check_step_response(DampedMode(omega, zeta, dt), phi, casing.mass,
                      static_cast<int>(3.0 * 2.0 * M_PI / omega / dt), 1, true,
                      [&]() -> const Eigen::VectorXd& {
                        const StepReport r = integrator.step();
                        EXPECT_EQ(r.n_active, 0);
                        u = integrator.casing() / s;
                        return u;
                      });
}

/// Keys present but zero: every history entry identical to keys absent.
void expect_same_history(const History& a, const History& b) {
  ASSERT_EQ(a.n_rows(), b.n_rows());
  int differences = 0;
  for (int i = 0; i < a.n_rows(); ++i) {
    differences += a.time[i] != b.time[i] || a.gap[i] != b.gap[i] || a.lambda[i] != b.lambda[i] ||
                   a.energy[i] != b.energy[i] || a.external_work[i] != b.external_work[i] ||
                   a.contact_work[i] != b.contact_work[i] || b.damping_work[i] != 0.0;
  }
  std::printf("%d rows, %d differ\n", a.n_rows(), differences);
  EXPECT_EQ(differences, 0);
}

Case with_damping(const std::string& damping_json, double duration) {
  nlohmann::json d = nlohmann::json::parse(
      std::ifstream(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json"));
  d["damping"] = nlohmann::json::parse(damping_json);
  d["time"]["duration"] = duration;
  return parse_case(d, "test_damping");
}

TEST(Damping, ZeroDampingIsTheUndampedRunBitForBit) {
  Case absent = default_case();
  absent.time.duration = 0.005; // contact from 3.96 ms: the contact solver runs
  const Case zero =
      with_damping(R"({"rayleigh": {"alpha": 0, "beta": 0}, "modal_ratio": 0})", 0.005);
  EXPECT_FALSE(zero.damping.rayleigh.any());
  const RunResult full_absent = run_reference(absent, {});
  const RunResult full_zero = run_reference(zero, {});
  ASSERT_GT(full_absent.summary.first_contact_step, 0);
  expect_same_history(full_absent.history, full_zero.history);
  ReducedRunOptions options;
  const RunResult cb_absent = run_reduced(absent, "cb", 10, options).run;
  const RunResult cb_zero = run_reduced(zero, "cb", 10, options).run;
  expect_same_history(cb_absent.history, cb_zero.history);
}

/// The energy balance of a damped contact run, and W_damp > 0.
void expect_balance(const RunSummary& s) {
  std::printf("%s: %s, %d steps; W_ext %.6e J, W_contact %.6e J, W_damp %.6e J, balance error "
              "%.3e J (scale %.3e J)\n",
              s.method.c_str(), s.status.c_str(), s.steps, s.final_external_work,
              s.final_contact_work, s.final_damping_work, s.energy_balance_error, s.energy_scale);
  EXPECT_TRUE(s.completed);
  EXPECT_GT(s.final_damping_work, 0.0);
  // E = E0 + W_ext + W_contact - W_damp is an identity of the scheme
  // (central_difference.hpp); round-off over 4e4 steps, each carrying
  // eps |u| / |u_{n+1} - u_n| (~1e3 here) relative: 4e4 * 2.2e-16 * 1e3 = 1e-8
  // of the energy scale (the undamped bound of test_reference_contact).
  EXPECT_LE(s.energy_balance_error, 1e-8 * s.energy_scale);
}

TEST(Damping, EnergyBalanceClosesWithDamping) {
  const Case c =
      with_damping(R"({"rayleigh": {"alpha": 30, "beta": 2e-6}, "modal_ratio": 0.02})", 0.02);
  expect_balance(run_reference(c, {}).summary);
  ReducedRunOptions options;
  expect_balance(run_reduced(c, "cb", 10, options).run.summary);
  expect_balance(run_reduced(c, "ccm", 10, options).run.summary);
}

TEST(Damping, ModalDampingMatrix) {
  const Case c = default_case();
  const BladedDisk bd = assemble_bladed_disk(c);
  const ReducedBasis cb = reduce_bladed_disk(bd, "cb", 5);
  const Eigen::VectorXd d = modal_damping(cb, 0.01);
  // CB: 2 zeta omega_i on u_eta (q = (u_eta, q_B)), omega_i^2 = K^_ii = phi_i^T K phi_i
  // (M^_etaeta = I). K^_ii rounds within n eps |T_i|^T |K| |T_i| (Higham eq. 3.5,
  // n = 682 terms), and sqrt halves a relative error.
  for (int i = 0; i < 5; ++i) {
    const Eigen::VectorXd t = cb.transformation.col(i);
    const double rounding =
        bd.n_dofs() * eps * abs_product(t, bd.stiffness, t) / cb.stiffness(i, i);
    const double error = std::abs(d(i) / (0.02 * std::sqrt(cb.stiffness(i, i))) - 1.0);
    std::printf("CB mode %d: |C^_ii / (2 zeta sqrt(K^_ii)) - 1| = %.3e (bound %.3e)\n", i, error,
                0.5 * rounding + 2 * eps);
    EXPECT_LE(error, 0.5 * rounding + 2 * eps) << i;
  }
  // None on the boundary coordinates.
  for (int b : cb.boundary_position)
    EXPECT_EQ(d(b), 0.0);
  const ReducedBasis guyan = reduce_bladed_disk(bd, "guyan", 0);
  EXPECT_EQ(modal_damping(guyan, 0.01).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(modal_damping(cb, 1.0), std::invalid_argument);
  EXPECT_THROW(modal_damping(cb, -0.1), std::invalid_argument);
}

TEST(Damping, CaseFileKeys) {
  const Case c = with_damping(
      R"({"rayleigh": {"alpha": 1.5, "beta": 2e-6}, "modal_ratio": 0.01, "note": "why"})", 0.02);
  EXPECT_EQ(c.damping.rayleigh.alpha, 1.5);
  EXPECT_EQ(c.damping.rayleigh.beta, 2e-6);
  EXPECT_EQ(c.damping.modal_ratio, 0.01);
  const Case only_ratio = with_damping(R"({"modal_ratio": 0.005})", 0.02);
  EXPECT_FALSE(only_ratio.damping.rayleigh.any());
  for (const char* bad :
       {R"({"rayleigh": {"alpha": -1, "beta": 0}})", R"({"rayleigh": {"alpha": 0, "beta": -1e-9}})",
        R"({"modal_ratio": 1})", R"({"modal_ratio": -0.5})", R"({"rayleigh": {"alpha": 1}})",
        R"({"ratio": 0.01})"}) {
    try {
      with_damping(bad, 0.02);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const CaseError& e) {
      std::printf("%s -> %s\n", bad, e.what());
      EXPECT_NE(std::string(e.what()).find("damping"), std::string::npos);
    }
  }
}

} // namespace
} // namespace rsi
