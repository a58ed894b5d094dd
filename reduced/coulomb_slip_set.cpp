#include "coulomb_slip_set.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "message_number.hpp"

namespace rsi {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr int kMaxSolves = 40;
constexpr int kStalled = 3;
constexpr double kSingular =
    1e-12; ///< (1)'s reciprocal condition estimate below which it is singular

} // namespace

CoulombSlipSet::CoulombSlipSet(double mu)
    : m_mu(mu) {
  if (!(mu > 0.0) || !std::isfinite(mu))
    throw std::invalid_argument("CoulombSlipSet: mu = " + message_number(mu) +
                                ", allowed a finite value > 0");
}

bool CoulombSlipSet::solve(const Eigen::Ref<const Eigen::MatrixXd>& w,
                           const Eigen::Ref<const Eigen::VectorXd>& predicted,
                           Eigen::VectorXd& lambda) {
  const int m = static_cast<int>(w.rows());
  if (w.cols() != m || m % 3 != 0 || predicted.size() != m)
    throw std::invalid_argument(
        "CoulombSlipSet::solve: W is " + std::to_string(w.rows()) + " x " +
        std::to_string(w.cols()) + " and predicted has " + std::to_string(predicted.size()) +
        " entries, allowed W square of size 3 nc and predicted of W's size");
  const int nc = m / 3;
  if (!w.allFinite() || !predicted.allFinite()) return false; // the Gauss-Seidel reports it
  const bool warm = lambda.size() == m;
  m_iterations = 0;
  m_set.clear();
  m_in.assign(nc, 0);
  m_e.resize(2, nc);
  // Row r of [g; s] at the multipliers of `set` (W symmetric: its column r
  // is its row, contiguous).
  const auto row_at = [&](int r, const Eigen::VectorXd& multipliers, const std::vector<int>& set) {
    double y = predicted(r);
    for (int c : set)
      y += w.col(r).segment<3>(3 * c).dot(multipliers.segment<3>(3 * c));
    return y;
  };
  const auto slip_at = [&](int c, const Eigen::VectorXd& multipliers, const std::vector<int>& set) {
    return Eigen::Vector2d(row_at(3 * c + 1, multipliers, set),
                           row_at(3 * c + 2, multipliers, set));
  };
  const auto join = [&](int c, const Eigen::Vector2d& direction) {
    const double size = direction.norm();
    if (!(size > 0.0) || !std::isfinite(size)) return false;
    m_e.col(c) = direction / size;
    m_set.push_back(c);
    m_in[c] = 1;
    return true;
  };
  // S: the contacts that carried a force and the closing ones; e: their
  // slips at the warm start's multipliers (one fixed-point iteration ahead
  // of the warm start's own directions).
  std::vector<int>& carried = m_carried;
  carried.clear();
  for (int c = 0; c < nc; ++c)
    if (warm && lambda(3 * c) > 0.0) carried.push_back(c);
  for (int c = 0; c < nc; ++c)
    if ((warm && lambda(3 * c) > 0.0) || predicted(3 * c) < 0.0)
      if (!join(c, warm ? slip_at(c, lambda, carried)
                        : Eigen::Vector2d(predicted.segment<2>(3 * c + 1))))
        return false;

  m_lambda.setZero(m);
  double last_move = std::numeric_limits<double>::infinity();
  int stalled = 0;
  bool factored = false;
  while (m_iterations < kMaxSolves) {
    const int k = static_cast<int>(m_set.size());
    for (int c = 0; c < nc; ++c)
      if (!m_in[c]) m_lambda.segment<3>(3 * c).setZero();
    if (k > 0) {
      m_a.resize(k, k);
      m_rhs.resize(k);
      for (int i = 0; i < k; ++i) {
        const int ci = 3 * m_set[i];
        m_rhs(i) = -predicted(ci);
        for (int j = 0; j < k; ++j) {
          const int cj = 3 * m_set[j];
          m_a(i, j) = w(ci, cj) -
                      m_mu * (w(ci, cj + 1) * m_e(0, m_set[j]) + w(ci, cj + 2) * m_e(1, m_set[j]));
        }
      }
      // Factored once a set: the directions move (1) by mu |W_nt| |de|, and
      // iterative refinement on the set's first factors converges at that
      // rate to the same solution (the gap check below is its residual).
      if (!factored) {
        m_lu.compute(m_a);
        if (!(m_lu.rcond() > kSingular)) return false;
        m_ln = m_lu.solve(m_rhs);
        factored = true;
      } else {
        m_ln += m_lu.solve(m_rhs - m_a * m_ln);
      }
      ++m_iterations;
      if (!m_ln.allFinite()) return false;
      int leaving = -1;
      double lowest = 0.0;
      for (int i = 0; i < k; ++i)
        if (m_ln(i) < lowest) lowest = m_ln(i), leaving = i;
      if (leaving >= 0) {
        m_in[m_set[leaving]] = 0;
        m_set.erase(m_set.begin() + leaving);
        factored = false;
        last_move = std::numeric_limits<double>::infinity(), stalled = 0;
        continue;
      }
      for (int i = 0; i < k; ++i) {
        const int c = m_set[i];
        m_lambda(3 * c) = m_ln(i);
        m_lambda.segment<2>(3 * c + 1) = (-m_mu * m_ln(i)) * m_e.col(c);
      }
    }
    int closing = -1;
    double deepest = 0.0;
    for (int c = 0; c < nc; ++c) {
      if (m_in[c]) continue;
      const double g = row_at(3 * c, m_lambda, m_set);
      if (g < deepest) deepest = g, closing = c;
    }
    if (closing >= 0) {
      if (!join(closing, slip_at(closing, m_lambda, m_set))) return false;
      factored = false;
      last_move = std::numeric_limits<double>::infinity(), stalled = 0;
      continue;
    }
    double move = 0.0;
    for (int c : m_set) {
      const Eigen::Vector2d s = slip_at(c, m_lambda, m_set);
      if (!(s.dot(m_e.col(c)) > 0.0)) return false; // stick or reversal
      const Eigen::Vector2d e = s / s.norm();
      move = std::max(move, (e - m_e.col(c)).cwiseAbs().maxCoeff());
      m_e.col(c) = e;
    }
    // (1)'s residual on S: a solve or refinement on backward-stable factors
    // leaves about (3 k + 1) eps of the row's terms |g~_c| + sum |W_cj|
    // |lambda_j| (after refinement, whatever the pivots' growth); forming (1)
    // 3 eps and g (3 k terms) 3 k eps more: (6 k + 10) eps with a margin. A
    // set whose refinement has not reached it yet takes another iteration.
    const auto closed = [&]() {
      for (int c : m_set) {
        double size = std::abs(predicted(3 * c));
        for (int j : m_set)
          size +=
              w.col(3 * c).segment<3>(3 * j).cwiseAbs().dot(m_lambda.segment<3>(3 * j).cwiseAbs());
        if (!(std::abs(row_at(3 * c, m_lambda, m_set)) <= (6.0 * k + 10.0) * eps * size))
          return false;
      }
      return true;
    };
    if (move <= 8.0 * eps && closed()) {
      lambda = m_lambda;
      m_state.assign(nc, ReducedContactState::open);
      for (int c : m_set)
        m_state[c] = ReducedContactState::slip;
      return true;
    }
    // Stalled: the directions stop contracting (a converged set refining
    // (1) to its bound does not count).
    if (move > 8.0 * eps) {
      stalled = move < last_move ? 0 : stalled + 1;
      if (stalled >= kStalled) return false;
      last_move = move;
    }
  }
  return false;
}

} // namespace rsi
