#pragma once
// The reference solver of the per-step frictional contact problem
// (frictional_contact_problem.hpp): Alart-Curnier's augmented Lagrangian
// equations solved by a semismooth (generalized) Newton method with an
// Armijo line search, and a nonsmooth Gauss-Seidel fallback.
//
// Equations (Alart, Curnier, CMAME 92 (1991) 353; Christensen, Klarbring,
// Pang, Stroemberg, IJNME 42 (1998) 145). With q = q~ + W lambda, per
// contact c with augmentations r = r_n = 1 / W_nn > 0 and r_t = 1 /
// max_k W_tk,tk > 0 [N/m] (each row's own scale: one r for both gave line
// search failures when B's normal and tangential rows differ in scale):
//   a     = lambda_n - r g                   (augmented normal multiplier)
//   rho   = mu max(a, 0)                     (radius of the friction disk)
//   tau   = lambda_t - r_t s                 (augmented tangential multiplier)
//   F_n   = lambda_n - max(a, 0)
//   F_t   = lambda_t - P_rho(tau),   P_rho = projection on {|x| <= rho} in R^d.
// F(lambda) = 0 if and only if lambda solves the problem: F_n = 0 is
// Signorini (a > 0: g = 0, lambda_n = a > 0; a <= 0: lambda_n = 0, g >= 0);
// F_t = 0 with |tau| <= rho is stick (lambda_t = tau, so s = 0, |lambda_t|
// <= mu lambda_n), with |tau| > rho slip (lambda_t = rho tau/|tau|, and
// tau = lambda_t - r_t s gives (|tau| - rho) tau/|tau| = -r_t s: tau/|tau|
// = -s/|s|, so lambda_t = -mu lambda_n s/|s|); rho = 0 forces lambda_t = 0.
// F is piecewise smooth (piecewise linear for d = 1), hence semismooth; the
// Newton matrix is the derivative of the active piece:
//   closed (a > 0): dF_n = r W_n;            open: dF_n = e_n^T;
//   rho = 0:         dF_t = E_t;
//   stick:           dF_t = r_t W_t;
//   slip:            dF_t = E_t - tau^ d(rho) - (rho/|tau|)(I - tau^ tau^T)(E_t - r_t W_t),
//                    d(rho) = mu (e_n^T - r W_n), tau^ = tau/|tau|,
// (W_n, W_t: the rows of W of the contact; e, E: rows of the identity).
// The Newton system is equilibrated, S J S^-1 (S dx) = -S F with S =
// diag(W)^1/2: on closed rows it is W's correlation matrix, on open rows the
// identity, whatever the scale of each row of B, so that the condition
// estimate decides singularity on a meaningful matrix; the merit function
// of the line search is 1/2 |S F|^2 for the same reason.
// On a row of the Newton matrix that is a row of the identity (an open
// contact's normal row, a tangential row with rho = 0) the step is set to
// -F_i exactly after the equilibrated solve: otherwise a multiplier whose
// solution is 0 shrinks by a factor eps a step into the denormals and never
// passes the relative stopping test (found at an opening contact of the
// default case, test FrictionalContact.OpeningFromAWarmStartReachesZeroExactly).
//
// Why this algorithm: it treats the three states of every contact in one
// system, so no outer loop over guessed open/stick/slip sets (which can
// cycle with friction), it converges locally quadratically (superlinearly
// at worst) to the exact solution, and for d = 1 a step on the right piece
// lands on it exactly, which is what "solved to round-off" needs. Far from
// the solution the Armijo line search (sigma = 1e-4, halving down to
// 2^-30) keeps the iterates from wandering. Globalisation, in order:
//   1. Newton from the initial guess with r, r_t as above, then with both
//      multiplied by 10, then by 0.1 (the basin depends on r);
//   2. if all three stop without decrease or at the iteration limit (not
//      if one found a singular Newton matrix: that is reported) and nc > 1:
//      nonsmooth block Gauss-Seidel (Jean, Moreau: contact by contact, the
//      one-contact problem with the others frozen, solved by step 1) until
//      no multiplier moves by 1e-10 Lambda or max_sweeps, then step 1 again
//      from its result to reach round-off;
//   3. otherwise failure, with every attempt's message.
// Measured (verification FrictionalContact.ScaledCoupledProblems: rows of
// B over 6 decades, all contacts coupled, 1-22 contacts, mu up to 1): every
// problem with kappa = max_c mu |W_nt,c| / W_nn,c < 1 (251 of 800) solved
// and certified; of the 549 with kappa >= 1 (up to 6e4), 15 reported
// unsolved. Dense linear algebra: Eigen's PartialPivLU and its rcond() (m = (1 + d) nc
// <= 66; measured 127 us for 22 random coupled 2D contacts from lambda = 0,
// 155 us for 16 in 3D, 6-8 us from a warm start at the solution).
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
// Failure: singular Newton matrix (the reciprocal condition estimate of the
// equilibrated matrix below m eps, or NaN for a zero pivot; for a
// stick or closed contact this is W singular on the active rows: the
// multipliers are then not unique), no decrease along the Newton direction
// (step below 2^-30), iteration limit, Gauss-Seidel not settling. Status and
// message, never thrown: the caller decides (the integrator should stop
// with IntegrationError and the message).
//
// Uniqueness: for mu = 0 the problem is the optimality system of a convex
// QP, min 1/2 l^T W l + q~^T l over lambda_n >= 0, lambda_t = 0, unique in g
// and, for W positive definite on the normal rows, in lambda. For mu > 0 it
// may have several solutions when tangential-normal coupling is strong:
// for one 2D contact with W = [[a, b], [b, c]], slip in the direction
// sigma = sign(b) gives lambda_n = -g~ / (a - mu |b|), so for mu |b| > a an
// open contact (g~ > 0) also has a slipping solution (verification test
// FrictionalContact.NonUniqueWithStrongCoupling). We assume
// kappa = max_c mu |W_nt,c| / W_nn,c < 1 (|W_nt,c|: Euclidean norm of the
// contact's normal-tangential coupling in W). For one 2D contact this
// excludes the second solution above (and the test
// SingleContact2DCoupledEnumeration finds exactly one solution on a grid
// of (g~, s~)); for several contacts it is the regime in which the solver
// is verified, not a proven uniqueness condition. The laws of this project
// meet it easily: a contact's rows act on its node's own orthonormal
// directions, so W_nt,c = dt^2 e_n^T M^-1 e_t couples only through the
// mass (zero for a lumped or isotropic node block) and mu = 0.15. Outside
// the regime the solver returns one certified solution, the one its path
// from the initial guess reaches, or reports failure.

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
  int attempts = 0;       ///< Newton attempts (1 unless a restart was needed)
  int sweeps = 0;         ///< Gauss-Seidel sweeps of the fallback (0: not used)
  bool ok() const { return status == FrictionalContactStatus::converged; }
};

struct FrictionalContactSolverOptions {
  int max_iterations = 100; ///< Newton steps per attempt, >= 1
  int max_sweeps = 500;     ///< Gauss-Seidel sweeps of the fallback, >= 1
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
