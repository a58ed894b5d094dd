#pragma once
// The exact solution of ONE contact's Coulomb problem, the local step of the
// nonsmooth Gauss-Seidel of coulomb_gauss_seidel.hpp (issue 12).
//
// One contact with d tangential directions (d = 1 or 2), its (1+d) square
// block W_cc of W and the free vector r = [r_n; r_t] (the predicted [g~; s~]
// plus the other contacts' forces W_cc' lambda_c'):
//     y = [g; s] = r + W_cc lambda,  lambda = [lambda_n; lambda_t].
// Find lambda with g >= 0, lambda_n >= 0, g lambda_n = 0, |lambda_t| <=
// mu lambda_n, s = 0 inside the cone, lambda_t = -mu lambda_n s/|s| on it.
// Write w_nn = W_cc(0,0), w_nt = W_cc(0, 1..d) (row), w_tn = W_cc(1..d, 0),
// W_tt = W_cc(1..d, 1..d), rho = -r_n.
//
// Candidates (derivation):
//  - open, lambda = 0: valid iff r_n >= 0. It is returned whenever valid; it
//    is the only solution when mu |w_nt| < w_nn (a closed solution would
//    need (w_nn - mu |w_nt|) lambda_n <= -r_n <= 0).
//  - r_n < 0, mu = 0: lambda = (rho / w_nn, 0), classified slip (the law
//    lambda_t = -0 s/|s| holds whatever s).
//  - r_n < 0, stick: y = 0, lambda = -W_cc^-1 r (LU solve); valid iff lambda_n >= 0 and
//    |lambda_t| <= mu lambda_n.
//  - r_n < 0, slip in the unit direction e (s = sigma e, sigma > 0):
//    lambda_t = -mu lambda_n e, g = 0 gives lambda_n = rho / (w_nn - mu w_nt e)
//    (needs a positive denominator), and s parallel to e. Multiplying s by
//    rho / lambda_n > 0:
//        H(e) = b + A e,  b = w_nn r_t + rho w_tn,  A = -mu (r_t w_nt + rho W_tt),
//    must satisfy H(e) = kappa e with kappa > 0.
//      d = 1: e = +1 or -1, two closed-form candidates.
//      d = 2: e = (cos th, sin th); f(th) = e x H(e) = cos th H_2 - sin th H_1
//      is a trigonometric polynomial of degree 2, so with t = tan((th - th0)/2)
//      (1 + t^2)^2 f is the quartic, in the frame turned by th0 (b' = R^T b,
//      A' = R^T A R),
//        (A'21 - b'2) t^4 - 2 (b'1 + A'22 - A'11) t^3 - 2 (A'21 + 2 A'12) t^2
//        + 2 (A'22 - A'11 - b'1) t + (b'2 + A'21).
//      th0 is the multiple of pi/4 with the largest |f(th0 + pi)| = |leading
//      coefficient|, so no root sits at t = infinity (a nonzero f of degree 2
//      cannot be small at all 8 samples). Its roots (eigenvalues of the 4 x 4
//      companion matrix, Eigen::EigenSolver) are polished by Newton's method
//      on f(th) and each gives a candidate.
// A slip candidate's violation is how far s is from sigma e, sigma >= 0,
// relative to the size of the terms summed into s (|r_t| + |w_tn| lambda_n
// + |W_tt| |lambda_t|, the largest entry):
//     (|s - (s . e) e| + max(-s . e, 0)) / size,
// round-off (a few eps) at a genuine solution, of order 1 at a root with s
// against e; unlike mu lambda_n |e - s/|s|| it stays well-conditioned as
// |s| -> 0 (near the stick boundary). A stick candidate's violation is
// max(-lambda_n, |lambda_t| - mu lambda_n, 0) / |lambda|.
// Choice: open when r_n >= 0; else stick when the stick multiplier lies in
// the cone (lambda_n >= 0, |lambda_t| <= mu lambda_n, as computed); else,
// for d = 2, first the warm path: when `current` slips (lambda_t != 0),
// Newton's method from its direction e = -lambda_t/|lambda_t|, taken if it
// converges to a root of violation <= 64 eps (an exact slip solution, the
// one continuous with the sweeps); else the slip candidate of least
// violation, and between candidates within 64 eps of it the one nearest
// `current` (the previous iterate: continuity of the sweeps where the slip
// problem has several solutions, which needs a large mu). Deciding stick by
// the cone test, not by comparing violations, keeps the choice exact near
// the stick/slip boundary.
// Cost (measured, one core): d = 1 0.05 us; d = 2 2.2 us through the
// quartic (the 4 x 4 eigenvalue problem dominates), less on the warm path.

#include <Eigen/Core>
#include <Eigen/LU>

#include "reduced_coulomb_certificate.hpp"

namespace rsi {

struct LocalCoulombSolution {
  Eigen::Vector3d lambda = Eigen::Vector3d::Zero(); ///< entries 0..d used [N]
  ReducedContactState state = ReducedContactState::open;
  /// the chosen candidate's relative violation of the law (above) [-]
  double violation = 0.0;
};

/// A contact's (1+d) square block, stored without heap allocation.
using CoulombBlockMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;

/// The local solution of the problem above. `w` holds W_cc in its leading
/// (1+d) square block, `w_lu` its LU factors with partial pivoting (used for
/// stick when r_n < 0 and mu > 0: a backward-stable solve, so the stick
/// residual y_c is round-off of |r| + |W_cc| |lambda| whatever W_cc's
/// condition); `r` and `current` in their first 1+d entries. The
/// caller (CoulombGaussSeidel) has checked d, mu and that W_cc is regular
/// where it is used: w_nn > 0 when r_n < 0, and W_cc invertible when also
/// mu > 0.
LocalCoulombSolution local_coulomb_solution(const Eigen::Matrix3d& w,
                                            const Eigen::PartialPivLU<CoulombBlockMatrix>& w_lu,
                                            const Eigen::Vector3d& r, int d, double mu,
                                            const Eigen::Vector3d& current);

} // namespace rsi
