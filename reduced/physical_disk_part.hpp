#pragma once
// The reduced bladed disk advanced in its coordinates q (disk_part.hpp),
// damped or not:
//   q~ = 2 q_n - q_{n-1} - dt^2 A^-1 K^ q_n - dt A^-1 C^ (q_n - q_{n-1}),
// A = M^ + dt/2 C^, with A^-1 K^ and dt A^-1 C^ dense, formed once. C^ is
// diagonal (modal_damping.hpp: 2 zeta omega_i on the kept modes, 0 on the
// boundary) or full (the projected Rayleigh alpha M^ + beta K^), both with
// the centred velocity (q_{n+1} - q_{n-1}) / (2 dt); the step's damping
// term (q_{n+1} - q_{n-1})^T C^ (q_{n+1} - q_{n-1}) (reduced_integrator.hpp:
// W_damp). Energy E_{n-1/2} = 1/2 v^T M^ v + 1/2 q_{n-1}^T K^ q_n,
// v = (q_n - q_{n-1}) / dt (4 r^2 flops, computed when asked).

#include "disk_part.hpp"

namespace rsi {

class PhysicalDiskPart final : public DiskPart {
public:
  /// `diagonal` (r entries) or `full` (r x r) is C^ when `damped`, checked
  /// by the caller (at most one given, finite, >= 0); both empty undamped.
  /// Throws ReducedIntegrationError when A is not positive definite.
  PhysicalDiskPart(const ReducedBasis& basis, double dt, bool damped,
                   const Eigen::VectorXd& diagonal, const Eigen::MatrixXd& full);

  void predict() override;
  void add_coulomb_correction(const TipContact& tip, double f, double ft) override;
  void add_sliding_correction(const TipContact& tip, double f, double mu) override {
    m_dq -= f * (m_flexibility.col(tip.q_u) + mu * tip.sign * m_flexibility.col(tip.q_v));
  }
  void apply_correction() override { m_q_next += m_dq; }
  double step_damping_product() override;
  double energy() const override;
  /// The dense A^-1 K^ q (2 r^2) and 4 r of vector updates; damped, also
  /// dt A^-1 C^ (q_n - q_{n-1}) (2 r^2) and about 5 r for the difference and
  /// W_damp, and a full C^ its product for W_damp (2 r^2).
  double flops_per_step() const override;

private:
  Eigen::MatrixXd m_aq;        ///< A^-1 K^
  Eigen::VectorXd m_cq;        ///< diag(C^) (empty undamped or with a full C^)
  Eigen::MatrixXd m_cq_matrix; ///< a full C^ (empty unless given)
  Eigen::VectorXd m_cq_dq;     ///< C^ (q_{n+1} - q_{n-1}), for W_damp with a full C^
  Eigen::MatrixXd m_bq;        ///< dt A^-1 C^ (damped only)
};

} // namespace rsi
