#include "reduced_integrator.hpp"

#include <Eigen/LU>

namespace rsi {

ReducedIntegrator::ReducedIntegrator(const ReducedBasis& basis, const Casing& casing, double dt,
                                     const ReducedTipContact& contact)
    : m_kq(basis.stiffness)
    , m_mq(basis.mass)
    , m_kc(casing.stiffness)
    , m_mc(casing.mass)
    , m_dt(dt)
    , m_mu(contact.friction_coefficient())
    , m_contact(contact) {
  const Eigen::LLT<Eigen::MatrixXd> mq_factor(m_mq);
  if (mq_factor.info() != Eigen::Success)
    throw ReducedIntegrationError(
        "reduced integrator: the reduced mass matrix is not positive definite");
  m_mq_inverse = mq_factor.solve(Eigen::MatrixXd::Identity(m_mq.rows(), m_mq.cols()));
  m_aq = mq_factor.solve(m_kq);
  m_mc_factor.compute(casing.mass);
  if (m_mc_factor.info() != Eigen::Success)
    throw ReducedIntegrationError(
        "reduced integrator: the casing mass matrix is not positive definite");
  m_mc_inverse = m_mc_factor.solve(Eigen::MatrixXd::Identity(casing.n_dofs(), casing.n_dofs()));
}

double ReducedIntegrator::casing_flops_per_step() const {
  const auto nnz_l = static_cast<double>(m_mc_factor.matrixL().nestedExpression().nonZeros());
  return 2.0 * static_cast<double>(m_kc.nonZeros()) + 4.0 * nnz_l +
         13.0 * static_cast<double>(m_kc.rows());
}

double ReducedIntegrator::flops_per_step() const {
  const auto r = static_cast<double>(m_kq.rows());
  return 2.0 * r * r + 12.0 * r + casing_flops_per_step();
}

double ReducedIntegrator::energy() const {
  const Eigen::VectorXd vq = (m_q - m_q_prev) / m_dt;
  const Eigen::VectorXd vc = (m_c - m_c_prev) / m_dt;
  return 0.5 * vq.dot(m_mq * vq) + 0.5 * m_q_prev.dot(m_kq * m_q) + 0.5 * vc.dot(m_mc * vc) +
         0.5 * m_c_prev.dot(m_kc_c);
}

void ReducedIntegrator::start(const Eigen::VectorXd& casing_force) {
  m_n = 0;
  m_q = m_q_prev = Eigen::VectorXd::Zero(m_kq.rows());
  m_c = m_kc_c = Eigen::VectorXd::Zero(m_kc.rows());
  m_c_prev = 0.5 * m_dt * m_dt * m_mc_factor.solve(casing_force);
  m_contact.evaluate(m_q, m_q, m_c, m_c, 0.0, m_tips);
  m_gap.resize(m_contact.n_tips());
  for (int k = 0; k < m_contact.n_tips(); ++k)
    m_gap(k) = m_tips[k].gap;
  m_lambda = Eigen::VectorXd::Zero(m_contact.n_tips());
  m_initial_energy = energy();
  m_external_work = m_contact_work = 0.0;
}

double ReducedIntegrator::flexibility(const TipContact& i, const TipContact& j) const {
  // G_i^q = -e(u_i), D_j^q = -e(u_j) - mu s_j e(v_j).
  double w = m_mq_inverse(i.q_u, j.q_u) + m_mu * j.sign * m_mq_inverse(i.q_u, j.q_v);
  // G_i^c = sum_a N_a e(cu_a), D_j^c = sum_b N_b (e(cu_b) + mu s_j e(cv_b)).
  for (int a = 0; a < 4; ++a) {
    if (i.c_u[a] < 0) continue;
    for (int b = 0; b < 4; ++b) {
      if (j.c_u[b] < 0) continue;
      w += i.shape[a] * j.shape[b] *
           (m_mc_inverse(i.c_u[a], j.c_u[b]) + m_mu * j.sign * m_mc_inverse(i.c_u[a], j.c_v[b]));
    }
  }
  return m_dt * m_dt * w;
}

double ReducedIntegrator::direction_dot(const TipContact& j, const Eigen::VectorXd& dq,
                                        const Eigen::VectorXd& dc) const {
  double sum = -dq(j.q_u) - m_mu * j.sign * dq(j.q_v);
  for (int b = 0; b < 4; ++b)
    if (j.c_u[b] >= 0) sum += j.shape[b] * (dc(j.c_u[b]) + m_mu * j.sign * dc(j.c_v[b]));
  return sum;
}

void ReducedIntegrator::solve_contact(const std::vector<TipContact>& tips) {
  const int nt = static_cast<int>(tips.size());
  m_lambda.setZero(nt);
  std::vector<char> active(nt, 0);
  int n_active = 0;
  for (int k = 0; k < nt; ++k)
    n_active += active[k] = tips[k].gap < 0.0;
  if (n_active == 0) return;
  Eigen::MatrixXd w_all(nt, nt);
  std::vector<char> known(nt * nt, 0);
  auto w = [&](int i, int j) {
    if (!known[i * nt + j]) {
      w_all(i, j) = flexibility(tips[i], tips[j]);
      known[i * nt + j] = 1;
    }
    return w_all(i, j);
  };
  for (int round = 0; round < 2 * nt + 2; ++round) {
    std::vector<int> set;
    for (int k = 0; k < nt; ++k)
      if (active[k]) set.push_back(k);
    const int m = static_cast<int>(set.size());
    m_lambda.setZero(nt);
    if (m == 0) return;
    Eigen::MatrixXd wa(m, m);
    Eigen::VectorXd minus_gap(m);
    for (int a = 0; a < m; ++a) {
      minus_gap(a) = -tips[set[a]].gap;
      for (int b = 0; b < m; ++b)
        wa(a, b) = w(set[a], set[b]);
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(wa);
    const Eigen::VectorXd la = lu.solve(minus_gap);
    if (!la.allFinite() || (wa * la - minus_gap).norm() > 1e-8 * minus_gap.norm())
      throw ReducedIntegrationError("reduced integrator: singular contact matrix W at step " +
                                    std::to_string(m_n + 1));
    bool changed = false;
    for (int a = 0; a < m; ++a)
      if (la(a) < 0.0) active[set[a]] = 0, changed = true; // drop every negative multiplier
    if (changed) continue;
    for (int a = 0; a < m; ++a)
      m_lambda(set[a]) = la(a);
    for (int k = 0; k < nt; ++k) { // constraints the correction would close
      if (active[k]) continue;
      double g = tips[k].gap;
      for (int a = 0; a < m; ++a)
        g += w(k, set[a]) * la(a);
      if (g < 0.0) active[k] = 1, changed = true;
    }
    if (!changed) return;
  }
  throw ReducedIntegrationError("reduced integrator: the active set did not settle at step " +
                                std::to_string(m_n + 1));
}

StepReport ReducedIntegrator::step(const Eigen::VectorXd& casing_force) {
  const double dt2 = m_dt * m_dt;
  m_q_next.noalias() = 2.0 * m_q - m_q_prev - dt2 * (m_aq * m_q);
  m_c_next = m_mc_factor.solve(casing_force - m_kc_c);
  m_c_next = 2.0 * m_c - m_c_prev + dt2 * m_c_next;
  const double t_next = (m_n + 1) * m_dt;
  m_contact.evaluate(m_q_next, (m_q_next - m_q) / m_dt, m_c_next, (m_c_next - m_c) / m_dt, t_next,
                     m_tips);
  const std::vector<TipContact> predicted = m_tips;
  solve_contact(predicted);

  const bool corrected = m_lambda.any();
  if (corrected) {
    m_dq.setZero(m_q.size());
    m_dc.setZero(m_c.size());
    for (int j = 0; j < m_lambda.size(); ++j) {
      if (m_lambda(j) == 0.0) continue;
      const TipContact& tip = predicted[j];
      const double f = dt2 * m_lambda(j);
      m_dq -= f * (m_mq_inverse.col(tip.q_u) + m_mu * tip.sign * m_mq_inverse.col(tip.q_v));
      for (int b = 0; b < 4; ++b)
        if (tip.c_u[b] >= 0)
          m_dc += f * tip.shape[b] *
                  (m_mc_inverse.col(tip.c_u[b]) + m_mu * tip.sign * m_mc_inverse.col(tip.c_v[b]));
    }
    m_q_next += m_dq;
    m_c_next += m_dc;
  }
  // Works of step n: (F_n + R_n)^T (x_{n+1} - x_{n-1}) / 2.
  const Eigen::VectorXd span_q = m_q_next - m_q_prev;
  const Eigen::VectorXd span_c = m_c_next - m_c_prev;
  m_external_work += 0.5 * casing_force.dot(span_c);
  for (int j = 0; j < m_lambda.size(); ++j)
    if (m_lambda(j) != 0.0)
      m_contact_work += 0.5 * m_lambda(j) * direction_dot(predicted[j], span_q, span_c);

  m_q_prev.swap(m_q);
  m_q.swap(m_q_next);
  m_c_prev.swap(m_c);
  m_c.swap(m_c_next);
  m_kc_c.noalias() = m_kc * m_c;
  ++m_n;

  StepReport report;
  if (corrected)
    m_contact.evaluate(m_q, (m_q - m_q_prev) / m_dt, m_c, (m_c - m_c_prev) / m_dt, t_next, m_tips);
  for (int k = 0; k < m_lambda.size(); ++k) {
    const double g = m_tips[k].gap;
    const double l = m_lambda(k);
    m_gap(k) = g;
    report.max_penetration = std::max(report.max_penetration, -g);
    report.min_lambda = std::min(report.min_lambda, l);
    report.max_complementarity = std::max(report.max_complementarity, std::abs(l * g));
    if (l == 0.0) continue;
    ++report.n_active;
    if (m_mu > 0.0 && m_tips[k].sign != predicted[k].sign) {
      ++report.sliding_reversals;
      report.max_friction_residual = std::max(
          report.max_friction_residual, m_mu * l * std::abs(m_tips[k].sign - predicted[k].sign));
    }
  }
  return report;
}

} // namespace rsi
