#pragma once
// The shift-invert operator y = (K - sigma M)^-1 x of the generalized
// problem K phi = lambda M phi, for Spectra's SymGEigsShiftSolver (rows(),
// cols(), set_shift(sigma), perform_op(x, y)) and for blocks of vectors
// (solve()).
//
// K - sigma M is factorized by CHOLMOD (linalg/cholmod_factor, supernodal
// L L^T by default), so it must be positive definite: K symmetric positive
// definite and sigma below the lowest eigenvalue (sigma = 0 for a supported
// part; a singular K fails). M symmetric; its explicit zeros are dropped
// (CalculiX writes M on K's pattern, two thirds zeros for solid elements).
// Both matrices in full (symmetric) storage, only their lower triangles are
// read; the operator keeps its own copies of them (owns them).
//
// Status: set_shift() factorizes and records the result in info() and
// message() without throwing, so the caller checks it before iterating;
// perform_op() on a failed factor, or a failed CHOLMOD solve, throws
// std::runtime_error (Spectra cannot take a status from it). solve()
// returns false instead. n_solves() counts the right-hand sides solved.
// Both poll the interruption flag first (interruption_flag.hpp) and throw
// Interrupted when a signal was recorded.

#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "cholmod_factor.hpp"

namespace rsi {

class CholmodShiftInvert {
public:
  using Scalar = double;

  CholmodShiftInvert(const Eigen::SparseMatrix<double>& stiffness,
                     const Eigen::SparseMatrix<double>& mass,
                     CholmodFactor::Method method = CholmodFactor::Method::supernodal);

  Eigen::Index rows() const { return m_lower.rows(); }
  Eigen::Index cols() const { return m_lower.rows(); }

  /// Factorizes K - sigma M (the analysis of the pattern on the first call;
  /// the shift of the present successful factor again: nothing to do).
  void set_shift(double sigma);
  double shift() const { return m_sigma; }
  bool factorized() const { return m_factor.info() == CholmodFactor::Status::successful; }
  CholmodFactor::Status info() const { return m_factor.info(); }
  const std::string& message() const { return m_factor.message(); }
  const CholmodFactor& factor() const { return m_factor; }

  /// y = (K - sigma M)^-1 x (n entries each); throws std::runtime_error on failure.
  void perform_op(const double* x_in, double* y_out) const;
  /// x = (K - sigma M)^-1 b for every column; false on failure.
  [[nodiscard]] bool solve(const Eigen::Ref<const Eigen::MatrixXd>& b,
                           Eigen::Ref<Eigen::MatrixXd> x) const;
  /// Right-hand sides solved so far (a block of k counts k).
  long n_solves() const { return m_n_solves; }

private:
  Eigen::SparseMatrix<double> m_lower;   ///< lower triangle of K - sigma M (pattern of K + M)
  Eigen::SparseMatrix<double> m_lower_k; ///< lower triangle of K on that pattern
  Eigen::SparseMatrix<double> m_lower_m; ///< lower triangle of M on that pattern
  CholmodFactor m_factor;
  double m_sigma = 0.0;
  mutable long m_n_solves = 0;
};

} // namespace rsi
