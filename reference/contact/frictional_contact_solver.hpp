#pragma once
// The reference solver of the per-step frictional contact problem
// (frictional_contact_problem.hpp): Alart-Curnier's augmented Lagrangian
// equations solved by a semismooth (generalized) Newton method with an
// Armijo line search on 1/2 |F|^2.
//
// Equations (Alart, Curnier, CMAME 92 (1991) 353; Christensen, Klarbring,
// Pang, Stroemberg, IJNME 42 (1998) 145). With q = q~ + W lambda, per
// contact c with augmentation r_c = 1 / W_nn,c > 0 [N/m]:
//   a     = lambda_n - r g                   (augmented normal multiplier)
//   rho   = mu max(a, 0)                     (radius of the friction disk)
//   tau   = lambda_t - r s                   (augmented tangential multiplier)
//   F_n   = lambda_n - max(a, 0)
//   F_t   = lambda_t - P_rho(tau),   P_rho = projection on {|x| <= rho} in R^d.
// F(lambda) = 0 if and only if lambda solves the problem: F_n = 0 is
// Signorini (a > 0: g = 0, lambda_n = a > 0; a <= 0: lambda_n = 0, g >= 0);
// F_t = 0 with |tau| <= rho is stick (lambda_t = tau, so s = 0, |lambda_t|
// <= mu lambda_n), with |tau| > rho slip (lambda_t = rho tau/|tau|, and
// tau = lambda_t - r s gives (|tau| - rho) tau/|tau| = -r s: tau/|tau| =
// -s/|s|, so lambda_t = -mu lambda_n s/|s|); rho = 0 forces lambda_t = 0.
// F is piecewise smooth (piecewise linear for d = 1), hence semismooth; the
// Newton matrix is the derivative of the active piece:
//   closed (a > 0): dF_n = r W_n;            open: dF_n = e_n^T;
//   rho = 0:         dF_t = E_t;
//   stick:           dF_t = r W_t;
//   slip:            dF_t = E_t - tau^ d(rho) - (rho/|tau|)(I - tau^ tau^T)(E_t - r W_t),
//                    d(rho) = mu (e_n^T - r W_n), tau^ = tau/|tau|,
// (W_n, W_t: the rows of W of the contact; e, E: rows of the identity).
//
// Why this algorithm: it treats the three states of every contact in one
// system, so no outer loop over guessed open/stick/slip sets (which can
// cycle with friction), it converges locally quadratically (superlinearly
// at worst) to the exact solution, and for d = 1 a step on the right piece
// lands on it exactly, which is what "solved to round-off" needs. Far from
// the solution the Armijo line search on 1/2 |F|^2 (sigma = 1e-4, halving)
// keeps the iterates from wandering. If an attempt fails (no decrease,
// singular Newton matrix, iteration limit) it restarts from the initial
// guess with r multiplied by 10, then by 0.1, then 100, then 0.01 (the
// convergence basin depends on r), and reports failure if all five fail.
// Dense linear algebra (Eigen's FullPivLU, m = (1 + d) nc <= 66 here).
//
// Stopping test (natural residuals, the certificate's scales of
// frictional_contact_problem.hpp): with eta = 4 (m + 1) eps, delta_i =
// |q~_i| + sum_j |W_ij||lambda_j| and Lambda = max|lambda|, per contact by
// its current piece:
//   closed: |g| <= eta delta_n and lambda_n >= -eta Lambda;
//           stick: |s_k| <= eta delta_k and |lambda_t| <= mu lambda_n + eta Lambda;
//           slip:  ||lambda_t| - mu lambda_n| <= eta Lambda and
//                  |lambda_t |s| + mu lambda_n s| <= eta Lambda delta_t;
//           rho = 0 (mu = 0): |lambda_t| <= eta Lambda;
//   open:   |lambda_n|, |lambda_t| <= eta Lambda and g >= -eta delta_n.
// These are the certificate's residuals (same q and delta, bit for bit), so
// a converged solution has, with the default theta = 64 (m + 1) eps = 16 eta
// (certify() then classes the solver's open contacts open, its slip
// contacts slip, and calls stick only contacts the solver has in stick):
// scaled penetration, negative lambda_n, complementarity <= eta; cone
// violation <= (1 + mu) eta; stick residual <= sqrt(d) eta; slip residual
// <= sqrt(d) max(1, 2 mu + eta) eta (a solver-slip contact: eta; a
// solver-stick contact on the cone's edge: |s| <= sqrt(d) eta delta_t and
// |lambda_t| + mu lambda_n <= (2 mu + eta) Lambda; mu = 0: |lambda_t| <=
// eta Lambda and |s| <= sqrt(d) delta_t). The round-off of q_i alone is up to gamma_{m+1}
// delta_i ~ (m + 1) eps delta_i (Higham eq. 3.5) at worst, sqrt(m + 1) eps
// delta_i typically; eta = 4 (m + 1) eps leaves a factor 4 above the worst.
//
// Failure: singular Newton matrix (FullPivLU not invertible, or reciprocal
// condition estimate below m eps; for a stick or closed contact this is W
// singular on the active rows), no decrease along the Newton direction
// (step below 2^-30), iteration limit. Status and message, never thrown:
// the caller decides (the integrator should stop with IntegrationError).
//
// Uniqueness: for mu = 0 the problem is the optimality system of a convex
// QP, min 1/2 l^T W l + q~^T l over lambda_n >= 0, lambda_t = 0, unique in g
// and, for W positive definite on the normal rows, in lambda. For mu > 0 it
// may have several solutions when tangential-normal coupling is strong:
// for one 2D contact with W = [[a, b], [b, c]], slip in the direction
// sigma = sign(b) gives lambda_n = -g~ / (a - mu |b|), so for mu |b| > a an
// open contact (g~ > 0) also has a slipping solution (verification test
// FrictionalContact.NonUniqueWithStrongCoupling). We assume the regime where
// the solution is unique (mu |W_nt| < W_nn contact by contact, with
// |W_nt| the Euclidean norm of the coupling row, met by the laws of this
// project whose contact rows act on a node's own orthogonal dofs: W_nt is
// then small); outside it the solver returns one certified solution, the
// one its Newton path from the initial guess reaches.

#include <string>

#include <Eigen/Core>

#include "frictional_contact_problem.hpp"

namespace rsi {

enum class FrictionalContactStatus { converged, singular, no_convergence };

struct FrictionalContactSolution {
  FrictionalContactStatus status = FrictionalContactStatus::no_convergence;
  std::string message;    ///< what failed (empty when converged)
  Eigen::VectorXd lambda; ///< (lambda_n, lambda_t) per contact, ordered like W [N]
  Eigen::VectorXd q;      ///< gaps and slips q~ + W lambda at lambda [m]
  int iterations = 0;     ///< Newton steps, over all attempts
  int attempts = 0;       ///< 1 unless a restart was needed
  bool ok() const { return status == FrictionalContactStatus::converged; }
};

struct FrictionalContactSolverOptions {
  int max_iterations = 100; ///< Newton steps per attempt, >= 1
};

class FrictionalContactSolver {
public:
  /// Throws std::invalid_argument for max_iterations < 1.
  explicit FrictionalContactSolver(const FrictionalContactSolverOptions& options = {});

  /// Solves from lambda = 0.
  FrictionalContactSolution solve(const FrictionalContactProblem& problem) const;
  /// Solves from `initial` (size n_unknowns, finite; e.g. the previous
  /// step's multipliers). Throws std::invalid_argument otherwise.
  FrictionalContactSolution solve(const FrictionalContactProblem& problem,
                                  const Eigen::Ref<const Eigen::VectorXd>& initial) const;

private:
  FrictionalContactSolverOptions m_options;
};

} // namespace rsi
