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
    : SparseRows(a, shortest_first(a), std::vector<int>(static_cast<size_t>(a.rows()), 0)) {}

SparseRows::SparseRows(const RowMajorMatrix& a, const std::vector<int>& order,
                       const std::vector<int>& stage)
    : m_rows(a.rows())
    , m_cols(a.cols()) {
  if (static_cast<Eigen::Index>(stage.size()) != a.rows())
    throw std::invalid_argument("SparseRows: one stage per row of A");
  for (int i : order)
    if (i < 0 || i >= a.rows())
      throw std::invalid_argument("SparseRows: row " + std::to_string(i) + " outside 0.." +
                                  std::to_string(a.rows() - 1));
  auto length = [&](int i) { return static_cast<int>(a.row(i).nonZeros()); };
  for (size_t first = 0; first < order.size();) {
    // The run: rows of one length and one stage, consecutive in `order`.
    size_t end = first + 1;
    while (end < order.size() && length(order[end]) == length(order[first]) &&
           stage[order[end]] == stage[order[first]])
      ++end;
    const int run_length = length(order[first]);
    m_runs.push_back({static_cast<int>(m_row.size()), static_cast<int>(end - first), run_length,
                      static_cast<int>(m_index.size())});
    size_t k = first;
    for (; k + 1 < end; k += 2) { // pairs, entries interleaved
      m_row.push_back(order[k]);
      m_row.push_back(order[k + 1]);
      RowMajorMatrix::InnerIterator it0(a, order[k]);
      RowMajorMatrix::InnerIterator it1(a, order[k + 1]);
      for (; it0; ++it0, ++it1) {
        m_index.push_back(static_cast<int>(it0.col()));
        m_index.push_back(static_cast<int>(it1.col()));
        m_value.push_back(it0.value());
        m_value.push_back(it1.value());
      }
    }
    for (; k < end; ++k) { // the odd row
      m_row.push_back(order[k]);
      for (RowMajorMatrix::InnerIterator it(a, order[k]); it; ++it) {
        m_index.push_back(static_cast<int>(it.col()));
        m_value.push_back(it.value());
      }
    }
    first = end;
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
