#include "transpose_product.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace rsi {

Eigen::MatrixXd transpose_product(const Eigen::SparseMatrix<double>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& x) {
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  if (x.rows() != a.rows())
    throw std::invalid_argument("transpose_product: x has " + std::to_string(x.rows()) +
                                " rows, A has " + std::to_string(a.rows()));
  const Eigen::Index m = a.cols();
  const RowMatrix xr = x;
  RowMatrix yr(m, x.cols());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* value = a.valuePtr();
  const int* nonzeros = a.innerNonZeroPtr(); // non-null only for an uncompressed A
  auto rows = [&](Eigen::Index first, Eigen::Index last) {
    for (Eigen::Index i = first; i < last; ++i) {
      auto yi = yr.row(i);
      yi.setZero();
      const int end = nonzeros ? outer[i] + nonzeros[i] : outer[i + 1];
      for (int k = outer[i]; k < end; ++k)
        yi += value[k] * xr.row(inner[k]);
    }
  };
  // Below ~2e7 multiply-adds a thread costs more than it saves.
  const double work = static_cast<double>(a.nonZeros()) * static_cast<double>(x.cols());
  if (work < 2e7 || std::thread::hardware_concurrency() < 2) {
    rows(0, m);
  } else {
    const Eigen::Index middle =
        std::lower_bound(outer, outer + m, outer[m] / 2) - outer; // half the nonzeros
    std::thread second(rows, middle, m);
    rows(0, middle);
    second.join();
  }
  return yr;
}

} // namespace rsi
