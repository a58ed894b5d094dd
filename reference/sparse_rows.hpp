#pragma once
// The rows of a sparse matrix, stored for the row sums a_i . x that a
// reference step is made of: K'u (838 rows, 9.4 nonzeros a row on the
// default case) and the triangular solves with the mass factor (about 4 a
// row; reference/mass_factor, reference/residual_solve).
//
// Why not Eigen's `y.noalias() = A * x` (or compressed rows summed by a
// loop): with rows this short, the work per row (loading its bounds,
// setting up the loop, a remainder, a mispredicted exit) costs as much as
// the multiply-adds: Eigen's row-major kernel and a four-sum CSR loop both
// spend about 67k instructions on K'u's 7.9k nonzeros (callgrind), and the
// rows of L cost 12 instructions a nonzero that way. Here the rows are
// stored in a chosen order as runs of equal length; each run is summed by a
// kernel unrolled for that length (no loop bounds, no remainder), in up to
// four independent partial sums (no add waits on the previous one), and
// two rows at a time in the two lanes of an SSE2 register where the
// processor has them (one index load per entry, but one multiply and one
// add per two entries). bench/RESULTS.md has the measured times.
//
// Which rows may be summed together: in a triangular solve a row reads
// results of earlier rows, so rows are paired only within a stage, a set
// of consecutive rows (in the stored order) that do not read each other
// (the levels of the mass factor). A product is a single stage.
//
// Round-off: the partial sums add the terms of a row in another order than
// one running sum. Each is the exact sum of the row's m products, each
// rounded, within gamma_m sum_k |a_ik x_k|, gamma_m = m eps / (1 - m eps)
// (Higham, Accuracy and Stability, eq. 3.5), so two orders differ by at most
// 2 gamma_m sum_k |a_ik| |x_k|. A row gives the same bits whether it is
// summed alone or in a pair (same partial sums, lane by lane).

#include <algorithm>
#include <array>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

class SparseRows {
public:
  SparseRows() = default;
  /// Every row of A, shortest first, as one stage (for products).
  explicit SparseRows(const RowMajorMatrix& a);
  /// The rows order[0], order[1], ... of A, summed in that order, where
  /// consecutive rows i, j with stage[i] == stage[j] do not read each
  /// other's results (stage: one entry per row of A). For a triangular
  /// solve, a row comes after those it reads, in a later stage. Throws
  /// std::invalid_argument for a row out of range or a stage of the wrong size.
  SparseRows(const RowMajorMatrix& a, const std::vector<int>& order, const std::vector<int>& stage);

  Eigen::Index n_rows() const { return static_cast<Eigen::Index>(m_row.size()); }
  Eigen::Index n_nonzeros() const { return static_cast<Eigen::Index>(m_value.size()); }
  /// y(i) = a_i . x for every stored row i: x of A.cols() entries, y of
  /// A.rows() (std::invalid_argument otherwise), y not x.
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const;

  /// For each stored row i, in the stored order: store(i, a_i . x), with x
  /// read when the row is summed, so that store may write into x (a
  /// triangular solve). Rows of one stage may be summed before either is
  /// stored. Dispatches each run to the kernel of its length.
  template <class Store> void for_each_row(const double* x, Store&& store) const;

private:
  static constexpr int max_unrolled = 16; ///< longer rows take a loop, one at a time

  /// Rows of one length and one stage, stored from first_entry on: pairs of
  /// rows with their entries interleaved (row 2p's k-th entry, then row
  /// 2p+1's), then the odd row if any; rows longer than max_unrolled are
  /// stored one after the other.
  struct Run {
    int first_row; ///< index into m_row
    int n_rows;
    int length;      ///< nonzeros of each row of the run
    int first_entry; ///< index into m_index, m_value
  };

  /// The rows of a run of rows of Length nonzeros (max_unrolled + 1: any
  /// longer length, by a loop).
  template <int Length, class Store>
  static void run_rows(const SparseRows& rows, const Run& run, const double* x, Store& store);
  template <class Store>
  using Kernel = void (*)(const SparseRows&, const Run&, const double*, Store&);
  /// run_rows<0>, ..., run_rows<max_unrolled + 1>, indexed by length.
  template <class Store, int... Length>
  static constexpr std::array<Kernel<Store>, sizeof...(Length)>
  kernels(std::integer_sequence<int, Length...>) {
    return {&run_rows<Length, Store>...};
  }

  Eigen::Index m_rows = 0; ///< of A
  Eigen::Index m_cols = 0;
  std::vector<int> m_row;      ///< the row of A of each stored row
  std::vector<int> m_index;    ///< column indices, in the runs' layout
  std::vector<double> m_value; ///< the entries, in the runs' layout
  std::vector<Run> m_runs;
};

/// The sum of the Length products value[k] x[index[k]], in up to four
/// partial sums started from the first products (no add of a zero).
template <int Length>
__attribute__((always_inline)) inline double unrolled_dot(const double* value, const int* index,
                                                          const double* x) {
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

/// unrolled_dot of two rows whose entries are interleaved (value[2k],
/// index[2k] of the first, value[2k + 1], index[2k + 1] of the second):
/// the same partial sums, lane by lane; the sums go to *first, *second.
template <int Length>
__attribute__((always_inline)) inline void unrolled_dot_pair(const double* value, const int* index,
                                                             const double* x, double* first,
                                                             double* second) {
#if defined(__SSE2__)
  constexpr int sums = Length < 4 ? Length : 4;
  __m128d s[sums];
#pragma GCC unroll 4
  for (int k = 0; k < sums; ++k)
    s[k] = _mm_mul_pd(_mm_loadu_pd(value + 2 * k),
                      _mm_loadh_pd(_mm_load_sd(x + index[2 * k]), x + index[2 * k + 1]));
#pragma GCC unroll 16
  for (int k = sums; k < Length; ++k)
    s[k % sums] = _mm_add_pd(
        s[k % sums], _mm_mul_pd(_mm_loadu_pd(value + 2 * k),
                                _mm_loadh_pd(_mm_load_sd(x + index[2 * k]), x + index[2 * k + 1])));
  __m128d total;
  if constexpr (sums == 1)
    total = s[0];
  else if constexpr (sums == 2)
    total = _mm_add_pd(s[0], s[1]);
  else if constexpr (sums == 3)
    total = _mm_add_pd(_mm_add_pd(s[0], s[1]), s[2]);
  else
    total = _mm_add_pd(_mm_add_pd(s[0], s[1]), _mm_add_pd(s[2], s[3]));
  _mm_storel_pd(first, total);
  _mm_storeh_pd(second, total);
#else
  double even_value[Length], odd_value[Length];
  int even_index[Length], odd_index[Length];
  for (int k = 0; k < Length; ++k) {
    even_value[k] = value[2 * k], even_index[k] = index[2 * k];
    odd_value[k] = value[2 * k + 1], odd_index[k] = index[2 * k + 1];
  }
  *first = unrolled_dot<Length>(even_value, even_index, x);
  *second = unrolled_dot<Length>(odd_value, odd_index, x);
#endif
}

template <int Length, class Store>
void SparseRows::run_rows(const SparseRows& rows, const Run& run, const double* x, Store& store) {
  const int* row = rows.m_row.data() + run.first_row;
  const int* index = rows.m_index.data() + run.first_entry;
  const double* value = rows.m_value.data() + run.first_entry;
  if constexpr (Length > max_unrolled) { // a loop of four sums, four terms a trip
    const int length = run.length;
    for (int r = 0; r < run.n_rows; ++r, index += length, value += length) {
      double s0 = value[0] * x[index[0]];
      double s1 = value[1] * x[index[1]];
      double s2 = value[2] * x[index[2]];
      double s3 = value[3] * x[index[3]];
      int k = 4;
      for (; k + 3 < length; k += 4) {
        s0 += value[k] * x[index[k]];
        s1 += value[k + 1] * x[index[k + 1]];
        s2 += value[k + 2] * x[index[k + 2]];
        s3 += value[k + 3] * x[index[k + 3]];
      }
      for (; k < length; ++k)
        s0 += value[k] * x[index[k]];
      store(row[r], (s0 + s1) + (s2 + s3));
    }
  } else if constexpr (Length == 0) {
    for (int r = 0; r < run.n_rows; ++r)
      store(row[r], 0.0);
  } else {
    int r = 0;
    for (; r + 1 < run.n_rows; r += 2, index += 2 * Length, value += 2 * Length) {
      double first, second;
      unrolled_dot_pair<Length>(value, index, x, &first, &second);
      store(row[r], first);
      store(row[r + 1], second);
    }
    if (r < run.n_rows) store(row[r], unrolled_dot<Length>(value, index, x));
  }
}

template <class Store> void SparseRows::for_each_row(const double* x, Store&& store) const {
  using Plain = std::remove_reference_t<Store>;
  static constexpr std::array<Kernel<Plain>, max_unrolled + 2> kernel =
      kernels<Plain>(std::make_integer_sequence<int, max_unrolled + 2>());
  for (const Run& run : m_runs)
    kernel[std::min(run.length, max_unrolled + 1)](*this, run, x, store);
}

} // namespace rsi
