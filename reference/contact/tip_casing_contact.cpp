#include "tip_casing_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "casing_point.hpp"

namespace rsi {

TipCasingContact::TipCasingContact(const BladedDisk& bladed_disk, const Casing& casing,
                                   const Case& c)
    : m_tip_radial(bladed_disk.tip_radial)
    , m_tip_tangential(bladed_disk.tip_tangential)
    , m_casing_elements(casing.n_elements)
    , m_tip_radius(c.bladed_disk.tip_radius)
    , m_casing_radius(casing.radius)
    , m_omega(c.operating_point.rotation_speed)
    , m_mu(c.operating_point.friction_coefficient) {
  for (int k = 0; k < bladed_disk.n_sectors; ++k)
    m_tip_angle0.push_back(2.0 * M_PI * k / bladed_disk.n_sectors + bladed_disk.geometry.tip_angle);
  for (int first : casing.node_first_dof)
    m_casing_node_dof.push_back(first < 0 ? -1 : bladed_disk.n_dofs() + first);
}

std::vector<int> TipCasingContact::dofs_read(int n_dofs) const {
  std::vector<int> dofs(m_tip_radial);
  dofs.insert(dofs.end(), m_tip_tangential.begin(), m_tip_tangential.end());
  for (int first : m_casing_node_dof)
    if (first >= 0)
      for (int d = 0; d < 4; ++d) // u, u_s, v, v_s
        dofs.push_back(first + d);
  for (int dof : dofs)
    if (dof < 0 || dof >= n_dofs)
      throw std::invalid_argument("TipCasingContact: dof " + std::to_string(dof) +
                                  " outside a system of " + std::to_string(n_dofs) + " dofs");
  return dofs;
}

void TipCasingContact::evaluate(const Eigen::Ref<const Eigen::VectorXd>& x,
                                const Eigen::Ref<const Eigen::VectorXd>& v, double t,
                                ContactState& s) const {
  const int nc = n_constraints();
  s.gap.resize(nc);
  s.sliding_velocity.resize(nc);
  s.friction_sign.resize(nc);
  s.gradient.resize(nc);
  s.direction.resize(nc);
  for (int k = 0; k < nc; ++k) {
    const int iu = m_tip_radial[k];
    const int iv = m_tip_tangential[k];
    const double alpha = m_tip_angle0[k] + m_omega * t + x(iv) / m_tip_radius;
    if (!std::isfinite(alpha)) {
      // A non-finite state faces no casing element (the index would be
      // garbage): a non-finite gap, which the run monitor reports as a blow-up.
      s.gap(k) = s.sliding_velocity(k) = std::numeric_limits<double>::quiet_NaN();
      s.friction_sign(k) = 0.0;
      s.gradient[k].clear();
      s.direction[k].clear();
      continue;
    }
    const CasingPoint p = casing_point(alpha, m_casing_elements, m_casing_radius, m_casing_node_dof);
    const Eigen::Vector4d& n = p.shape;
    const int n_nodes = p.n_nodes;
    const int* first = p.first;
    const int* shape_offset = p.shape_offset;
    double u_casing = 0.0;
    double v_casing_rate = 0.0;
    for (int a = 0; a < n_nodes; ++a)
      for (int d = 0; d < 2; ++d) {
        const double shape = n(shape_offset[a] + d);
        u_casing += shape * x(first[a] + d);
        v_casing_rate += shape * v(first[a] + 2 + d);
      }
    s.gap(k) = m_casing_radius + u_casing - (m_tip_radius + x(iu));
    s.sliding_velocity(k) = m_omega * (m_tip_radius + x(iu)) + v(iv) - v_casing_rate;
    const double sign =
        m_mu > 0.0
            ? (s.sliding_velocity(k) > 0.0 ? 1.0 : (s.sliding_velocity(k) < 0.0 ? -1.0 : 0.0))
            : 0.0;
    s.friction_sign(k) = sign;
    // G_k = [-1 on u_k, N on the casing u, u_s]; D_k = mu s_k T_k followed
    // by G_k, T_k = [-1 on v_k, N on the casing v, v_s]. Written in place:
    // the rows keep their storage from call to call.
    const double scale = m_mu * sign;
    const int length = 1 + 2 * n_nodes;
    SparseRow& normal = s.gradient[k];
    SparseRow& direction = s.direction[k];
    normal.resize(length);
    direction.resize(2 * length);
    normal[0] = {iu, -1.0};
    direction[0] = {iv, -1.0 * scale};
    for (int a = 0; a < n_nodes; ++a)
      for (int d = 0; d < 2; ++d) {
        const double shape = n(shape_offset[a] + d);
        normal[1 + 2 * a + d] = {first[a] + d, shape};
        direction[1 + 2 * a + d] = {first[a] + 2 + d, shape * scale};
      }
    std::copy(normal.begin(), normal.end(), direction.begin() + length);
  }
}

} // namespace rsi
