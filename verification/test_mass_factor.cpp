// reference/mass_factor: CHOLMOD's LDL^T of P M P^T applied in the permuted
// coordinates, against a dense Cholesky (Eigen LLT) of the same matrix.

#include <limits>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "mass_factor.hpp"

namespace rsi {
namespace {

/// A sparse SPD matrix with a scattered pattern (so AMD reorders it): a ring
/// of n unknowns with random couplings c_ij in (-1, 1) to 3 random partners,
/// diagonal = 4 + sum |c_ij| + shift (for shift 0 strictly diagonally
/// dominant, eigenvalues >= 4 by Gershgorin).
Eigen::SparseMatrix<double> scattered_spd(int n, double diagonal_shift) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> partner(0, n - 1);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const int j = partner(rng);
      if (j == i) continue;
      const double c = value(rng);
      a(i, j) += c, a(j, i) += c;
    }
  for (int i = 0; i < n; ++i)
    a(i, i) = 4.0 + a.row(i).cwiseAbs().sum() + diagonal_shift;
  return a.sparseView();
}

TEST(MassFactor, SolveMatchesDenseCholeskyInThePermutedCoordinates) {
  const int n = 40;
  const Eigen::SparseMatrix<double> m = scattered_spd(n, 0.0);
  MassFactor factor(m);
  const Eigen::VectorXi& position = factor.position();
  // permuted(A)(position(i), position(j)) = A(i, j), exactly (a permutation).
  const Eigen::MatrixXd mp = Eigen::MatrixXd(factor.permuted(m));
  const Eigen::MatrixXd md = Eigen::MatrixXd(m);
  double moved = 0.0;
  for (int i = 0; i < n; ++i) {
    moved += position(i) != i;
    for (int j = 0; j < n; ++j)
      ASSERT_EQ(mp(position(i), position(j)), md(i, j));
  }
  EXPECT_GT(moved, 0) << "the test matrix should make AMD reorder";

  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  Eigen::VectorXd r(n); // b in the permuted order
  for (int i = 0; i < n; ++i)
    r(position(i)) = b(i);
  factor.solve_in_place(r);
  const Eigen::VectorXd x = Eigen::LLT<Eigen::MatrixXd>(md).solve(b);
  double error = 0.0;
  for (int i = 0; i < n; ++i)
    error = std::max(error, std::abs(r(position(i)) - x(i)));
  // Both solves are backward stable: forward error <= c n eps cond(M) |x|
  // (Higham, Accuracy and Stability, thm 10.4), c = 10.
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(md).eigenvalues();
  const double cond = lambda.maxCoeff() / lambda.minCoeff();
  const double eps = std::numeric_limits<double>::epsilon();
  EXPECT_LE(error, 10.0 * n * eps * cond * x.cwiseAbs().maxCoeff());
  // 2 nnz(L) + ... : L has at least the strict lower entries of M.
  EXPECT_GE(factor.nonzeros_l(),
            (Eigen::SparseMatrix<double>(m.triangularView<Eigen::StrictlyLower>())).nonZeros());
}

TEST(MassFactor, IndefiniteMatrixIsRefused) {
  // A shift of -20 makes every diagonal entry negative (checked), so M is indefinite.
  const Eigen::SparseMatrix<double> m = scattered_spd(40, -20.0);
  ASSERT_LT(Eigen::MatrixXd(m).diagonal().maxCoeff(), 0.0);
  EXPECT_THROW(MassFactor{m}, MassFactorError);
}

} // namespace
} // namespace rsi
