#include "physical_disk_part.hpp"

namespace rsi {

namespace {

/// A = M^ + dt/2 C^ (M^ undamped).
Eigen::MatrixXd damped_mass(const Eigen::MatrixXd& mass, double dt, bool damped,
                            const Eigen::VectorXd& diagonal, const Eigen::MatrixXd& full) {
  Eigen::MatrixXd a_q = mass;
  if (damped && full.size() != 0)
    a_q += 0.5 * dt * full;
  else if (damped)
    a_q.diagonal() += 0.5 * dt * diagonal;
  return a_q;
}

} // namespace

PhysicalDiskPart::PhysicalDiskPart(const ReducedBasis& basis, double dt, bool damped,
                                   const Eigen::VectorXd& diagonal, const Eigen::MatrixXd& full)
    : DiskPart(basis, dt, damped_mass(basis.mass, dt, damped, diagonal, full), damped) {
  if (m_damped && full.size() != 0)
    m_cq_matrix = full;
  else if (m_damped)
    m_cq = diagonal;
  m_aq = m_factor->solve(m_kq);
  m_factor.reset();
  if (m_damped)
    m_bq = m_cq_matrix.size() != 0 ? Eigen::MatrixXd(dt * (m_flexibility * m_cq_matrix))
                                   : Eigen::MatrixXd(dt * (m_flexibility * m_cq.asDiagonal()));
}

double PhysicalDiskPart::flops_per_step() const {
  const auto r = static_cast<double>(m_kq.rows());
  double flops = 2.0 * r * r + 4.0 * r;
  if (m_damped) flops += 2.0 * r * r + 5.0 * r;
  if (m_cq_matrix.size() != 0) flops += 2.0 * r * r; // C^ dq of W_damp
  return flops;
}

double PhysicalDiskPart::energy() const {
  const Eigen::VectorXd vq = (m_q - m_q_prev) / m_dt;
  return 0.5 * vq.dot(m_mq * vq) + 0.5 * m_q_prev.dot(m_kq * m_q);
}

void PhysicalDiskPart::predict() {
  const double dt2 = m_dt * m_dt;
  m_q_next = 2.0 * m_q - m_q_prev;
  m_q_next.noalias() -= dt2 * (m_aq * m_q);
  if (m_damped) { // - dt A^-1 C^ (q_n - q_{n-1})
    m_dq = m_q - m_q_prev;
    m_q_next.noalias() -= m_bq * m_dq;
  }
}

void PhysicalDiskPart::add_coulomb_correction(const TipContact& tip, double f, double ft) {
  m_dq -= f * m_flexibility.col(tip.q_u);
  if (ft != 0.0) m_dq += ft * m_flexibility.col(tip.q_v);
}

double PhysicalDiskPart::step_damping_product() {
  m_dq = m_q_next - m_q_prev;
  if (m_cq_matrix.size() != 0) {
    m_cq_dq.noalias() = m_cq_matrix * m_dq;
    return m_dq.dot(m_cq_dq);
  }
  return m_dq.dot(m_cq.cwiseProduct(m_dq));
}

} // namespace rsi
