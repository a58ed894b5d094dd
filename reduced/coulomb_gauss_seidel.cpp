#include "coulomb_gauss_seidel.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/SVD>

#include "message_number.hpp"

namespace rsi {

CoulombGaussSeidel::CoulombGaussSeidel(int d, double mu, const CoulombGaussSeidelOptions& options)
    : m_d(d)
    , m_mu(mu)
    , m_options(options) {
  const std::string where = "CoulombGaussSeidel: ";
  if (d != 1 && d != 2)
    throw std::invalid_argument(where + "d (tangential directions) = " + std::to_string(d) +
                                ", allowed 1 or 2");
  if (!(mu >= 0.0) || !std::isfinite(mu))
    throw std::invalid_argument(where + "mu = " + message_number(mu) +
                                ", allowed a finite value >= 0");
  if (options.max_sweeps < 1)
    throw std::invalid_argument(where + "max_sweeps = " + std::to_string(options.max_sweeps) +
                                ", allowed >= 1");
  if (!(options.relative_change >= 0.0 && options.relative_change < 1.0))
    throw std::invalid_argument(where + "relative_change = " +
                                message_number(options.relative_change) + ", allowed [0, 1)");
  if (!(options.singular_tolerance > 0.0 && options.singular_tolerance < 1.0))
    throw std::invalid_argument(where + "singular_tolerance = " +
                                message_number(options.singular_tolerance) + ", allowed (0, 1)");
  if (!(options.local_violation > 0.0 && options.local_violation < 1.0))
    throw std::invalid_argument(where + "local_violation = " +
                                message_number(options.local_violation) + ", allowed (0, 1)");
}

void CoulombGaussSeidel::prepare(const Eigen::Ref<const Eigen::MatrixXd>& w, int c,
                                 double diagonal) {
  const int b = 1 + m_d;
  const int o = b * c;
  // W_cc equal to the bit to the one a previous solve prepared (a constant
  // W: the component integrator's, every step): its regularity and LU are
  // those already there. Comparing 9 numbers costs nothing against the SVD.
  if (m_mu != 0.0 && m_cached[c] && m_block[c].topLeftCorner(b, b) == w.block(o, o, b, b)) {
    m_prepared[c] = 1;
    return;
  }
  m_block[c].setZero();
  m_block[c].topLeftCorner(b, b) = w.block(o, o, b, b);
  m_cached[c] = m_mu != 0.0;
  if (m_mu == 0.0) {
    m_regularity[c] = diagonal > 0.0 ? w(o, o) / diagonal : 0.0;
  } else {
    const CoulombBlockMatrix block = w.block(o, o, b, b);
    const Eigen::JacobiSVD<CoulombBlockMatrix> svd(block);
    const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> sigma = svd.singularValues();
    m_regularity[c] = sigma(0) > 0.0 ? sigma(b - 1) / sigma(0) : 0.0;
    if (m_regularity[c] > m_options.singular_tolerance) m_lu[c].compute(block);
  }
  m_prepared[c] = 1;
}

CoulombGaussSeidelReport
CoulombGaussSeidel::solve(const Eigen::Ref<const Eigen::MatrixXd>& w,
                          const Eigen::Ref<const Eigen::VectorXd>& predicted,
                          Eigen::VectorXd& lambda) {
  const std::string where = "CoulombGaussSeidel::solve: ";
  const int b = 1 + m_d;
  if (w.rows() != w.cols() || w.rows() % b != 0)
    throw std::invalid_argument(where + "W is " + std::to_string(w.rows()) + " x " +
                                std::to_string(w.cols()) +
                                ", allowed square of size (1+d) nc = " + std::to_string(b) + " nc");
  const int m = static_cast<int>(w.rows());
  const int nc = m / b;
  if (predicted.size() != m)
    throw std::invalid_argument(where + "predicted has " + std::to_string(predicted.size()) +
                                " entries, allowed W's size " + std::to_string(m));
  if (!w.allFinite()) throw std::invalid_argument(where + "W: entries must be finite");
  if (!predicted.allFinite())
    throw std::invalid_argument(where + "predicted: entries must be finite");
  if (lambda.size() != m) lambda.setZero(m);
  if (!lambda.allFinite())
    throw std::invalid_argument(where + "lambda (start): entries must be finite");

  // Per contact, prepared when it first closes (most stay open): the block,
  // its regularity and (mu > 0) its LU factors.
  m_state.assign(nc, ReducedContactState::open);
  if (static_cast<int>(m_block.size()) != nc) m_cached.assign(nc, 0); // kept while nc is
  m_block.resize(nc);
  m_lu.resize(nc);
  m_regularity.resize(nc);
  m_prepared.assign(nc, 0);
  const double diagonal = m > 0 ? w.diagonal().cwiseAbs().maxCoeff() : 0.0;

  CoulombGaussSeidelReport report;
  for (int sweep = 1; sweep <= m_options.max_sweeps; ++sweep) {
    // y = [g~; s~] + W lambda from scratch, over the contacts that carry a
    // force only (most are open in a rotor/stator step).
    m_y = predicted;
    for (int c = 0; c < nc; ++c)
      if (lambda.segment(b * c, b).any())
        m_y.noalias() += w.middleCols(b * c, b) * lambda.segment(b * c, b);
    double change = 0.0;
    double size = 0.0;
    for (int c = 0; c < nc; ++c) {
      const int o = b * c;
      Eigen::Vector3d current = Eigen::Vector3d::Zero();
      Eigen::Vector3d r = Eigen::Vector3d::Zero();
      current.head(b) = lambda.segment(o, b);
      r.head(b) = m_y.segment(o, b);
      if (current.any()) r.head(b).noalias() -= w.block(o, o, b, b) * current.head(b);
      if (r(0) < 0.0 && !m_prepared[c]) prepare(w, c, diagonal);
      if (r(0) < 0.0 && !(m_regularity[c] > m_options.singular_tolerance)) {
        report.status = CoulombSweepStatus::singular_block;
        report.sweeps = sweep;
        report.failed_contact = c;
        report.message = where + "contact " + std::to_string(c) +
                         " closes (r_n = " + message_number(r(0)) +
                         " m) but its block W_cc is singular (" +
                         (m_mu == 0.0 ? "w_nn / max W_ii = " : "sigma_min / sigma_max = ") +
                         message_number(m_regularity[c]) + ", allowed > " +
                         message_number(m_options.singular_tolerance) + ")";
        return report;
      }
      const LocalCoulombSolution local =
          local_coulomb_solution(m_block[c], m_lu[c], r, m_d, m_mu, current);
      const double local_size = local.lambda.cwiseAbs().maxCoeff();
      if (!(local.violation <= m_options.local_violation) || !local.lambda.allFinite()) {
        report.status = CoulombSweepStatus::no_local_solution;
        report.sweeps = sweep;
        report.failed_contact = c;
        report.message = where + "contact " + std::to_string(c) +
                         ": no local solution (best candidate, " + to_string(local.state) +
                         ", violates the law by " + message_number(local.violation) +
                         " relative; allowed " + message_number(m_options.local_violation) +
                         ") at sweep " + std::to_string(sweep) + ", mu = " + message_number(m_mu);
        return report;
      }
      const Eigen::Vector3d delta = local.lambda - current;
      const double moved = delta.cwiseAbs().maxCoeff();
      if (moved > 0.0) {
        m_y.noalias() += w.middleCols(o, b) * delta.head(b);
        lambda.segment(o, b) = local.lambda.head(b);
      }
      m_state[c] = local.state;
      change = std::max(change, moved);
      size = std::max(size, local_size);
    }
    report.sweeps = sweep;
    report.last_change = change;
    report.size = size;
    if (change <= m_options.relative_change * size) return report;
  }
  report.status = CoulombSweepStatus::max_sweeps;
  report.message = where + "no convergence in " + std::to_string(m_options.max_sweeps) +
                   " sweeps (last change " + message_number(report.last_change) +
                   " N for |lambda| " + message_number(report.size) + " N, allowed " +
                   message_number(m_options.relative_change) +
                   " relative), mu = " + message_number(m_mu);
  return report;
}

} // namespace rsi
