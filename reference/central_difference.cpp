#include "central_difference.hpp"

#include <cmath>
#include <string>

#include <Eigen/LU>

namespace rsi {

CentralDifference::CentralDifference(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass, double dt,
                                     const ContactLaw& law)
    : m_k(stiffness)
    , m_m(mass)
    , m_dt(dt)
    , m_law(law)
    , m_inverse_columns(mass.rows()) {
  if (!(dt > 0.0)) throw std::invalid_argument("CentralDifference: dt must be > 0");
  if (stiffness.rows() != mass.rows() || stiffness.cols() != mass.cols() ||
      mass.rows() != mass.cols())
    throw std::invalid_argument("CentralDifference: K and M must be square and of the same size");
  m_mass_factor.compute(m_m);
  if (m_mass_factor.info() != Eigen::Success)
    throw IntegrationError(
        "central differences: the mass matrix is not positive definite (Cholesky failed)");
}

const Eigen::VectorXd& CentralDifference::inverse_mass_column(int dof) {
  Eigen::VectorXd& column = m_inverse_columns[dof];
  if (column.size() == 0) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(m_m.rows());
    e(dof) = 1.0;
    column = m_mass_factor.solve(e);
  }
  return column;
}

Eigen::VectorXd CentralDifference::inverse_mass_times(const SparseRow& row) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(m_m.rows());
  for (const auto& [dof, c] : row)
    out += c * inverse_mass_column(dof);
  return out;
}

double CentralDifference::discrete_energy() const {
  const Eigen::VectorXd v = (m_u - m_u_prev) / m_dt;
  return 0.5 * v.dot(m_m * v) + 0.5 * m_u_prev.dot(m_k * m_u);
}

void CentralDifference::start(const Eigen::Ref<const Eigen::VectorXd>& f0) {
  const int n = static_cast<int>(m_m.rows());
  m_n = 0;
  m_u = Eigen::VectorXd::Zero(n);
  m_u_prev = 0.5 * m_dt * m_dt * m_mass_factor.solve(f0);
  m_ku = Eigen::VectorXd::Zero(n);
  m_lambda = Eigen::VectorXd::Zero(m_law.n_constraints());
  m_gap = m_law.evaluate(m_u, Eigen::VectorXd::Zero(n), 0.0).gap;
  m_energy = discrete_energy();
  m_initial_energy = m_energy;
  m_external_work = 0.0;
  m_contact_work = 0.0;
}

Eigen::VectorXd CentralDifference::solve_active_set(const ContactState& s,
                                                    Eigen::VectorXd& correction) {
  const int nc = m_law.n_constraints();
  const double dt2 = m_dt * m_dt;
  std::vector<bool> active(nc);
  for (int k = 0; k < nc; ++k)
    active[k] = s.gap(k) < 0.0;
  std::vector<Eigen::VectorXd> md(nc); // M^-1 D_k^T, computed when k first becomes active
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(nc);
  correction = Eigen::VectorXd::Zero(m_m.rows());
  for (int iteration = 0; iteration <= 4 * nc + 4; ++iteration) {
    std::vector<int> idx;
    for (int k = 0; k < nc; ++k)
      if (active[k]) idx.push_back(k);
    const int na = static_cast<int>(idx.size());
    if (na == 0) {
      correction.setZero();
      return lambda;
    }
    Eigen::MatrixXd w(na, na);
    Eigen::VectorXd rhs(na);
    for (int b = 0; b < na; ++b)
      if (md[idx[b]].size() == 0) md[idx[b]] = inverse_mass_times(s.direction[idx[b]]);
    for (int a = 0; a < na; ++a) {
      rhs(a) = -s.gap(idx[a]);
      for (int b = 0; b < na; ++b)
        w(a, b) = dt2 * dot(s.gradient[idx[a]], md[idx[b]]);
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(w);
    if (!lu.isInvertible())
      throw IntegrationError("central differences: singular contact matrix W (" +
                             std::to_string(na) + " active constraints) at step " +
                             std::to_string(m_n + 1));
    const Eigen::VectorXd la = lu.solve(rhs);
    Eigen::Index most_negative = 0;
    if (la.minCoeff(&most_negative) < 0.0) {
      active[idx[most_negative]] = false;
      continue;
    }
    correction.setZero();
    for (int b = 0; b < na; ++b)
      correction += (dt2 * la(b)) * md[idx[b]];
    bool added = false;
    for (int k = 0; k < nc; ++k)
      if (!active[k] && s.gap(k) + dot(s.gradient[k], correction) < 0.0) {
        active[k] = true;
        added = true;
      }
    if (added) continue;
    lambda.setZero();
    for (int b = 0; b < na; ++b)
      lambda(idx[b]) = la(b);
    return lambda;
  }
  throw IntegrationError("central differences: the active set did not settle at step " +
                         std::to_string(m_n + 1));
}

StepReport CentralDifference::step(const Eigen::Ref<const Eigen::VectorXd>& f_n) {
  const double dt2 = m_dt * m_dt;
  const Eigen::VectorXd predicted = 2.0 * m_u - m_u_prev + dt2 * m_mass_factor.solve(f_n - m_ku);
  const double t_next = (m_n + 1) * m_dt;
  const ContactState s = m_law.evaluate(predicted, (predicted - m_u) / m_dt, t_next);
  Eigen::VectorXd correction;
  m_lambda = solve_active_set(s, correction);
  const Eigen::VectorXd next = predicted + correction;

  // Works of step n: (F_n + R_n)^T (u_{n+1} - u_{n-1}) / 2, R_n = sum lambda_k D_k^T.
  const Eigen::VectorXd half_span = 0.5 * (next - m_u_prev);
  m_external_work += f_n.dot(half_span);
  for (int k = 0; k < m_lambda.size(); ++k)
    if (m_lambda(k) != 0.0) m_contact_work += m_lambda(k) * dot(s.direction[k], half_span);

  m_u_prev = m_u;
  m_u = next;
  m_ku = m_k * m_u;
  ++m_n;
  m_energy = discrete_energy();

  // Monitors at the corrected state (SPEC V5).
  const ContactState after = m_law.evaluate(m_u, (m_u - m_u_prev) / m_dt, t_next);
  m_gap = after.gap;
  StepReport report;
  const double mu = m_law.friction_coefficient();
  for (int k = 0; k < m_lambda.size(); ++k) {
    report.max_penetration = std::max(report.max_penetration, -m_gap(k));
    report.min_lambda = std::min(report.min_lambda, m_lambda(k));
    report.max_complementarity =
        std::max(report.max_complementarity, std::abs(m_lambda(k) * m_gap(k)));
    if (m_lambda(k) == 0.0) continue;
    ++report.n_active;
    if (mu > 0.0) {
      // The friction force applied is -mu s lambda (s from the prediction); the
      // law wants -mu sign(v_slide) lambda with the corrected sliding velocity.
      const double actual =
          after.sliding_velocity(k) > 0.0 ? 1.0 : (after.sliding_velocity(k) < 0.0 ? -1.0 : 0.0);
      const double residual = mu * m_lambda(k) * std::abs(s.friction_sign(k) - actual);
      report.max_friction_residual = std::max(report.max_friction_residual, residual);
      if (actual != s.friction_sign(k)) ++report.sliding_reversals;
    }
  }
  return report;
}

} // namespace rsi
