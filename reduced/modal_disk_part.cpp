#include "modal_disk_part.hpp"

#include <stdexcept>
#include <string>

namespace rsi {

ModalDiskPart::ModalDiskPart(const ReducedBasis& basis, double dt, const ReducedModes& modes)
    : DiskPart(basis, dt, basis.mass, false) {
  m_factor.reset();
  const Eigen::Index r = m_kq.rows();
  if (modes.shapes.rows() != r || modes.shapes.cols() != r || modes.omega_squared.size() != r)
    throw std::invalid_argument("ReducedIntegrator: the reduced modes must be " +
                                std::to_string(r) + " x " + std::to_string(r));
  m_psi = modes.shapes;
  m_lambda_disk = modes.omega_squared;
  m_boundary = basis.boundary_position;
  m_psi_boundary.resize(static_cast<Eigen::Index>(m_boundary.size()), r);
  m_boundary_index.assign(static_cast<size_t>(r), -1);
  for (size_t i = 0; i < m_boundary.size(); ++i) {
    m_psi_boundary.row(static_cast<Eigen::Index>(i)) = m_psi.row(m_boundary[i]);
    m_boundary_index[static_cast<size_t>(m_boundary[i])] = static_cast<int>(i);
  }
  m_boundary_flexibility = m_psi_boundary * m_psi_boundary.transpose();
  m_eta = m_eta_prev = m_eta_next = m_deta = Eigen::VectorXd::Zero(r);
  m_q_boundary = m_dq_boundary =
      Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m_boundary.size()));
}

double ModalDiskPart::flops_per_step() const {
  const auto r = static_cast<double>(m_kq.rows());
  return 2.0 * static_cast<double>(m_boundary.size()) * r + 5.0 * r;
}

double ModalDiskPart::energy() const {
  return 0.5 * ((m_eta - m_eta_prev) / m_dt).squaredNorm() +
         0.5 * m_eta_prev.dot(m_lambda_disk.cwiseProduct(m_eta));
}

void ModalDiskPart::start(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  DiskPart::start(q0);
  // eta = Psi^T M^ q, the same start in modal coordinates; q, q_prev whole.
  m_eta.noalias() = m_psi.transpose() * (m_mq * m_q);
  m_eta_prev = m_eta - (0.5 * m_dt * m_dt) * m_lambda_disk.cwiseProduct(m_eta);
  if (q0.isZero(0.0)) m_eta_prev = m_eta;
  m_q.noalias() = m_psi * m_eta;
  m_q_prev.noalias() = m_psi * m_eta_prev;
}

void ModalDiskPart::form_boundary(const Eigen::VectorXd& eta, Eigen::VectorXd& q) {
  m_q_boundary.noalias() = m_psi_boundary * eta;
  for (size_t i = 0; i < m_boundary.size(); ++i)
    q(m_boundary[i]) = m_q_boundary(static_cast<Eigen::Index>(i));
}

void ModalDiskPart::predict() {
  const double dt2 = m_dt * m_dt;
  m_eta_next = 2.0 * m_eta - m_eta_prev;
  m_eta_next -= dt2 * m_lambda_disk.cwiseProduct(m_eta);
  form_boundary(m_eta_next, m_q_next);
}

void ModalDiskPart::clear_correction() {
  DiskPart::clear_correction();
  m_deta.setZero();
  m_dq_boundary.setZero();
}

void ModalDiskPart::apply_correction() {
  // q_B = Psi_B (eta~ + d eta) = q~_B + Psi_B Psi_B^T (sum of f e): the
  // predictor's q~_B plus the corrections' columns (add).
  m_eta_next += m_deta;
  m_q_boundary += m_dq_boundary;
  for (size_t i = 0; i < m_boundary.size(); ++i)
    m_q_next(m_boundary[i]) = m_q_boundary(static_cast<Eigen::Index>(i));
}

void ModalDiskPart::advance() {
  DiskPart::advance();
  m_eta_prev.swap(m_eta);
  m_eta.swap(m_eta_next);
}

} // namespace rsi
