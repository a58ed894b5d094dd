#pragma once
// The mass matrix of an explicit integrator, factorized once and applied
// every step: M = P^T L D L^T P with L unit lower triangular.
//
// CHOLMOD does the analysis (its fill-reducing AMD order), the simplicial
// LDL^T factorization and reports its status; every pivot D_jj > 0 is
// checked. The factor is then copied out of CHOLMOD and its rows and
// columns renumbered, P being AMD followed by that renumbering:
//  - by connected component of M (the trees of L's elimination forest;
//    on the default case the bladed disk and the casing), so that each is
//    a contiguous block of positions, where the columns of M^-1 are
//    nonzero (block(), used for the contact correction);
//  - within a block by level: a column no row depends on has level 0, any
//    other is one above the highest column its row of L reads. That keeps
//    L lower triangular (l_ij != 0, i > j puts i above j) with the same
//    entries, and rows of one level do not depend on each other.
// The solves take the rows level by level across the blocks: the rows of a
// level do not read each other, so two of them can be summed at once
// (reference/sparse_rows) and the processor can overlap them, instead of
// following the chain of AMD's order (78 levels on the default case,
// against 838 rows).
//
// The integrator keeps its state in these permuted coordinates u' = P u,
// so a step applies L^-1, D^-1 and L^-T with no permutation. Both
// triangular solves are in row (dot) form, x_i = b_i - sum_j l_ij x_j, the
// rows of L for the forward solve and those of L^T (the columns of L) for
// the backward one, stored as reference/sparse_rows (within a level, rows
// of equal length together). bench/RESULTS.md compares this apply with
// Eigen's triangular solves on the same factor and with cholmod_solve2.

#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "failure_kinds.hpp"
#include "sparse_rows.hpp"

namespace rsi {

/// The mass matrix is not symmetric positive definite.
class MassFactorError : public NumericalFailure {
public:
  using NumericalFailure::NumericalFailure;
};

class MassFactor {
public:
  /// Factorizes M (symmetric, full storage); throws MassFactorError if it is
  /// not positive definite (a pivot D_jj <= 0) or CHOLMOD fails.
  explicit MassFactor(const Eigen::SparseMatrix<double>& mass);

  Eigen::Index n_dofs() const { return m_position.size(); }
  /// u'(position(i)) = u(i): where physical dof i sits in the permuted order.
  const Eigen::VectorXi& position() const { return m_position; }
  /// P A P^T for a matrix A of the same size (K, M in the integrator's coordinates).
  Eigen::SparseMatrix<double> permuted(const Eigen::SparseMatrix<double>& a) const;
  /// r <- (P M P^T)^-1 r = L^-T D^-1 L^-1 r.
  void solve_in_place(Eigen::Ref<Eigen::VectorXd> r) const;
  /// Entries of L below its unit diagonal: the solve does 4 flops per entry, plus n for D.
  double nonzeros_l() const { return static_cast<double>(m_l_rows.nonZeros()); }
  /// The contiguous range [first, first + size) of positions of the
  /// connected component of M that holds `position`: (M'^-1)_ij = 0 for i
  /// outside the range of j.
  std::pair<Eigen::Index, Eigen::Index> block(Eigen::Index position) const {
    const int b = m_block_of(position);
    return {m_block_start[b], m_block_start[b + 1] - m_block_start[b]};
  }
  /// L (strictly lower part, permuted coordinates) and D^-1, for tests and benchmarks.
  const RowMajorMatrix& strictly_lower_l() const { return m_l_rows; }
  const Eigen::VectorXd& inverse_d() const { return m_inverse_d; }

private:
  Eigen::VectorXi m_position;
  RowMajorMatrix m_l_rows;        ///< strictly lower part of L, by rows
  SparseRows m_forward;           ///< rows of L, level by level upward
  SparseRows m_backward;          ///< rows of L^T, level by level downward
  Eigen::VectorXd m_inverse_d;    ///< 1 / D_jj
  Eigen::VectorXi m_block_of;     ///< the block of each position
  std::vector<int> m_block_start; ///< first position of each block, then n
};

} // namespace rsi
