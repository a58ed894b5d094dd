#pragma once
// Undamped modal analysis K phi = omega^2 M phi of an assembled part.
//
// Dense path: LAPACKE dsygvd (symmetric-definite generalized problem, all
// eigenpairs). Sparse path, for models too large for dense matrices:
// Spectra's Lanczos solvers, shift-invert about sigma = 0 for the lowest
// modes (needs K nonsingular: a supported part) and Cholesky mode for
// omega_max. Assumes K symmetric, M symmetric positive definite. A failure
// (M not positive definite, K singular, no convergence) is reported as
// ModalError, never ignored. Eigenvectors are mass-normalised:
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
  double omega_max = 0.0;        ///< largest omega of the whole model [rad/s]

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

/// omega_max [rad/s] alone, by Lanczos (Spectra, Cholesky mode): cheap for
/// any size, for the stability limit of explicit integration.
double max_angular_frequency(const Eigen::SparseMatrix<double>& stiffness,
                             const Eigen::SparseMatrix<double>& mass);

/// The `count` lowest modes (1 <= count <= n, count < n for the sparse
/// path) and omega_max of the model.
Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count,
                   ModalSolver solver = ModalSolver::automatic);

} // namespace rsi
