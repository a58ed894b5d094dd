#include "sliding_sign_solve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "reduced_integrator.hpp"

namespace rsi {

void SlidingSignSolve::start(int n_tips) {
  TipContactSolve::start(n_tips);
  m_lambda_t_zero = true;
}

double SlidingSignSolve::flexibility(const TipContact& i, const TipContact& j) const {
  // G_i^q = -e(u_i), D_j^q = -e(u_j) - mu s_j e(v_j).
  const Eigen::MatrixXd& disk_flexibility = m_disk.flexibility();
  double w =
      disk_flexibility(i.q_u, j.q_u) + m_mu * j.sign * disk_flexibility(i.q_u, j.q_v);
  // G_i^c = sum_a N_a e(cu_a), D_j^c = sum_b N_b (e(cu_b) + mu s_j e(cv_b)).
  const Eigen::MatrixXd& casing_flexibility = m_casing.flexibility();
  for (int a = 0; a < 4; ++a) {
    if (i.c_u[a] < 0) continue;
    for (int b = 0; b < 4; ++b) {
      if (j.c_u[b] < 0) continue;
      w += i.shape[a] * j.shape[b] *
           (casing_flexibility(i.c_u[a], j.c_u[b]) +
            m_mu * j.sign * casing_flexibility(i.c_u[a], j.c_v[b]));
    }
  }
  return m_dt * m_dt * w;
}

double SlidingSignSolve::direction_dot(const TipContact& j, const Eigen::VectorXd& q_a,
                                       const Eigen::VectorXd& q_b, const Eigen::VectorXd& c_a,
                                       const Eigen::VectorXd& c_b) const {
  double sum = -(q_a(j.q_u) - q_b(j.q_u)) - m_mu * j.sign * (q_a(j.q_v) - q_b(j.q_v));
  for (int b = 0; b < 4; ++b)
    if (j.c_u[b] >= 0)
      sum += j.shape[b] *
             ((c_a(j.c_u[b]) - c_b(j.c_u[b])) + m_mu * j.sign * (c_a(j.c_v[b]) - c_b(j.c_v[b])));
  return sum;
}

void SlidingSignSolve::solve(const std::vector<TipContact>& tips, int step,
                             StepReport& /*report*/) {
  const int nt = static_cast<int>(tips.size());
  m_lambda.setZero(nt);
  int n_active = 0;
  for (int k = 0; k < nt; ++k)
    n_active += tips[k].gap < 0.0;
  if (n_active == 0) return;
  m_active.resize(nt);
  for (int k = 0; k < nt; ++k)
    m_active[k] = tips[k].gap < 0.0;
  m_w_all.resize(nt, nt);
  m_known.assign(static_cast<size_t>(nt) * nt, 0);
  auto w = [&](int i, int j) {
    if (!m_known[i * nt + j]) {
      m_w_all(i, j) = flexibility(tips[i], tips[j]);
      m_known[i * nt + j] = 1;
    }
    return m_w_all(i, j);
  };
  for (int round = 0; round < 2 * nt + 2; ++round) {
    m_set.clear();
    for (int k = 0; k < nt; ++k)
      if (m_active[k]) m_set.push_back(k);
    const int m = static_cast<int>(m_set.size());
    m_lambda.setZero(nt);
    if (m == 0) return;
    m_wa.resize(m, m);
    m_minus_gap.resize(m);
    for (int a = 0; a < m; ++a) {
      m_minus_gap(a) = -tips[m_set[a]].gap;
      for (int b = 0; b < m; ++b)
        m_wa(a, b) = w(m_set[a], m_set[b]);
    }
    m_lu.compute(m_wa);
    m_la = m_lu.solve(m_minus_gap);
    m_residual.noalias() = m_wa * m_la;
    m_residual -= m_minus_gap;
    if (!m_la.allFinite() || m_residual.norm() > 1e-8 * m_minus_gap.norm())
      throw ReducedIntegrationError("reduced integrator: singular contact matrix W at step " +
                                        std::to_string(step) + " (" + std::to_string(m) +
                                        " active tips)",
                                    contact_remedy());
    bool changed = false;
    for (int a = 0; a < m; ++a)
      if (m_la(a) < 0.0) m_active[m_set[a]] = 0, changed = true; // drop every negative multiplier
    if (changed) continue;
    for (int a = 0; a < m; ++a)
      m_lambda(m_set[a]) = m_la(a);
    for (int k = 0; k < nt; ++k) { // constraints the correction would close
      if (m_active[k]) continue;
      double g = tips[k].gap;
      for (int a = 0; a < m; ++a)
        g += w(k, m_set[a]) * m_la(a);
      if (g < 0.0) m_active[k] = 1, changed = true;
    }
    if (!changed) return;
  }
  throw ReducedIntegrationError("reduced integrator: the active set did not settle at step " +
                                    std::to_string(step),
                                step_remedy());
}

void SlidingSignSolve::gather_correction(const std::vector<TipContact>& tips, DiskPart& disk,
                                         CasingPart& casing) const {
  const double dt2 = m_dt * m_dt;
  for (int j = 0; j < m_lambda.size(); ++j) {
    if (m_lambda(j) == 0.0) continue;
    const TipContact& tip = tips[j];
    const double f = dt2 * m_lambda(j);
    disk.add_sliding_correction(tip, f, m_mu);
    casing.add_sliding_correction(tip, f, m_mu);
  }
}

void SlidingSignSolve::add_contact_work(const std::vector<TipContact>& tips, bool corrected,
                                        double& work) {
  for (int j = 0; j < m_lambda.size(); ++j)
    if (m_lambda(j) != 0.0)
      work += 0.5 * m_lambda(j) *
              direction_dot(tips[j], m_disk.next(), m_disk.previous(), m_casing.next(),
                            m_casing.previous());
  // The tangential force the law applied, -mu sign lambda (tangential_lambda()).
  if (corrected) {
    for (int j = 0; j < m_lambda.size(); ++j)
      m_lambda_t(j) = m_lambda(j) != 0.0 ? -m_mu * tips[j].sign * m_lambda(j) : 0.0;
    m_lambda_t_zero = false;
  } else if (!m_lambda_t_zero) {
    m_lambda_t.setZero();
    m_lambda_t_zero = true;
  }
}

void SlidingSignSolve::report_tip(const TipContact& now, const TipContact& predicted,
                                  double lambda, StepReport& report) const {
  if (m_mu > 0.0 && now.sign != predicted.sign) {
    ++report.sliding_reversals;
    report.max_friction_residual = std::max(report.max_friction_residual,
                                            m_mu * lambda * std::abs(now.sign - predicted.sign));
  }
}

} // namespace rsi
