#pragma once
// The undamped reduced bladed disk advanced in its modes (disk_part.hpp;
// the modes: critical_step.hpp reduced_modes, computed once with the
// basis): K^ Psi = M^ Psi Lambda, Psi^T M^ Psi = I, q = Psi eta, and the
// disk's step is mode by mode,
//   eta~_i = 2 eta_i - eta_{i,prev} - dt^2 lambda_i eta_i,
// central differences being invariant under the change of coordinates (the
// same scheme, not an approximation). Only the boundary entries of q are
// formed, q_B = Psi_B eta (2 n_B r flops: the contact reads nothing else);
// the correction is eta += dt^2 Psi^T B_q^T lambda (M^-1 = Psi Psi^T, rows
// of Psi at the tip dofs), and the energy 1/2 |eta_{n+1} - eta_n|^2/dt^2 +
// 1/2 eta_n^T Lambda eta_{n+1} costs O(r): the physical path's 2 r^2 step
// and 4 r^2 energy (every row at one step a row) become 2 n_B r and O(r).
// q() forms Psi eta when asked. A damped disk (C^ is not diagonal in Psi)
// keeps the physical part (physical_disk_part.hpp).

#include "disk_part.hpp"

namespace rsi {

class ModalDiskPart final : public DiskPart {
public:
  /// `modes` (r x r) copied. Throws std::invalid_argument for modes of the
  /// wrong size, ReducedIntegrationError when M^ is not positive definite.
  ModalDiskPart(const ReducedBasis& basis, double dt, const ReducedModes& modes);

  Eigen::VectorXd q() const override { return m_psi * m_eta; }
  void start(const Eigen::Ref<const Eigen::VectorXd>& q0) override;
  void predict() override;
  void clear_correction() override;
  void add_coulomb_correction(const TipContact& tip, double f, double ft) override {
    add(tip.q_u, -f);
    if (ft != 0.0) add(tip.q_v, ft);
  }
  void add_sliding_correction(const TipContact& tip, double f, double mu) override {
    add(tip.q_u, -f);
    if (mu * tip.sign != 0.0) add(tip.q_v, -f * mu * tip.sign);
  }
  void apply_correction() override;
  void advance() override;
  double energy() const override;
  /// q_B = Psi_B eta (2 n_B r) and about 5 r.
  double flops_per_step() const override;

private:
  /// The correction f e_position in q, as eta += f Psi^T e_position and, for
  /// the tips' entries of q, q_B += f Psi_B Psi_B^T e_position (44 entries a
  /// term instead of Psi_B times the whole corrected eta).
  void add(int position, double f) {
    m_deta.noalias() += f * m_psi.row(position).transpose();
    m_dq_boundary.noalias() += f * m_boundary_flexibility.col(m_boundary_index[position]);
  }
  /// q's boundary entries = Psi_B eta.
  void form_boundary(const Eigen::VectorXd& eta, Eigen::VectorXd& q);

  Eigen::MatrixXd m_psi;                  ///< Psi, r x r, M^-orthonormal
  Eigen::VectorXd m_lambda_disk;          ///< Lambda = diag(Psi^T K^ Psi)
  std::vector<int> m_boundary;            ///< positions of the boundary (tip) entries in q
  Eigen::MatrixXd m_psi_boundary;         ///< Psi_B: the rows of Psi at m_boundary
  std::vector<int> m_boundary_index;      ///< q position -> index in m_boundary (-1: not a tip's)
  Eigen::MatrixXd m_boundary_flexibility; ///< Psi_B Psi_B^T
  Eigen::VectorXd m_eta, m_eta_prev, m_eta_next, m_deta, m_q_boundary, m_dq_boundary;
};

} // namespace rsi
