#include "liner_slip_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rsi {

namespace {

constexpr int kMaxPieces = 20;

bool same_piece(const LinearPiece& a, const LinearPiece& b) {
  return a.lower == b.lower && a.upper == b.upper;
}

bool finite_piece(const LinearPiece& p) {
  return std::isfinite(p.slope) && std::isfinite(p.intercept) && !std::isnan(p.lower) &&
         !std::isnan(p.upper);
}

} // namespace

LinerSlipSet::LinerSlipSet(double mu)
    : m_slip(mu) {}

bool LinerSlipSet::solve(const Eigen::MatrixXd& w, const Eigen::VectorXd& predicted,
                         const PieceAt& piece_at, Eigen::VectorXd& lambda) {
  const Eigen::Index m = w.rows();
  if (w.cols() != m || m % 3 != 0 || predicted.size() != m || lambda.size() != m)
    throw std::invalid_argument("LinerSlipSet::solve: W, predicted and lambda must be of one size "
                                "3 nc (W square)");
  const int nc = static_cast<int>(m / 3);
  m_iterations = 0;
  m_lambda = lambda;
  // -g_c at the multipliers (W symmetric: column 3c is row 3c).
  const auto depth = [&](int c) { return -(predicted(3 * c) + w.col(3 * c).dot(m_lambda)); };
  m_piece.resize(static_cast<size_t>(nc));
  for (int c = 0; c < nc; ++c) {
    m_piece[c] = piece_at(c, depth(c));
    if (!finite_piece(m_piece[c])) return false;
  }
  for (int solves = 0; solves < kMaxPieces; ++solves) {
    // The series spring of each contact's piece (header).
    m_w = w;
    m_pred = predicted;
    for (int c = 0; c < nc; ++c) {
      const LinearPiece& p = m_piece[c];
      if (p.slope > 0.0) {
        m_w(3 * c, 3 * c) += 1.0 / p.slope;
        m_pred(3 * c) -= p.intercept / p.slope;
      } else if (p.lower == -std::numeric_limits<double>::infinity()) {
        m_pred(3 * c) += p.upper; // below every bar: rigid at the least wear
      } else {
        return false; // a flat piece over touching bars (H = 0)
      }
    }
    ++m_iterations;
    if (!m_slip.solve(m_w, m_pred, m_lambda)) return false;
    bool moved = false;
    for (int c = 0; c < nc; ++c) {
      const double d = depth(c);
      LinearPiece q = piece_at(c, d);
      if (!finite_piece(q)) return false;
      const bool below_every_bar = q.lower == -std::numeric_limits<double>::infinity();
      // Closed on the rigid stand-in (d = the least wear up to round-off):
      // onto the first bars' piece.
      if (m_lambda(3 * c) > 0.0 && !(q.slope > 0.0) && below_every_bar)
        q = piece_at(c, std::max(d, q.upper));
      if (!finite_piece(q)) return false;
      // A flat piece over touching bars (H = 0): no series spring (header).
      if (!(q.slope > 0.0) && q.lower != -std::numeric_limits<double>::infinity()) return false;
      if (same_piece(q, m_piece[c])) continue;
      m_piece[c] = q;
      moved = true;
    }
    if (!moved) {
      lambda = m_lambda;
      return true;
    }
  }
  return false;
}

} // namespace rsi
