// reference/mass_factor: CHOLMOD's LDL^T of P M P^T applied in the permuted
// coordinates by its own triangular solves, against a dense Cholesky (Eigen
// LLT) of the same matrix and against Eigen's sparse triangular solves on
// the same factor.

#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

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

/// Two scattered SPD blocks of sizes n1 and n2 (no coupling), their dofs
/// interleaved (dof 2k in the first while k < n1), so that the factor must
/// find the blocks.
Eigen::SparseMatrix<double> two_interleaved_blocks(int n1, int n2) {
  const Eigen::MatrixXd a = Eigen::MatrixXd(scattered_spd(n1, 0.0));
  const Eigen::MatrixXd b = Eigen::MatrixXd(scattered_spd(n2, 1.0));
  const int n = n1 + n2;
  std::vector<int> dof(n); // dof of block index k (first block, then second)
  int next_a = 0;
  int next_b = n1;
  for (int i = 0; i < n; ++i) {
    const bool to_a = next_b == n || (next_a < n1 && i % 2 == 0);
    dof[to_a ? next_a++ : next_b++] = i;
  }
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n1; ++i)
    for (int j = 0; j < n1; ++j)
      m(dof[i], dof[j]) = a(i, j);
  for (int i = 0; i < n2; ++i)
    for (int j = 0; j < n2; ++j)
      m(dof[n1 + i], dof[n1 + j]) = b(i, j);
  return m.sparseView();
}

TEST(MassFactor, FactorReproducesThePermutedMatrixAndItsBlocks) {
  const int n1 = 30;
  const int n2 = 17;
  const Eigen::SparseMatrix<double> m = two_interleaved_blocks(n1, n2);
  const MassFactor factor(m);
  const int n = n1 + n2;
  // L D L^T = P M P^T, entrywise within 2 gamma_{n} (|L| |D| |L^T|) (Higham, thm 10.3, LDL^T).
  const Eigen::MatrixXd l = Eigen::MatrixXd::Identity(n, n) +
                            Eigen::MatrixXd(Eigen::SparseMatrix<double>(factor.strictly_lower_l()));
  EXPECT_EQ((l - Eigen::MatrixXd(l.triangularView<Eigen::Lower>())).cwiseAbs().maxCoeff(), 0.0)
      << "L must be lower triangular in the permuted numbering";
  const Eigen::VectorXd d = factor.inverse_d().cwiseInverse();
  const Eigen::MatrixXd mp = Eigen::MatrixXd(factor.permuted(m));
  const Eigen::MatrixXd ldlt = l * d.asDiagonal() * l.transpose();
  const Eigen::MatrixXd scale = l.cwiseAbs() * d.cwiseAbs().asDiagonal() * l.transpose().cwiseAbs();
  const double eps = std::numeric_limits<double>::epsilon();
  const double gamma_n = n * eps / (1.0 - n * eps);
  const double ratio = ((ldlt - mp).cwiseAbs().array() /
                        (2.0 * gamma_n * scale.array() + std::numeric_limits<double>::min()))
                           .maxCoeff();
  std::printf("max |L D L^T - P M P^T| / (2 gamma_n |L||D||L^T|) = %.3f\n", ratio);
  EXPECT_LE(ratio, 1.0);

  // Each block is a contiguous range; M'^-1 vanishes outside the range of a column.
  int sizes[2] = {0, 0};
  for (int p = 0; p < n;) {
    const auto [first, size] = factor.block(p);
    ASSERT_EQ(first, p);
    for (int q = p; q < p + size; ++q)
      ASSERT_EQ(factor.block(q).first, first);
    (size == n1 ? sizes[0] : sizes[1]) = static_cast<int>(size);
    p += static_cast<int>(size);
  }
  EXPECT_EQ(sizes[0], n1);
  EXPECT_EQ(sizes[1], n2);
  for (int p = 0; p < n; ++p) {
    Eigen::VectorXd column = Eigen::VectorXd::Unit(n, p);
    factor.solve_in_place(column);
    const auto [first, size] = factor.block(p);
    EXPECT_EQ(column.head(first).cwiseAbs().sum() + column.tail(n - first - size).cwiseAbs().sum(),
              0.0)
        << "column " << p;
  }
}

TEST(MassFactor, SolveMatchesEigensTriangularSolvesOnTheSameFactor) {
  // The same L and D through Eigen's sparse triangular solves: the two
  // differ only in the order of the sums. Each is within c n eps cond(M) |x|
  // of the exact solution (as in the dense check above, c = 10), so they
  // are within twice that of each other.
  const Eigen::SparseMatrix<double> m = two_interleaved_blocks(40, 25);
  const MassFactor factor(m);
  const Eigen::SparseMatrix<double> l = factor.strictly_lower_l();
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(m.rows(), -2.0, 1.0);
  Eigen::VectorXd x = r;
  factor.solve_in_place(x);
  Eigen::VectorXd z = r;
  l.triangularView<Eigen::UnitLower>().solveInPlace(z);
  z.array() *= factor.inverse_d().array();
  l.transpose().triangularView<Eigen::UnitUpper>().solveInPlace(z);
  const double error = (x - z).cwiseAbs().maxCoeff();
  const Eigen::VectorXd lambda =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(m)).eigenvalues();
  const double cond = lambda.maxCoeff() / lambda.minCoeff();
  const double bound = 2.0 * 10.0 * m.rows() * std::numeric_limits<double>::epsilon() * cond *
                       z.cwiseAbs().maxCoeff();
  std::printf("max |x - x_Eigen| = %.3e (bound %.3e, cond(M) = %.1f)\n", error, bound, cond);
  EXPECT_LE(error, bound);
  Eigen::VectorXd wrong_size(3);
  EXPECT_THROW(factor.solve_in_place(wrong_size), std::invalid_argument);
}

TEST(MassFactor, IndefiniteMatrixIsRefused) {
  // A shift of -20 makes every diagonal entry negative (checked), so M is indefinite.
  const Eigen::SparseMatrix<double> m = scattered_spd(40, -20.0);
  ASSERT_LT(Eigen::MatrixXd(m).diagonal().maxCoeff(), 0.0);
  EXPECT_THROW(MassFactor{m}, MassFactorError);
}

} // namespace
} // namespace rsi
