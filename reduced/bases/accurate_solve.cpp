#include "accurate_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

#include "reduced_basis.hpp"

namespace rsi {

namespace {

/// Largest |change| / |column| over the columns: the step's size in units of
/// each column's magnitude.
double relative_step(const Eigen::MatrixXd& step, const Eigen::MatrixXd& x) {
  double worst = 0.0;
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    const double scale = x.col(j).cwiseAbs().maxCoeff();
    const double size = step.col(j).cwiseAbs().maxCoeff();
    if (size > 0.0) worst = std::max(worst, scale > 0.0 ? size / scale : HUGE_VAL);
  }
  return worst;
}

} // namespace

namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using DenseRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A sum kept as hi + lo, with every rounding error of the additions and
// products gathered in lo in the order they arise (after Ogita, Rump, Oishi
// 2005, Algorithm 5.3 "Dot2", which adds each pair of errors first; the
// error bound is that of summing the same terms in any order). Compiled
// with -ffp-contract=off (reduced/CMakeLists.txt): a product fused into a
// following addition would lose the error TwoProduct recovers.

/// hi + a = s + e exactly (TwoSum, Knuth): hi <- s, lo += e.
inline void two_sum_into(double& hi, double& lo, double a) {
  const double s = hi + a;
  const double z = s - hi;
  lo += (hi - (s - z)) + (a - z);
  hi = s;
}

/// x y = p + e exactly (TwoProduct through fma): lo += e, then p added.
inline void two_product_into(double& hi, double& lo, double x, double y) {
  const double p = x * y;
  lo += std::fma(x, y, -p);
  two_sum_into(hi, lo, p);
}

constexpr Eigen::Index lanes = 8;

/// The compensated residual of the columns of groups first_group ..
/// last_group - 1, `lanes` columns a group: the sums of one row for the
/// columns of a group are independent chains, each adding the same terms in
/// the same order as one column summed alone (so the same bits), which the
/// compiler runs side by side in one vector register; x is read
/// by rows (`xt`), the group's entries of a row contiguous. Cloned for x86-64
/// levels v4 (AVX-512) and v3 (AVX2, FMA) besides the default (GCC
/// target_clones, chosen at load time); fma is exact and each lane's
/// operations are IEEE operations in every clone, so all give the same bits
/// (verification/reduced/test_accurate_solve.cpp checks the clone the
/// processor runs against the same sums one entry at a time).
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void
residual_columns(const RowMajor& rows, const Eigen::MatrixXd& low_product, const AccurateMatrix& b,
                 const DenseRows& xt, Eigen::Index first_group, Eigen::Index last_group,
                 Eigen::MatrixXd& r) {
  const bool has_a_low = low_product.size() > 0;
  const bool has_b_low = b.low.size() > 0;
  const Eigen::Index n_cols = xt.cols();
  for (Eigen::Index group = first_group; group < last_group; ++group) {
    const Eigen::Index c0 = group * lanes;
    const Eigen::Index width = std::min(lanes, n_cols - c0);
    for (Eigen::Index i = 0; i < rows.rows(); ++i) {
      double hi[lanes] = {};
      double lo[lanes] = {};
      for (Eigen::Index k = 0; k < width; ++k) {
        two_sum_into(hi[k], lo[k], b.value(i, c0 + k));
        if (has_b_low) two_sum_into(hi[k], lo[k], b.low(i, c0 + k));
        if (has_a_low) two_sum_into(hi[k], lo[k], -low_product(i, c0 + k));
      }
      if (width == lanes) {
        for (RowMajor::InnerIterator it(rows, i); it; ++it) {
          const double v = -it.value();
          const double* xr = xt.data() + it.col() * n_cols + c0;
          for (Eigen::Index k = 0; k < lanes; ++k)
            two_product_into(hi[k], lo[k], v, xr[k]);
        }
      } else {
        for (RowMajor::InnerIterator it(rows, i); it; ++it) {
          const double v = -it.value();
          const double* xr = xt.data() + it.col() * n_cols + c0;
          for (Eigen::Index k = 0; k < width; ++k)
            two_product_into(hi[k], lo[k], v, xr[k]);
        }
      }
      for (Eigen::Index k = 0; k < width; ++k)
        r(i, c0 + k) = hi[k] + lo[k];
    }
  }
}

/// compensated_residual with A already in rows; the groups of columns split
/// between two threads when the work is worth one (each column is summed by
/// one thread: the split does not change a bit).
Eigen::MatrixXd residual(const RowMajor& rows, const Eigen::MatrixXd& a_low,
                         const AccurateMatrix& b, const Eigen::MatrixXd& x) {
  const Eigen::MatrixXd low_product =
      a_low.size() > 0 ? Eigen::MatrixXd(a_low * x) : Eigen::MatrixXd();
  const DenseRows xt = x;
  Eigen::MatrixXd r(b.value.rows(), b.value.cols());
  const Eigen::Index groups = (x.cols() + lanes - 1) / lanes;
  const double work = static_cast<double>(rows.nonZeros()) * static_cast<double>(x.cols());
  if (groups < 2 || work < 1e7 || std::thread::hardware_concurrency() < 2) {
    residual_columns(rows, low_product, b, xt, 0, groups, r);
  } else {
    const Eigen::Index middle = groups / 2;
    std::thread second([&] { residual_columns(rows, low_product, b, xt, middle, groups, r); });
    residual_columns(rows, low_product, b, xt, 0, middle, r);
    second.join();
  }
  return r;
}

} // namespace

Eigen::MatrixXd compensated_residual(const Eigen::SparseMatrix<double>& a,
                                     const Eigen::MatrixXd& a_low, const AccurateMatrix& b,
                                     const Eigen::MatrixXd& x) {
  return residual(RowMajor(a), a_low, b, x);
}

AccurateMatrix accurate_solve(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& a_low,
                              const AccurateMatrix& b, const WorkingSolve& solve,
                              const std::string& name) {
  constexpr int max_steps = 10;
  const RowMajor rows = a;
  AccurateMatrix x{solve(b.value), {}};
  for (int step = 0; step < max_steps; ++step) {
    x.low = solve(residual(rows, a_low, b, x.value));
    const Eigen::MatrixXd next = x.value + x.low;
    if ((next.array() == x.value.array()).all()) return x;
    x.value = next;
  }
  // Still moving: accept a last step within the last bit of every column
  // (an entry near a rounding tie may flip between its two neighbours).
  const double size = relative_step(x.low, x.value);
  if (size <= 2.0 * std::numeric_limits<double>::epsilon()) return x;
  std::ostringstream message;
  message << name << ": iterative refinement did not converge in " << max_steps
          << " steps (last correction " << size
          << " of the solution): the system is too ill-conditioned for double precision";
  throw ReductionError(message.str());
}

} // namespace rsi
