#pragma once
// Craig-Chang-Martinez (paper eqs. 8-20): psi free-interface modes Phi_1
// (modes of the whole bladed disk, the lowest unless selected otherwise) and n_B attachment modes
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
// By count: the psi lowest free modes. By selection (mode_selection.hpp):
// any psi of a pool of the lowest modes, R then the residual of the kept ones.
// Valid range: 0 <= psi <= n - n_B.

#include <chrono>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "accurate_solve.hpp"
#include "modal_analysis.hpp"
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

/// The candidates of a residual-flexibility basis, computed as the
/// count-based builder computes them for `count` modes: with few modes
/// (few_modes(count, n) sparse) the `count` lowest free modes by Lanczos and
/// K^-1 E_B (refined, CHOLMOD); with many, every mode (LAPACK dense), R then
/// being the sum over the modes not kept (no K^-1, no cancellation).
struct FreeInterfacePool {
  Modes modes;   ///< ascending; every mode when `complete`, else the `count` lowest
  int count = 0; ///< the candidates are modes 0 .. count-1
  bool complete = false;
  AccurateMatrix flexibility; ///< K^-1 E_B, n x n_B (only when not complete; see below)
};

/// Throws ReductionError, its message starting with `name`, for a singular
/// or indefinite K. `count` in [0, n - n_B] (not checked here). With
/// `flexibility_columns` (boundary positions), the sparse path's
/// `flexibility` holds K^-1 on those boundary columns only, in that order
/// (turned_residual_flexibility.hpp turns one sector's).
FreeInterfacePool free_interface_pool(const Eigen::SparseMatrix<double>& stiffness,
                                      const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                      int count, const std::string& name,
                                      const std::vector<int>* flexibility_columns = nullptr);

/// cond(R_B) of the boundary's residual flexibility (symmetric part), or
/// ReductionError, its message starting with `name`, when it is at or above
/// 1/(n eps): no significant digit left in R_B^-1 (paper §5.3).
double residual_flexibility_condition(const Eigen::MatrixXd& r_b, int n, const std::string& name);

/// T and cond(R_B) keeping the pool's modes `kept` (ascending indices below
/// pool.count) as Phi_1. Throws ReductionError, its message starting with
/// `name`, for a numerically singular R_B.
ResidualFlexibilityTransformation residual_flexibility_transformation(const Partition& p,
                                                                      const FreeInterfacePool& pool,
                                                                      const std::vector<int>& kept,
                                                                      const std::string& name);

/// T and cond(R_B) for psi in [0, n - n_B] (not checked here: the callers
/// state their own range): the pool of psi modes, every one kept. Throws
/// ReductionError, its message starting with `name`, for a singular or
/// indefinite K or a numerically singular R_B.
ResidualFlexibilityTransformation
residual_flexibility_transformation(const Eigen::SparseMatrix<double>& stiffness,
                                    const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                    int psi, const std::string& name);

/// ReductionError unless 0 <= psi <= n - n_B.
void check_free_interface_count(const Partition& p, int psi);

/// The basis keeping the pool's modes `kept` (ascending), in that order;
/// `start` is when the work began (build_seconds). mode_index = kept.
ReducedBasis craig_chang_martinez(const Eigen::SparseMatrix<double>& stiffness,
                                  const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                  const FreeInterfacePool& pool, const std::vector<int>& kept,
                                  std::chrono::steady_clock::time_point start);

struct CyclicBoundary;

/// The psi lowest free-interface modes. With `cyclic` (a cyclic component)
/// and few modes (few_modes sparse), T and its projections from the turned
/// constraint modes (turned_residual_flexibility.hpp); otherwise, and
/// without `cyclic`, as the pool's builder above.
ReducedBasis craig_chang_martinez(const Eigen::SparseMatrix<double>& stiffness,
                                  const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                  int psi, const CyclicBoundary* cyclic = nullptr);

} // namespace rsi
