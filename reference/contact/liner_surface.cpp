#include "liner_surface.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

namespace rsi {

LinerSurface::LinerSurface(const RigidSurfaceContact& law, const LinerGeometry& geometry,
                           const LinerMaterial& material, const LinerPatch& patch)
    : m_law(law), m_liner(geometry, material), m_patch(patch) {
  if (!(patch.circumferential >= 0.0 && patch.axial >= 0.0))
    throw std::invalid_argument("the tip patch's widths (" + std::to_string(patch.circumferential) +
                                ", " + std::to_string(patch.axial) + ") must be >= 0");
  for (int c = 0; c < law.n_contacts(); ++c) {
    const double z = law.axis().dot(law.node(c).position);
    try {
      m_rows.push_back(patch.present() ? patch_rows(m_liner, z, patch.axial)
                                       : std::vector<int>{m_liner.axial_row(z)});
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument("contact node " + std::to_string(c) + " at axial coordinate " +
                                  std::to_string(z) + " is not over the liner's axial extent [" +
                                  std::to_string(geometry.z_min) + ", " +
                                  std::to_string(geometry.z_max) + "]");
    }
  }
}

std::vector<int> LinerSurface::cells(int contact, double t) const {
  const double theta = m_law.rotation_speed() * t + m_law.frame(contact).angle;
  const std::vector<int>& rows = m_rows.at(static_cast<size_t>(contact));
  const std::vector<int> sectors =
      m_patch.present()
          ? patch_sectors(m_liner, theta, m_patch.circumferential / m_liner.geometry().radius)
          : std::vector<int>{m_liner.angular_cell(theta)};
  std::vector<int> out;
  for (int j : rows)
    for (int i : sectors) out.push_back(j * m_liner.n_theta() + i);
  return out;
}

void LinerSurface::begin_step() { m_pending.clear(); }

double LinerSurface::respond(int contact, double t_next, double rigid_gap, double compliance) {
  const std::vector<int> under = cells(contact, t_next);
  std::vector<LinerCellState> states;
  for (int k : under) {
    LinerCellState state = m_liner.state(k);
    for (const Pending& p : m_pending)
      if (p.cell == k) state = p.response.state;
    states.push_back(state);
  }
  if (!m_patch.present()) {
    const double delta_pred = -rigid_gap - states[0].wear;
    const LinerBarResponse r = m_liner.compliant_force(states[0], delta_pred, compliance);
    m_pending.push_back({under[0], r});
    return r.force;
  }
  const LinerPatchResponse r = patch_compliant_force(m_liner, states, -rigid_gap, compliance);
  for (std::size_t i = 0; i < under.size(); ++i) m_pending.push_back({under[i], r.bars[i]});
  return r.force;
}

void LinerSurface::commit_step() {
  m_elastic_energy = 0.0;
  const double k = m_liner.stiffness();
  for (const Pending& p : m_pending) {
    m_liner.commit(p.cell, p.response);
    m_elastic_energy += p.response.force * p.response.force / (2.0 * k);
    const double h = m_liner.geometry().thickness;
    if (m_worn_through.empty() && p.response.state.wear >= h) {
      std::ostringstream m;
      m.precision(6);
      m << "the abradable liner is worn through at sector " << p.cell % m_liner.n_theta()
        << ", row " << p.cell / m_liner.n_theta() << ": wear " << p.response.state.wear
        << " >= its thickness " << h;
      m_worn_through = m.str();
    }
  }
  m_pending.clear();
}

} // namespace rsi
