#pragma once
// The rotor part of a reduced component with a mass-carrying boundary (CB,
// CCM, Guyan, characteristic constraint modes; M^ positive definite): scheme 1 of
// component_integrator.hpp, the whole x = q advanced explicitly (component_rotor_part.hpp).
//    A = M^ + dt/2 C^ (Cholesky once, status checked). The step n -> n+1:
//      x~ = 2 x_n - x_{n-1} - dt^2 A^-1 K^ x_n - dt A^-1 C^ (x_n - x_{n-1})
//           + dt^2 A^-1 f(t_n)   (dt^2 A^-1 f0 and dt^2 A^-1 f1 formed once),
//      x_{n+1} = x~ + dt^2 A^-1 B^T lambda_n,
//    lambda_n from the contact at x_{n+1}: [g; s] = [g~; s~] + W lambda_n,
//      W = dt^2 B A^-1 B^T  (3 nc square, an inverse mass times dt^2),
//    g~, s~ at u~_B, the boundary entries of x~ (rigid_casing_part.hpp).
//    Stable for dt < 2/omega_max of (K^, M^) (the discrete energy is
//    positive definite iff so; C^ >= 0 only removes energy); active
//    contacts only lower omega_max (constraints interlace the eigenvalues
//    from below).
// Start at rest at x_0 = q0: x_{-1} = x_0 - dt^2/2 M^-1 K^ x_0, so
// (x_1 - x_{-1})/(2 dt) = 0 without contact; with a force x_{-1} = x_0 -
// dt^2/2 M^-1 (K^ x_0 - f(0)), at rest under the load of t = 0.
// Costs per contact-free step (dense): 2 r^2 (+ 2 r^2 damped); a step with
// a closing contact adds 2 r 3 nc.

#include <Eigen/Core>

#include "component_rotor_part.hpp"

namespace rsi {

class MassCarryingBoundaryPart final : public ComponentRotorPart {
public:
  /// rows: B_B (3 nc x n_B). Throws ComponentIntegrationError when A is not
  /// positive definite.
  MassCarryingBoundaryPart(const ReducedBasis& basis, const ComponentIntegratorOptions& options,
                           const Eigen::MatrixXd& rows);

  bool contact_at_next_level() const override { return false; }
  void start(const Eigen::Ref<const Eigen::VectorXd>& q0) override;
  /// No balance at t = 0: lambda_0 acts on x_1.
  void start_balance(const Eigen::VectorXd& /*lambda0*/) override {}
  void predict(const Eigen::VectorXd& lambda, double t_n, double t_next) override;
  const Eigen::VectorXd& trial_boundary() const override { return m_ut; }
  const Eigen::VectorXd& boundary() const override { return m_ub; }
  void correct(const Eigen::VectorXd& lambda) override;
  Eigen::VectorXd boundary_increment() const override { return boundary_of(m_dx); }
  void add_step_work() override;
  void advance() override;
  bool finite() const override { return m_x.allFinite(); }
  Eigen::VectorXd q() const override { return m_x; }

private:
  void state_in_basis(Eigen::VectorXd& x, Eigen::VectorXd& xp) const override;

  Eigen::MatrixXd m_p;             ///< dt^2 A^-1 K^
  Eigen::MatrixXd m_d;             ///< dt A^-1 C^ (damped)
  Eigen::MatrixXd m_g;             ///< the correction per unit lambda, dt^2 A^-1 B^T (r x 3 nc)
  Eigen::VectorXd m_gf0, m_gf1;    ///< dt^2 A^-1 f0, dt^2 A^-1 f1 (with a force)
  Eigen::VectorXd m_x, m_xp, m_xn; ///< x_n, x_{n-1}, x_{n+1}
  Eigen::VectorXd m_ut;            ///< u~_B, the boundary entries of x~
  Eigen::VectorXd m_ub;            ///< u_B^n, the boundary entries of x_n
  Eigen::VectorXd m_dx;            ///< x_{n+1} - x_{n-1} of the corrected step
};

} // namespace rsi
