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

/// Modes asked of a solver that cannot resolve them (exit status 2 in the
/// CLI): every eigenvalue by the dense solver, whose resolution n eps
/// lambda_max the lowest eigenvalue does not clear (see lowest_modes).
class ModalResolutionError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
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

/// The dense solver's resolution of the eigenvalues of `modes` (all of a
/// model's, with omega_max): the solver is backward stable on
/// C = L^-1 K L^-T (M = L L^T), so it places every eigenvalue to within
/// p(n) eps ||C||_2 = p(n) eps lambda_max (LAPACK Users' Guide, 3rd ed.,
/// §4.7 and §4.10; p(n) taken as n): n eps lambda_max. An eigenvalue at or
/// below it is not resolved, its sign included (a blade 1e-8 m thick came
/// out at -6e-4 Hz), and a rigid motion's sits there.
double dense_resolution(const Modes& modes);

/// The `count` lowest modes (1 <= count <= n, count < n for the sparse
/// path) and omega_max of the model.
///
/// With `automatic`, never a negative, zero or NaN eigenvalue (issue 13,
/// class 7): when the dense solver does not resolve the lowest eigenvalue
/// (dense_resolution), the sparse path solves the same model instead
/// (shift-invert about 0 on a factor of K resolves the low end down to K's
/// own rounding); with count = n there is no sparse path, and
/// ModalResolutionError says so. `dense` returns the dense solver's
/// eigenvalues as they are (a free part's rigid motions at round-off, for
/// tests; Craig-Bampton and Craig-Chang-Martinez check them themselves).
/// The sparse path refuses, as ModalError, a lowest mode whose energy is
/// not resolved (linalg/energy_resolution: a null vector, a K too stiff
/// for double precision) or whose eigenvalue is not positive, and as
/// ModalResolutionError modes asked beyond what shift-invert resolves:
/// computing theta = 1/lambda to within p(n) eps theta_max, it resolves
/// eigenvalues only below lambda_min / (n eps) (the mirror image of
/// dense_resolution; most of the modes of a stiff model reach past it: a
/// blade 1e-7 m thick, 600 of 682 modes, gave one at -6e8 rad^2/s^2).
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
