#pragma once
// The rows of a sparse matrix, stored for the row sums a_i . x that a
// reference step is made of: K'u (838 rows, 9.4 nonzeros a row on the
// default case) and the two triangular solves with the mass factor (about
// 4 a row, reference/mass_factor).
//
// Why not Eigen's `y.noalias() = A * x` (or compressed rows summed by a
// loop): with rows this short, the per-row work (loading the row's bounds,
// setting up the loop, a remainder, a mispredicted exit) costs as much as
// the multiply-adds. Eigen's row-major kernel and a four-sum CSR loop both
// spend about 67k instructions on K'u's 7.9k nonzeros (callgrind), and
// the rows of L cost 12 instructions a nonzero. Here the rows are stored
// in a chosen order as runs of equal length, and each run is summed by a
// kernel unrolled for that length: no per-row loop bounds, no remainder,
// and up to four independent partial sums, so that no add waits on the
// previous one (bench/RESULTS.md, bench_mass_solve).
//
// Round-off: the partial sums add the terms of a row in another order than
// one running sum. Each is the exact sum of the row's m products, each
// rounded, within gamma_{m} sum_k |a_ik x_k|, gamma_m = m eps / (1 - m eps)
// (Higham, Accuracy and Stability, eq. 3.5), so two orders differ by at most
// 2 gamma_m sum_k |a_ik| |x_k|.

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

class SparseRows {
public:
  SparseRows() = default;
  /// Every row of A, stored shortest first (for products).
  explicit SparseRows(const RowMajorMatrix& a);
  /// The rows order[0], order[1], ... of A, kept in that order (for a
  /// triangular solve, an order in which a row comes after those it reads).
  /// Throws std::invalid_argument for a row out of range.
  SparseRows(const RowMajorMatrix& a, const std::vector<int>& order);

  Eigen::Index n_rows() const { return static_cast<Eigen::Index>(m_row.size()); }
  Eigen::Index n_nonzeros() const { return static_cast<Eigen::Index>(m_value.size()); }
  /// y(i) = a_i . x for every stored row i: x of A.cols() entries, y of
  /// A.rows() (std::invalid_argument otherwise), y not x.
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const;

  /// For each stored row i, in the stored order: store(i, a_i . x), with x
  /// read when the row is summed, so that store may write into x (a
  /// triangular solve). Dispatches each run to the kernel of its length.
  template <class Store> void for_each_row(const double* x, Store&& store) const;

private:
  struct Run {
    int first_row; ///< index into m_row
    int n_rows;
    int length;      ///< nonzeros of each row of the run
    int first_entry; ///< index into m_index, m_value
  };
  static constexpr int max_unrolled = 16; ///< longer runs take the plain loop

  template <int Length, class Store>
  void run_rows(const Run& run, const double* x, Store& store) const;
  template <int Length, class Store>
  void dispatch(const Run& run, const double* x, Store& store) const;

  Eigen::Index m_rows = 0; ///< of A
  Eigen::Index m_cols = 0;
  std::vector<int> m_row;      ///< the row of A of each stored row
  std::vector<int> m_index;    ///< column indices, row after row
  std::vector<double> m_value; ///< the entries, row after row
  std::vector<Run> m_runs;
};

/// The sum of the Length products value[k] x[index[k]], in up to four
/// partial sums started from the first products (no add of a zero).
template <int Length>
inline double unrolled_dot(const double* value, const int* index, const double* x) {
  constexpr int sums = Length < 4 ? Length : 4;
  double s[sums];
#pragma GCC unroll 4
  for (int k = 0; k < sums; ++k)
    s[k] = value[k] * x[index[k]];
#pragma GCC unroll 16
  for (int k = sums; k < Length; ++k)
    s[k % sums] += value[k] * x[index[k]];
  if constexpr (sums == 1)
    return s[0];
  else if constexpr (sums == 2)
    return s[0] + s[1];
  else if constexpr (sums == 3)
    return (s[0] + s[1]) + s[2];
  else
    return (s[0] + s[1]) + (s[2] + s[3]);
}

template <int Length, class Store>
void SparseRows::run_rows(const Run& run, const double* x, Store& store) const {
  const int* row = m_row.data() + run.first_row;
  const int* index = m_index.data() + run.first_entry;
  const double* value = m_value.data() + run.first_entry;
  for (int r = 0; r < run.n_rows; ++r, index += Length, value += Length) {
    if constexpr (Length == 0)
      store(row[r], 0.0);
    else
      store(row[r], unrolled_dot<Length>(value, index, x));
  }
}

template <int Length, class Store>
void SparseRows::dispatch(const Run& run, const double* x, Store& store) const {
  if constexpr (Length > max_unrolled) { // the plain loop, in four sums
    const int* row = m_row.data() + run.first_row;
    const int* index = m_index.data() + run.first_entry;
    const double* value = m_value.data() + run.first_entry;
    for (int r = 0; r < run.n_rows; ++r, index += run.length, value += run.length) {
      double s[4] = {0.0, 0.0, 0.0, 0.0};
      for (int k = 0; k < run.length; ++k)
        s[k % 4] += value[k] * x[index[k]];
      store(row[r], (s[0] + s[1]) + (s[2] + s[3]));
    }
  } else if (run.length == Length) {
    run_rows<Length>(run, x, store);
  } else {
    dispatch<Length + 1>(run, x, store);
  }
}

template <class Store> void SparseRows::for_each_row(const double* x, Store&& store) const {
  for (const Run& run : m_runs)
    dispatch<0>(run, x, store);
}

} // namespace rsi
