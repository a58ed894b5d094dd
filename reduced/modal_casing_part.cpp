#include "modal_casing_part.hpp"

#include <stdexcept>
#include <string>

#include "reduced_integrator.hpp"

namespace rsi {

ModalCasingPart::ModalCasingPart(const Casing& casing, const CasingBasis& basis, double dt,
                                 const RayleighDamping& damping)
    : CasingPart(casing, dt, damping) {
  const int nc = casing.n_dofs();
  if (basis.shapes.rows() != nc || basis.size() < 1 ||
      basis.omega_squared.size() != basis.size())
    throw std::invalid_argument("ReducedIntegrator: the casing basis must have " +
                                std::to_string(nc) + " rows (the casing's dofs), got " +
                                std::to_string(basis.shapes.rows()));
  m_phi = basis.shapes;
  m_omega_squared = basis.omega_squared;
  m_modal_gamma = m_damping.alpha + m_damping.beta * m_omega_squared.array();
  const Eigen::ArrayXd a = 1.0 + 0.5 * dt * m_modal_gamma.array();
  if (!(a.minCoeff() > 0.0) || !a.allFinite())
    throw ReducedIntegrationError(
        "reduced integrator: the modal casing's 1 + dt/2 gamma_i is not positive (gamma_i = "
        "alpha + beta omega_i^2 of damping.rayleigh); damping.rayleigh.alpha and beta must be "
        ">= 0 and finite");
  m_modal_a_inverse = a.inverse().matrix();
  m_phi_scaled_t = m_modal_a_inverse.asDiagonal() * m_phi.transpose();
  m_flexibility = m_phi * m_phi_scaled_t;
  const int m = basis.size();
  m_force_modal = m_p = m_p_prev = m_p_next = m_dp = Eigen::VectorXd::Zero(m);
}

double ModalCasingPart::flops_per_step() const {
  const auto n = static_cast<double>(m_kc.rows());
  const auto m = static_cast<double>(m_phi.cols());
  double flops = 2.0 * n * m + 10.0 * m;
  if (m_damped) flops += 2.0 * static_cast<double>(m_mc.nonZeros() + m_kc.nonZeros()) + 5.0 * n;
  return flops;
}

double ModalCasingPart::energy() const {
  return 0.5 * ((m_p - m_p_prev) / m_dt).squaredNorm() +
         0.5 * m_p_prev.dot(m_omega_squared.cwiseProduct(m_p));
}

void ModalCasingPart::start() {
  m_c = Eigen::VectorXd::Zero(m_kc.rows());
  // At rest p_{-1} = dt^2/2 Phi^T F (the modal mass is I), c = Phi p.
  m_p.setZero();
  m_p_prev = 0.5 * m_dt * m_dt * m_force_modal;
  m_c_prev.noalias() = m_phi * m_p_prev;
}

void ModalCasingPart::predict() {
  const double dt2 = m_dt * m_dt;
  const Eigen::Index m = m_p.size();
  for (Eigen::Index i = 0; i < m; ++i) {
    double acc = -m_omega_squared(i) * m_p(i);
    if (!m_force_zero) acc += m_force_modal(i);
    if (m_damped) acc -= m_modal_gamma(i) * (m_p(i) - m_p_prev(i)) / m_dt;
    m_p_next(i) = 2.0 * m_p(i) - m_p_prev(i) + dt2 * m_modal_a_inverse(i) * acc;
  }
  m_c_next.noalias() = m_phi * m_p_next;
}

void ModalCasingPart::clear_correction() {
  m_dp.setZero();
  m_terms.clear();
}

void ModalCasingPart::add_correction(const TipContact& tip, double f_u, double f_v) {
  // c_u and c_v interleaved per node, as summed before the modal casing
  // existed (the full-casing histories stay bit for bit).
  for (int b = 0; b < 4; ++b) {
    if (tip.c_u[b] < 0) continue;
    m_dp += (f_u * tip.shape[b]) * m_phi_scaled_t.col(tip.c_u[b]);
    m_terms.emplace_back(tip.c_u[b], f_u * tip.shape[b]);
    if (f_v == 0.0) continue;
    m_dp += (f_v * tip.shape[b]) * m_phi_scaled_t.col(tip.c_v[b]);
    m_terms.emplace_back(tip.c_v[b], f_v * tip.shape[b]);
  }
}

void ModalCasingPart::apply_correction() {
  // c = Phi (p~ + dp) = c~ + sum of f Phi diag(1/a) Phi^T e_dof: with fewer
  // terms than modes the columns of A_c^-1 (n_c each) cost less than Phi p
  // again (n_c N_c); the same c up to round-off.
  m_p_next += m_dp;
  if (static_cast<Eigen::Index>(m_terms.size()) < m_p_next.size()) {
    for (const auto& [dof, f] : m_terms)
      m_c_next.noalias() += f * m_flexibility.col(dof);
  } else {
    m_c_next.noalias() = m_phi * m_p_next;
  }
}

void ModalCasingPart::advance() {
  CasingPart::advance();
  m_p_prev.swap(m_p);
  m_p.swap(m_p_next);
}

} // namespace rsi
