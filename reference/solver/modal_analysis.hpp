#pragma once
// Undamped modal analysis K phi = omega^2 M phi of an assembled part.
//
// Dense path: LAPACKE dsygvd (symmetric-definite generalized problem, all
// eigenpairs). Sparse path, for models too large for dense matrices, the
// lowest modes by shift-invert about sigma = 0 (needs K nonsingular: a
// supported part):
//  - under 10,000 dofs, Spectra's Lanczos on Eigen's SparseLU of K, as
//    before: the campaign's stored thresholds were measured with it and its
//    CB runs take one vector of pairs of equal eigenvalues, which depends on
//    the solver's round-off (modal_analysis.cpp);
//  - from 10,000 dofs, the block Krylov-Schur method on CHOLMOD's
//    supernodal factor of K (block_shift_invert; Rotor 37's 50 modes in
//    seconds, bench/RESULTS.md), or Spectra's Lanczos on that factor
//    (cholmod_shift_invert) when the block basis would fill half the space.
// omega_max: Spectra's Lanczos in Cholesky mode on CHOLMOD's L L^T of M.
// Assumes K symmetric, M symmetric positive semi-definite. A failure (K
// singular, M not positive semi-definite, no convergence) is reported as
// ModalError, never ignored; so is an M that is not positive definite in
// the dense path and in max_angular_frequency (no finite omega_max). The
// sparse path needs M only positive semi-definite (massless directions are
// infinite eigenvalues, never among the lowest) and then sets omega_max to
// +infinity: CalculiX's mass of Rotor 37 (C3D15 wedges) is singular (about 100
// directions with M phi = 0 to 1e-15). Eigenvectors are mass-normalised:
// Phi^T M Phi = I, Phi^T K Phi = diag(omega^2).

#include <stdexcept>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

class ModalError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct Modes {
  Eigen::VectorXd omega_squared; ///< ascending [rad^2/s^2]
  Eigen::MatrixXd shapes;        ///< columns mass-normalised
  double omega_max = 0.0;        ///< largest omega of the model [rad/s], +inf if M singular

  int n_modes() const { return static_cast<int>(omega_squared.size()); }
  double frequency_hz(int i) const;
  /// Central-difference stability limit 2 / omega_max [s].
  double critical_time_step() const { return 2.0 / omega_max; }
};

enum class ModalSolver {
  automatic, ///< dense up to dense_limit dofs, sparse above
  dense,
  sparse
};

/// Largest model solved densely by ModalSolver::automatic (dense storage
/// of K and M: 2 n^2 doubles, 64 MB at this size).
constexpr int dense_limit = 2000;

/// True if K phi is zero to working precision: |K phi|_inf at most four
/// times the rounding of the product, 4 gamma_p || |K| |phi| ||_inf (rows of
/// at most p terms; Higham, Accuracy and Stability, eq. 3.5). A rigid
/// motion's phi passes; an elastic mode's K phi = lambda M phi stands clear of
/// it even when lambda_min / lambda_max is below n eps (refined or stiff
/// models). `residual` and `bound` receive the two numbers for messages.
bool within_product_rounding(const Eigen::SparseMatrix<double>& stiffness,
                             const Eigen::VectorXd& phi, double& residual, double& bound);

/// omega_max [rad/s] alone, by Lanczos (Spectra, Cholesky mode on CHOLMOD's
/// factor of M): cheap for any size, for the stability limit of explicit
/// integration. ModalError if M is not positive definite.
double max_angular_frequency(const Eigen::SparseMatrix<double>& stiffness,
                             const Eigen::SparseMatrix<double>& mass);

/// Up to this size the sparse path keeps Spectra's shift-invert Lanczos on
/// Eigen's SparseLU (fast at these sizes: the 2D bladed disks of this suite
/// have up to 5,000 dofs), from it the block method on CHOLMOD
/// (solver/block_shift_invert). The campaign's stored thresholds were
/// measured with the former, and its CB runs split pairs of equal
/// eigenvalues (cyclic symmetry: CB-4 ... CB-64 take one vector of a pair
/// equal to 1e-13), whose vector, and so the reduced model, depends on the
/// round-off of the solver.
constexpr int block_method_min_dofs = 10000;

/// The `count` lowest modes (1 <= count <= n, count < n for the sparse
/// path) and omega_max of the model.
Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count,
                   ModalSolver solver = ModalSolver::automatic);

class CholmodShiftInvert;

/// The same by the sparse path on a factor of K (shift 0) the caller has
/// already made, for a caller that needs K^-1 for more than the modes
/// (Craig-Bampton's constraint modes and fixed-interface modes share K_II's
/// factor): the block method, or Lanczos on that factor when the block
/// basis would not fit. 1 <= count < n.
Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count,
                   CholmodShiftInvert& factorized);

} // namespace rsi
