#pragma once
// The sliding_sign law's contact solve (tip_contact_solve.hpp): the first
// version's friction, always sliding, operation for operation (SPEC §3).
// Per tip k the gap row G_k (-e(u_k) on q, +N on the casing's u, u_s at the
// tip's angle) says which gaps close, and the force direction
// D_k = G_k + mu s_k T_k (T_k: -e(v_k) on q, +N on the casing's v, v_s;
// s_k the sign of the predicted sliding velocity) along which the force acts:
//   W_ij = dt^2 (G_i^q A^-1 D_j^qT + G_i^c A_c^-1 D_j^cT), W lambda = -g~ on the
//   active set {g~_k < 0}; every negative lambda dropped at once, constraints
//   closed by the correction added, until both hold (forward-increment
//   Lagrange multipliers, Carpenter-Taylor-Katona 1991);
//   (q, c)_{n+1} = (q~, c~) + dt^2 (A^-1 D^qT, A_c^-1 D^cT) lambda.
// W is not symmetric; it is solved by LU with partial pivoting and its
// residual checked. The tangential force the law applies, -mu s_k lambda_k,
// is the tangential multiplier reported. A closed tip whose sliding sign
// differs between the prediction and the corrected state counts as a
// sliding reversal, with the friction residual mu lambda |s - s~|.

#include <Eigen/LU>

#include "tip_contact_solve.hpp"

namespace rsi {

class SlidingSignSolve final : public TipContactSolve {
public:
  SlidingSignSolve(const DiskPart& disk, const CasingPart& casing, double dt, double mu)
      : TipContactSolve(disk, casing, dt, mu) {}

  void start(int n_tips) override;
  void solve(const std::vector<TipContact>& tips, int step, StepReport& report) override;
  void gather_correction(const std::vector<TipContact>& tips, DiskPart& disk,
                         CasingPart& casing) const override;
  void add_contact_work(const std::vector<TipContact>& tips, bool corrected,
                        double& work) override;
  void report_tip(const TipContact& now, const TipContact& predicted, double lambda,
                  StepReport& report) const override;

private:
  /// W_ij (above).
  double flexibility(const TipContact& i, const TipContact& j) const;
  /// D_j . (a - b) over (q, c): the force direction of tip j applied to the
  /// displacement from (q_b, c_b) to (q_a, c_a), read at its entries only.
  double direction_dot(const TipContact& j, const Eigen::VectorXd& q_a, const Eigen::VectorXd& q_b,
                       const Eigen::VectorXd& c_a, const Eigen::VectorXd& c_b) const;

  bool m_lambda_t_zero = true;
  // Work storage, kept between steps.
  std::vector<char> m_known;
  Eigen::MatrixXd m_w_all, m_wa;
  Eigen::VectorXd m_minus_gap, m_la, m_residual;
  Eigen::PartialPivLU<Eigen::MatrixXd> m_lu;
};

} // namespace rsi
