#pragma once
// The Coulomb law's contact solve (tip_contact_solve.hpp), stick and slip:
// per tip k two rows, in the order (n, t) of coulomb_gauss_seidel.hpp,
//   B_n,k = G_k:  -e(u_k) on q,  +N on the casing (u, u_s) at alpha~_k,
//   B_t,k = T_k:  +e(v_k) on q,  -N on the casing (v, v_s) at alpha~_k,
// the predicted gap g~_k and forward slip increment s~_k over the step
// (reduced_contact.hpp: Omega (R_t + u~_k) dt + (v~_k - v_k,n) - N . (c~_v - c_v,n)),
//   [g; s] = [g~; s~] + W lambda,  W = dt^2 (B_q A_q^-1 B_q^T + B_c A_c^-1 B_c^T),
// solved by CoulombGaussSeidel (warm-started with the previous step's
// multipliers) on the tips whose predicted gap is negative; a tip left out
// whose gap the correction would close (g~_k + W_k: lambda < 0) joins and the
// problem is solved again. (q, c)_{n+1} = (q~, c~) + dt^2 (A_q^-1 B_q^T,
// A_c^-1 B_c^T) lambda. lambda_n pushes the tip inward and the casing
// outward; lambda_t is the tangential force on the tip along +v
// (counter-clockwise), the casing takes -lambda_t at the contact point; a
// slipping tip has lambda_t = -mu lambda_n sign(s). Contact work of the step
// sum over rows lambda_r B_r (x_{n+1} - x_{n-1}) / 2. A solver failure
// (no convergence, singular block, no local solution) or a non-finite
// prediction throws ReducedIntegrationError naming the step. The step
// report carries the certificate (reduced_coulomb_certificate) of the
// step's problem: max_cone_violation [N]; max_stick_slip_residual, scaled
// (dimensionless): stick |s_c| / sigma_c, slip max(-s_c e_c, 0) / sigma_c
// (e_c = -sign(lambda_t,c), the slip direction the force claims) and
// | |lambda_t,c| - mu lambda_n,c | / (mu lambda_n,c), with sigma_c =
// |s~_c| + ||W_tc,:||_1 max_j |lambda_j| the size of the terms summed into
// s_c (a well-conditioned slip test: s_c = 0 up to round-off is not counted
// as slip against lambda_t), and open max |lambda_c| / max_j |lambda_j|.
// CoulombGaussSeidel stops at a sweep whose largest change Delta <= 1e-14
// max |lambda|; the contacts visited after c then moved s_c by at most
// ||W_tc,:||_1 Delta, and forming y costs about m eps of its terms (m = 2
// times the tips solved, <= 44): every scaled residual is <= 1e-14 + m eps
// <= 2e-14 at a converged step. stick_slip_transitions (tips whose state open /
// stick / slip changed since the previous step); n_stick, n_slip. With
// mu = 0 a closed tip is classified slip (lambda_t = 0).

#include <vector>

#include <Eigen/Core>

#include "coulomb_gauss_seidel.hpp"
#include "tip_contact_solve.hpp"

namespace rsi {

class CoulombTipSolve final : public TipContactSolve {
public:
  /// The parts must outlive the solve (not owned).
  CoulombTipSolve(const DiskPart& disk, const CasingPart& casing, double dt, double mu);

  void start(int n_tips) override;
  void solve(const std::vector<TipContact>& tips, int step, StepReport& report) override;
  void gather_correction(const std::vector<TipContact>& tips, DiskPart& disk,
                         CasingPart& casing) const override;
  void add_contact_work(const std::vector<TipContact>& tips, bool corrected,
                        double& work) override;

private:
  /// [W_nn W_nt; W_tn W_tt] of tips i, j (rows of i, columns of j).
  Eigen::Matrix2d block(const TipContact& i, const TipContact& j) const;

  CoulombGaussSeidel m_coulomb;
  std::vector<ReducedContactState> m_state_before;
  Eigen::VectorXd m_warm; ///< (lambda_n, lambda_t) per tip, the next solve's start
  Eigen::VectorXd m_rows_lambda, m_rows_y;
};

} // namespace rsi
