#pragma once
// Positive definiteness to working precision: whether double precision
// resolves the energy x^T A x of a symmetric matrix A (a stiffness K or a
// mass M) at the motion where it is least resolved (issue 13, class 7).
//
// x^T A x is a sum of terms a_ij x_i x_j whose magnitudes add up to
// |x|^T |A| |x|. Its rounding, in the assembled entries of A and in the
// product itself, is up to gamma_p |x|^T |A| |x|, gamma_p = p eps / (1 - p
// eps) with p the most entries in a row of A (Higham, Accuracy and
// Stability of Numerical Algorithms, 2nd ed., eq. 3.5, the rounding of the
// product A x). So
//     c(x) = |x|^T |A| |x| / x^T A x
// is the condition number of the energy of x, and the energy is resolved,
// its sign and leading digit known, only if gamma_p c(x) < 1. A is positive
// definite to working precision if that holds at every x; the motion that
// decides is the least-energy one, the lowest mode of A x = lambda B x (B:
// a mass, or the identity). A slender member shows why: bending a thin
// beam whose elements meet at an angle moves their axial terms, which
// cancel to the bending energy, smaller by (thickness / length)^2; below
// eps that energy, and the frequency it sets, is rounding (a negative
// frequency from the dense modal solver, not the 1e-4 Hz it should be).
//
// The lowest mode is found by inverse iteration x <- A^-1 B x on CHOLMOD's
// factor of A (linalg/cholmod_factor); a factorization that stops at a
// pivot <= 0 already shows A not positive definite.

#include <functional>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

/// The energy x^T A x and its rounding level.
struct EnergyResolution {
  double energy = 0.0;    ///< x^T A x
  double magnitude = 0.0; ///< |x|^T |A| |x|
  double rounding = 0.0;  ///< gamma_p |x|^T |A| |x|, the energy's uncertainty
  int row_terms = 0;      ///< p, the most entries in a row of A

  /// The condition number c(x) = |x|^T |A| |x| / x^T A x (infinite or
  /// negative for an energy <= 0).
  double condition() const { return magnitude / energy; }
  /// 1 / gamma_p: the largest condition number double precision resolves.
  double resolvable_condition() const { return magnitude / rounding; }
  bool resolved() const { return energy > rounding; }
};

/// The energy of `x` under the symmetric `a` (full storage) and its rounding level.
EnergyResolution energy_resolution(const Eigen::SparseMatrix<double>& a,
                                   const Eigen::Ref<const Eigen::VectorXd>& x);

/// The least-resolved energy of a symmetric `a`, judged at the lowest mode
/// of a x = lambda b x (b symmetric positive definite, full storage; b = the
/// identity if empty).
struct DefinitenessCheck {
  bool factorized = false;     ///< CHOLMOD's L L^T of a exists (every pivot > 0)
  std::string why;             ///< when not: CHOLMOD's message (the column of the pivot)
  Eigen::VectorXd motion;      ///< the lowest mode found (b-normalised); empty if not factorized
  double eigenvalue = 0.0;     ///< its Rayleigh quotient x^T a x / x^T b x
  int iterations = 0;          ///< inverse iterations made
  EnergyResolution resolution; ///< of `motion`

  bool positive_definite() const { return factorized && resolution.resolved(); }
};

/// Inverse iteration from a fixed pseudo-random start until the Rayleigh
/// quotient changes by less than 1 % in a step (the decision compares
/// gamma_p c(x) with 1, orders of magnitude: 1 % on the energy is 1 % on
/// c), at most 100 steps (the error of the vector shrinks by lambda_1 /
/// lambda_k each step, lambda_k the first eigenvalue outside the lowest
/// cluster; a cluster of equal eigenvalues, the 22 blades' first family,
/// converges as one).
DefinitenessCheck check_positive_definite(const Eigen::SparseMatrix<double>& a,
                                          const Eigen::SparseMatrix<double>& b);

/// x = A^-1 rhs with a factor of A the caller made; false on failure.
using FactorSolve = std::function<bool(const Eigen::VectorXd& rhs, Eigen::VectorXd& x)>;

/// The same inverse iteration on a factor of `a` the caller already has
/// (a factorization that succeeded: `factorized` is set).
DefinitenessCheck lowest_energy(const Eigen::SparseMatrix<double>& a,
                                const Eigen::SparseMatrix<double>& b, const FactorSolve& solve);

} // namespace rsi
