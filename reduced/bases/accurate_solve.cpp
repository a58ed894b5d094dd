#include "accurate_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "reduced_basis.hpp"

namespace rsi {

namespace {

/// A sum kept as hi + lo, with every rounding error of the additions and
/// products gathered in lo (Ogita, Rump, Oishi 2005, Algorithm 5.3 "Dot2").
class CompensatedSum {
public:
  /// TwoSum (Knuth): hi + a = s + e exactly.
  void add(double a) {
    const double s = m_hi + a;
    const double z = s - m_hi;
    m_lo += (m_hi - (s - z)) + (a - z);
    m_hi = s;
  }
  /// TwoProduct through fma: x y = p + e exactly.
  void add_product(double x, double y) {
    const double p = x * y;
    m_lo += std::fma(x, y, -p);
    add(p);
  }
  double value() const { return m_hi + m_lo; }

private:
  double m_hi = 0.0;
  double m_lo = 0.0;
};

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

Eigen::MatrixXd compensated_residual(const Eigen::SparseMatrix<double>& a,
                                     const Eigen::MatrixXd& a_low, const AccurateMatrix& b,
                                     const Eigen::MatrixXd& x) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = a;
  const bool has_a_low = a_low.size() > 0;
  const bool has_b_low = b.low.size() > 0;
  const Eigen::MatrixXd low_product = has_a_low ? Eigen::MatrixXd(a_low * x) : Eigen::MatrixXd();
  Eigen::MatrixXd r(b.value.rows(), b.value.cols());
  // Columns in groups of `lanes`: the sums of one row for several columns
  // are independent chains the processor overlaps (each column's own sum
  // adds the same terms in the same order as one column at a time, so the
  // result is the same to the bit).
  constexpr Eigen::Index lanes = 4;
  const Eigen::Index n_cols = x.cols();
  for (Eigen::Index c0 = 0; c0 < n_cols; c0 += lanes) {
    const Eigen::Index width = std::min(lanes, n_cols - c0);
    for (Eigen::Index i = 0; i < rows.rows(); ++i) {
      CompensatedSum sum[lanes];
      for (Eigen::Index k = 0; k < width; ++k) {
        sum[k].add(b.value(i, c0 + k));
        if (has_b_low) sum[k].add(b.low(i, c0 + k));
        if (has_a_low) sum[k].add(-low_product(i, c0 + k));
      }
      if (width == lanes) {
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, i); it; ++it) {
          const double v = -it.value();
          const double* xr = &x(it.col(), c0);
          const Eigen::Index stride = x.outerStride();
          sum[0].add_product(v, xr[0]);
          sum[1].add_product(v, xr[stride]);
          sum[2].add_product(v, xr[2 * stride]);
          sum[3].add_product(v, xr[3 * stride]);
        }
      } else {
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, i); it; ++it)
          for (Eigen::Index k = 0; k < width; ++k)
            sum[k].add_product(-it.value(), x(it.col(), c0 + k));
      }
      for (Eigen::Index k = 0; k < width; ++k)
        r(i, c0 + k) = sum[k].value();
    }
  }
  return r;
}

AccurateMatrix accurate_solve(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& a_low,
                              const AccurateMatrix& b, const WorkingSolve& solve,
                              const std::string& name) {
  constexpr int max_steps = 10;
  AccurateMatrix x{solve(b.value), {}};
  for (int step = 0; step < max_steps; ++step) {
    x.low = solve(compensated_residual(a, a_low, b, x.value));
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
