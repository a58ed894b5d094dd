#include "massless_boundary_part.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "component_integration_error.hpp"

namespace rsi {

MasslessBoundaryPart::MasslessBoundaryPart(const ReducedBasis& basis,
                                           const ComponentIntegratorOptions& options,
                                           const Eigen::MatrixXd& rows)
    : ComponentRotorPart(basis, options)
    , m_nc(static_cast<int>(rows.rows() / 3)) {
  const Eigen::MatrixXd mbb = block(m_m, m_boundary, m_boundary);
  const Eigen::MatrixXd mbi = block(m_m, m_boundary, m_interior);
  if (mbb.cwiseAbs().maxCoeff() != 0.0 || (m_ni && mbi.cwiseAbs().maxCoeff() != 0.0))
    throw std::invalid_argument(where() + "the basis is flagged massless_boundary but M^_BB or "
                                          "M^_BI is not exactly zero");
  if (m_c.size() && take(m_c, m_boundary).any())
    throw std::invalid_argument(where() + "damping on a massless boundary coordinate, allowed 0");
  const Eigen::LLT<Eigen::MatrixXd> kbb(block(m_k, m_boundary, m_boundary));
  if (kbb.info() != Eigen::Success)
    throw ComponentIntegrationError(where() + "K^_BB of the massless boundary is not positive "
                                              "definite (static condensation failed); use a "
                                              "method with a massed boundary (cb, ccm)");
  const Eigen::MatrixXd kbi = block(m_k, m_boundary, m_interior);
  m_z = -kbb.solve(kbi);
  m_g = kbb.solve(Eigen::MatrixXd(rows.transpose()));
  m_w = rows * m_g;
  Eigen::MatrixXd ai = block(m_m, m_interior, m_interior);
  if (m_c.size()) ai.diagonal() += 0.5 * m_dt * take(m_c, m_interior);
  const Eigen::LLT<Eigen::MatrixXd> llt(ai);
  if (llt.info() != Eigen::Success)
    throw ComponentIntegrationError(where() + "M^_II + dt/2 C^_I is not positive definite "
                                              "(Cholesky failed)",
                                    mass_remedy());
  // With u_B^n = Z q_I^n + S B_B^T lambda_n (the balance (B)), the force of
  // (I) is K^_II q + K^_IB u_B = K_c q + K^_IB S B_B^T lambda_n, K_c the
  // condensed stiffness K^_II - K^_IB S K^_BI (Omega_1^2 for MacNeal): a
  // contact-free step applies K_c and Z only (2 (psi^2 + psi n_B) flops),
  // the contact adds the columns of the contacts that carry a force.
  Eigen::MatrixXd kc = block(m_k, m_interior, m_interior) + kbi.transpose() * m_z;
  kc = 0.5 * (kc + kc.transpose()).eval();
  m_p = (m_dt * m_dt) * llt.solve(kc);
  m_pb = (m_dt * m_dt) * llt.solve(Eigen::MatrixXd(kbi.transpose() * m_g));
  if (m_force) {
    // (B): u_B = Z q_I + S B_B^T lambda + S f_B; (I) sees f_I - K^_IB S f_B.
    m_sf0 = kbb.solve(take(m_f0, m_boundary));
    m_sf1 = kbb.solve(take(m_f1, m_boundary));
    m_gf0 = (m_dt * m_dt) *
            llt.solve(Eigen::VectorXd(take(m_f0, m_interior) - kbi.transpose() * m_sf0));
    m_gf1 = (m_dt * m_dt) *
            llt.solve(Eigen::VectorXd(take(m_f1, m_interior) - kbi.transpose() * m_sf1));
  }
  if (m_c.size()) {
    m_ci = take(m_c, m_interior);
    const Eigen::MatrixXd mii = block(m_m, m_interior, m_interior);
    if (Eigen::MatrixXd(mii.diagonal().asDiagonal()) == mii) {
      // Diagonal M^_II (MacNeal: I): dt A^-1 C^ is the diagonal dt c/(m + dt/2 c).
      m_d_diagonal = (m_dt * m_ci).cwiseQuotient(mii.diagonal() + 0.5 * m_dt * m_ci);
    } else {
      m_d = m_dt * llt.solve(Eigen::MatrixXd(m_ci.asDiagonal()));
    }
  }
}

void MasslessBoundaryPart::start(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  m_external_work = 0.0;
  m_damping_work = 0.0;
  // The boundary at rest before t = 0: u_B^{-1} = -S K^_BI q_I^0 (contact free);
  // at t = 0 the contact is solved on the condensed boundary, lambda_0 with u_B^0.
  // With a force, the load of t = 0 acts on the boundary from t = 0 on:
  // u~_B^0 = u_B^{-1} + S f_B(0), its slip relative to u_B^{-1}.
  m_x = take(Eigen::VectorXd(q0), m_interior);
  m_up = m_z * m_x;
  m_u = m_up;
  if (!m_force)
    m_un = m_up;
  else
    m_un = m_up + m_sf0 + std::cos(m_phi_f) * m_sf1;
}

void MasslessBoundaryPart::start_balance(const Eigen::VectorXd& lambda0) {
  const double h2 = 0.5 * m_dt * m_dt;
  const double c0 = std::cos(m_phi_f);
  m_u = m_up + m_g * lambda0;
  if (m_force) m_u += m_sf0 + c0 * m_sf1;
  const Eigen::MatrixXd mii = block(m_m, m_interior, m_interior);
  const Eigen::LLT<Eigen::MatrixXd> llt(mii);
  Eigen::VectorXd force =
      block(m_k, m_interior, m_interior) * m_x + block(m_k, m_interior, m_boundary) * m_u;
  if (m_force) force -= take(Eigen::VectorXd(m_f0 + c0 * m_f1), m_interior);
  m_xp = m_x - h2 * llt.solve(force);
}

void MasslessBoundaryPart::predict(const Eigen::VectorXd& lambda, double t_n, double t_next) {
  // (I): q_I^{n+1} with u_B^n in balance with lambda_n.
  m_xn = 2.0 * m_x - m_xp;
  m_xn.noalias() -= m_p * m_x;
  for (int c = 0; c < m_nc; ++c)
    if (lambda.segment(3 * c, 3).any())
      m_xn.noalias() -= m_pb.middleCols(3 * c, 3) * lambda.segment(3 * c, 3);
  if (m_d.size()) m_xn.noalias() -= m_d * (m_x - m_xp);
  if (m_d_diagonal.size()) m_xn -= m_d_diagonal.cwiseProduct(m_x - m_xp);
  m_cn = 0.0;
  if (m_force) {
    m_cn = std::cos(m_omega_f * t_n + m_phi_f);
    m_xn += m_gf0 + m_cn * m_gf1;
  }
  // (B) at n+1, before the contact on the condensed boundary.
  m_un.noalias() = m_z * m_xn;
  if (m_force) m_un += m_sf0 + std::cos(m_omega_f * t_next + m_phi_f) * m_sf1;
}

void MasslessBoundaryPart::correct(const Eigen::VectorXd& lambda) {
  if (lambda.any()) m_un.noalias() += m_g * lambda;
}

void MasslessBoundaryPart::add_step_work() {
  if (m_force) {
    // f(t_n)^T (x_{n+1} - x_{n-1})/2 over the boundary and the interior rows.
    double w = 0.0;
    for (int k = 0; k < m_nb; ++k)
      w += (m_f0(m_boundary[k]) + m_cn * m_f1(m_boundary[k])) * (m_un(k) - m_up(k));
    for (int k = 0; k < m_ni; ++k)
      w += (m_f0(m_interior[k]) + m_cn * m_f1(m_interior[k])) * (m_xn(k) - m_xp(k));
    m_external_work += 0.5 * w;
  }
  if (m_c.size()) {
    m_work_b = m_xn - m_xp;
    m_damping_work += m_work_b.dot(m_ci.cwiseProduct(m_work_b)) / (4.0 * m_dt);
  }
}

void MasslessBoundaryPart::advance() {
  m_xp.swap(m_x);
  m_x.swap(m_xn);
  m_up.swap(m_u);
  m_u.swap(m_un);
}

Eigen::VectorXd MasslessBoundaryPart::q() const {
  Eigen::VectorXd x(m_r);
  for (int k = 0; k < m_nb; ++k)
    x(m_boundary[k]) = m_u(k);
  for (int k = 0; k < m_ni; ++k)
    x(m_interior[k]) = m_x(k);
  return x;
}

void MasslessBoundaryPart::state_in_basis(Eigen::VectorXd& x, Eigen::VectorXd& xp) const {
  x.resize(m_r);
  xp.resize(m_r);
  for (int k = 0; k < m_nb; ++k) {
    x(m_boundary[k]) = m_u(k);
    xp(m_boundary[k]) = m_up(k);
  }
  for (int k = 0; k < m_ni; ++k) {
    x(m_interior[k]) = m_x(k);
    xp(m_interior[k]) = m_xp(k);
  }
}

} // namespace rsi
