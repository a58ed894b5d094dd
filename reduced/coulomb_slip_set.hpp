#pragma once
// A direct solve of one contact step with Coulomb friction when every
// closed contact slips (issue 26: the rubbing blade's step), tried before
// the nonsmooth Gauss-Seidel of coulomb_gauss_seidel.hpp and written apart
// from it. Same problem, d = 2 (n, t1, t2 per contact):
//     [g; s] = [g~; s~] + W lambda,  W symmetric, 3 nc square,
// Signorini and Coulomb per contact (coulomb_gauss_seidel.hpp).
//
// Derivation. Let S be the contacts that slip, each in the unit direction
// e_c (s_c = sigma_c e_c, sigma_c > 0), and every other contact open.
// Coulomb's slip law fixes lambda_t,c = -mu lambda_n,c e_c, so lambda is
// linear in the normal multipliers of S, and the closed gaps g_c = 0, c in S,
// are |S| linear equations:
//     sum_{j in S} (W_{n_c n_j} - mu W_{n_c t_j} e_j) lambda_n,j = -g~_c.  (1)
// Given S and the directions, (1) is a |S| square system (LU with partial
// pivoting). The directions are then the fixed point e_c = s_c / |s_c| of
// the slips that (1)'s lambda produces. Its contraction: a change de of the
// directions moves s by about mu |W_tt| |lambda_n| de, so the map contracts
// by rho ~ mu |W_tt| lambda_n / |s| (summed over the coupled contacts): a
// small rho where the casing slides past the tip at r Omega dt = 4.2 mm a
// step (Rotor 37) against the friction forces' slips.
// Iteration (at most 40 solves of (1)):
//   - S starts as the contacts that carried a force at the warm start (the
//     previous step's multipliers, lambda_n > 0) and the closing ones
//     (g~_c < 0); e_c as the slips s_c/|s_c| at the warm start's multipliers
//     (one iteration of the fixed point ahead of their own directions);
//   - (1) is factored once a set (LU, partial pivoting); while only the
//     directions move, lambda_n,S is refined on those factors,
//     lambda_n += LU^-1 (-g~_S - A(e) lambda_n): A(e) moves by mu |W_nt| |de|,
//     so the refinement contracts at that rate to (1)'s solution;
//   - a negative lambda_n leaves S (the most negative first);
//   - an open contact that (1)'s forces close (g_c < 0) joins S (the most
//     penetrated first, e = s_c/|s_c|);
//   - else each e_c is replaced by s_c/|s_c|, and the solve ends when no
//     direction moved by more than 8 eps (max norm) and (1)'s residual is
//     within the bound below.
// Measured on Rotor 37, MacNeal-50 (16 tip nodes, 5 sliding a step on
// average): rho about 1/50 (the directions' move falls from 4e-4 to 8 eps
// in 6 to 8 iterations): 8.05 solves of (1) a step with a closing contact,
// one factorization a set and refinements otherwise.
// It declines (returns false, lambda untouched) when a slip turns against
// its direction (s_c . e_c <= 0) or vanishes (stick or reversal: the
// Gauss-Seidel decides those), when the directions stop contracting (no
// decrease over 3 iterations once a set is fixed), when (1) is singular
// (LU's reciprocal condition estimate <= 1e-12), when W or [g~; s~] is not
// finite, or after 40 solves. An accepted lambda is a solution of the law: open
// contacts have lambda = 0 and g >= 0 as computed; slipping ones lambda_n
// >= 0, |lambda_t| = mu lambda_n, g_c = (1)'s residual (at most (6 k + 10)
// eps of the size of its row's terms, k = |S|: the solve or refinement on
// backward-stable factors, forming (1) and g) and lambda_t,c + mu lambda_n,c s_c/|s_c| =
// mu lambda_n,c (e_c - e'_c), at most 8 eps mu lambda_n,c per entry. For mu
// below the bound of uniqueness it is the solution the Gauss-Seidel
// converges to (test_coulomb_slip_set).
//
// Cost per solve of (1): the k^3/3 flops of an LU once a set, else 2 k^2
// for the refinement's residual and 2 k^2 for its triangular solves; 2 * 3k
// flops for each of the (nc - k) + 2k rows of [g; s] the iteration reads.
// Against the Gauss-Seidel's 8 sweeps a step (Rotor 37 as above) of local
// solves through Newton's method on the slip angle: bench/RESULTS.md,
// session 37.

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "reduced_coulomb_certificate.hpp"

namespace rsi {

class CoulombSlipSet {
public:
  /// mu: friction coefficient, finite and > 0 (std::invalid_argument).
  explicit CoulombSlipSet(double mu);

  /// Tries the step's problem (`w`: W, 3 nc square, symmetric to the bit:
  /// its columns are read as its rows;
  /// `predicted`: [g~; s~]). `lambda`: the warm start on entry (W's size,
  /// or anything else for none); on success the solution, with every
  /// contact open or slipping (states()); on decline unchanged.
  bool solve(const Eigen::Ref<const Eigen::MatrixXd>& w,
             const Eigen::Ref<const Eigen::VectorXd>& predicted, Eigen::VectorXd& lambda);

  /// Per contact, the state of the last accepted solve.
  const std::vector<ReducedContactState>& states() const { return m_state; }
  /// Solves of (1) in the last call.
  int iterations() const { return m_iterations; }

private:
  double m_mu;
  int m_iterations = 0;
  std::vector<ReducedContactState> m_state;
  std::vector<int> m_set;      ///< S, contact indices
  std::vector<int> m_carried;  ///< the warm start's contacts with lambda_n > 0
  std::vector<char> m_in;      ///< contact c is in S
  Eigen::Matrix2Xd m_e;        ///< e_c per contact (columns)
  Eigen::MatrixXd m_a;         ///< (1) on S
  Eigen::VectorXd m_rhs, m_ln; ///< -g~_S and lambda_n,S
  Eigen::VectorXd m_lambda;    ///< the candidate lambda
  Eigen::PartialPivLU<Eigen::MatrixXd> m_lu;
};

} // namespace rsi
