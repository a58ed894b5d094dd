#pragma once
// Explicit central differences with forward-increment Lagrange multipliers
// (SPEC §3; Carpenter, Taylor, Katona 1991) for M u'' + K u = F + R.
//
//   predictor   u~ = 2 u_n - u_{n-1} + dt^2 M^-1 (F_n - K u_n)
//   contact     on the active set A = {k : g_k(u~) < 0} solve W lambda = -g~
//               with W_ij = dt^2 G_i M^-1 D_j^T (not symmetric), drop the
//               most negative lambda and re-solve until lambda >= 0; add
//               any constraint the correction closes and re-solve
//   corrector   u_{n+1} = u~ + dt^2 M^-1 D^T lambda,  R_n = D^T lambda
// started from rest: u_0 = 0, u_{-1} = dt^2/2 M^-1 F_0.
//
// Rayleigh damping C = alpha M + beta K (SPEC §8; alpha, beta >= 0) enters
// with the centred velocity (u_{n+1} - u_{n-1}) / (2 dt), the scheme
//   M (u_{n+1} - 2 u_n + u_{n-1}) / dt^2 + C (u_{n+1} - u_{n-1}) / (2 dt) + K u_n = F_n + R_n.
// With A = M + dt/2 C and u_{n+1} - u_{n-1} = (u_{n+1} - 2 u_n + u_{n-1}) + 2 (u_n - u_{n-1})
// it is the undamped step with A in place of M and one more force:
//   u~ = 2 u_n - u_{n-1} + dt^2 A^-1 (F_n - K u_n - C (u_n - u_{n-1}) / dt),
//   u_{n+1} = u~ + dt^2 A^-1 D^T lambda,  W = dt^2 G A^-1 D^T,
// so A is factorized once in place of M (the contact flexibility W is A's).
// Without damping A = M and every operation is the first round's (the same
// bits). Stability, mode i (M, K, C share their modes: zeta_i = alpha /
// (2 omega_i) + beta omega_i / 2, w = omega_i dt): x_{n+1} = z x_n gives
//   (1 + zeta_i w) z^2 - (2 - w^2) z + (1 - zeta_i w) = 0,
// whose roots lie in the closed unit disc, distinct on its circle (Jury:
// |a0| <= a2, a2 + a1 + a0 = w^2 > 0, a2 - a1 + a0 = 4 - w^2 > 0) for
// 0 < w < 2, inside it for zeta_i > 0, and one reaches z = -1
// at w = 2: the critical step stays 2 / omega_i for every zeta_i >= 0, and
// the check dt < 2 / omega_max stands unchanged. (A
// lagged velocity (u_n - u_{n-1}) / dt keeps M^-1 but lowers it to
// (2 / omega_i)(sqrt(1 + zeta_i^2) - zeta_i), which stiffness-proportional
// damping drives far below the undamped step on the highest modes.) The
// decay per step is |z|^2 = (1 - zeta_i w) / (1 + zeta_i w), a rate of
// zeta_i omega_i (1 + (zeta_i w)^2 / 3 + ...): second order in dt.
//
// Energy: multiplying the scheme by (u_{n+1} - u_{n-1})/2 gives exactly
//   E_{n+1/2} - E_{n-1/2} = (F_n + R_n)^T (u_{n+1} - u_{n-1}) / 2
//                           - (u_{n+1} - u_{n-1})^T C (u_{n+1} - u_{n-1}) / (4 dt)
// with the discrete energy E_{n+1/2} = 1/2 v^T M v + 1/2 u_n^T K u_{n+1},
// v = (u_{n+1} - u_n)/dt. The works W_ext, W_contact and W_damp (the last
// term, >= 0) are summed step by step and E is computed from its
// definition, so E - E_0 - W_ext - W_contact + W_damp is round-off unless
// the scheme is broken. C u is kept from step to step as alpha M'u + beta
// K'u (K'u is the predictor's anyway), so the damping costs one product
// with M' a step (none with alpha = 0).
//
// M^-1 (A^-1 when damped) is applied through the LDL^T factor of P M P^T (reference/mass_factor:
// CHOLMOD's AMD order and factorization, pivots checked, applied by its own
// triangular solves). The state is kept in the permuted coordinates
// u' = P u, with K' = P K P^T and M' = P M P^T, so a step applies the factor
// with no permutation (permuting a vector in place took 15 % of a step), and
// K'u' is summed by reference/sparse_rows. The contact law sees physical
// vectors, but only the dofs it reads (ContactLaw::dofs_read: 200 of 838 on
// the default case) are gathered and differentiated per evaluation; the
// whole physical u_n is gathered only when displacement() is asked for. The
// columns M^-1 e_i met by contact rows are computed once and cached, each as
// the contiguous block of the permuted order where it is nonzero. The energy
// costs a product with M, so it is computed when asked (the works are summed
// at every step).
//
// Coulomb friction with stick and slip (issue 12 item 2; the case's
// friction_law "coulomb"): constructed with a FrictionalContactLaw in place
// of a ContactLaw, the contact step is the per-step problem of
// frictional_contact_problem.hpp:
//   law.evaluate(u_n, u~, t_{n+1}, dt) -> g~, s~ (the forward tangential
//       increment over the step), rows B (per contact n, t1 [, t2]);
//   if every g~_c >= 0 and the previous lambda is zero: lambda = 0 (no
//       contact can close; the solver is not called);
//   else on the contacts in play P = {c : g~_c < 0 or lambda_c of the
//       previous step != 0}: W = dt^2 B_P A^-1 B_P^T (upper triangle from the
//       cached columns of A^-1, mirrored: exactly symmetric), solve
//       [g; s] = [g~; s~] + W lambda with FrictionalContactSolver warm
//       started from the previous lambda (IntegrationError with the step and
//       the solver's message if it fails); a contact outside P that the
//       correction would close (g~_c + G_c du < 0) joins P and the problem is
//       solved again (outside P lambda_c = 0, exactly the open state, so the
//       problem on P with every other g >= 0 is the whole problem);
//   u_{n+1} = u~ + dt^2 A^-1 B^T lambda, R_n = B^T lambda (every row enters
//   the contact work, as above), and the StepReport carries certify()'s
//   residuals: max_cone_violation [N] raw, max_stick_slip_residual the
//   larger of the scaled stick and slip residuals, stick_slip_transitions
//   the contacts whose class (open, stick, slip) changed since the previous
//   step, n_stick, n_slip; max_friction_residual the raw slip residual
//   |lambda_t + mu lambda_n s/|s|| [N]; sliding_reversals counts contacts
//   slipping at both steps whose slip direction -lambda_t/|lambda_t| turned
//   by more than 90 degrees.
// The ContactLaw path ("sliding_sign") is not touched by any of this: the
// same operations in the same order as before.

#include <stdexcept>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>

#include "case_file.hpp"
#include "contact_law.hpp"
#include "failure_kinds.hpp"
#include "frictional_contact_law.hpp"
#include "frictional_contact_problem.hpp"
#include "frictional_contact_solver.hpp"
#include "liner_surface.hpp"
#include "history.hpp"
#include "mass_factor.hpp"
#include "sparse_rows.hpp"

namespace rsi {

/// A numerical failure of the integrator (factorization, singular W).
class IntegrationError : public NumericalFailure {
public:
  using NumericalFailure::NumericalFailure;
};

class CentralDifference {
public:
  /// K, M of the whole system (square, same size), time step dt > 0,
  /// Rayleigh damping alpha, beta >= 0 (zero: undamped). `law` must outlive
  /// the integrator (not owned). Throws IntegrationError if M is not
  /// positive definite, std::invalid_argument for a negative or non-finite
  /// damping coefficient.
  CentralDifference(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, double dt, const ContactLaw& law,
                    const RayleighDamping& damping = RayleighDamping{});
  /// The same with Coulomb friction with stick and slip (the class comment):
  /// `law` must outlive the integrator (not owned); solver_options for the
  /// per-step FrictionalContactSolver. Throws as above.
  CentralDifference(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, double dt,
                    const FrictionalContactLaw& law,
                    const RayleighDamping& damping = RayleighDamping{},
                    const FrictionalContactSolverOptions& solver_options = {});

  /// Start from rest under the force f0 at t = 0.
  void start(const Eigen::Ref<const Eigen::VectorXd>& f0);
  /// The external force F_n of the following steps (held until changed:
  /// a piecewise constant force costs nothing per step).
  void set_force(const Eigen::Ref<const Eigen::VectorXd>& f);
  /// Advance from t_n to t_{n+1} under the force set.
  StepReport step();

  int step_index() const { return m_n; } ///< n of the current u_n
  double time() const { return m_n * m_dt; }
  /// u_n in physical order, gathered from the state when asked (n loads);
  /// valid until the next step() or start().
  const Eigen::VectorXd& displacement() const;
  /// Normal multipliers of the last step, one per constraint (contact) [N].
  const Eigen::VectorXd& lambda() const { return m_lambda; }
  /// Coulomb law: tangential multipliers of the last step, n_tangents() per
  /// contact (t1 [, t2]) [N]; empty for a ContactLaw.
  const Eigen::VectorXd& lambda_tangential() const { return m_lambda_t; }
  /// d of the FrictionalContactLaw (1 or 2); 0 for a ContactLaw.
  int n_tangents() const { return m_n_tangents; }
  /// Coulomb law: each contact's class after the last step (all open at start).
  const std::vector<ContactClass>& contact_classes() const { return m_classes; }
  const Eigen::VectorXd& gap() const { return m_gap; } ///< gaps at u_n
  double energy() const; ///< E_{n-1/2} [J], computed from its definition
  double initial_energy() const { return m_initial_energy; }
  double external_work() const { return m_external_work; }
  double contact_work() const { return m_contact_work; }
  /// The Coulomb path's normal problem becomes the abradable liner's
  /// compliant solve, node by node (liner_surface.hpp; docs/decisions.md,
  /// "The abradable liner"): F = F_bar(delta~ - W_nn F), then Coulomb with
  /// the radius mu F on the node's tangential rows (stick: lambda_t =
  /// -s~ / W_tt; slip: the projection on the disk), exact when W is diagonal
  /// with equal entries on each node's three rows, which is checked here
  /// (a lumped mass without stiffness-proportional damping gives it).
  /// The cells' states are committed once per step, after the correction.
  /// `liner` must outlive the integrator and be built on this integrator's
  /// FrictionalContactLaw. Throws std::invalid_argument if W is not so.
  void attach_liner(LinerSurface& liner);
  /// With a liner, the contact work W_contact of the balance E = E0 + W_ext
  /// + W_contact - W_damp - W_plastic with E = E_blade + E_bars (E_bars =
  /// sum F^2 / (2 k) of the last step's bars): the work of the contact on
  /// the blade plus the bars' own work by their law (E_bars + W_plastic).
  /// The balance is then the blade's discrete energy identity, to round-off
  /// (it does not check the liner: liner_unmatched_work does).
  double liner_contact_work() const;
  /// With a liner: the bars' work in the integrator's trapezoid, sum F
  /// (delta_{n+1} - delta_{n-1}) / 2 with delta = -g (the blade's normal
  /// work taken with the other sign plus the moving surface's, -F (g0(t_{n+1})
  /// - g0(t_{n-1})) / 2), minus their exact work by the law (E_bars +
  /// W_plastic). Two parts: the scheme's dissipation of a bar it sees at
  /// t_{n+1} (elastic bar: k/4 sum (delta_{n+1} - delta_{n-1})^2 plus end
  /// terms, first order in dt), and the cells' switches: a node that passes
  /// into the next cell at a fixed position meets that cell's own surface,
  /// so the bar it leaves unloads without work (its elastic energy gone) and
  /// the bar it enters is loaded without work (energy that then yields).
  /// Measured on blade3d-rubbing with a soft liner the second dominates (the
  /// bars' law made 3.2e4 N mm of plastic work, the contact force's
  /// trapezoid work on the bars was about 1.6e3): the radial bars do not
  /// resist the tangential cut, a limit of the cell model (decisions.md).
  double liner_unmatched_work() const;
  /// W_damp, the work the damping force took out up to step n-1 (>= 0) [J].
  double damping_work() const { return m_damping_work; }
  /// Flops of a contact-free step: K'u (2 nnz(K)), L^-1 and L^-T (2 nnz(L)
  /// each), D^-1 (n) and about 12 n of vector updates (force, predictor,
  /// velocity, gathers); the contact geometry of a few tips is left out.
  /// Damped, also M'u (2 nnz(M), alpha > 0) and about 8 n for C'u, the
  /// damping force and W_damp (L is then A's factor).
  double flops_per_step() const;

private:
  CentralDifference(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, double dt, const ContactLaw* law,
                    const FrictionalContactLaw* frictional, const RayleighDamping& damping,
                    const FrictionalContactSolverOptions& solver_options);
  /// The nonzero block of a column of M'^-1: entries first .. first + size - 1.
  struct InverseMassColumn {
    Eigen::Index first = 0;
    Eigen::VectorXd values;
    double operator()(Eigen::Index i) const {
      return i >= first && i < first + values.size() ? values(i - first) : 0.0;
    }
  };
  /// M'^-1 e_p(dof) (permuted coordinates) for a physical dof, cached.
  const InverseMassColumn& inverse_mass_column(int dof);
  /// dt^2 G M^-1 D^T for one pair of rows, from the cached columns of M^-1.
  double contact_flexibility(const SparseRow& gradient, const SparseRow& direction);
  /// G u for a row G in physical dofs and u in permuted coordinates.
  double permuted_dot(const SparseRow& row, const Eigen::VectorXd& u) const;
  /// W_damp += (u_{n+1} - u_{n-1})^T C (u_{n+1} - u_{n-1}) / (4 dt), after the
  /// state has moved to u_{n+1}; keeps C'u' for the next step.
  void add_damping_work();
  /// r <- A'^-1 r through the factor of P A P^T (A = M undamped).
  void apply_inverse_mass(Eigen::VectorXd& r) { m_mass_factor.solve_in_place(r); }
  /// On the dofs the law reads: physical <- P^T permuted, velocity <-
  /// (physical - u_n) / dt; the other entries are left as they are.
  void to_physical(const Eigen::VectorXd& permuted, Eigen::VectorXd& physical,
                   Eigen::VectorXd& velocity) const;
  /// The multipliers (all constraints) and the correction u_{n+1} - u~ of the
  /// predicted state, by the active-set iteration of the class comment.
  void solve_active_set(const ContactState& predicted, Eigen::VectorXd& lambda,
                        Eigen::VectorXd& correction);
  /// m_predicted <- u~' (permuted) and, on the law's dofs, m_x_next <- u~.
  void predict();
  /// m_predicted = u'_{n+1}: the external work of the step, then the state
  /// moves to n + 1 (K'u', damping work).
  void advance();
  /// step() with the FrictionalContactLaw (class comment).
  StepReport step_coulomb();
  /// The multipliers of the step on the contacts in play (m_in_play),
  /// written to m_lambda, m_lambda_t; the correction into m_correction; the
  /// certificate of the problem solved into `certificate` (classes of the
  /// contacts in play, in m_play order).
  void solve_coulomb(FrictionalContactCertificate& certificate);
  /// The same with the liner's normal law (attach_liner), every contact.
  void solve_liner(FrictionalContactCertificate& certificate, double t_next);

  double m_dt;
  const ContactLaw* m_law;                   ///< sliding_sign path (or nullptr)
  const FrictionalContactLaw* m_frictional;  ///< Coulomb path (or nullptr)
  FrictionalContactSolver m_solver;
  int m_n_tangents = 0;
  RayleighDamping m_damping;
  bool m_damped;                     ///< alpha or beta > 0
  MassFactor m_mass_factor;          ///< of A = M + dt/2 C (M undamped)
  const Eigen::VectorXi& m_position; ///< u'(m_position(i)) = u(i)
  RowMajorMatrix m_k;                ///< K'
  RowMajorMatrix m_m;                ///< M'
  SparseRows m_k_rows;               ///< K', stored for its product
  std::vector<int> m_law_dofs;       ///< the physical dofs the law reads
  std::vector<int> m_law_positions;  ///< where they sit in u'
  /// The columns met so far, by physical dof: M is block diagonal (bladed
  /// disk, casing), so a casing column has 156 nonzeros of 838, contiguous
  /// in the permuted order (MassFactor::block).
  std::vector<InverseMassColumn> m_inverse_columns;

  int m_n = 0;
  // Permuted coordinates.
  Eigen::VectorXd m_u;
  Eigen::VectorXd m_u_prev;
  Eigen::VectorXd m_ku; ///< K' u'_n
  // Damped runs only: C' u'_n and C' u'_{n-1}, with C' = alpha M' + beta K'.
  SparseRows m_m_rows;       ///< M', for its product (alpha > 0)
  Eigen::VectorXd m_mu;      ///< M' u'_{n+1} (work storage)
  Eigen::VectorXd m_cu;      ///< C' u'_n
  Eigen::VectorXd m_cu_prev; ///< C' u'_{n-1}
  Eigen::VectorXd m_cu_next; ///< C' u'_{n+1} (work storage)
  // Work storage, kept to avoid allocations in the step loop.
  Eigen::VectorXd m_force; ///< F' = P F
  bool m_forced = false;   ///< F != 0
  Eigen::VectorXd m_predicted;
  Eigen::VectorXd m_correction;
  // Physical coordinates, for the contact law: only m_law_dofs are kept.
  Eigen::VectorXd m_x;      ///< u_n
  Eigen::VectorXd m_x_next; ///< the prediction, then u_{n+1}
  Eigen::VectorXd m_velocity;
  mutable Eigen::VectorXd m_displacement; ///< all of u_n, when asked
  mutable int m_displacement_step = -1;   ///< the n of m_displacement
  // Active-set storage, reused from step to step.
  std::vector<char> m_active;
  std::vector<int> m_active_index;
  Eigen::MatrixXd m_w;        ///< W_ij, computed when first met in a step
  Eigen::MatrixXi m_w_step;   ///< the step m_w(i, j) was computed for
  Eigen::MatrixXd m_w_active; ///< W on the active set
  Eigen::VectorXd m_rhs;      ///< -g~ on the active set
  Eigen::VectorXd m_lambda_active;
  Eigen::FullPivLU<Eigen::MatrixXd> m_lu;
  ContactState m_predicted_state;
  ContactState m_state; ///< at u_n
  Eigen::VectorXd m_lambda;
  Eigen::VectorXd m_gap;
  // Coulomb storage (FrictionalContactLaw only).
  FrictionalContactGeometry m_geometry;       ///< of the prediction
  FrictionalContactGeometry m_geometry_after; ///< at u_{n+1}
  Eigen::VectorXd m_lambda_t;                 ///< d per contact [N]
  std::vector<char> m_in_play;                ///< per contact
  std::vector<int> m_play;                    ///< the contacts in play, ascending
  Eigen::MatrixXd m_wf;                       ///< W entries by row pair, cached per step
  Eigen::MatrixXi m_wf_step;                  ///< the step m_wf(i, j) was computed for
  std::vector<ContactClass> m_classes;        ///< after the last step
  Eigen::VectorXd m_slip_direction;           ///< -lambda_t/|lambda_t| of the last slip step, d per contact
  int m_reversals_this_step = 0;
  double m_initial_energy = 0.0;
  double m_external_work = 0.0;
  double m_contact_work = 0.0;
  double m_damping_work = 0.0;
  LinerSurface* m_liner = nullptr; ///< attach_liner (or nullptr)
  double m_normal_work = 0.0;      ///< liner: the normal rows' part of m_contact_work
  double m_wall_work = 0.0;        ///< liner: -F (g0_{n+1} - g0_{n-1}) / 2 summed
};

} // namespace rsi
