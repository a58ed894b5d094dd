// reference/residual_solve: M'^-1 (f - A u) in one pass over the rows of A
// and L, against the same quantity formed the plain way (Eigen's product,
// then MassFactor::solve_in_place) and against a dense LLT solve.
//
// Tolerance (Higham, Accuracy and Stability, eq. 3.5 and thm 10.4): the
// residual f - A u is formed in another order, so each entry differs by at
// most 2 gamma_m (|f| + |A||u|), m the longest row; M^-1 turns that into at
// most ||M^-1||_inf 2 gamma_m || |f| + |A||u| ||_inf, and each solve is
// within c n eps cond(M) |x| of the exact one (c = 10, as in test_mass_factor).

#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "mass_factor.hpp"
#include "residual_solve.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// A random sparse symmetric positive definite matrix in two blocks of sizes
/// n1 and n2 (no coupling between them), 4 random couplings a row,
/// diagonally dominant; fixed seed.
Eigen::SparseMatrix<double> two_block_spd(int n1, int n2) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const int n = n1 + n2;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    const int first = i < n1 ? 0 : n1;
    const int size = i < n1 ? n1 : n2;
    std::uniform_int_distribution<int> partner(first, first + size - 1);
    for (int k = 0; k < 4; ++k) {
      const int j = partner(rng);
      if (j == i) continue;
      const double c = value(rng);
      m(i, j) += c, m(j, i) += c;
    }
  }
  for (int i = 0; i < n; ++i)
    m(i, i) = 3.0 + m.row(i).cwiseAbs().sum();
  return m.sparseView();
}

/// A random sparse n x n matrix, 0-20 entries a row; fixed seed.
RowMajorMatrix random_matrix(int n) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  std::uniform_int_distribution<int> column(0, n - 1);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < i % 21; ++k)
      entries.emplace_back(i, column(rng), value(rng)); // duplicates are summed
  RowMajorMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  return a;
}

TEST(ResidualSolve, MatchesTheProductThenTheSolveToRoundOff) {
  const int n = 70;
  const Eigen::SparseMatrix<double> m = two_block_spd(45, 25);
  const MassFactor factor(m);
  const RowMajorMatrix a = random_matrix(n);
  ResidualSolve residual_solve(factor, a);
  EXPECT_EQ(residual_solve.nonzeros_a(), a.nonZeros());

  const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0).array().sin();
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, 0.0, 9.0).array().cos();
  const Eigen::VectorXd x = residual_solve.apply(f, u);
  Eigen::VectorXd plain = f - a * u;
  factor.solve_in_place(plain);
  // The permuted M' = P M P^T, dense.
  const Eigen::MatrixXd mp = Eigen::MatrixXd(factor.permuted(m));
  const Eigen::VectorXd dense = Eigen::LLT<Eigen::MatrixXd>(mp).solve(f - a * u);

  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(mp).eigenvalues();
  const double cond = lambda.maxCoeff() / lambda.minCoeff();
  const double inverse_norm = mp.inverse().cwiseAbs().rowwise().sum().maxCoeff();
  Eigen::Index longest = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    longest = std::max(longest, a.row(i).nonZeros() + factor.strictly_lower_l().row(i).nonZeros());
  const double gamma = longest * eps / (1.0 - longest * eps);
  const double residual_scale = (f.cwiseAbs() + a.cwiseAbs() * u.cwiseAbs()).maxCoeff();
  const double bound = inverse_norm * 2.0 * gamma * residual_scale +
                       2.0 * 10.0 * n * eps * cond * dense.cwiseAbs().maxCoeff();
  const double against_plain = (x - plain).cwiseAbs().maxCoeff();
  const double against_dense = (x - dense).cwiseAbs().maxCoeff();
  std::printf("max |x - x_plain| = %.3e, max |x - x_dense| = %.3e (bound %.3e; cond(M) = %.1f, "
              "||M^-1|| = %.3f, longest row %ld)\n",
              against_plain, against_dense, bound, cond, inverse_norm, static_cast<long>(longest));
  EXPECT_LE(against_plain, bound);
  EXPECT_LE(against_dense, bound);
}

TEST(ResidualSolve, BadSizesAreRefused) {
  const MassFactor factor(two_block_spd(6, 4));
  EXPECT_THROW(ResidualSolve(factor, random_matrix(9)), std::invalid_argument);
  ResidualSolve residual_solve(factor, random_matrix(10));
  EXPECT_THROW(residual_solve.apply(Eigen::VectorXd::Zero(10), Eigen::VectorXd::Zero(9)),
               std::invalid_argument);
}

} // namespace
} // namespace rsi
