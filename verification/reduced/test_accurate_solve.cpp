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
