#pragma once
// The lowest eigenpairs of K phi = lambda M phi by a block Krylov method on
// the shift-invert operator T = K^-1 M (shift 0): block Krylov-Schur.
//
// Method. T is self-adjoint in the M inner product and its eigenvalues are
// theta = 1/lambda, so the lowest lambda are the largest theta. The basis V
// of a block Krylov space of T is kept M-orthonormal; each step solves
// K W = M Q for the newest block Q of b vectors at once (one CHOLMOD
// supernodal solve with b right-hand sides: BLAS-3, about 7 times cheaper a
// vector than b single solves on Rotor 37, bench/RESULTS.md), M-orthogonalizes
// W against V twice (block classical Gram-Schmidt, BLAS-3) and then within
// itself (SVQB twice: the eigendecomposition of the column-scaled M-Gram
// matrix, which keeps the relation W = Q R exact and drops numerically
// dependent directions). The projection coefficients are the entries of
// H = V^T M T V, so T V = V H + Q_next B holds with the next block Q_next
// and its coupling B. Rayleigh-Ritz: H = S Theta S^T (LAPACKE dsyevd; the
// projected pencil is (H, I) because V^T M V = I to round-off), Ritz vectors
// V S. When the basis holds max_basis vectors, it restarts thick
// (Krylov-Schur): it keeps the n_kept Ritz vectors of largest theta, whose
// relation T Y = Y Theta + Q_next (B S) stays exact, so no Krylov
// information is thrown away but the rest.
//
// Convergence. After every step with at least `count` Ritz vectors, the
// estimates e_i = |B s_i| / theta_i (the Ritz residuals of T, relative) are
// compared with a trigger, at first the tolerance; when every wanted one
// passes, the true residuals |K phi - lambda M phi| / |K phi| of the wanted
// Ritz vectors are computed (one product K Phi), with lambda their Rayleigh
// quotients phi^T K phi / phi^T M phi. A mode has converged when its
// residual is below tolerance + eps ||K||_1 |phi| / |K phi|, the second term
// being the rounding level of K phi itself (about a shift sigma != 0 the
// residual is relative to |K phi| + |lambda| |M phi|, its floor eps
// (||K||_1 + |lambda| ||M||_1) |phi| over the same, as solver/modal_check
// measures it, and a rigid-body mode, whose energy phi^T K phi is not
// resolved, converges on its Ritz estimate: its K phi is what is left of
// the other modes in it, and its true residual stays of order one): for
// the lowest modes of a stiff
// model it is the larger one (Rotor 37's first mode: 1.4e-7, its residual
// stalls at 1.4e-8). The true residual runs 5 to 1000 times the estimate
// (the next block holds stiffer directions), so a mode that fails is
// checked again once its estimate fell by the factor it missed by. A
// residual r bounds the relative eigenvalue error by about |r|^2 / gap
// (symmetric pencils): tolerance 1e-9 gives eigenvalues far below 1e-8
// unless two are closer than 1e-10 relative. A restart cycle whose checks
// do not halve the worst residual (relative to tolerance + floor) of the
// cycle before has stalled: not_converged at once, rather than after
// max_restarts (modal_analysis then takes Lanczos on the same factor).
//
// The first block is T X with X random (fixed seed: reproducible), so every
// basis vector is in the range of T: M may be singular (positive
// semi-definite; its null space holds the infinite eigenvalues, never
// wanted). K must be symmetric positive definite (a supported part; a
// failed factorization, or a lowest mode whose energy the factor does not
// resolve, as in reduced/bases/guyan, is the status
// stiffness_not_positive_definite), or, with a shift sigma < 0
// (options.shift: T = (K - sigma M)^-1 M, theta = 1 / (lambda - sigma)),
// positive semi-definite with K - sigma M positive definite (a free part:
// its rigid-body modes are the eigenvalues 0); M symmetric positive
// semi-definite; both in full (symmetric) storage. The eigenvalues are the
// Rayleigh quotients phi^T K phi / phi^T M phi, whatever the shift.
//
// Parameters (BlockShiftInvertOptions): the block size b trades the solve's
// speed a vector (BLAS-3 grows with b) against the Krylov degree per solve
// (falls with b); b = 24, n_kept = count + b/2, max_basis = n_kept + 10 b
// solved Rotor 37's 50 modes in the fewest seconds (bench/RESULTS.md).
//
// Cost a step: one block solve, one sparse product M W, 8 n m b flops of
// Gram-Schmidt (m the basis size) and 12 n b^2 of SVQB, all BLAS-3. Memory:
// V and M V, 2 n (max_basis + b) doubles, besides CHOLMOD's factor of K;
// no n x n matrix.
//
// Errors: bad arguments throw std::invalid_argument("block_shift_invert:
// ..."); numerical failure (K not positive definite, M not positive
// semi-definite on the Krylov space, no convergence in max_restarts restarts)
// is the result's status with a message.

#include <cstdint>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "cholmod_factor.hpp"

namespace rsi {

struct BlockShiftInvertOptions {
  /// b, vectors a block solve: b >= 1.
  int block_size = 24;
  /// Ritz vectors kept at a restart, count <= n_kept; 0: count + b / 2.
  int n_kept = 0;
  /// Largest basis before a restart, n_kept + b <= max_basis <= n - b; 0: n_kept + 10 b.
  int max_basis = 0;
  /// Restarts before giving up, >= 0.
  int max_restarts = 50;
  /// On |K phi - lambda M phi| / |K phi| (plus its rounding level), in (0, 1).
  double tolerance = 1e-9;
  /// Of the random first block.
  std::uint64_t seed = 20261123;
  /// sigma: the operator is (K - sigma M)^-1 M, K - sigma M positive definite
  /// (0 for a supported part, below 0 for a free one, whose K is singular);
  /// not used when a factor is given (its own shift is).
  double shift = 0.0;
  CholmodFactor::Method factorization = CholmodFactor::Method::supernodal;
};

struct BlockShiftInvertResult {
  enum class Status {
    successful,
    stiffness_not_positive_definite,
    mass_not_semidefinite,
    not_converged,
    failed
  };
  Status status = Status::failed;
  std::string message;             ///< why not successful
  Eigen::VectorXd eigenvalues;     ///< count lambda, ascending
  Eigen::MatrixXd eigenvectors;    ///< n x count, M-orthonormal
  Eigen::VectorXd residuals;       ///< |K phi - lambda M phi| / |K phi| of each (sigma != 0: header)
  Eigen::VectorXd residual_floors; ///< eps ||K||_1 |phi| / |K phi|: its rounding level (the same)
  long n_solves = 0;               ///< right-hand sides solved (a block of b counts b)
  int n_block_solves = 0;          ///< block solves
  int n_restarts = 0;
  int basis_size = 0; ///< of the last Rayleigh-Ritz
  struct Seconds {
    double factorization = 0.0; ///< analysis and numeric factorization of K
    double solves = 0.0;        ///< block solves
    double products = 0.0;      ///< sparse M W and K Phi
    double orthogonalization = 0.0;
    double rayleigh_ritz = 0.0; ///< eigendecompositions of H, Ritz vectors, restarts
  } seconds;
};

class CholmodShiftInvert;

/// The `count` lowest eigenpairs (1 <= count; the basis must fit: max_basis + b <= n).
/// `factorized`, if given, is a successful factor of this K - sigma M at its
/// shift sigma (0: of K), used instead of factorizing again (a caller that
/// needs K^-1 for more than the modes factorizes once); its size is checked
/// (std::invalid_argument), and options.factorization and options.shift are
/// then not used.
BlockShiftInvertResult block_shift_invert(const Eigen::SparseMatrix<double>& stiffness,
                                          const Eigen::SparseMatrix<double>& mass, int count,
                                          const BlockShiftInvertOptions& options = {},
                                          const CholmodShiftInvert* factorized = nullptr);

} // namespace rsi
