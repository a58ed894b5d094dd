#include "coulomb_tip_solve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "reduced_integrator.hpp"

namespace rsi {

CoulombTipSolve::CoulombTipSolve(const DiskPart& disk, const CasingPart& casing, double dt,
                                 double mu)
    : TipContactSolve(disk, casing, dt, mu)
    , m_coulomb(1, mu) {}

void CoulombTipSolve::start(int n_tips) {
  TipContactSolve::start(n_tips);
  m_state_before = m_state;
  m_warm = Eigen::VectorXd::Zero(2 * n_tips);
}

Eigen::Matrix2d CoulombTipSolve::block(const TipContact& i, const TipContact& j) const {
  // Rows B_n,i = (-e(u_i); +N_i on c_u), B_t,i = (+e(v_i); -N_i on c_v); the
  // same for the columns of j.
  const Eigen::MatrixXd& disk_flexibility = m_disk.flexibility();
  double nn = disk_flexibility(i.q_u, j.q_u);
  double nt = -disk_flexibility(i.q_u, j.q_v);
  double tn = -disk_flexibility(i.q_v, j.q_u);
  double tt = disk_flexibility(i.q_v, j.q_v);
  const Eigen::MatrixXd& casing_flexibility = m_casing.flexibility();
  for (int a = 0; a < 4; ++a) {
    if (i.c_u[a] < 0) continue;
    for (int b = 0; b < 4; ++b) {
      if (j.c_u[b] < 0) continue;
      const double nab = i.shape[a] * j.shape[b];
      nn += nab * casing_flexibility(i.c_u[a], j.c_u[b]);
      nt -= nab * casing_flexibility(i.c_u[a], j.c_v[b]);
      tn -= nab * casing_flexibility(i.c_v[a], j.c_u[b]);
      tt += nab * casing_flexibility(i.c_v[a], j.c_v[b]);
    }
  }
  const double dt2 = m_dt * m_dt;
  Eigen::Matrix2d w;
  w << dt2 * nn, dt2 * nt, dt2 * tn, dt2 * tt;
  return w;
}

void CoulombTipSolve::solve(const std::vector<TipContact>& tips, int step, StepReport& report) {
  const int nt = static_cast<int>(tips.size());
  m_state_before.swap(m_state);
  m_state.assign(nt, ReducedContactState::open);
  m_lambda.setZero(nt);
  m_lambda_t.setZero(nt);
  m_certificate = ReducedCoulombCertificate{};
  m_active.assign(nt, 0);
  m_set.clear();
  m_w.resize(0, 0);
  m_rows.resize(0);
  int n_active = 0;
  for (int k = 0; k < nt; ++k) {
    if (!std::isfinite(tips[k].gap) || !std::isfinite(tips[k].slip))
      throw ReducedIntegrationError("reduced integrator: non-finite predicted gap or slip of tip " +
                                        std::to_string(k + 1) + " at step " + std::to_string(step) +
                                        " (the state blew up)",
                                    step_remedy());
    if (tips[k].gap < 0.0) m_active[k] = 1, ++n_active;
  }
  if (n_active > 0) {
    for (int round = 0;; ++round) {
      m_set.clear();
      for (int k = 0; k < nt; ++k)
        if (m_active[k]) m_set.push_back(k);
      const int m = static_cast<int>(m_set.size());
      m_w.resize(2 * m, 2 * m);
      m_rows.resize(2 * m);
      m_rows_lambda.resize(2 * m);
      for (int a = 0; a < m; ++a) {
        const TipContact& tip = tips[m_set[a]];
        m_rows(2 * a) = tip.gap;
        m_rows(2 * a + 1) = tip.slip;
        m_rows_lambda.segment<2>(2 * a) = m_warm.segment<2>(2 * m_set[a]);
        for (int b = 0; b < m; ++b)
          m_w.block<2, 2>(2 * a, 2 * b) = block(tip, tips[m_set[b]]);
      }
      const CoulombGaussSeidelReport solved = m_coulomb.solve(m_w, m_rows, m_rows_lambda);
      if (!solved.converged())
        throw ReducedIntegrationError("reduced integrator: Coulomb contact problem at step " +
                                          std::to_string(step) + ": " + solved.message,
                                      contact_remedy());
      for (int a = 0; a < m; ++a)
        m_warm.segment<2>(2 * m_set[a]) = m_rows_lambda.segment<2>(2 * a);
      bool joined = false; // tips left out whose gap the correction would close
      for (int k = 0; k < nt; ++k) {
        if (m_active[k]) continue;
        double g = tips[k].gap;
        for (int a = 0; a < m; ++a) {
          const Eigen::Matrix2d w = block(tips[k], tips[m_set[a]]);
          g += w(0, 0) * m_rows_lambda(2 * a) + w(0, 1) * m_rows_lambda(2 * a + 1);
        }
        if (g < 0.0) m_active[k] = 1, joined = true;
      }
      if (!joined) break;
      if (round >= nt)
        throw ReducedIntegrationError(
            "reduced integrator: the set of closing tips did not settle at step " +
                std::to_string(step),
            step_remedy());
    }
    m_predicted_kept = tips;
    const std::vector<ReducedContactState>& states = m_coulomb.states();
    const int m = static_cast<int>(m_set.size());
    for (int a = 0; a < m; ++a) {
      m_lambda(m_set[a]) = m_rows_lambda(2 * a);
      m_lambda_t(m_set[a]) = m_rows_lambda(2 * a + 1);
      m_state[m_set[a]] = states[a];
    }
    m_certificate = reduced_coulomb_certificate(m_w, m_rows, 1, m_mu, m_rows_lambda, states);
    // The scaled stick/slip residual (reduced_integrator.hpp).
    m_rows_y = m_rows;
    m_rows_y.noalias() += m_w * m_rows_lambda;
    const double largest = m_rows_lambda.cwiseAbs().maxCoeff();
    double scaled = largest > 0.0 ? m_certificate.max_open_residual / largest : 0.0;
    for (int a = 0; a < m; ++a) {
      const double ln = m_rows_lambda(2 * a);
      const double lt = m_rows_lambda(2 * a + 1);
      const double slip = m_rows_y(2 * a + 1);
      const double sigma =
          std::abs(m_rows(2 * a + 1)) + m_w.row(2 * a + 1).cwiseAbs().sum() * largest;
      if (states[a] == ReducedContactState::stick) {
        if (sigma > 0.0) scaled = std::max(scaled, std::abs(slip) / sigma);
      } else if (states[a] == ReducedContactState::slip) {
        if (lt != 0.0 && sigma > 0.0) {
          const double e = lt > 0.0 ? -1.0 : 1.0; // the slip direction lambda_t opposes
          scaled = std::max(scaled, std::max(-slip * e, 0.0) / sigma);
        }
        if (m_mu * ln > 0.0)
          scaled = std::max(scaled, std::abs(std::abs(lt) - m_mu * ln) / (m_mu * ln));
      }
    }
    report.max_cone_violation = m_certificate.max_cone_violation;
    report.max_stick_slip_residual = scaled;
  }
  // Tips outside the solved set stay open with lambda = 0: their start is 0.
  for (int k = 0; k < nt; ++k) {
    if (!m_active[k]) m_warm.segment<2>(2 * k).setZero();
    if (m_state[k] != m_state_before[k]) ++report.stick_slip_transitions;
    report.n_stick += m_state[k] == ReducedContactState::stick;
    report.n_slip += m_state[k] == ReducedContactState::slip;
  }
}

void CoulombTipSolve::gather_correction(const std::vector<TipContact>& tips, DiskPart& disk,
                                        CasingPart& casing) const {
  const double dt2 = m_dt * m_dt;
  for (int j = 0; j < m_lambda.size(); ++j) {
    if (m_lambda(j) == 0.0 && m_lambda_t(j) == 0.0) continue;
    const TipContact& tip = tips[j];
    const double f = dt2 * m_lambda(j);
    const double ft = dt2 * m_lambda_t(j);
    disk.add_coulomb_correction(tip, f, ft);
    casing.add_correction(tip, f, -ft);
  }
}

void CoulombTipSolve::add_contact_work(const std::vector<TipContact>& tips, bool /*corrected*/,
                                       double& work) {
  for (int j = 0; j < m_lambda.size(); ++j)
    if (m_lambda(j) != 0.0) {
      // B_n . dx and B_t . dx over dx = x_{n+1} - x_{n-1}, at tip j's entries.
      const TipContact& tip = tips[j];
      const Eigen::VectorXd& q_next = m_disk.next();
      const Eigen::VectorXd& q_prev = m_disk.previous();
      const Eigen::VectorXd& c_next = m_casing.next();
      const Eigen::VectorXd& c_prev = m_casing.previous();
      double normal = -(q_next(tip.q_u) - q_prev(tip.q_u));
      double tangential = q_next(tip.q_v) - q_prev(tip.q_v);
      for (int b = 0; b < 4; ++b)
        if (tip.c_u[b] >= 0) {
          normal += tip.shape[b] * (c_next(tip.c_u[b]) - c_prev(tip.c_u[b]));
          tangential -= tip.shape[b] * (c_next(tip.c_v[b]) - c_prev(tip.c_v[b]));
        }
      work += 0.5 * (m_lambda(j) * normal + m_lambda_t(j) * tangential);
    }
}

} // namespace rsi
