#pragma once
// A random Delassus matrix for the contact solvers' tests: W = scale B M^-1
// B^T with M = A A^T / n + I (n dofs, SPD) and B random (rows x n, of full
// row rank for rows <= n with probability 1), symmetrised to the bit.

#include <random>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace rsi {

inline Eigen::MatrixXd random_delassus(int n, int rows, double scale, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd a(n, n), b(rows, n);
  for (int i = 0; i < n * n; ++i)
    a(i) = normal(rng);
  for (int i = 0; i < rows * n; ++i)
    b(i) = normal(rng);
  const Eigen::MatrixXd mass = a * a.transpose() / n + Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd w = scale * (b * Eigen::LLT<Eigen::MatrixXd>(mass).solve(b.transpose()));
  return 0.5 * (w + w.transpose());
}

} // namespace rsi
