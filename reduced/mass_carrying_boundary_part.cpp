#include "mass_carrying_boundary_part.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "component_integration_error.hpp"

namespace rsi {

MassCarryingBoundaryPart::MassCarryingBoundaryPart(const ReducedBasis& basis,
                                                   const ComponentIntegratorOptions& options,
                                                   const Eigen::MatrixXd& rows)
    : ComponentRotorPart(basis, options) {
  Eigen::MatrixXd a = m_m;
  if (m_c.size()) a.diagonal() += 0.5 * m_dt * m_c;
  const Eigen::LLT<Eigen::MatrixXd> llt(a);
  if (llt.info() != Eigen::Success)
    throw ComponentIntegrationError(where() + "M^ + dt/2 C^ of the " + basis.method +
                                        " model is not positive definite (Cholesky failed)",
                                    mass_remedy());
  m_p = (m_dt * m_dt) * llt.solve(m_k);
  if (m_c.size()) m_d = m_dt * llt.solve(Eigen::MatrixXd(m_c.asDiagonal()));
  const Eigen::MatrixXd bt = boundary_transpose(rows);
  m_g = (m_dt * m_dt) * llt.solve(bt);
  m_w = bt.transpose() * m_g;
  if (m_force) {
    m_gf0 = (m_dt * m_dt) * llt.solve(m_f0);
    m_gf1 = (m_dt * m_dt) * llt.solve(m_f1);
  }
}

void MassCarryingBoundaryPart::start(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  m_external_work = 0.0;
  m_damping_work = 0.0;
  const double h2 = 0.5 * m_dt * m_dt;
  // At rest: x_{-1} = x_0 - dt^2/2 M^-1 K^ x_0, so (x_1 - x_{-1})/(2 dt) = 0 without contact.
  // With a force: x_{-1} = x_0 - dt^2/2 M^-1 (K^ x_0 - f(0)), at rest under the load of t = 0.
  m_x = q0;
  const Eigen::LLT<Eigen::MatrixXd> llt(m_m);
  if (!m_force)
    m_xp = m_x - h2 * llt.solve(m_k * m_x);
  else
    m_xp = m_x - h2 * llt.solve(Eigen::VectorXd(m_k * m_x - m_f0 - std::cos(m_phi_f) * m_f1));
  m_ub = boundary_of(m_x);
}

void MassCarryingBoundaryPart::predict(const Eigen::VectorXd& /*lambda*/, double t_n,
                                       double /*t_next*/) {
  m_xn = 2.0 * m_x - m_xp;
  m_xn.noalias() -= m_p * m_x;
  if (m_d.size()) m_xn.noalias() -= m_d * (m_x - m_xp);
  m_cn = 0.0;
  if (m_force) {
    m_cn = std::cos(m_omega_f * t_n + m_phi_f);
    m_xn += m_gf0 + m_cn * m_gf1;
  }
  m_ut = boundary_of(m_xn);
}

void MassCarryingBoundaryPart::correct(const Eigen::VectorXd& lambda) {
  // lambda_n of (*), enforcing the contact at x_{n+1}.
  if (lambda.any()) m_xn.noalias() += m_g * lambda;
  m_dx = m_xn - m_xp;
}

void MassCarryingBoundaryPart::add_step_work() {
  if (m_force) m_external_work += 0.5 * (m_f0.dot(m_dx) + m_cn * m_f1.dot(m_dx));
  if (m_c.size()) m_damping_work += m_dx.dot(m_c.cwiseProduct(m_dx)) / (4.0 * m_dt);
}

void MassCarryingBoundaryPart::advance() {
  m_xp.swap(m_x);
  m_x.swap(m_xn);
  m_ub = boundary_of(m_x);
}

void MassCarryingBoundaryPart::state_in_basis(Eigen::VectorXd& x, Eigen::VectorXd& xp) const {
  x = m_x;
  xp = m_xp;
}

} // namespace rsi
