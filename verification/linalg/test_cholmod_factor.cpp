// CHOLMOD's symbolic analysis run from several threads at once
// (reference/linalg/cholmod_handles.hpp, cholmod_analyze_serialized): the
// factor, hence every solve, must be the one a lone analysis gives, bit for
// bit, whatever else the process analyses at the same time. rsi sweep
// builds its speed subspace's bases two at a time (--jobs 2), and its rows
// must not depend on --jobs or the ranks (issue 26: byte-identical to one
// process).
//
// The matrix: the 27-point stencil on a 20^3 grid (8,000 unknowns, the
// coupling of a 3D solid's nodes), for which CHOLMOD's default analysis
// keeps METIS's ordering over AMD's (checked first: on a matrix where AMD
// wins, METIS's shared random generator never shows, and the test could
// not fail). METIS 5 draws from one generator per process; without the
// lock, two analyses at once gave another permutation in 20 of 20 tries
// (and this test failed: tried).

#include <cstdio>
#include <thread>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <gtest/gtest.h>

#include "cholmod_factor.hpp"
#include "cholmod_handles.hpp"

namespace rsi {
namespace {

/// Lower triangle of the 27-point stencil on an n^3 grid: diagonal 6 plus a
/// small ramp (no two pivots alike), -0.2 to each of the 26 neighbours;
/// diagonally dominant (6 > 26 x 0.2), so positive definite.
Eigen::SparseMatrix<double> stencil_27(int n) {
  std::vector<Eigen::Triplet<double>> t;
  const auto id = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  const int size = n * n * n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int a = id(i, j, k);
        t.emplace_back(a, a, 6.0 + 1e-3 * a / size);
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            for (int dk = -1; dk <= 1; ++dk) {
              const int ii = i + di, jj = j + dj, kk = k + dk;
              if (ii < 0 || jj < 0 || kk < 0 || ii >= n || jj >= n || kk >= n) continue;
              const int b = id(ii, jj, kk);
              if (b > a) t.emplace_back(b, a, -0.2);
            }
      }
  Eigen::SparseMatrix<double> lower(size, size);
  lower.setFromTriplets(t.begin(), t.end());
  lower.makeCompressed();
  return lower;
}

Eigen::VectorXd solved(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& b) {
  CholmodFactor factor;
  EXPECT_EQ(factor.factorize(lower), CholmodFactor::Status::successful) << factor.message();
  Eigen::VectorXd x(b.size());
  EXPECT_TRUE(factor.solve(CholmodFactor::System::a, b, x));
  return x;
}

TEST(CholmodFactor, ConcurrentAnalysesAreTheSerialOne) {
  const Eigen::SparseMatrix<double> lower = stencil_27(20);
  {
    CholmodHandles c;
    c.common.print = 0;
    cholmod_sparse a = cholmod_lower_view(lower);
    c.factor = cholmod_analyze_serialized(&a, &c.common);
    ASSERT_NE(c.factor, nullptr);
    ASSERT_EQ(c.factor->ordering, CHOLMOD_METIS)
        << "CHOLMOD kept another ordering than METIS's: the matrix does not exercise "
           "METIS's generator (the precondition of this test)";
  }
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(lower.rows(), -1.0, 2.0);
  const Eigen::VectorXd reference = solved(lower, b);
  int differing = 0;
  constexpr int rounds = 6;
  for (int round = 0; round < rounds; ++round) {
    Eigen::VectorXd x1, x2;
    std::thread first([&] { x1 = solved(lower, b); });
    std::thread second([&] { x2 = solved(lower, b); });
    first.join();
    second.join();
    // Bit for bit: the same ordering and the same arithmetic.
    differing += (x1.array() != reference.array()).any();
    differing += (x2.array() != reference.array()).any();
  }
  std::printf("%d of %d concurrent factor-and-solve runs differ from the lone one\n", differing,
              2 * rounds);
  EXPECT_EQ(differing, 0);
}

} // namespace
} // namespace rsi
