#pragma once
// Undamped modal analysis K phi = omega^2 M phi of an assembled part.
//
// Assumes K and M symmetric, M positive semi-definite (massless directions
// are infinite eigenvalues, never among the lowest: consistent masses of
// C3D20R, C3D10, C3D15, CPS3, S8R... elements are singular), K positive
// semi-definite with no null vector in common with M (a free part: its
// rigid-body motions are eigenvalues 0). Eigenvectors are mass-normalised:
// Phi^T M Phi = I, Phi^T K Phi = diag(omega^2).
//
// Dense path (up to dense_limit dofs): LAPACKE dsygvd on (K, M) when M is
// positive definite (all eigenpairs, every eigenvalue to n eps lambda_max);
// otherwise, or when that answer fails its check (an ill-conditioned M: the
// solver is backward stable on L^-1 K L^-T, M = L L^T, not on the pencil),
// the shift-invert form: dsygvd on (M, K - sigma M), sigma = 0 for a K
// positive definite to working precision, below the spectrum otherwise
// (shift_below_spectrum).
// Sparse path, for models too large for dense matrices, the lowest modes by
// shift-invert about sigma = 0, or about sigma < 0 when K is singular to
// working precision (a free part):
//  - under 10,000 dofs, Spectra's Lanczos on Eigen's SparseLU of K, as
//    before: the campaign's stored thresholds were measured with it and its
//    CB runs take one vector of pairs of equal eigenvalues, which depends on
//    the solver's round-off (modal_analysis.cpp), with the mass scaled by a
//    power of 4 for Spectra's absolute thresholds (lanczos_mass_scale);
//    a free part's on a CHOLMOD factor of K - sigma M;
//  - from 10,000 dofs, the block Krylov-Schur method on CHOLMOD's
//    supernodal factor of K - sigma M (block_shift_invert; Rotor 37's 50
//    modes in seconds, bench/RESULTS.md), or Spectra's Lanczos on that
//    factor (cholmod_shift_invert) when the block basis would fill half the
//    space.
// Every answer is checked (solver/modal_check: residuals, M-orthonormality,
// a Sturm count) and carries the uncertainty of each eigenvalue
// (Modes::accuracy); a sparse answer that fails falls back to the dense
// shift-invert solver up to 4,000 dofs; a failure left is ModalCheckError.
// omega_max: Spectra's Lanczos in Cholesky mode on CHOLMOD's L L^T of M,
// +infinity for a singular M (Rotor 37's C3D15 mass: about 100 directions
// with M phi = 0 to 1e-15); max_angular_frequency needs M positive definite.
// A failure (K or M not positive semi-definite, no convergence, a failed
// check) is reported as ModalError, never ignored.

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "failure_kinds.hpp"

namespace rsi {

class ModalError : public NumericalFailure {
public:
  using NumericalFailure::NumericalFailure;
};

/// Modes asked of a solver that cannot resolve them (exit status 2 in the
/// CLI): every eigenvalue by the dense solver, whose resolution n eps
/// lambda_max the lowest eigenvalue does not clear (see lowest_modes).
class ModalResolutionError : public BadInput {
public:
  using BadInput::BadInput;
};

/// What the check of a set of modes found (solver/modal_check.hpp): every
/// returned pair's residual, the M-orthonormality, the Sturm count, and the
/// uncertainty of each eigenvalue [rad^2/s^2] from the rounding of the
/// input (a) and the solver (b).
struct ModalAccuracy {
  bool checked = false;
  bool passed = false;
  std::string failure;               ///< which check failed, its value and bound
  std::string solver;                ///< which solver returned the modes
  std::string replaced;              ///< the solver tried first and why its answer was not kept
  double shift = 0.0;                ///< sigma, K - sigma M positive definite (the bounds' pencil)
  int input_digits = 17;             ///< significant digits the entries of K and M carry
  double input_rounding = 0.0;       ///< their relative rounding eps_in
  Eigen::VectorXd residual;          ///< r_i
  Eigen::VectorXd residual_bound;    ///< tau_r + gamma_n kappa_i
  double orthonormality = 0.0;       ///< max |Phi^T M Phi - I|
  double orthonormality_bound = 0.0; ///< tau_o + gamma_n |M|_1 max |phi|^2
  double sturm_shift = 0.0;          ///< tau = lambda_top + w
  int sturm_count = -1;              ///< eigenvalues below it (negative pivots)
  double sturm_shift_below = 0.0;    ///< lambda_top - w, when the count above exceeds the modes
  int sturm_count_below = -1;        ///< eigenvalues below that (-1: not needed)
  int returned_below = 0;            ///< modes returned below it
  Eigen::VectorXd rounding;          ///< a_i [rad^2/s^2]
  Eigen::VectorXd solver_error;      ///< b_i [rad^2/s^2]
  Eigen::VectorXd uncertainty;       ///< a_i + b_i [rad^2/s^2]
  std::vector<bool> zero;            ///< |lambda_i| <= uncertainty_i: a rigid-body motion
  int n_zero = 0;                    ///< how many
  /// Orthonormal directions z with K z = 0 and M z = 0 the dense solver left
  /// out (n x z; no eigenvalue there, 0/0), empty for a regular pencil.
  Eigen::MatrixXd null_directions;
};

struct Modes {
  Eigen::VectorXd omega_squared; ///< ascending [rad^2/s^2]
  Eigen::MatrixXd shapes;        ///< columns mass-normalised
  double omega_max = 0.0;        ///< largest omega of the model [rad/s], +inf if M singular
  ModalAccuracy accuracy;        ///< the check of these modes (lowest_modes always checks)

  int n_modes() const { return static_cast<int>(omega_squared.size()); }
  /// sign(lambda) sqrt(|lambda|) / 2 pi, as computed (also for a zero mode).
  double frequency_hz(int i) const;
  /// Whether mode i is zero to its uncertainty (a rigid-body motion); false if not checked.
  bool is_zero(int i) const;
  /// The frequency as claimed: 0 for a zero mode, else frequency_hz(i) [Hz].
  double claimed_frequency_hz(int i) const;
  /// The bound on |f_i - f_exact| [Hz]: u_i / (2 lambda_i) f_i (f proportional to
  /// sqrt(lambda)), sqrt(|lambda_i| + u_i) / 2 pi for a zero mode; NaN if not checked.
  double uncertainty_hz(int i) const;
  /// Significant digits of frequency_hz(i) the uncertainty leaves: floor(-log10 of the
  /// relative uncertainty), 0 to 17; 0 for a zero mode.
  int digits(int i) const;
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

/// Above dense_limit, ModalSolver::automatic still solves densely when more
/// than a quarter of the modes are asked, up to this size: Lanczos keeps a
/// basis of about 2 count vectors and costs O(n count^2) a restart, the
/// dense solver about 10 n^3 flops once (the 4,101-dof blade3d with 4,000
/// modes: 7 min of Lanczos); dense storage, about 6 n^2 doubles, is 3 GB
/// here. Above it, all n modes are refused (the sparse path needs count < n).
constexpr int dense_many_modes_limit = 8000;

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
/// out at -6e-4 Hz), and a rigid motion's sits there. For modes of a
/// singular M (omega_max infinite: the shift-invert form) the checked
/// uncertainty of the lowest one.
double dense_resolution(const Modes& modes);

/// Whether M is positive definite to working precision (CHOLMOD's L L^T of
/// it exists): the dense solver on (K, M) and omega_max need it.
bool positive_definite_mass(const Eigen::SparseMatrix<double>& mass);

/// A shift sigma < 0 below every eigenvalue of (K, M) for K positive
/// semi-definite (a free part: its rigid-body modes at 0), for shift-invert:
/// minus the power of 4 nearest eps^(1/4) d (1.2e-4 d), d the smallest
/// K_ii / M_ii (M_ii > 0; a Rayleigh quotient, an element's frequency
/// squared, the scale of the stiff end of the spectrum; -1 if no dof has
/// both). Near 0, so that the elastic eigenvalues keep their separation in
/// theta = 1 / (lambda - sigma) (a shift of -d crowded a free cube's lowest
/// 10 into 0.7 % of theta, and the block method stalled); far from 0 for
/// the conditioning of K - sigma M, lambda_max / |sigma| = 1e4 lambda_max / d
/// (at sqrt(eps) d the M-orthonormality of the dense solver's vectors fell
/// to 6e-10 on a 729-dof cube), and for its definiteness: the rigid-body
/// energy |sigma| phi^T M phi stands 1e10 above the rounding of phi^T K phi,
/// gamma_p |phi|^T |K| |phi| (about 1e-14 d). K - sigma M is positive
/// definite unless K and M share a null vector.
double shift_below_spectrum(const Eigen::SparseMatrix<double>& stiffness,
                            const Eigen::SparseMatrix<double>& mass);

/// The `count` lowest modes (1 <= count <= n, count < n for the sparse
/// path) and omega_max of the model, checked (modes.accuracy).
///
/// With `automatic`, never an unresolved eigenvalue taken for a result
/// (issue 13, class 7): when the dense solver does not resolve the lowest
/// eigenvalue (dense_resolution), the sparse path solves the same model
/// instead (shift-invert resolves the low end down to K's own rounding);
/// with count = n there is no sparse path, and ModalResolutionError says
/// so. `dense` returns the dense solver's eigenvalues as they are, checked
/// (a free part's rigid motions at round-off, for tests; Craig-Bampton and
/// Craig-Chang-Martinez check them themselves). On the sparse path a K
/// singular to working precision (the lowest mode's energy not resolved,
/// linalg/energy_resolution: a free part, or one too stiff for double
/// precision) is solved about a shift below the spectrum: its zero modes
/// come out at 0 within their uncertainty (Modes::is_zero). Modes asked
/// beyond what shift-invert resolves are ModalResolutionError: computing
/// theta = 1/(lambda - sigma) to within p(n) eps theta_max, it resolves
/// eigenvalues only below sigma + (lambda_min - sigma) / (n eps) (the mirror
/// image of dense_resolution; most of the modes of a stiff model reach past
/// it: a blade 1e-7 m thick, 600 of 682 modes, gave one at -6e8 rad^2/s^2);
/// so are more modes than M has finite eigenvalues (its rank). A failed
/// check is ModalCheckError (a ModalError), naming the check and its numbers.
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
