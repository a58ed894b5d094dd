#include "tip_ring_frictional_contact.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "casing_point.hpp"

namespace rsi {

TipRingFrictionalContact::TipRingFrictionalContact(const BladedDisk& bladed_disk,
                                                   const Casing& casing, const Case& c)
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

std::vector<int> TipRingFrictionalContact::dofs_read(int n_dofs) const {
  std::vector<int> dofs(m_tip_radial);
  dofs.insert(dofs.end(), m_tip_tangential.begin(), m_tip_tangential.end());
  for (int first : m_casing_node_dof)
    if (first >= 0)
      for (int d = 0; d < 4; ++d) // u, u_s, v, v_s
        dofs.push_back(first + d);
  for (int dof : dofs)
    if (dof < 0 || dof >= n_dofs)
      throw std::invalid_argument("TipRingFrictionalContact: dof " + std::to_string(dof) +
                                  " outside a system of " + std::to_string(n_dofs) +
                                  " dofs, allowed [0, n_dofs)");
  return dofs;
}

void TipRingFrictionalContact::evaluate(const Eigen::Ref<const Eigen::VectorXd>& current,
                                        const Eigen::Ref<const Eigen::VectorXd>& predicted,
                                        double t_next, double dt,
                                        FrictionalContactGeometry& out) const {
  const std::string where = "TipRingFrictionalContact::evaluate: ";
  if (current.size() != predicted.size())
    throw std::invalid_argument(where + "current has " + std::to_string(current.size()) +
                                " entries and predicted " + std::to_string(predicted.size()) +
                                ", allowed equal sizes");
  if (!std::isfinite(t_next)) throw std::invalid_argument(where + "t_next must be finite");
  if (!(std::isfinite(dt) && dt > 0.0))
    throw std::invalid_argument(where + "dt must be in (0, inf)");
  const int nc = n_contacts();
  out.normal_gap.resize(nc);
  out.slip.resize(nc);
  out.rows.resize(2 * nc);
  for (int k = 0; k < nc; ++k) {
    const int iu = m_tip_radial[k];
    const int iv = m_tip_tangential[k];
    if (iu >= predicted.size() || iv >= predicted.size())
      throw std::invalid_argument(where + "tip dof outside vectors of " +
                                  std::to_string(predicted.size()) + " entries");
    // The casing point the tip faces, as TipCasingContact::evaluate.
    const double alpha = m_tip_angle0[k] + m_omega * t_next + predicted(iv) / m_tip_radius;
    if (!std::isfinite(alpha)) {
      // A non-finite state faces no casing element (the index would be
      // garbage): non-finite g~ and s~, which the integrator refuses with the step.
      out.normal_gap(k) = out.slip(k) = std::numeric_limits<double>::quiet_NaN();
      out.rows[2 * k].clear();
      out.rows[2 * k + 1].clear();
      continue;
    }
    const CasingPoint p = casing_point(alpha, m_casing_elements, m_casing_radius, m_casing_node_dof);
    const Eigen::Vector4d& n = p.shape;
    const int n_nodes = p.n_nodes;
    const int* first = p.first;
    const int* shape_offset = p.shape_offset;
    double u_casing = 0.0;
    double v_casing_increment = 0.0;
    for (int a = 0; a < n_nodes; ++a)
      for (int d = 0; d < 2; ++d) {
        const double shape = n(shape_offset[a] + d);
        if (first[a] + 2 + d >= predicted.size())
          throw std::invalid_argument(where + "casing dof outside vectors of " +
                                      std::to_string(predicted.size()) + " entries");
        u_casing += shape * predicted(first[a] + d);
        v_casing_increment += shape * (predicted(first[a] + 2 + d) - current(first[a] + 2 + d));
      }
    out.normal_gap(k) = m_casing_radius + u_casing - (m_tip_radius + predicted(iu));
    out.slip(k) = m_omega * (m_tip_radius + predicted(iu)) * dt + (predicted(iv) - current(iv)) -
                  v_casing_increment;
    SparseRow& normal = out.rows[2 * k];
    SparseRow& tangent = out.rows[2 * k + 1];
    const int length = 1 + 2 * n_nodes;
    normal.resize(length);
    tangent.resize(length);
    normal[0] = {iu, -1.0};
    tangent[0] = {iv, 1.0};
    for (int a = 0; a < n_nodes; ++a)
      for (int d = 0; d < 2; ++d) {
        const double shape = n(shape_offset[a] + d);
        normal[1 + 2 * a + d] = {first[a] + d, shape};
        tangent[1 + 2 * a + d] = {first[a] + 2 + d, -shape};
      }
  }
}

} // namespace rsi
