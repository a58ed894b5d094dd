#include "liner_surface.hpp"

#include <stdexcept>
#include <string>

namespace rsi {

LinerSurface::LinerSurface(const RigidSurfaceContact& law, const LinerGeometry& geometry,
                           const LinerMaterial& material)
    : m_law(law), m_liner(geometry, material) {
  for (int c = 0; c < law.n_contacts(); ++c) {
    const double z = law.axis().dot(law.node(c).position);
    try {
      m_rows.push_back(m_liner.axial_row(z));
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument("contact node " + std::to_string(c) + " at axial coordinate " +
                                  std::to_string(z) + " is not over the liner's axial extent [" +
                                  std::to_string(geometry.z_min) + ", " +
                                  std::to_string(geometry.z_max) + "]");
    }
  }
}

int LinerSurface::cell(int contact, double t) const {
  const double theta = m_law.rotation_speed() * t + m_law.frame(contact).angle;
  return m_rows.at(static_cast<size_t>(contact)) * m_liner.n_theta() + m_liner.angular_cell(theta);
}

void LinerSurface::begin_step() { m_pending.clear(); }

LinerBarResponse LinerSurface::respond(int contact, double t_next, double rigid_gap,
                                       double compliance) {
  const int k = cell(contact, t_next);
  LinerCellState state = m_liner.state(k);
  for (const Pending& p : m_pending)
    if (p.cell == k) state = p.response.state;
  const double delta_pred = -rigid_gap - state.wear;
  const LinerBarResponse r = m_liner.compliant_force(state, delta_pred, compliance);
  m_pending.push_back({k, r});
  return r;
}

void LinerSurface::commit_step() {
  m_elastic_energy = 0.0;
  const double k = m_liner.stiffness();
  for (const Pending& p : m_pending) {
    m_liner.commit(p.cell, p.response);
    m_elastic_energy += p.response.force * p.response.force / (2.0 * k);
  }
  m_pending.clear();
}

} // namespace rsi
