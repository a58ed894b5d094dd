#include "coulomb_node_solve.hpp"

#include <algorithm>
#include <string>

#include "component_integration_error.hpp"
#include "message_number.hpp"
#include "reduced_coulomb_certificate.hpp"

namespace rsi {

namespace {
const std::string kWhere = "ComponentIntegrator: ";
} // namespace

CoulombNodeSolve::CoulombNodeSolve(int n_contacts, double dt, double mu,
                                   const CoulombGaussSeidelOptions& options, bool closing_subset)
    : m_nc(n_contacts)
    , m_dt(dt)
    , m_mu(mu)
    , m_subset(closing_subset)
    , m_solver(2, mu, options) {
  if (mu > 0.0) m_slip.emplace(mu);
}

void CoulombNodeSolve::set_contact_matrix(const Eigen::MatrixXd& w) {
  m_w = 0.5 * (w + w.transpose()).eval();
  m_lambda_next.setZero(3 * m_nc);
  m_state.assign(m_nc, ReducedContactState::open);
}

void CoulombNodeSolve::set_flexibility(const Eigen::MatrixXd* h, double scale) {
  m_h = h != nullptr && h->cols() > 0 ? h : nullptr;
  m_h_scale = scale;
}

Eigen::VectorXd CoulombNodeSolve::certificate_point(const Eigen::VectorXd& predicted,
                                                    const std::vector<int>& active) const {
  // y = predicted + (W + scale h h^T) lambda, lambda zero off the active
  // contacts: W's active columns, and h (h_A^T lambda_A) = h m_z.
  Eigen::VectorXd y = predicted;
  for (size_t i = 0; i < active.size(); ++i)
    y.noalias() += m_w.middleCols(3 * active[i], 3) * m_lambda_next.segment(3 * active[i], 3);
  y.noalias() += m_h_scale * (*m_h * m_z);
  return y;
}

void CoulombNodeSolve::start() {
  m_contact_work = 0.0;
  m_sweeps = 0;
  m_lambda_next.setZero();
  m_state.assign(m_nc, ReducedContactState::open);
}

void CoulombNodeSolve::add_contact_work(const Eigen::VectorXd& lambda_n,
                                        const Eigen::MatrixXd& rows,
                                        const Eigen::VectorXd& increment) {
  m_contact_work += 0.5 * lambda_n.dot(rows * increment);
}

void CoulombNodeSolve::solve(const Eigen::VectorXd& predicted, int step, StepReport& report) {
  const std::vector<ReducedContactState> before = m_state;
  // The direct slip solve first unless a contact stuck at the previous step
  // (coulomb_slip_set.hpp: it declines stick, and would only cost there).
  bool sticking = false;
  for (ReducedContactState s : before)
    sticking = sticking || s == ReducedContactState::stick;
  bool closing = false;
  for (int c = 0; c < m_nc; ++c)
    closing = closing || predicted(3 * c) < 0.0;
  if (!closing) {
    // lambda = 0 solves the step's problem: g = g~ >= 0 for every contact.
    m_lambda_next.setZero();
    m_state.assign(m_nc, ReducedContactState::open);
  } else {
    // The solve on the contacts that may carry a force: A = the closing ones
    // (g~ < 0) and those that carried a force at the previous step (fewer
    // re-solves), grown by every contact that the others' forces close
    // (g~_c + W_cA lambda_A < 0), until none does. A lambda that vanishes off
    // A, with those gaps >= 0, satisfies the whole problem's law (open
    // contacts: lambda_c = 0, g_c >= 0); the certificate below checks it on
    // the whole W. Most steps close few of the contacts: the Gauss-Seidel
    // works on 3 |A| rows instead of 3 nc.
    std::vector<int> active;
    std::vector<char> in(m_nc, 0);
    for (int c = 0; c < m_nc; ++c)
      if (predicted(3 * c) < 0.0 || m_lambda_next(3 * c) > 0.0 || !m_subset) {
        active.push_back(c);
        in[c] = 1;
      }
    for (;;) {
      const int na = static_cast<int>(active.size());
      m_wa.resize(3 * na, 3 * na);
      m_pa.resize(3 * na);
      m_la.resize(3 * na);
      for (int i = 0; i < na; ++i) {
        m_pa.segment(3 * i, 3) = predicted.segment(3 * active[i], 3);
        m_la.segment(3 * i, 3) = m_lambda_next.segment(3 * active[i], 3); // warm start
        for (int j = 0; j < na; ++j)
          m_wa.block(3 * i, 3 * j, 3, 3) = m_w.block(3 * active[i], 3 * active[j], 3, 3);
      }
      if (m_h != nullptr) {
        m_ha.resize(3 * na, m_h->cols());
        for (int i = 0; i < na; ++i)
          m_ha.middleRows(3 * i, 3) = m_h->middleRows(3 * active[i], 3);
        // Symmetric to the last bit, as the whole W was (its symmetrised copy).
        const Eigen::MatrixXd share = m_h_scale * (m_ha * m_ha.transpose());
        m_wa += 0.5 * (share + share.transpose());
      }
      const bool direct = m_slip && !sticking && m_slip->solve(m_wa, m_pa, m_la);
      if (!direct) {
        const CoulombGaussSeidelReport r = m_solver.solve(m_wa, m_pa, m_la);
        m_sweeps += r.sweeps;
        if (!r.converged())
          throw ComponentIntegrationError(kWhere + "step " + std::to_string(step) +
                                              " (t = " + message_number(step * m_dt) +
                                              " s): contact solve failed: " + r.message,
                                          remedied_by({Remedy::smaller_step_safety_or_friction}));
      }
      const std::vector<ReducedContactState>& solved =
          direct ? m_slip->states() : m_solver.states();
      m_lambda_next.setZero();
      m_state.assign(m_nc, ReducedContactState::open);
      for (int i = 0; i < na; ++i) {
        m_lambda_next.segment(3 * active[i], 3) = m_la.segment(3 * i, 3);
        m_state[active[i]] = solved[i];
      }
      bool grown = false;
      if (m_h != nullptr) m_z.noalias() = m_ha.transpose() * m_la;
      for (int c = 0; c < m_nc; ++c) {
        if (in[c]) continue;
        double g = predicted(3 * c);
        for (int i = 0; i < na; ++i)
          g += m_w.row(3 * c).segment(3 * active[i], 3).dot(m_la.segment(3 * i, 3));
        if (m_h != nullptr) g += m_h_scale * m_h->row(3 * c).dot(m_z);
        if (g < 0.0) {
          active.push_back(c);
          in[c] = 1;
          grown = true;
        }
      }
      if (!grown) break;
    }
    const ReducedCoulombCertificate cert =
        m_h == nullptr
            ? reduced_coulomb_certificate(m_w, predicted, 2, m_mu, m_lambda_next, m_state)
            : reduced_coulomb_certificate_of(certificate_point(predicted, active), 2, m_mu,
                                             m_lambda_next, m_state);
    report.max_penetration = cert.max_penetration;
    report.min_lambda = cert.min_normal;
    report.max_complementarity = cert.max_complementarity;
    report.max_cone_violation = cert.max_cone_violation;
    // Scaled: stick residual per the largest predicted slip, slip residual
    // per the largest friction bound mu lambda_n (0 when the step has none).
    double slip_scale = 0.0, force_scale = 0.0;
    for (int c = 0; c < m_nc; ++c) {
      slip_scale = std::max(slip_scale, predicted.segment(3 * c + 1, 2).norm());
      force_scale = std::max(force_scale, m_mu * m_lambda_next(3 * c));
    }
    const double stick = slip_scale > 0.0 ? cert.max_stick_residual / slip_scale : 0.0;
    const double slip = force_scale > 0.0 ? cert.max_slip_residual / force_scale : 0.0;
    report.max_stick_slip_residual =
        std::max({stick, slip, force_scale > 0.0 ? cert.max_open_residual / force_scale : 0.0});
    report.n_stick = cert.n_stick;
    report.n_slip = cert.n_slip;
  }
  report.n_active = report.n_stick + report.n_slip;
  for (int c = 0; c < m_nc; ++c)
    if (m_state[c] != before[c]) ++report.stick_slip_transitions;
}

} // namespace rsi
