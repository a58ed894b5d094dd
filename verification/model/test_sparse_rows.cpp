// reference/sparse_rows: the row sums of the reference step's products and
// triangular solves, against Eigen's sparse product and triangular solve.
// The bound on the difference is that of two summation orders (Higham,
// Accuracy and Stability, eq. 3.5): each is within gamma_m sum_k |a_ik x_k|
// of the exact row sum, gamma_m = m eps / (1 - m eps), m the row's length.

#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include "assembler.hpp"
#include "bladed_disk.hpp"
#include "casing.hpp"
#include "mass_factor.hpp"
#include "sparse_rows.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

double gamma(Eigen::Index m) {
  return m * eps / (1.0 - m * eps);
}

/// Rows of every length from 0 to 40 (the unrolled kernels go to 16, longer
/// rows take the plain loop), random columns and entries, fixed seed.
RowMajorMatrix random_rows(int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> column(0, n - 1);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    const int length = i % 41;
    std::vector<bool> used(n, false);
    for (int k = 0; k < length;) {
      const int j = column(rng);
      if (used[j]) continue;
      used[j] = true;
      entries.emplace_back(i, j, value(rng));
      ++k;
    }
  }
  RowMajorMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  return a;
}

/// max_i |y_i - z_i| / (2 gamma_{m_i} sum_k |a_ik| |x_k|): <= 1 for two row sums of A x.
double worst_ratio_to_bound(const RowMajorMatrix& a, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& y, const Eigen::VectorXd& z) {
  const Eigen::VectorXd magnitude = a.cwiseAbs() * x.cwiseAbs();
  double worst = 0.0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    const double bound = 2.0 * gamma(a.row(i).nonZeros()) * magnitude(i);
    const double difference = std::abs(y(i) - z(i));
    if (bound == 0.0)
      EXPECT_EQ(difference, 0.0) << "row " << i;
    else
      worst = std::max(worst, difference / bound);
  }
  return worst;
}

TEST(SparseRows, ProductMatchesEigenWithinTheSummationBound) {
  const RowMajorMatrix a = random_rows(300);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(300, -3.0, 5.0).array().sin();
  Eigen::VectorXd y(300);
  SparseRows(a).multiply(x, y);
  const Eigen::VectorXd z = a * x;
  const double ratio = worst_ratio_to_bound(a, x, y, z);
  std::printf("random rows of length 0-40: max |y - y_Eigen| / (2 gamma_m sum |a||x|) = %.3f\n",
              ratio);
  EXPECT_LE(ratio, 1.0);
}

TEST(SparseRows, PairedRowsGiveTheBitsOfSingleRows) {
  // SparseRows(a) sums rows two at a time where it can; with a stage per
  // row it sums them one at a time. The partial sums are the same, lane by
  // lane, so the results must be equal, not just close.
  const RowMajorMatrix a = random_rows(300);
  std::vector<int> order(300);
  for (int i = 0; i < 300; ++i)
    order[i] = i;
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(300, -3.0, 5.0).array().cos();
  Eigen::VectorXd paired(300), single(300);
  SparseRows(a).multiply(x, paired);
  SparseRows(a, order, order).multiply(x, single);
  std::printf("max |paired - single| = %.3e\n", (paired - single).cwiseAbs().maxCoeff());
  EXPECT_EQ((paired - single).cwiseAbs().maxCoeff(), 0.0);
}

TEST(SparseRows, StiffnessProductOfTheDefaultSystemMatchesEigen) {
  const Case c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  const MassFactor factor(block_diagonal(bd.mass, casing.mass));
  const RowMajorMatrix k = factor.permuted(block_diagonal(bd.stiffness, casing.stiffness));
  const Eigen::VectorXd u = 1e-3 * Eigen::VectorXd::LinSpaced(k.rows(), 0.0, 50.0).array().cos();
  Eigen::VectorXd y(k.rows());
  SparseRows(k).multiply(u, y);
  const Eigen::VectorXd z = k * u;
  const double ratio = worst_ratio_to_bound(k, u, y, z);
  std::printf("K'u, %ld dofs, %ld nonzeros: max |y - y_Eigen| / (2 gamma_m sum |k||u|) = %.3f\n",
              static_cast<long>(k.rows()), static_cast<long>(k.nonZeros()), ratio);
  EXPECT_LE(ratio, 1.0);
}

TEST(SparseRows, RowsInAGivenOrderSolveAUnitLowerTriangularSystem) {
  // The strictly lower part of the random rows, I + that as L; solved row
  // after row in the natural order by for_each_row writing into x, against
  // Eigen's triangular solve. Both are forward substitutions; the difference
  // is round-off amplified by L^-1 (bounded by the printed error's size).
  const int n = 300;
  const RowMajorMatrix lower = random_rows(n).triangularView<Eigen::StrictlyLower>();
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i)
    order[i] = i;
  // One row per stage: each row may read all earlier ones.
  const SparseRows rows(lower, order, order);
  EXPECT_EQ(rows.n_rows(), n);
  EXPECT_EQ(rows.n_nonzeros(), lower.nonZeros());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  Eigen::VectorXd x = b;
  double* data = x.data();
  rows.for_each_row(data, [data](int i, double sum) { data[i] -= sum; });
  Eigen::VectorXd z = b;
  lower.triangularView<Eigen::UnitLower>().solveInPlace(z);
  // Residual of the computed solution: |b - L x| <= gamma_m (|L| |x|) row by
  // row for a backward-stable substitution (Higham, thm 8.5), with L's diagonal.
  const Eigen::VectorXd residual = b - x - lower * x;
  const Eigen::VectorXd scale = x.cwiseAbs() + lower.cwiseAbs() * x.cwiseAbs();
  double worst = 0.0;
  for (int i = 0; i < n; ++i)
    worst =
        std::max(worst, std::abs(residual(i)) / (gamma(lower.row(i).nonZeros() + 2) * scale(i)));
  std::printf("forward substitution: max |b - L x| / (gamma_{m+2} (|L||x|)_i) = %.3f, "
              "max |x - x_Eigen| / max |x| = %.3e\n",
              worst, (x - z).cwiseAbs().maxCoeff() / x.cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 1.0);
}

TEST(SparseRows, BadArgumentsAreRefused) {
  const RowMajorMatrix a = random_rows(10);
  const std::vector<int> stage(10, 0);
  EXPECT_THROW(SparseRows(a, {0, 10}, stage), std::invalid_argument);
  EXPECT_THROW(SparseRows(a, {-1}, stage), std::invalid_argument);
  EXPECT_THROW(SparseRows(a, {0, 1}, {0, 0}), std::invalid_argument);
  Eigen::VectorXd y(10);
  EXPECT_THROW(SparseRows(a).multiply(Eigen::VectorXd::Zero(9), y), std::invalid_argument);
}

} // namespace
} // namespace rsi
