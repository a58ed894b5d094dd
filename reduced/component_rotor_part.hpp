#pragma once
// The rotor part of a reduced component's integration
// (component_integrator.hpp): the component's share of the central-difference
// step (*) of that header in the reduced coordinates q of a ReducedBasis
// (the boundary dofs u_B are coordinates of q, at
// ReducedBasis::boundary_position, or, for characteristic constraint modes,
// u_B = Psi_c q_c: boundary_of), whichever constraint determines the
// step's multiplier: mass_carrying_boundary_part.hpp (CB, CCM, Guyan; the
// contact at x_{n+1} determines lambda_n) or massless_boundary_part.hpp
// (MacNeal; a static balance of u_B at every time level, lambda_{n+1} with
// u_B^{n+1}). Each states its scheme in its header. The part holds K^, M^,
// C^ = diag(c) (zero on the boundary) and the external force
//   f(t) = f0 + f1 cos(omega_f t + phi_f)
// in reduced coordinates (r entries each, zeros where not given; none:
// skipped, not added as zeros), hands the contact problem its matrix W
// (3 nc square) and the trial boundary displacement u~_B of each step, takes
// the contact's correction B_B^T lambda, and sums the step's
//   W_ext  += f(t_n)^T (x_{n+1} - x_{n-1})/2,
//   W_damp += (x_{n+1} - x_{n-1})^T C^ (x_{n+1} - x_{n-1})/(4 dt),
// with the energy E_{n-1/2} = 1/2 v^T M^ v + 1/2 x_{n-1}^T K^ x_n,
// v = (x_n - x_{n-1})/dt. The part's arguments are checked by
// ComponentIntegrator (sizes, finiteness, signs).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "component_integrator_options.hpp"
#include "failure_kinds.hpp"
#include "reduced_basis.hpp"

namespace rsi {

class ComponentRotorPart {
public:
  virtual ~ComponentRotorPart() = default;
  ComponentRotorPart(const ComponentRotorPart&) = delete;
  ComponentRotorPart& operator=(const ComponentRotorPart&) = delete;

  int n_reduced() const { return m_r; }
  /// W of the contact problem (3 nc square, as formed: not yet symmetrised).
  const Eigen::MatrixXd& contact_matrix() const { return m_w; }
  /// true: the step's contact determines lambda_{n+1} with u_B^{n+1} (a
  /// static balance at every time level, also at t = 0); false: lambda_n,
  /// enforcing the contact at x_{n+1}.
  virtual bool contact_at_next_level() const = 0;

  bool has_external_force() const { return m_force; }
  /// f(t), r entries (zeros without a force).
  Eigen::VectorXd external_force(double t) const;

  /// At rest at q0 (r entries, checked by the caller), no work summed.
  virtual void start(const Eigen::Ref<const Eigen::VectorXd>& q0) = 0;
  /// The balance at t = 0 with the contact's lambda_0 (only when
  /// contact_at_next_level(): the contact was solved at trial_boundary()).
  virtual void start_balance(const Eigen::VectorXd& lambda0) = 0;
  /// The prediction of the step t_n -> t_next with the multipliers of the
  /// step that produced x_n; sets trial_boundary().
  virtual void predict(const Eigen::VectorXd& lambda, double t_n, double t_next) = 0;
  /// u~_B of the last prediction (n_B entries).
  virtual const Eigen::VectorXd& trial_boundary() const = 0;
  /// u_B at the last time level reached (the slips' origin; n_B entries).
  virtual const Eigen::VectorXd& boundary() const = 0;
  /// Adds the contact's correction of the step's solved multipliers.
  virtual void correct(const Eigen::VectorXd& lambda) = 0;
  /// u_B^{n+1} - u_B^{n-1} of the corrected step.
  virtual Eigen::VectorXd boundary_increment() const = 0;
  /// Sums the corrected step's W_ext and W_damp.
  virtual void add_step_work() = 0;
  /// x_{n-1} <- x_n <- x_{n+1}.
  virtual void advance() = 0;

  /// x_n in the basis' coordinate order.
  virtual Eigen::VectorXd q() const = 0;
  /// The explicitly advanced coordinates of x_n are finite (the boundary of
  /// a massless one is checked through the gaps).
  virtual bool finite() const = 0;
  /// E_{n-1/2} [energy unit of the component].
  double energy() const;
  double external_work() const { return m_external_work; }
  double damping_work() const { return m_damping_work; }

protected:
  ComponentRotorPart(const ReducedBasis& basis, const ComponentIntegratorOptions& options);
  /// x_n and x_{n-1} in the basis' coordinate order (r entries each).
  virtual void state_in_basis(Eigen::VectorXd& x, Eigen::VectorXd& xp) const = 0;
  /// The rows `rows` and columns `cols` of a.
  static Eigen::MatrixXd block(const Eigen::MatrixXd& a, const std::vector<int>& rows,
                               const std::vector<int>& cols);
  /// The entries `rows` of a.
  static Eigen::VectorXd take(const Eigen::VectorXd& a, const std::vector<int>& rows);
  /// u_B of the reduced coordinates x: its entries at m_boundary, or
  /// Psi_c q_c (characteristic constraint modes).
  Eigen::VectorXd boundary_of(const Eigen::VectorXd& x) const;
  /// B_q^T = (rows U)^T, r x 3 nc, for the contact rows B_B (3 nc x n_B) and
  /// u_B = U x (a selection, or Psi_c on q_c).
  Eigen::MatrixXd boundary_transpose(const Eigen::MatrixXd& rows) const;
  /// What to change when the reduced mass fails: a consistent mass may be
  /// singular (Rotor 37's C3D15), T^T M T with it.
  static FailureAdvice mass_remedy();
  /// The prefix of the messages.
  static const std::string& where();

  double m_dt;
  int m_r, m_nb, m_ni;
  std::vector<int> m_boundary;     ///< positions of u_B in q (boundary order); none for CC
  Eigen::MatrixXd m_shapes;        ///< Psi_c, n_B x n_c (CC: u_B = Psi_c q_c); empty otherwise
  std::vector<int> m_interior;     ///< the other positions, ascending
  Eigen::MatrixXd m_k;             ///< K^
  Eigen::MatrixXd m_m;             ///< M^
  Eigen::VectorXd m_mass_diagonal; ///< M^'s diagonal when M^ is diagonal (energy), else empty
  Eigen::VectorXd m_c;             ///< diag C^ (empty: undamped)
  Eigen::MatrixXd m_w;             ///< W of the contact problem, set by the derived part
  // External force (m_force false: none, the vectors empty).
  bool m_force = false;
  double m_omega_f = 0.0, m_phi_f = 0.0;
  Eigen::VectorXd m_f0, m_f1; ///< f0, f1 (r entries; zeros where not given)
  double m_cn = 0.0;          ///< cos(omega_f t_n + phi_f) of the step (with a force)
  double m_external_work = 0.0, m_damping_work = 0.0;
};

} // namespace rsi
