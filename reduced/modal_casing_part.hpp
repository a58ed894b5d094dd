#pragma once
// The casing in modal coordinates as the reduced integrator's casing part
// (casing_part.hpp; the basis: casing_basis.hpp): c = Phi p, Phi^T M_c Phi =
// I, Phi^T K_c Phi = Omega^2 = diag, and the casing's part of the step is,
// mode by mode (C_c = alpha M_c + beta K_c is diagonal there, gamma_i =
// alpha + beta omega_i^2, a_i = 1 + dt/2 gamma_i),
//   p~_i = 2 p_i - p_{i,prev} + dt^2 (f_i - omega_i^2 p_i - gamma_i (p_i - p_{i,prev}) / dt) / a_i,
// f = Phi^T F, then c~ = Phi p~ (every casing dof is read by the 22 tips'
// contact evaluation: the reconstruction is the cost, 2 n_c N_c flops). The
// contact rows stay the physical ones at the casing dofs; A_c^-1 becomes
// Phi diag(1/a) Phi^T (the flexibility the modal casing has), and the
// correction is applied to p: p += dt^2 diag(1/a) Phi^T B_c^T lambda, then
// c = Phi p again. Energy, works and W_damp keep their physical formulas:
// with c = Phi p they are the modal ones to round-off. The critical step is
// 2 / max(omega_max(K^, M^), max omega_i).

#include <utility>
#include <vector>

#include "casing_basis.hpp"
#include "casing_part.hpp"

namespace rsi {

class ModalCasingPart final : public CasingPart {
public:
  /// `basis` is copied. Throws std::invalid_argument for a basis whose rows
  /// are not the casing's dofs, ReducedIntegrationError when some a_i is not
  /// positive.
  ModalCasingPart(const Casing& casing, const CasingBasis& basis, double dt,
                  const RayleighDamping& damping);

  void start() override;
  void predict() override;
  void clear_correction() override;
  void add_correction(const TipContact& tip, double f_u, double f_v) override;
  void add_sliding_correction(const TipContact& tip, double f, double mu) override {
    add_correction(tip, f, f * mu * tip.sign);
  }
  void apply_correction() override;
  void advance() override;
  /// E_{n-1/2} in O(N_c): the same as the physical one (Phi^T M_c Phi = I,
  /// Phi^T K_c Phi = diag(omega^2)), and the one of the equations advanced.
  double energy() const override;
  /// The reconstruction c = Phi p (2 n_c m) and about 10 m (damped: the same
  /// W_damp products as the full casing).
  double flops_per_step() const override;

private:
  void force_changed() override { m_force_modal.noalias() = m_phi.transpose() * m_force; }

  Eigen::MatrixXd m_phi;             ///< Phi, n_c x m
  Eigen::MatrixXd m_phi_scaled_t;    ///< diag(1/a) Phi^T, m x n_c: the correction's columns
  Eigen::VectorXd m_omega_squared;   ///< omega_i^2
  Eigen::VectorXd m_modal_gamma;     ///< gamma_i = alpha + beta omega_i^2
  Eigen::VectorXd m_modal_a_inverse; ///< 1 / a_i
  Eigen::VectorXd m_force_modal;     ///< Phi^T F
  Eigen::VectorXd m_p, m_p_prev, m_p_next, m_dp;
  std::vector<std::pair<int, double>> m_terms; ///< (casing dof, f) of the step's correction
};

} // namespace rsi
