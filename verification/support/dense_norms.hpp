#pragma once
// Norms and pieces of dense matrices that the reduction checks bound their
// round-off with (reduction_rows, test_macneal).

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include "partition.hpp"

namespace rsi {

inline double norm_inf(const Eigen::SparseMatrix<double>& a) {
  return (a.cwiseAbs() * Eigen::VectorXd::Ones(a.cols())).maxCoeff();
}

inline double norm_inf(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  return a.cwiseAbs().rowwise().sum().maxCoeff();
}

/// Extreme eigenvalues (min, max) of a dense symmetric matrix.
inline std::pair<double, double> extreme_eigenvalues(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  const Eigen::VectorXd w = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
                                0.5 * (a + a.transpose()), Eigen::EigenvaluesOnly)
                                .eigenvalues();
  return {w(0), w(w.size() - 1)};
}

/// ||A||_2 of an n x c matrix with few columns (or rows): through the
/// c x c Gram matrix, never n x n.
inline double norm2(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  const Eigen::MatrixXd gram = a.cols() <= a.rows() ? Eigen::MatrixXd(a.transpose() * a)
                                                    : Eigen::MatrixXd(a * a.transpose());
  return std::sqrt(std::max(extreme_eigenvalues(gram).second, 0.0));
}

/// The block A(rows, cols) of a dense matrix.
inline Eigen::MatrixXd dense_block(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                   const std::vector<int>& rows, const std::vector<int>& cols) {
  return take_rows(Eigen::MatrixXd(take_rows(a, rows).transpose()), cols).transpose();
}

} // namespace rsi
