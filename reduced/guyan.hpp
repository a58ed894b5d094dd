#pragma once
// Guyan static condensation: the constraint modes of the boundary
// (paper §4.2): for a unit displacement of boundary dof b, the others held
// at zero and no interior load, u_I = -K_II^-1 K_IB e_b. Coordinates q = q_B.
// Equal to Craig-Bampton with eta = 0 and to Craig-Chang-Martinez with
// psi = 0 (SPEC V4). Assumes K_II positive definite (the hub is clamped).

#include <chrono>

#include <Eigen/SparseCore>

#include "partition.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// Psi_I = -K_II^-1 K_IB (n_I x n_B), by a sparse Cholesky factorization
/// (CHOLMOD). Throws ReductionError if K_II is not positive definite.
Eigen::MatrixXd constraint_modes(const Eigen::SparseMatrix<double>& stiffness, const Partition& p);

/// Completes a basis whose transformation is set: the n_boundary boundary
/// coordinates sit at q[first_boundary_position ...], K^ = T^T K T and
/// M^ = T^T M T (symmetrized: the products are symmetric up to round-off),
/// and the build time since `start`.
void finish_basis(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int n_boundary,
                  int first_boundary_position, std::chrono::steady_clock::time_point start,
                  ReducedBasis& basis);

ReducedBasis guyan(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, const Partition& p);

} // namespace rsi
