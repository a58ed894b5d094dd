#pragma once
// Central differences with forward-increment Lagrange multipliers for ONE
// reduced component rubbing on a rigid casing (issue 12 items 1 and 4; SPEC
// §3, §8), with Coulomb stick/slip solved by CoulombGaussSeidel. Written
// apart from the reference integrator and from reduced_integrator (which
// couples the 2D bladed disk to a full casing).
//
// Model. q = the reduced coordinates of a ReducedBasis (CB, CCM, Guyan or
// MacNeal; every one keeps the boundary dofs u_B as coordinates, at
// ReducedBasis::boundary_position). The contact rows of node c are
// B_c = F_c P_c (F_c the rigid casing's frame rows e_n, e_t1, e_t2; P_c
// picks its ux, uy, uz from q), B = [B_1; ...; B_nc] (3 nc x r), and
//   M^ q'' + C^ q' + K^ q = B^T lambda + f(t),
// lambda = (lambda_n, lambda_t1, lambda_t2) per contact [force], C^ =
// diag(c) the modal damping of modal_damping.hpp (zero on the boundary),
// f(t) an optional external force in reduced coordinates (T^T times the
// physical load; r entries),
//   f(t) = f0 + f1 cos(omega_f t + phi_f),
// f0, f1 each r entries or empty (= 0), applied from t = 0 on; none by
// default (issue 12 item 5: the pressed oscillator of
// verification/support/coulomb_oscillator.hpp needs a normal load and a tangential
// one). Zero initial conditions (start()), or rest at q0 for tests. Every
// time-n equation is discretized alike,
//   M^ (x_{n+1} - 2 x_n + x_{n-1})/dt^2 + C^ (x_{n+1} - x_{n-1})/(2 dt) + K^ x_n
//     = B^T lambda_n + f(t_n),                                            (*)
// the two schemes differ in which constraint determines lambda_n. Without
// a force every step does exactly the arithmetic it did before the force
// existed (the force terms are skipped, not added as zeros).
//
// 1. Mass-carrying boundary (CB, CCM, Guyan; M^ positive definite).
//    A = M^ + dt/2 C^ (Cholesky once, status checked). The step n -> n+1:
//      x~ = 2 x_n - x_{n-1} - dt^2 A^-1 K^ x_n - dt A^-1 C^ (x_n - x_{n-1})
//           + dt^2 A^-1 f(t_n)   (dt^2 A^-1 f0 and dt^2 A^-1 f1 formed once),
//      x_{n+1} = x~ + dt^2 A^-1 B^T lambda_n,
//    lambda_n from the contact at x_{n+1}: [g; s] = [g~; s~] + W lambda_n,
//      W = dt^2 B A^-1 B^T  (3 nc square, an inverse mass times dt^2),
//    g~_c = g(t_{n+1}) + e_n . u~_c, s~_c = [e_t1; e_t2](u~_c - u_c^n) + (0, r_c Omega dt)
//    (rigid_casing.hpp). Stable for dt < 2/omega_max of (K^, M^) (the
//    discrete energy below is positive definite iff so; C^ >= 0 only
//    removes energy); active contacts only lower omega_max (constraints
//    interlace the eigenvalues from below).
//
// 2. Massless boundary (MacNeal: M^_BB = 0, M^_BI = 0, C^_BB = 0).
//    Split x = (u_B, q_I). The boundary rows of (*) lose their inertia and
//    become a static balance at every time level,
//      K^_BB u_B^n + K^_BI q_I^n = B_B^T lambda_n + f_B(t_n),           (B)
//    the interior rows stay explicit,
//      A_I (q_I^{n+1} - 2 q_I^n + q_I^{n-1}) = -dt^2 (K^_II q_I^n + K^_IB u_B^n - f_I(t_n))
//                                              - dt C^_I (q_I^n - q_I^{n-1}),   (I)
//    A_I = M^_II + dt/2 C^_I (B_I = 0: contact acts on the boundary only).
//    f_B, f_I: the boundary and interior rows of f. A force on the boundary
//    rows has no mass to accelerate: it enters the static balance (B) at
//    the same time level as lambda_n, u_B^n = -S K^_BI q_I^n + S B_B^T
//    lambda_n + S f_B(t_n), S = K^_BB^-1 (the boundary jumps with the load,
//    as a massless node does); the contact is solved against it.
//    In (I) the code uses (B) to write K^_II q_I^n + K^_IB u_B^n =
//    K_c q_I^n + K^_IB S B_B^T lambda_n + K^_IB S f_B(t_n), K_c = K^_II -
//    K^_IB S K^_BI the condensed stiffness (the same numbers in exact
//    arithmetic, fewer flops): the interior sees f_I - K^_IB S f_B.
//    The step n -> n+1 (NLstep's leapfrog, Monjaraz-Tec, Gross, Krack,
//    Comput. Struct. 260 (2022) 106698: explicit on the modes, static
//    condensation of the boundary with the contact solved on it):
//      q_I^{n+1} from (I), with u_B^n of the previous step's balance;
//      u~_B = -S K^_BI q_I^{n+1} + S f_B(t_{n+1}),   S = K^_BB^-1 (Cholesky once; for
//             MacNeal's CCM coordinates S = R_B, the residual flexibility,
//             and -S K^_BI = Phi_1B: the kept modes' boundary motion);
//      u_B^{n+1} = u~_B + S B_B^T lambda_{n+1}, lambda_{n+1} from the
//             contact at time n+1: [g; s] = [g~; s~] + W lambda_{n+1},
//      W = B_B S B_B^T  (a COMPLIANCE [length/force]: the condensed static
//             flexibility of the boundary; no dt^2 M^-1 anywhere),
//    g~, s~ as above with u~_B (the slip increment is relative to u_B^n).
//    (B) then holds at n+1 to round-off, and (I) at n+1 uses the balanced
//    u_B^{n+1}: the pair is (*) at every n, with lambda_n paired with x_n.
//    Stable step without contact: eliminating u_B with (B) at lambda = 0
//    leaves q_I'' + C q_I' + (K^_II - K^_IB S K^_BI) q_I = 0, whose largest
//    eigenvalue (M^_II = I) is omega_max^2 of reduced/critical_step (for
//    MacNeal the condensed stiffness is Omega_1^2: omega_max = omega_psi),
//    so dt < 2/omega_psi: what the constructor checks. Caveat: a CLOSED
//    contact constrains u_B (its normal; in stick also its tangents), and
//    the interior then sees the constrained condensation, stiffer than the
//    free one (the infinite eigenvalues of the massless boundary come down
//    when u_B is held; all of u_B held, K^_II = Omega^2 + Phi_1B^T R_B^-1
//    Phi_1B for MacNeal). A long closed contact can thus be unstable at a
//    step the free modes allow; run_component's energy monitor reports it.
//    Measured (bench_component_rubbing, bench/RESULTS.md), Rotor 37
//    MacNeal-50: 2/omega of the interior 1.70e-5 s free, 1.63e-5 s with the
//    16 normals held, 1.03e-5 s with the whole boundary held, against the
//    README's 4.675e-6 s.
//
// Energy (both schemes; the central-difference identity of (*), multiplied
// by (x_{n+1} - x_{n-1})/2):
//   E_{n+1/2} = 1/2 v^T M^ v + 1/2 x_n^T K^ x_{n+1},  v = (x_{n+1} - x_n)/dt,
//   E_{n+1/2} - E_{n-1/2} = lambda_n^T B (x_{n+1} - x_{n-1})/2
//                         + f(t_n)^T (x_{n+1} - x_{n-1})/2
//                         - (x_{n+1} - x_{n-1})^T C^ (x_{n+1} - x_{n-1})/(4 dt),
// summed into W_contact, W_ext and W_damp: E = E_0 + W_ext + W_contact -
// W_damp closes to the round-off of (*) (of the Cholesky solves, and for
// MacNeal of (B)). The massless boundary's rows of M^, C^ vanish, so the
// identity holds for either choice of the start's u_B^{-1}; start() takes
// the contact-free, load-free balance -S K^_BI q_I^0 (the structure at rest
// before t = 0; the load f(0) and the contact act from t = 0 on).
//
// Costs per contact-free step (dense): CB/CCM 2 r^2 (+ 2 r^2 damped);
// MacNeal 2 (psi^2 + psi n_B) (+ 3 psi damped, M^_II = I) plus about 30 nc
// for the gaps and slips.
// A step with a closing contact adds the Gauss-Seidel solve (on the
// closing contacts only, grown while their forces close others) and 2 r 3 nc.
//
// Errors: bad arguments throw std::invalid_argument ("ComponentIntegrator:
// what, allowed range"); a failed factorization, a dt at or above the
// critical step (unless forced), a contact solve that does not converge or
// a non-finite state throw ComponentIntegrationError naming the step.

#include <array>
#include <stdexcept>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "coulomb_gauss_seidel.hpp"
#include "failure_kinds.hpp"
#include "history.hpp"
#include "reduced_basis.hpp"
#include "reduced_stepper.hpp"
#include "rigid_casing.hpp"

namespace rsi {

class ComponentIntegrationError : public NumericalFailure {
public:
  using NumericalFailure::NumericalFailure;
};

struct ComponentIntegratorOptions {
  double dt = 0.0;         ///< time step [s], > 0 and finite
  double mu = 0.0;         ///< Coulomb friction coefficient, >= 0
  Eigen::VectorXd damping; ///< diag(C^), r entries >= 0 (modal_damping), or empty: undamped
  bool force_step = false; ///< integrate even if dt >= 2/omega_max
  /// Solve each step's contact on the closing contacts only (grown as
  /// needed); false: on the whole W (the plain way, kept to cross-check).
  bool closing_subset = true;
  CoulombGaussSeidelOptions coulomb;
  /// External force f(t) = force_constant + force_harmonic cos(force_frequency t
  /// + force_phase) in reduced coordinates (header, (*)); each vector r finite
  /// entries or empty (= 0). Both empty: no force (the default).
  Eigen::VectorXd force_constant; ///< f0 [force]
  Eigen::VectorXd force_harmonic; ///< f1 [force]
  double force_frequency = 0.0;   ///< omega_f [rad/s], finite
  double force_phase = 0.0;       ///< phi_f [rad], finite
};

class ComponentIntegrator final : public ReducedStepper {
public:
  /// `basis` and `casing` are copied from (not kept). Throws
  /// std::invalid_argument (bad options, a force of the wrong size, a casing
  /// whose boundary indices do not exist in the basis) or ComponentIntegrationError (failed
  /// factorization; dt >= 2/omega_max without force_step).
  ComponentIntegrator(const ReducedBasis& basis, const RigidCasing& casing,
                      const ComponentIntegratorOptions& options);

  bool massless_boundary() const { return m_massless; }
  double omega_max() const { return m_omega_max; }
  double critical_dt() const { return 2.0 / m_omega_max; }
  double dt() const { return m_dt; }
  int n_contacts() const { return m_nc; }
  const RigidCasing& casing() const { return m_casing; }

  /// Zero initial conditions at t = 0 (the contact at t = 0 solved for a
  /// massless boundary).
  void start() override;
  /// At rest at the reduced coordinates q0 (r entries; for a massless
  /// boundary only the interior part is used: the boundary follows (B)).
  void start(const Eigen::Ref<const Eigen::VectorXd>& q0);
  /// Step n -> n+1. Throws ComponentIntegrationError naming the step on a
  /// contact solve that fails or a non-finite state.
  StepReport step() override;

  int step_index() const override { return m_n; }
  double time() const override { return m_n * m_dt; }
  /// x_n in the basis' coordinate order.
  Eigen::VectorXd q() const;
  /// The physical displacement row . x_n (row: a row of T, r entries).
  double response(const Eigen::Ref<const Eigen::RowVectorXd>& row) const;
  /// g_c at x_n, nc entries.
  const Eigen::VectorXd& gap() const override { return m_gap; }
  /// The multipliers of the step that produced x_n (CB: lambda_{n-1}, which
  /// enforced the contact at x_n; MacNeal: lambda_n, in balance with
  /// u_B^n), 3 nc entries (n, t1, t2 per contact).
  const Eigen::VectorXd& lambda() const override { return m_lambda; }
  const std::vector<ReducedContactState>& states() const { return m_state; }
  /// E_{n-1/2} (after n steps) [energy unit of the component].
  double energy() const override;
  double initial_energy() const override { return m_initial_energy; }
  double contact_work() const override { return m_contact_work; }
  /// W_ext = sum_n f(t_n)^T (x_{n+1} - x_{n-1})/2 (0 without a force).
  double external_work() const override { return m_external_work; }
  bool has_external_force() const { return m_force; }
  /// f(t), r entries (zeros without a force).
  Eigen::VectorXd external_force(double t) const;
  double damping_work() const override { return m_damping_work; }
  /// W of every step's contact problem (3 nc square; constant over a run).
  const Eigen::MatrixXd& contact_matrix() const { return m_w; }
  /// Gauss-Seidel sweeps summed over the run.
  long sweeps() const { return m_sweeps; }

private:
  void predict_contact(const Eigen::VectorXd& u_trial, const Eigen::VectorXd& u_now, double t_next);
  /// Solves the contact of the prediction in m_pred into m_lambda, fills the report.
  void solve_contact(StepReport& report);
  void gaps_at(const Eigen::VectorXd& u_boundary, double t);
  /// Contact node c's ux, uy, uz from the boundary coordinates.
  Eigen::Vector3d node_of(const Eigen::VectorXd& u_boundary, int c) const;
  Eigen::VectorXd boundary_of(const Eigen::VectorXd& x) const;
  /// x_n and x_{n-1} in the basis' coordinate order (r entries each).
  void state_in_basis(Eigen::VectorXd& x, Eigen::VectorXd& xp) const;

  bool m_massless = false;
  bool m_subset = true;
  double m_dt = 0.0;
  double m_mu = 0.0;
  double m_omega_max = 0.0;
  int m_r = 0, m_nb = 0, m_ni = 0, m_nc = 0;
  int m_n = 0;
  std::vector<int> m_boundary; ///< positions of u_B in q (boundary order)
  std::vector<int> m_interior; ///< the other positions, ascending
  RigidCasing m_casing;
  Eigen::MatrixXd m_b;  ///< B_B: 3 nc x n_B, the contact rows on u_B
  Eigen::MatrixXd m_w;  ///< W, 3 nc square
  Eigen::MatrixXd m_g;  ///< the correction per unit lambda: CB dt^2 A^-1 B^T (r x 3nc); MacNeal S
                        ///< B_B^T (n_B x 3nc)
  Eigen::MatrixXd m_k;  ///< K^ (energy)
  Eigen::MatrixXd m_m;  ///< M^ (energy)
  Eigen::VectorXd m_c;  ///< diag C^ (empty: undamped)
  Eigen::VectorXd m_ci; ///< MacNeal: diag C^ on the interior coordinates (damped)
  // CB: x = full; MacNeal: x = interior q_I, u = u_B.
  Eigen::MatrixXd m_p;             ///< CB: dt^2 A^-1 K^; MacNeal: dt^2 A_I^-1 K^_II
  Eigen::MatrixXd m_pb;            ///< MacNeal: dt^2 A_I^-1 K^_IB S B_B^T (psi x 3 nc)
  Eigen::MatrixXd m_d;             ///< dt A^-1 C^ (damped, dense M^)
  Eigen::VectorXd m_d_diagonal;    ///< MacNeal with diagonal M^_II: dt A_I^-1 C^_I as a vector
  Eigen::MatrixXd m_z;             ///< MacNeal: -S K^_BI (n_B x psi)
  Eigen::VectorXd m_x, m_xp, m_xn; ///< CB: x_n, x_{n-1}; MacNeal: q_I^n, q_I^{n-1}; scratch
  Eigen::VectorXd m_u, m_up, m_un; ///< MacNeal: u_B^n, u_B^{n-1}; scratch
  Eigen::VectorXd m_pred, m_gap, m_lambda, m_lambda_next, m_work_b;
  Eigen::MatrixXd m_wa;       ///< W on the contacts of the step's active set
  Eigen::VectorXd m_pa, m_la; ///< [g~; s~] and lambda on them
  std::vector<ReducedContactState> m_state;
  CoulombGaussSeidel m_solver;
  // External force (m_force false: none, the vectors empty).
  bool m_force = false;
  double m_omega_f = 0.0, m_phi_f = 0.0;
  Eigen::VectorXd m_f0, m_f1; ///< f0, f1 (r entries; zeros where not given)
  /// The force's correction per step: CB dt^2 A^-1 f0, dt^2 A^-1 f1 (r);
  /// MacNeal dt^2 A_I^-1 (f_I - K^_IB S f_B) of f0, f1 (psi).
  Eigen::VectorXd m_gf0, m_gf1;
  Eigen::VectorXd m_sf0, m_sf1; ///< MacNeal: S f_B of f0, f1 (n_B)
  double m_initial_energy = 0.0, m_contact_work = 0.0, m_damping_work = 0.0;
  double m_external_work = 0.0;
  long m_sweeps = 0;
};

} // namespace rsi
