#pragma once
// Central differences with forward-increment Lagrange multipliers for ONE
// reduced component rubbing on a rigid casing (issue 12 items 1 and 4; SPEC
// §3, §8), with Coulomb stick/slip solved by CoulombGaussSeidel. Written
// apart from the reference integrator and from reduced_integrator (which
// couples the 2D bladed disk to a full casing).
//
// Model. q = the reduced coordinates of a ReducedBasis (CB, CCM, Guyan or
// MacNeal keep the boundary dofs u_B as coordinates, at
// ReducedBasis::boundary_position; characteristic constraint modes give
// u_B = Psi_c q_c). The contact rows of node c are
// B_c = F_c P_c (F_c the rigid casing's frame rows e_n, e_t1, e_t2; P_c
// picks its ux, uy, uz from q, or their rows of Psi_c), B = [B_1; ...; B_nc] (3 nc x r), and
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
// Composition. The integrator is three parts, each stating its equations in
// its header, stepped alike for every basis:
//   the rotor part (component_rotor_part.hpp): 1. a mass-carrying boundary
//     (CB, CCM, Guyan: mass_carrying_boundary_part.hpp) or 2. a massless
//     boundary (MacNeal: massless_boundary_part.hpp), chosen by
//     ReducedBasis::massless_boundary;
//   the casing part (component_casing_part.hpp): the rigid casing
//     (rigid_casing_part.hpp: B_B and the predicted gaps g~ and slips s~ at
//     the trial boundary displacement u~_B) or the flexible 3D casing in its
//     modes (solid_casing_part.hpp: its own modal step beside the rotor's,
//     its rows H on its modal coordinates, its share dt^2 H H^T of W, which
//     changes every step, and its own energy and works, added to the
//     rotor's);
//   the Coulomb contact solve (coulomb_node_solve.hpp): [g; s] = [g~; s~] +
//     W lambda on the closing contacts, W from the rotor part (plus the
//     flexible casing's dt^2 H H^T, given as H and formed on the closed
//     contacts only: flexibility_rows(), CoulombNodeSolve::set_flexibility).
// A step: the rotor part predicts (with the multipliers of the step that
// produced x_n), the casing part predicts [g~; s~] at its u~_B, the contact
// solve finds lambda, the rotor part takes the correction, the works are
// summed and the state advances; the gaps are then those at x_{n+1}.
//
// Energy (both schemes; the central-difference identity of (*), multiplied
// by (x_{n+1} - x_{n-1})/2):
//   E_{n+1/2} = 1/2 v^T M^ v + 1/2 x_n^T K^ x_{n+1},  v = (x_{n+1} - x_n)/dt,
//   E_{n+1/2} - E_{n-1/2} = lambda_n^T B (x_{n+1} - x_{n-1})/2
//                         + f(t_n)^T (x_{n+1} - x_{n-1})/2
//                         - (x_{n+1} - x_{n-1})^T C^ (x_{n+1} - x_{n-1})/(4 dt),
// summed into W_contact, W_ext and W_damp: E = E_0 + W_ext + W_contact -
// W_damp closes to the round-off of (*) (of the Cholesky solves, and for
// MacNeal of (B)).
//
// Errors: bad arguments throw std::invalid_argument ("ComponentIntegrator:
// what, allowed range"); a failed factorization, a dt at or above the
// critical step (unless forced), a contact solve that does not converge or
// a non-finite state throw ComponentIntegrationError naming the step.

#include <memory>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "component_casing_part.hpp"
#include "component_integration_error.hpp"
#include "component_integrator_options.hpp"
#include "component_contact_solve.hpp"
#include "component_rotor_part.hpp"
#include "coulomb_gauss_seidel.hpp"
#include "coulomb_node_solve.hpp"
#include "liner_contact_solve.hpp"
#include "history.hpp"
#include "reduced_basis.hpp"
#include "reduced_stepper.hpp"
#include "rigid_casing.hpp"
#include "rigid_casing_part.hpp"

namespace rsi {

class ComponentIntegrator final : public ReducedStepper {
public:
  /// `basis` and `casing` are copied from (not kept). Throws
  /// std::invalid_argument (bad options, a force of the wrong size, a casing
  /// whose boundary indices do not exist in the basis) or ComponentIntegrationError (failed
  /// factorization; dt >= 2/omega_max without force_step).
  ComponentIntegrator(const ReducedBasis& basis, const RigidCasing& casing,
                      const ComponentIntegratorOptions& options);
  /// Against a casing part of its own (solid_casing_part.hpp: the flexible
  /// 3D casing), made at options.dt; no liner. The critical step is the
  /// smaller of the rotor's and the casing part's.
  ComponentIntegrator(const ReducedBasis& basis, std::unique_ptr<ComponentCasingPart> casing,
                      const ComponentIntegratorOptions& options);

  bool massless_boundary() const { return m_rotor->contact_at_next_level(); }
  double omega_max() const { return m_omega_max; }
  double critical_dt() const { return 2.0 / m_omega_max; }
  double dt() const { return m_dt; }
  int n_contacts() const { return m_nc; }
  /// The tips' frames, radii and angles (the rigid casing itself, or the
  /// flexible casing's tips).
  const RigidCasing& casing() const { return m_casing->tips(); }
  /// The gap of contact c at time t with no displacement.
  double rest_gap(int c, double t) const { return m_casing->rest_gap(c, t); }
  /// The casing part (the flexible casing's modal state, for tests).
  const ComponentCasingPart& casing_part() const { return *m_casing; }

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
  Eigen::VectorXd q() const { return m_rotor->q(); }
  /// The physical displacement row . x_n (row: a row of T, r entries).
  double response(const Eigen::Ref<const Eigen::RowVectorXd>& row) const;
  /// g_c at x_n, nc entries.
  const Eigen::VectorXd& gap() const override { return m_casing->gap(); }
  /// The multipliers of the step that produced x_n (CB: lambda_{n-1}, which
  /// enforced the contact at x_n; MacNeal: lambda_n, in balance with
  /// u_B^n), 3 nc entries (n, t1, t2 per contact).
  const Eigen::VectorXd& lambda() const override { return m_lambda; }
  const std::vector<ReducedContactState>& states() const { return m_contact->states(); }
  /// E_{n-1/2} (after n steps) [energy unit of the component]; with a liner
  /// plus its bars' elastic energy F^2 / (2 k) of the last step.
  double energy() const override;
  double initial_energy() const override { return m_initial_energy; }
  /// W_contact; with a liner plus the bars' own work by their law (their
  /// elastic energy's change since the start and W_plastic), so that E = E0 + W_ext + W_contact - W_damp -
  /// W_plastic is the blade's identity, as in the full-order run
  /// (docs/decisions.md, "The abradable liner").
  double contact_work() const override;
  /// W_plastic, the liner's committed plastic work (0 without a liner).
  double plastic_work() const;
  /// The liner's solve, or nullptr without a liner.
  const LinerContactSolve* liner() const { return m_liner; }
  /// What the normal forces' trapezoid work on the moving casing surface
  /// misses of the bars' work (as the full-order summary's
  /// liner.unmatched_work); 0 without a liner.
  double liner_unmatched_work() const;
  /// W_ext = sum_n f(t_n)^T (x_{n+1} - x_{n-1})/2 (0 without a force).
  double external_work() const override;
  bool has_external_force() const { return m_rotor->has_external_force(); }
  /// f(t), r entries (zeros without a force).
  Eigen::VectorXd external_force(double t) const { return m_rotor->external_force(t); }
  double damping_work() const override { return m_rotor->damping_work(); }
  /// W of every step's contact problem (3 nc square; constant over a run),
  /// the rotor's share only against a flexible casing (whose dt^2 H H^T
  /// changes every step: CoulombNodeSolve::set_flexibility).
  const Eigen::MatrixXd& contact_matrix() const { return m_contact->contact_matrix(); }
  /// Gauss-Seidel sweeps summed over the run.
  long sweeps() const { return m_contact->sweeps(); }

private:
  /// The contact's solve of this step's prediction; a failure with a basis
  /// of characteristic constraint modes says that W's rank limits it.
  void solve_contact(StepReport& report);
  /// The constructors' common part, after m_casing is set.
  void init(const ReducedBasis& basis, const ComponentIntegratorOptions& options);

  double m_dt = 0.0;
  double m_omega_max = 0.0;
  int m_r = 0, m_nc = 0;
  /// n_c of a basis of characteristic constraint modes (0: u_B coordinates):
  /// W = B_q A^-1 B_q^T has rank at most n_c (solve_contact).
  int m_boundary_rank = 0;
  int m_n = 0;
  std::unique_ptr<ComponentContactSolve> m_contact;
  LinerContactSolve* m_liner = nullptr; ///< m_contact when it is the liner's
  double m_wall_work = 0.0;             ///< -sum lambda_n (g0(t_{n+1}) - g0(t_{n-1})) / 2
  double m_initial_bar_energy = 0.0;    ///< the bars' elastic energy at the start (MacNeal in contact at t = 0)
  std::unique_ptr<ComponentCasingPart> m_casing;
  CoulombNodeSolve* m_coulomb = nullptr; ///< m_contact when W changes every step (flexible casing)
  std::unique_ptr<ComponentRotorPart> m_rotor;
  Eigen::VectorXd m_lambda; ///< the multipliers of the step that produced x_n
  double m_initial_energy = 0.0;
};

} // namespace rsi
