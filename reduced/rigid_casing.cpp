#include "rigid_casing.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

#include "message_number.hpp"

namespace rsi {

RigidCasing::RigidCasing(const std::vector<Eigen::Vector3d>& positions,
                         const std::vector<std::array<int, 3>>& boundary_index,
                         const CasingGap& gap, double omega, double sliding_omega,
                         const Eigen::Vector3d& axis, std::vector<double> growth)
    : m_gap(gap)
    , m_growth(std::move(growth))
    , m_omega(omega)
    , m_sliding_omega(sliding_omega) {
  const std::string where = "RigidCasing: ";
  if (positions.size() != boundary_index.size())
    throw std::invalid_argument(where + "positions (" + std::to_string(positions.size()) +
                                ") and boundary_index (" + std::to_string(boundary_index.size()) +
                                ") must have one entry per contact node");
  if (!std::isfinite(omega))
    throw std::invalid_argument(where + "omega = " + message_number(omega) +
                                ", allowed a finite value");
  if (!std::isfinite(sliding_omega))
    throw std::invalid_argument(where + "sliding omega = " + message_number(sliding_omega) +
                                ", allowed a finite value");
  if (!std::isfinite(gap.g0))
    throw std::invalid_argument(where + "gap g0 = " + message_number(gap.g0) + ", allowed finite");
  if (!m_growth.empty() && m_growth.size() != positions.size())
    throw std::invalid_argument(where + "growth (" + std::to_string(m_growth.size()) +
                                ") must have one entry per contact node (" +
                                std::to_string(positions.size()) + ") or none");
  for (double g : m_growth)
    if (!std::isfinite(g))
      throw std::invalid_argument(where + "gap growth " + message_number(g) + ", allowed finite");
  if (gap.kind == CasingGapKind::linear && !std::isfinite(gap.rate))
    throw std::invalid_argument(where + "gap rate = " + message_number(gap.rate) +
                                ", allowed finite");
  if (gap.kind == CasingGapKind::oval && !(gap.g0 > 0.0))
    throw std::invalid_argument(where + "oval gap g_m = " + message_number(gap.g0) +
                                ", allowed > 0");
  if (gap.kind == CasingGapKind::oval && !(gap.width > 0.0 && gap.width < 1.0))
    throw std::invalid_argument(where + "oval gap width = " + message_number(gap.width) +
                                ", allowed (0, 1)");
  if (!axis.allFinite() || !(axis.norm() > 0.0))
    throw std::invalid_argument(where + "axis = (" + message_number(axis(0)) + ", " +
                                message_number(axis(1)) + ", " + message_number(axis(2)) +
                                "), allowed finite and nonzero");
  // Q = [b_1; b_2; a] (header).
  const Eigen::Vector3d a = axis / axis.norm();
  Eigen::Index k_max = 0;
  a.cwiseAbs().maxCoeff(&k_max);
  Eigen::Vector3d b1 = Eigen::Vector3d::Zero();
  b1((k_max + 1) % 3) = 1.0;
  b1 -= b1.dot(a) * a;
  b1 /= b1.norm();
  Eigen::Matrix3d q;
  q.row(0) = b1.transpose();
  q.row(1) = a.cross(b1).transpose();
  q.row(2) = a.transpose();
  std::set<int> seen;
  for (size_t c = 0; c < positions.size(); ++c) {
    const Eigen::Vector3d& x = positions[c];
    const Eigen::Vector3d s = q * x; // axis coordinates
    const double r = std::hypot(s(0), s(1));
    if (!x.allFinite() || !(r > 0.0))
      throw std::invalid_argument(where + "contact node " + std::to_string(c) +
                                  " lies on the rotation axis or is not finite (r = " +
                                  message_number(r) + "), allowed r > 0");
    for (int k : boundary_index[c])
      if (k < 0 || !seen.insert(k).second)
        throw std::invalid_argument(where + "contact node " + std::to_string(c) +
                                    ": boundary index " + std::to_string(k) +
                                    " negative or repeated, allowed distinct indices >= 0");
    // Q^T of the axis-coordinate vectors; + 0.0 makes a -0 entry +0, so
    // that a casing about z keeps its frames bit for bit.
    const Eigen::Vector3d en =
        (q.transpose() * Eigen::Vector3d(-s(0) / r, -s(1) / r, 0.0)).array() + 0.0;
    const Eigen::Vector3d et1 = a;
    const Eigen::Vector3d et2 = en.cross(et1);
    Eigen::Matrix3d f;
    f.row(0) = en.transpose();
    f.row(1) = et1.transpose();
    f.row(2) = et2.transpose();
    m_frame.push_back(f);
    m_index.push_back(boundary_index[c]);
    m_radius.push_back(r);
    m_phi.push_back(std::atan2(s(1), s(0)));
    m_axial.push_back(s(2));
  }
}

double RigidCasing::imposed_gap(int c, double t) const {
  return m_growth.empty() ? shape_gap(c, t) : shape_gap(c, t) - m_growth[c];
}

double RigidCasing::shape_gap(int c, double t) const {
  switch (m_gap.kind) {
  case CasingGapKind::constant:
    return m_gap.g0;
  case CasingGapKind::linear:
    return m_gap.g0 - m_gap.rate * t;
  case CasingGapKind::oval: {
    const double pi = 3.14159265358979323846;
    const double theta = m_omega * t + m_phi[c];
    double m = std::fmod(theta, pi);
    if (m < 0.0) m += pi; // mod(theta, pi) in [0, pi) for negative angles too
    const double x = (m / pi - 0.5) / m_gap.width;
    return m_gap.g0 * (1.0 - 2.0 * std::exp(-x * x));
  }
  }
  return m_gap.g0;
}

RigidCasing rigid_casing_of(const Component& component, const std::vector<int>& node_ids,
                            const CasingGap& gap, double omega, double sliding_omega,
                            std::vector<double> growth) {
  const std::string where = "rigid_casing_of: ";
  std::unordered_map<int, int> boundary_slot; // dof -> index in component.boundary
  for (int k = 0; k < static_cast<int>(component.boundary.size()); ++k)
    boundary_slot[component.boundary[k]] = k;
  std::unordered_map<int, std::array<int, 3>> translations; // node -> dofs ux, uy, uz
  for (int i = 0; i < component.n_dofs(); ++i) {
    const DofInfo& d = component.dofs[i];
    const int axis = d.kind == "ux" ? 0 : d.kind == "uy" ? 1 : d.kind == "uz" ? 2 : -1;
    if (axis < 0) continue;
    auto found = translations.find(d.node);
    if (found == translations.end())
      found = translations.emplace(d.node, std::array<int, 3>{-1, -1, -1}).first;
    found->second[axis] = i;
  }
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> index;
  for (int id : node_ids) {
    const auto node = std::find_if(component.nodes.begin(), component.nodes.end(),
                                   [id](const ComponentNode& n) { return n.id == id; });
    if (node == component.nodes.end())
      throw std::invalid_argument(where + "contact node " + std::to_string(id) +
                                  " has no coordinates in the component '" + component.name + "'");
    const auto dofs = translations.find(id);
    std::array<int, 3> slots{-1, -1, -1};
    for (int a = 0; a < 3; ++a) {
      const int dof = dofs == translations.end() ? -1 : dofs->second[a];
      const auto slot = boundary_slot.find(dof);
      if (dof < 0 || slot == boundary_slot.end())
        throw std::invalid_argument(where + "contact node " + std::to_string(id) + ": its u" +
                                    "xyz"[a] + " is not a boundary dof of '" + component.name +
                                    "' (the boundary must hold the contact nodes' translations)");
      slots[a] = slot->second;
    }
    positions.push_back(node->x);
    index.push_back(slots);
  }
  return RigidCasing(positions, index, gap, omega, sliding_omega, component.rotation_axis,
                     std::move(growth));
}

} // namespace rsi
