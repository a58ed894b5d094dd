#include "casing_part.hpp"

namespace rsi {

CasingPart::CasingPart(const Casing& casing, double dt, const RayleighDamping& damping)
    : m_dt(dt)
    , m_damping(damping)
    , m_damped(damping.any())
    , m_kc(casing.stiffness)
    , m_mc(casing.mass) {
  const int nc = casing.n_dofs();
  m_force = Eigen::VectorXd::Zero(nc);
  m_c = m_c_prev = Eigen::VectorXd::Zero(nc);
  m_c_next = m_work = Eigen::VectorXd::Zero(nc);
  if (m_damped) m_c_delta = m_c_damping = Eigen::VectorXd::Zero(nc);
}

void CasingPart::set_force(const Eigen::Ref<const Eigen::VectorXd>& force) {
  m_force = force;
  m_force_zero = (m_force.array() == 0.0).all();
  force_changed();
}

double CasingPart::step_external_work() {
  m_work = m_c_next - m_c_prev;
  return 0.5 * m_force.dot(m_work);
}

double CasingPart::step_damping_product() {
  m_c_delta = m_c_next - m_c_prev;
  m_c_damping.noalias() = m_mc * m_c_delta;
  m_c_damping *= m_damping.alpha;
  m_c_damping.noalias() += m_damping.beta * (m_kc * m_c_delta);
  return m_c_delta.dot(m_c_damping);
}

void CasingPart::advance() {
  m_c_prev.swap(m_c);
  m_c.swap(m_c_next);
}

} // namespace rsi
