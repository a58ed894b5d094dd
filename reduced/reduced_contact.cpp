#include "reduced_contact.hpp"

#include <cmath>
#include <limits>

#include "blade_geometry.hpp"
#include "ring_element.hpp"

namespace rsi {

ReducedTipContact::ReducedTipContact(const ReducedBasis& basis, const Casing& casing,
                                     const Case& c)
    : m_node_first(casing.node_first_dof)
    , m_tip_radius(c.bladed_disk.tip_radius)
    , m_casing_radius(casing.radius)
    , m_omega(c.operating_point.rotation_speed)
    , m_mu(c.operating_point.friction_coefficient)
    , m_law(c.operating_point.friction_law) {
  // The partition's boundary is the bladed disk's (u_0, v_0, u_1, v_1, ...);
  // only the tips' angles are read from the model, not its matrices.
  const int n_sectors = c.bladed_disk.n_blades;
  const double tip_angle = blade_geometry(c.bladed_disk).tip_angle;
  for (int k = 0; k < n_sectors; ++k) {
    m_q_u.push_back(basis.boundary_position[2 * k]);
    m_q_v.push_back(basis.boundary_position[2 * k + 1]);
    m_alpha0.push_back(2.0 * M_PI * k / n_sectors + tip_angle);
  }
}

void ReducedTipContact::evaluate(const Eigen::VectorXd& q, const Eigen::VectorXd& q_before,
                                 const Eigen::VectorXd& c, const Eigen::VectorXd& c_before,
                                 double dt, double t, std::vector<TipContact>& out) const {
  const int n_nodes = static_cast<int>(m_node_first.size());
  const double pitch = 2.0 * M_PI / n_nodes;
  out.resize(m_q_u.size());
  for (size_t k = 0; k < m_q_u.size(); ++k) {
    TipContact& tip = out[k];
    tip.q_u = m_q_u[k];
    tip.q_v = m_q_v[k];
    const double turns = (m_alpha0[k] + m_omega * t + q(tip.q_v) / m_tip_radius) / (2.0 * M_PI);
    if (!std::isfinite(turns)) {
      // A non-finite state has no contact point on the casing (its element
      // index would be garbage): the tip reports a non-finite gap and slip,
      // which the integrator refuses with the step number.
      tip.gap = tip.sliding = tip.slip = std::numeric_limits<double>::quiet_NaN();
      tip.sign = 0.0;
      tip.c_u.fill(-1);
      tip.c_v.fill(-1);
      tip.shape.fill(0.0);
      continue;
    }
    const double position = (turns - std::floor(turns)) * n_nodes; // in [0, n_nodes)
    const int element = std::min(static_cast<int>(position), n_nodes - 1);
    const Eigen::Vector4d n = hermite_values(position - element, m_casing_radius * pitch);
    double u_casing = 0.0;
    double v_casing_rate = 0.0;
    double v_casing_increment = 0.0;
    for (int a = 0; a < 4; ++a) {
      const int first = m_node_first[(element + a / 2) % n_nodes];
      tip.shape[a] = n(a);
      tip.c_u[a] = first < 0 ? -1 : first + a % 2;
      tip.c_v[a] = first < 0 ? -1 : first + 2 + a % 2;
      if (first < 0) continue;
      u_casing += n(a) * c(tip.c_u[a]);
      const double increment = c(tip.c_v[a]) - c_before(tip.c_v[a]);
      v_casing_rate += n(a) * (increment / dt);
      v_casing_increment += n(a) * increment;
    }
    tip.gap = m_casing_radius + u_casing - m_tip_radius - q(tip.q_u);
    tip.sliding = m_omega * (m_tip_radius + q(tip.q_u)) + (q(tip.q_v) - q_before(tip.q_v)) / dt -
                  v_casing_rate;
    tip.slip = m_omega * (m_tip_radius + q(tip.q_u)) * dt + (q(tip.q_v) - q_before(tip.q_v)) -
               v_casing_increment;
    tip.sign = m_mu > 0.0 ? static_cast<double>((tip.sliding > 0.0) - (tip.sliding < 0.0)) : 0.0;
  }
}

} // namespace rsi
