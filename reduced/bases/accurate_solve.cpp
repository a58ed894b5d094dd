#include "accurate_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

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

namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Columns c0, c0 + 4, ... below `last` of the compensated residual, in
/// groups of `lanes`: the sums of one row for several columns are independent
/// chains the processor overlaps (each column's own sum adds the same terms in
/// the same order as one column at a time, so the result is the same to the
/// bit). Cloned for processors with FMA (GCC target_clones: chosen at load
/// time), where std::fma is one instruction instead of a call into libm; fma
/// is exact either way, so both clones give the same bits.
__attribute__((target_clones("fma", "default"))) void
residual_columns(const RowMajor& rows, const Eigen::MatrixXd& low_product, const AccurateMatrix& b,
                 const Eigen::MatrixXd& x, Eigen::Index first_group, Eigen::Index last_group,
                 Eigen::MatrixXd& r) {
  constexpr Eigen::Index lanes = 4;
  const bool has_a_low = low_product.size() > 0;
  const bool has_b_low = b.low.size() > 0;
  const Eigen::Index n_cols = x.cols();
  for (Eigen::Index group = first_group; group < last_group; ++group) {
    const Eigen::Index c0 = group * lanes;
    const Eigen::Index width = std::min(lanes, n_cols - c0);
    for (Eigen::Index i = 0; i < rows.rows(); ++i) {
      CompensatedSum sum[lanes];
      for (Eigen::Index k = 0; k < width; ++k) {
        sum[k].add(b.value(i, c0 + k));
        if (has_b_low) sum[k].add(b.low(i, c0 + k));
        if (has_a_low) sum[k].add(-low_product(i, c0 + k));
      }
      if (width == lanes) {
        for (RowMajor::InnerIterator it(rows, i); it; ++it) {
          const double v = -it.value();
          const double* xr = &x(it.col(), c0);
          const Eigen::Index stride = x.outerStride();
          sum[0].add_product(v, xr[0]);
          sum[1].add_product(v, xr[stride]);
          sum[2].add_product(v, xr[2 * stride]);
          sum[3].add_product(v, xr[3 * stride]);
        }
      } else {
        for (RowMajor::InnerIterator it(rows, i); it; ++it)
          for (Eigen::Index k = 0; k < width; ++k)
            sum[k].add_product(-it.value(), x(it.col(), c0 + k));
      }
      for (Eigen::Index k = 0; k < width; ++k)
        r(i, c0 + k) = sum[k].value();
    }
  }
}

/// compensated_residual with A already in rows; the groups of four columns
/// split between two threads when the work is worth one (each column is
/// summed by one thread: the split does not change a bit).
Eigen::MatrixXd residual(const RowMajor& rows, const Eigen::MatrixXd& a_low,
                         const AccurateMatrix& b, const Eigen::MatrixXd& x) {
  const Eigen::MatrixXd low_product = a_low.size() > 0 ? Eigen::MatrixXd(a_low * x) : Eigen::MatrixXd();
  Eigen::MatrixXd r(b.value.rows(), b.value.cols());
  const Eigen::Index groups = (x.cols() + 3) / 4;
  const double work = static_cast<double>(rows.nonZeros()) * static_cast<double>(x.cols());
  if (groups < 2 || work < 1e7 || std::thread::hardware_concurrency() < 2) {
    residual_columns(rows, low_product, b, x, 0, groups, r);
  } else {
    const Eigen::Index middle = groups / 2;
    std::thread second([&] { residual_columns(rows, low_product, b, x, middle, groups, r); });
    residual_columns(rows, low_product, b, x, 0, middle, r);
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
