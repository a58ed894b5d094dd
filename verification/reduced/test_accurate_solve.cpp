// reduced/accurate_solve: residuals in twice working precision and
// iterative refinement to the correctly rounded solution, against exact
// arithmetic (integer systems, representable sums) and long double.

#include <cmath>
#include <random>

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include "accurate_solve.hpp"
#include "reduced_basis.hpp"

namespace rsi {
namespace {

Eigen::SparseMatrix<double> dense_to_sparse(const Eigen::MatrixXd& a) {
  return a.sparseView();
}

TEST(AccurateSolve, ResidualKeepsWhatWorkingPrecisionLoses) {
  // 1e16 + 1 - 1e16 = 1 exactly; in double 1e16 + 1 rounds to 1e16 (the
  // spacing there is 2), so the plain sum gives 0.
  const Eigen::MatrixXd a = Eigen::MatrixXd::Ones(1, 3);
  const Eigen::Vector3d x(1e16, 1.0, -1e16);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(1, 1);
  const double plain = (zero - a * x)(0);
  const double compensated = compensated_residual(dense_to_sparse(a), {}, {zero, {}}, x)(0);
  std::printf("0 - (1e16 + 1 - 1e16): plain %g, compensated %g\n", plain, compensated);
  EXPECT_EQ(plain, 0.0); // the case does show the loss
  EXPECT_EQ(compensated, -1.0);
}

/// The compensated sum one entry at a time, as accurate_solve.hpp states
/// it (Dot2 of Ogita, Rump, Oishi 2005 with the errors added as they
/// arise): b + b_low - a_low x, then - a_ij x_j for the row's entries in
/// column order, TwoSum and TwoProduct (fma) errors gathered in one sum.
double dot2_entry(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a,
                  const Eigen::MatrixXd& low_product, const AccurateMatrix& b,
                  const Eigen::MatrixXd& x, Eigen::Index i, Eigen::Index j) {
  double s = 0.0, c = 0.0;
  auto two_sum = [&](double t) {
    const double sum = s + t;
    const double z = sum - s;
    c += (s - (sum - z)) + (t - z);
    s = sum;
  };
  two_sum(b.value(i, j));
  if (b.low.size() > 0) two_sum(b.low(i, j));
  if (low_product.size() > 0) two_sum(-low_product(i, j));
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, i); it; ++it) {
    const double p = -it.value() * x(it.col(), j);
    c += std::fma(-it.value(), x(it.col(), j), -p);
    two_sum(p);
  }
  return s + c;
}

TEST(AccurateSolve, ResidualIsDot2EntryByEntry) {
  // The library's residual sums columns side by side (vector registers, two
  // threads when nnz(A) columns >= 1e7): every entry must be the bits of
  // its sum taken alone (the clone this processor runs). 21 columns: two groups of eight and a partial one;
  // 20,000 rows of about 30 entries: 1.2e7, the threaded path.
  const Eigen::Index n = 20000, columns = 21;
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uniform_int_distribution<Eigen::Index> column_of(0, n - 1);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < n; ++i)
    for (int k = 0; k < 30; ++k)
      entries.emplace_back(i, column_of(random), std::ldexp(uniform(random), k));
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  auto random_matrix = [&](double scale) {
    Eigen::MatrixXd m(n, columns);
    for (Eigen::Index k = 0; k < m.size(); ++k)
      m.data()[k] = scale * uniform(random);
    return m;
  };
  const Eigen::MatrixXd x = random_matrix(1e3);
  const AccurateMatrix b{random_matrix(1e10), random_matrix(1e-7)};
  const Eigen::MatrixXd r = compensated_residual(a, Eigen::MatrixXd(), b, x);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = a;
  long differing = 0;
  for (Eigen::Index j = 0; j < columns; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      differing += r(i, j) != dot2_entry(rows, Eigen::MatrixXd(), b, x, i, j);
  std::printf("%ld x %ld residual, %ld nonzeros: %ld entries differ from Dot2 alone\n",
              static_cast<long>(n), static_cast<long>(columns), static_cast<long>(a.nonZeros()),
              differing);
  EXPECT_EQ(differing, 0);
  // Without b's low part and with a dense a_low (its product subtracted first).
  const Eigen::MatrixXd small_low = Eigen::MatrixXd::Constant(3, 3, 1e-17);
  const Eigen::SparseMatrix<double> a3 = Eigen::MatrixXd::Constant(3, 3, 1.0 / 3.0).sparseView();
  const Eigen::MatrixXd x3 = Eigen::MatrixXd::Constant(3, 11, 3.0);
  const AccurateMatrix b3{Eigen::MatrixXd::Constant(3, 11, 3.0), {}};
  const Eigen::MatrixXd r3 = compensated_residual(a3, small_low, b3, x3);
  const Eigen::MatrixXd low3 = small_low * x3;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows3 = a3;
  for (Eigen::Index j = 0; j < 11; ++j)
    for (Eigen::Index i = 0; i < 3; ++i)
      EXPECT_EQ(r3(i, j), dot2_entry(rows3, low3, b3, x3, i, j));
}

TEST(AccurateSolve, RefinementReturnsTheExactSolutionOfAnIntegerSystem) {
  // Clamped 1D bending stencil [1 -4 6 -4 1] (a beam's K up to a factor):
  // cond grows as n^4, about 1e9 at n = 400. With integer x*, b = A x* is
  // exact in double, so the correctly rounded solution is x* itself.
  const int n = 400;
  std::vector<Eigen::Triplet<double>> entries;
  const double stencil[] = {1.0, -4.0, 6.0, -4.0, 1.0};
  for (int i = 0; i < n; ++i)
    for (int k = -2; k <= 2; ++k)
      if (i + k >= 0 && i + k < n) entries.emplace_back(i, i + k, stencil[k + 2]);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> integer(-1000, 1000);
  Eigen::MatrixXd exact(n, 2);
  for (Eigen::Index i = 0; i < exact.size(); ++i)
    exact.data()[i] = integer(rng);
  const Eigen::MatrixXd b = a * exact; // |entries| <= 16000: exact
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(a);
  ASSERT_EQ(factor.info(), Eigen::Success);
  const WorkingSolve solve = [&](const Eigen::MatrixXd& r) {
    return Eigen::MatrixXd(factor.solve(r));
  };
  const double plain_error = (solve(b) - exact).cwiseAbs().maxCoeff();
  const AccurateMatrix x = accurate_solve(a, {}, {b, {}}, solve, "test system");
  const double refined_error = (x.value - exact).cwiseAbs().maxCoeff();
  std::printf("bending stencil n = %d: max |x - x*| plain %.3e, refined %.3e, |low| %.3e\n", n,
              plain_error, refined_error, x.low.cwiseAbs().maxCoeff());
  EXPECT_GT(plain_error, 0.0); // the factor's round-off shows without refinement
  EXPECT_EQ(refined_error, 0.0);
  EXPECT_EQ(x.low.cwiseAbs().maxCoeff(), 0.0); // the residual of x* is exactly zero
}

TEST(AccurateSolve, LowPartsOfTheDataReachTheRoundedSolution) {
  // 3 x = 1 + 2^-54: x = 1/3 + 2^-54/3. fl(1/3) lies 1/3 ulp below 1/3
  // (ulp = 2^-54 there), so x lies 2/3 ulp above fl(1/3) and rounds to the
  // next double; the plain solve of 3 x = 1 stays at fl(1/3).
  const Eigen::SparseMatrix<double> three = dense_to_sparse(Eigen::MatrixXd::Constant(1, 1, 3.0));
  const WorkingSolve divide = [](const Eigen::MatrixXd& r) { return Eigen::MatrixXd(r / 3.0); };
  const Eigen::MatrixXd one = Eigen::MatrixXd::Ones(1, 1);
  const double third = 1.0 / 3.0;
  const double b_low =
      accurate_solve(three, {}, {one, Eigen::MatrixXd::Constant(1, 1, std::ldexp(1.0, -54))},
                     divide, "b low")
          .value(0);
  EXPECT_EQ(b_low, std::nextafter(third, 1.0));
  // (3 - 2^-52) x = 1: x = 1/3 + 2^-52/9 + ..., 4/9 ulp above 1/3, so 7/9
  // ulp above fl(1/3); long double (64-bit significand) rounds it the same.
  const double a_low = accurate_solve(three, Eigen::MatrixXd::Constant(1, 1, -std::ldexp(1.0, -52)),
                                      {one, {}}, divide, "a low")
                           .value(0);
  const double expected = static_cast<double>(1.0L / (3.0L - std::ldexp(1.0L, -52)));
  EXPECT_EQ(expected, std::nextafter(third, 1.0));
  EXPECT_EQ(a_low, expected);
}

TEST(AccurateSolve, NonContractingRefinementIsRefused) {
  // A = I with a "factor" returning 3 r: x <- x + 3 (b - x) doubles the error
  // each step, as a factor of a matrix with cond(A) eps > 1 would.
  const Eigen::SparseMatrix<double> identity = dense_to_sparse(Eigen::MatrixXd::Identity(2, 2));
  const WorkingSolve bad = [](const Eigen::MatrixXd& r) { return Eigen::MatrixXd(3.0 * r); };
  try {
    accurate_solve(identity, {}, {Eigen::MatrixXd::Ones(2, 1), {}}, bad, "the test matrix");
    FAIL() << "no exception";
  } catch (const ReductionError& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("the test matrix: iterative refinement did not converge"),
              std::string::npos);
  }
}

} // namespace
} // namespace rsi
