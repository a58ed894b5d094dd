#include "disk_part.hpp"

#include <string>

#include "reduced_integrator.hpp"

namespace rsi {

namespace {

// The case's M is positive definite (checked when it loads) and so is
// T^T M T for a basis T of full rank: a mass that fails here is a basis
// that lost its rank in rounding.
const std::string kReducedMassRemedy =
    "; the case's M passed its check when it loaded, so the basis T lost its rank in rounding: ";
const FailureAdvice kReducedMassAdvice =
    remedied_by({Remedy::fewer_modes_campaign_or_another_method});

} // namespace

DiskPart::DiskPart(const ReducedBasis& basis, double dt, const Eigen::MatrixXd& a, bool damped)
    : m_kq(basis.stiffness)
    , m_mq(basis.mass)
    , m_factor(std::in_place, a)
    , m_dt(dt)
    , m_damped(damped) {
  if (m_factor->info() != Eigen::Success)
    throw ReducedIntegrationError(std::string("reduced integrator: the reduced mass matrix") +
                                      (m_damped ? " plus dt/2 C^" : "") +
                                      " is not positive definite" + kReducedMassRemedy,
                                  kReducedMassAdvice);
  m_flexibility = m_factor->solve(Eigen::MatrixXd::Identity(m_mq.rows(), m_mq.cols()));
  m_tip_position = basis.boundary_position;
  m_q_next = m_dq = Eigen::VectorXd::Zero(m_kq.rows());
}

void DiskPart::tip_displacement(Eigen::VectorXd& out) const {
  // The modal part keeps q_n's boundary entries (modal_disk_part.hpp).
  out.resize(static_cast<Eigen::Index>(m_tip_position.size()));
  for (size_t i = 0; i < m_tip_position.size(); ++i)
    out(static_cast<Eigen::Index>(i)) = m_q(m_tip_position[i]);
}

void DiskPart::start(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  m_q = q0;
  if (q0.isZero(0.0)) {
    m_q_prev = m_q;
  } else {
    // q_{-1} = q0 + dt^2/2 M^-1 (-K^ q0): at rest, with M^ itself (not A).
    const Eigen::LLT<Eigen::MatrixXd> mass(m_mq);
    if (mass.info() != Eigen::Success)
      throw ReducedIntegrationError(
          "reduced integrator: the reduced mass matrix is not positive definite" +
              kReducedMassRemedy,
          kReducedMassAdvice);
    m_q_prev = m_q - 0.5 * m_dt * m_dt * mass.solve(m_kq * m_q);
  }
}

void DiskPart::advance() {
  m_q_prev.swap(m_q);
  m_q.swap(m_q_next);
}

} // namespace rsi
