#pragma once
// Nonsmooth block Gauss-Seidel over contacts for one step of contact with
// Coulomb friction (stick and slip), the reduced side's solver of issue 12
// (Jean & Moreau 1987, "Unilaterality and dry friction in the dynamics of
// rigid body collections"; Jean 1999, the NSCD method), written apart from
// the reference side's solver of the same problem.
//
// Problem (the shared per-step definition; Carpenter, Taylor, Katona 1991,
// SPEC §3): after the contact-free prediction, nc contacts with d tangential
// directions (d = 1: 2D tip/ring law, d = 2: 3D node-to-rigid-surface law),
//     [g; s] = [g~; s~] + W lambda,   W = dt^2 B M^-1 B^T,
// W (1+d) nc square, ordered per contact (n, t1[, t2]), symmetric positive
// semi-definite; find lambda with, per contact c, Signorini (g_c >= 0,
// lambda_n,c >= 0, g_c lambda_n,c = 0) and Coulomb (|lambda_t,c| <=
// mu lambda_n,c; stick s_c = 0 inside the cone; slip lambda_t,c =
// -mu lambda_n,c s_c/|s_c|; open contacts carry lambda_c = 0). Units: g, s
// [m], W [m/N], lambda [N]. The correction of the step is then
// u_{n+1} = u~ + dt^2 M^-1 B^T lambda (the caller's business).
//
// Algorithm. A sweep visits c = 0 .. nc-1 in order; for contact c, the
// others held, r_c = y_c - W_cc lambda_c (y = [g~; s~] + W lambda kept up to
// date) and lambda_c is replaced by the EXACT solution of its local
// (1+d)-square problem y_c = r_c + W_cc lambda_c (local_coulomb_solution.hpp:
// open; stick by an LU solve with W_cc; slip in closed form for d = 1 and
// from a quartic for d = 2), after which y is updated by the block column
// W_:c times the change. y is recomputed from scratch at the start of each
// sweep, so round-off does not accumulate over sweeps.
//
// Stopping (derived). Let Delta be the largest change of any multiplier in a
// sweep and L the largest multiplier. When the sweep ends, contact c's
// local law holds exactly for the y it saw; the contacts visited after it
// moved its y_c by at most ||W_c:||_1 Delta. So the certificate's gap and
// slip residuals are at most ||W||_inf Delta plus the round-off of forming
// y (about m eps (|g~| + ||W||_inf L), m = (1+d) nc). The solver stops at
// the first sweep with Delta <= relative_change * L (or Delta = 0), which
// puts the residuals at round-off for relative_change of order m eps: the
// default 1e-14 (45 eps) suits the laws' sizes (m = 44 for the 22 tips of
// the 2D case, 48 for the 16 nodes of Rotor 37). Measured on dense random W
// (test_coulomb_gauss_seidel): every case stops, the certificate at 6 % of
// its round-off bound at worst. A strongly coupled W converges slowly but
// steadily: on the mass-carrying Rotor 37 models (CB-10, CB-20, CCM-10 with
// the lumped mass, W = dt^2 B M^-1 B^T of 16 tip nodes that move almost as
// one body) the change fell by 0.975 a sweep, from 2e-4 L at sweep 50 to
// 1.04e-14 L at sweep 1000 of one step: about 1,000 sweeps from the previous
// step's lambda. max_sweeps is 20,000 for such W.
//
// Convergence (what we assume). mu = 0: a sweep is an exact block
// coordinate minimisation of the convex 1/2 l^T W l + [g~; s~]^T l over
// {lambda_n >= 0, lambda_t = 0}; for W's normal rows positive definite this
// converges linearly to the unique solution (Cryer 1971 for projected SOR;
// Luo & Tseng 1992 for coordinate descent), at a rate set by the coupling
// of the normal rows (one sweep when W is diagonal). mu > 0: for FIXED
// thresholds mu lambda_n the tangential sweep is again a coordinate
// minimisation (Tresca friction, convex); Coulomb ties the threshold to
// lambda_n, and the sweep is a perturbation of the convex one, of size mu
// times the normal/tangential coupling of W (the blocks W_nt within and
// between contacts, relative to the diagonal blocks). There is no general
// convergence theorem for mu > 0 (nor uniqueness for large mu; see Acary &
// Brogliato, Numerical Methods for Nonsmooth Dynamical Systems, 2008, on
// this NSGS): we assume W positive definite on the closing contacts and mu
// moderate, and the solver REPORTS a failure (status max_sweeps) instead of
// returning an unconverged lambda. Measured on dense random W (coupling
// between contacts as strong as within): mu = 0.5 converges in at most 111
// sweeps (nc = 8, d = 2), 55 (22 contacts, d = 1), 29 (16 contacts, d = 2);
// 200 random cases each at mu = 1 and at nearly singular W (cond 3e4) also
// converged (at most 285 sweeps).
// On the default 2D case's own W (CB-10 bladed disk, full casing; normal
// coupling between tips at most 0.095 of the diagonal) with all 22 tips
// closing: 10-12 sweeps sliding, 17 sticking, mu 0.15 and 0.5.
//
// Failures, reported as a status, never thrown: max_sweeps exceeded;
// singular_block when a contact closes (r_n < 0) but its block is singular
// (mu = 0: w_nn <= singular_tolerance max_i W_ii; mu > 0: the singular
// values of W_cc have sigma_min <= singular_tolerance sigma_max), a contact
// that cannot be closed or whose stick multiplier is not determined;
// no_local_solution when the best local candidate's relative violation
// (local_coulomb_solution.hpp: round-off at a genuine solution, of order 1
// otherwise) exceeds local_violation (a detector of gross trouble, e.g. no
// local solution for a very large mu or an indefinite block; not a
// certificate tolerance).
//
// Cost. Per sweep: refreshing y, 2 m (1+d) flops per contact carrying a
// force (2 m^2 at most); per contact 2 (1+d)^2 flops for r_c, the local
// solve (measured: d = 1 0.05 us; d = 2 0.16 us on the warm path, 2.2 us
// through the quartic) and 2 m (1+d) flops to update y when lambda_c
// changed; open contacts that stay open change nothing. Setup: one
// (1+d)-square SVD (regularity) and LU per contact, when it first closes.
// Measured whole solves on dense random W, all contacts coupled: 16
// contacts d = 2, 22 sweeps, 78 us cold; 22 contacts d = 1, 63 sweeps,
// 107 us. A warm start (the previous step's lambda) saves sweeps.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "local_coulomb_solution.hpp"
#include "reduced_coulomb_certificate.hpp"

namespace rsi {

struct CoulombGaussSeidelOptions {
  int max_sweeps = 20000; ///< >= 1 (a strongly coupled W needs about 1,000: Stopping)
  /// Stop when the largest change of a sweep is <= relative_change times the
  /// largest multiplier; in [0, 1) (0: only an unchanged sweep stops).
  double relative_change = 1e-14;
  /// Relative size below which a closing contact's block is singular; in (0, 1).
  double singular_tolerance = 1e-12;
  /// Relative local-solution violation reported as failure; in (0, 1).
  double local_violation = 1e-8;
};

enum class CoulombSweepStatus { converged, max_sweeps, singular_block, no_local_solution };

struct CoulombGaussSeidelReport {
  CoulombSweepStatus status = CoulombSweepStatus::converged;
  int sweeps = 0;           ///< sweeps done
  double last_change = 0.0; ///< Delta of the last sweep [N]
  double size = 0.0;        ///< largest |multiplier| at the end [N]
  int failed_contact = -1;  ///< the contact of a singular_block / no_local_solution failure
  std::string message;      ///< empty when converged
  bool converged() const { return status == CoulombSweepStatus::converged; }
};

class CoulombGaussSeidel {
public:
  /// d: tangential directions per contact, 1 or 2; mu: friction
  /// coefficient, finite and >= 0. Throws std::invalid_argument naming the
  /// parameter and its allowed range.
  CoulombGaussSeidel(int d, double mu, const CoulombGaussSeidelOptions& options = {});

  int tangential_dimension() const { return m_d; }
  double friction_coefficient() const { return m_mu; }

  /// Solves the step's problem. `w`: W, (1+d) nc square, finite;
  /// `predicted`: [g~; s~] in the same order, finite. `lambda`: on entry the
  /// starting iterate if it has W's size (a warm start; anything else starts
  /// from 0), on return the last iterate (the solution when converged).
  /// Throws std::invalid_argument on wrong sizes or non-finite entries;
  /// numerical failure is the returned status. Storage is reused between
  /// calls of the same size.
  CoulombGaussSeidelReport solve(const Eigen::Ref<const Eigen::MatrixXd>& w,
                                 const Eigen::Ref<const Eigen::VectorXd>& predicted,
                                 Eigen::VectorXd& lambda);

  /// Per contact: the state of the last solve (open / stick / slip).
  const std::vector<ReducedContactState>& states() const { return m_state; }

private:
  /// Block, regularity and LU of contact c; `diagonal` = max_i |W_ii|.
  void prepare(const Eigen::Ref<const Eigen::MatrixXd>& w, int c, double diagonal);

  int m_d;
  double m_mu;
  CoulombGaussSeidelOptions m_options;
  std::vector<ReducedContactState> m_state;
  std::vector<Eigen::Matrix3d> m_block;                      ///< W_cc, leading (1+d) square
  std::vector<Eigen::PartialPivLU<CoulombBlockMatrix>> m_lu; ///< LU of W_cc where regular (mu > 0)
  std::vector<char> m_prepared;     ///< contact c's block, regularity, LU are set
  std::vector<char> m_cached;       ///< m_block[c], its regularity and LU kept from an earlier solve (mu > 0)
  std::vector<double> m_regularity; ///< sigma_min/sigma_max (mu > 0) or w_nn/max W_ii (mu = 0)
  Eigen::VectorXd m_y;              ///< [g; s] of the current iterate
};

} // namespace rsi
