#pragma once
// The rows of a sparse matrix, stored for the row sums a_i . x that a
// reference step is made of: K'u (838 rows, 9.4 nonzeros a row on the
// default case) and the triangular solves with the mass factor (about 4 a
// row; reference/mass_factor).
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
  static constexpr int max_unrolled = 16; ///< longer rows take a loop

  /// Rows of one length and one stage, stored from first_entry on: pairs of
  /// rows with their entries interleaved (row 2p's k-th entry, then row
  /// 2p+1's), then the odd row if any.
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

/// Two doubles summed lane by lane: an SSE2 register where the processor
/// has one (GCC's vector + is addpd), else a pair of doubles (the same
/// arithmetic, lane by lane).
#if defined(__SSE2__)
using Lanes = __m128d;
/// value[0] x[index[0]] and value[1] x[index[1]].
__attribute__((always_inline)) inline Lanes lane_products(const double* value, const int* index,
                                                          const double* x) {
  return _mm_mul_pd(_mm_loadu_pd(value), _mm_loadh_pd(_mm_load_sd(x + index[0]), x + index[1]));
}
inline double first_lane(Lanes a) {
  return _mm_cvtsd_f64(a);
}
inline double second_lane(Lanes a) {
  return _mm_cvtsd_f64(_mm_unpackhi_pd(a, a));
}
#else
struct Lanes {
  double first, second;
};
inline Lanes lane_products(const double* value, const int* index, const double* x) {
  return {value[0] * x[index[0]], value[1] * x[index[1]]};
}
inline Lanes operator+(Lanes a, Lanes b) {
  return {a.first + b.first, a.second + b.second};
}
inline double first_lane(Lanes a) {
  return a.first;
}
inline double second_lane(Lanes a) {
  return a.second;
}
#endif

/// The k-th product value[k] x[index[k]] of one row (T = double), or the
/// k-th products of two rows whose entries are interleaved (T = Lanes).
template <class T>
__attribute__((always_inline)) inline T entry_product(const double* value, const int* index,
                                                      const double* x, int k) {
  if constexpr (std::is_same_v<T, double>)
    return value[k] * x[index[k]];
  else
    return lane_products(value + 2 * k, index + 2 * k, x);
}

/// The sum of the Length products value[k] x[index[k]] (one row, T =
/// double, stride 1) or of two rows whose entries are interleaved (T =
/// Lanes, stride 2: the first row's k-th entry at 2k, the second's at
/// 2k + 1), in up to four partial sums started from the first products (no
/// add of a zero), so that both give a row the same bits.
template <int Length, class T>
__attribute__((always_inline)) inline T unrolled_dot(const double* value, const int* index,
                                                     const double* x) {
  auto product = [&](int k) { return entry_product<T>(value, index, x, k); };
  constexpr int sums = Length < 4 ? Length : 4;
  T s[sums];
#pragma GCC unroll 4
  for (int k = 0; k < sums; ++k)
    s[k] = product(k);
#pragma GCC unroll 16
  for (int k = sums; k < Length; ++k)
    s[k % sums] = s[k % sums] + product(k);
  if constexpr (sums == 1)
    return s[0];
  else if constexpr (sums == 2)
    return s[0] + s[1];
  else if constexpr (sums == 3)
    return (s[0] + s[1]) + s[2];
  else
    return (s[0] + s[1]) + (s[2] + s[3]);
}

/// The same for a length known at run time (>= 4): four partial sums, four
/// terms a trip, the remainder into the first.
template <class T>
__attribute__((always_inline)) inline T looped_dot(const double* value, const int* index,
                                                   const double* x, int length) {
  auto product = [&](int k) { return entry_product<T>(value, index, x, k); };
  T s0 = product(0), s1 = product(1), s2 = product(2), s3 = product(3);
  int k = 4;
  for (; k + 3 < length; k += 4) {
    s0 = s0 + product(k);
    s1 = s1 + product(k + 1);
    s2 = s2 + product(k + 2);
    s3 = s3 + product(k + 3);
  }
  for (; k < length; ++k)
    s0 = s0 + product(k);
  return (s0 + s1) + (s2 + s3);
}

template <int Length, class Store>
void SparseRows::run_rows(const SparseRows& rows, const Run& run, const double* x, Store& store) {
  const int* row = rows.m_row.data() + run.first_row;
  const int* index = rows.m_index.data() + run.first_entry;
  const double* value = rows.m_value.data() + run.first_entry;
  if constexpr (Length == 0) {
    for (int r = 0; r < run.n_rows; ++r)
      store(row[r], 0.0);
  } else {
    constexpr bool unrolled = Length <= max_unrolled;
    const int length = unrolled ? Length : run.length;
    auto dot = [&](auto lanes) {
      using T = decltype(lanes);
      if constexpr (unrolled)
        return unrolled_dot<Length, T>(value, index, x);
      else
        return looped_dot<T>(value, index, x, length);
    };
    int r = 0;
    for (; r + 1 < run.n_rows; r += 2, index += 2 * length, value += 2 * length) {
      const Lanes sums = dot(Lanes{});
      store(row[r], first_lane(sums));
      store(row[r + 1], second_lane(sums));
    }
    if (r < run.n_rows) store(row[r], dot(0.0));
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
