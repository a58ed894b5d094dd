#include "sparse_rows.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace rsi {

namespace {

std::vector<int> shortest_first(const RowMajorMatrix& a) {
  std::vector<int> order(static_cast<size_t>(a.rows()));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int i, int j) { return a.row(i).nonZeros() < a.row(j).nonZeros(); });
  return order;
}

} // namespace

SparseRows::SparseRows(const RowMajorMatrix& a)
    : SparseRows(a, shortest_first(a)) {}

SparseRows::SparseRows(const RowMajorMatrix& a, const std::vector<int>& order)
    : m_rows(a.rows())
    , m_cols(a.cols()) {
  for (int i : order) {
    if (i < 0 || i >= a.rows())
      throw std::invalid_argument("SparseRows: row " + std::to_string(i) + " outside 0.." +
                                  std::to_string(a.rows() - 1));
    const int length = static_cast<int>(a.row(i).nonZeros());
    if (m_runs.empty() || m_runs.back().length != length)
      m_runs.push_back(
          {static_cast<int>(m_row.size()), 0, length, static_cast<int>(m_index.size())});
    ++m_runs.back().n_rows;
    m_row.push_back(i);
    for (RowMajorMatrix::InnerIterator it(a, i); it; ++it) {
      m_index.push_back(static_cast<int>(it.col()));
      m_value.push_back(it.value());
    }
  }
}

void SparseRows::multiply(const Eigen::Ref<const Eigen::VectorXd>& x,
                          Eigen::Ref<Eigen::VectorXd> y) const {
  if (x.size() != m_cols || y.size() != m_rows)
    throw std::invalid_argument("SparseRows::multiply: x must have " + std::to_string(m_cols) +
                                " entries and y " + std::to_string(m_rows));
  eigen_assert(x.data() != y.data() && "SparseRows::multiply: y must not be x");
  double* out = y.data();
  for_each_row(x.data(), [out](int row, double sum) { out[row] = sum; });
}

} // namespace rsi
