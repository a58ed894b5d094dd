#pragma once
// Craig-Chang-Martinez (paper eqs. 8-20): psi free-interface modes Phi_1
// (the lowest modes of the whole bladed disk) and n_B attachment modes
// through the residual flexibility R = K^-1 - Phi_1 Omega_1^-1 Phi_1^T
// (eq. 14), transformed to the coordinates q = (q_B, u_1) (eq. 20):
//   u_B = q_B,
//   u_I = R_I R_B^-1 q_B + (Phi_1I - R_I R_B^-1 Phi_1B) u_1,
// with R_B = R(B, B), R_I = R(I, B). K^-1 on the boundary columns comes
// from a sparse Cholesky factorization of K (CHOLMOD).
//
// R_B must be invertible: its condition number is reported, and a basis
// with cond(R_B) >= 1/(n eps) (no significant digit left in R_B^-1) is
// refused with ReductionError. Attachment modes on rotation dofs make R_B
// ill-conditioned (paper §5.3; Bladh, Pierre, Castanier, AIAA J. 41, 2003).
// K must be positive definite (a supported part: the hub clamped); a
// singular or indefinite K (CHOLMOD pivots, or the lowest eigenvalue on the
// dense path) is refused with ReductionError naming K.
// Valid range: 0 <= psi <= n - n_B.

#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "partition.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// The transformation of eq. 20 alone, shared with MacNeal's method (same
/// T, another mass): columns [attachment R(:, B) R_B^-1 | Phi_1 - attachment
/// Phi_1B], q = (q_B, u_1), exact identity and zeros on the boundary rows.
struct ResidualFlexibilityTransformation {
  Eigen::MatrixXd transformation; ///< T, n x (n_B + psi)
  double cond_rb = 0.0;           ///< cond(R_B)
  Eigen::VectorXd mode_omega;     ///< omega_i of the psi free modes Phi_1 [rad/s]
};

/// T and cond(R_B) for psi in [0, n - n_B] (not checked here: the callers
/// state their own range). Throws ReductionError, its message starting with
/// `name`, for a singular or indefinite K or a numerically singular R_B.
ResidualFlexibilityTransformation
residual_flexibility_transformation(const Eigen::SparseMatrix<double>& stiffness,
                                    const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                    int psi, const std::string& name);

ReducedBasis craig_chang_martinez(const Eigen::SparseMatrix<double>& stiffness,
                                  const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                  int psi);

} // namespace rsi
