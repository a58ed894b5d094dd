#pragma once
// Boundary / interior partition of the bladed disk (paper eq. 3): the
// boundary B is a list of dofs kept as physical coordinates (the 44 tip
// u, v by default), the interior I is every other dof, in increasing order.

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal_analysis.hpp"

namespace rsi {

struct Partition {
  std::vector<int> boundary; ///< B, in the order given
  std::vector<int> interior; ///< I, ascending

  int n() const { return static_cast<int>(boundary.size() + interior.size()); }
  int n_boundary() const { return static_cast<int>(boundary.size()); }
  int n_interior() const { return static_cast<int>(interior.size()); }
};

/// Throws std::invalid_argument for a repeated or out-of-range boundary dof.
Partition make_partition(int n_dofs, const std::vector<int>& boundary);

/// The block A(rows, cols) of a sparse matrix, as a sparse matrix.
Eigen::SparseMatrix<double> sparse_block(const Eigen::SparseMatrix<double>& a,
                                         const std::vector<int>& rows,
                                         const std::vector<int>& cols);

/// Scatter: the n x c matrix with rows `rows` taken from `block` and zero elsewhere.
Eigen::MatrixXd place_rows(int n, const std::vector<int>& rows,
                           const Eigen::Ref<const Eigen::MatrixXd>& block);

/// Gather: the rows `rows` of `a`.
Eigen::MatrixXd take_rows(const Eigen::Ref<const Eigen::MatrixXd>& a, const std::vector<int>& rows);

/// Gather: the columns `columns` of `a`, in that order.
Eigen::MatrixXd take_columns(const Eigen::Ref<const Eigen::MatrixXd>& a,
                             const std::vector<int>& columns);

/// Gather: the entries `entries` of `a`, in that order.
Eigen::VectorXd take_entries(const Eigen::Ref<const Eigen::VectorXd>& a,
                             const std::vector<int>& entries);

/// Lanczos (sparse) for a few modes, the dense solver when many are asked
/// (a quarter of the dofs or more, where Lanczos gains nothing).
inline ModalSolver few_modes(int count, int n) {
  return 4 * count < n ? ModalSolver::sparse : ModalSolver::dense;
}

} // namespace rsi
