#include "rigid_surface_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>

namespace rsi {

namespace {

std::string str(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

} // namespace

double ImposedGap::operator()(double theta) const {
  if (kind == Kind::constant) return value;
  // Floored modulo: theta - pi floor(theta / pi) in [0, pi).
  double m = theta - M_PI * std::floor(theta / M_PI);
  if (m >= M_PI) m -= M_PI; // round-off at a multiple of pi
  if (m < 0.0) m = 0.0;
  const double x = (m / M_PI - 0.5) / width;
  return value * (1.0 - 2.0 * std::exp(-x * x));
}

RigidSurfaceContact::RigidSurfaceContact(std::vector<RigidSurfaceNode> nodes, const ImposedGap& gap,
                                         double omega, double mu, double sliding_omega,
                                         const Eigen::Vector3d& axis)
    : m_nodes(std::move(nodes))
    , m_gap(gap)
    , m_omega(omega)
    , m_mu(mu)
    , m_sliding_omega(sliding_omega)
    , m_axis(axis) {
  const std::string where = "RigidSurfaceContact: ";
  if (!(axis.allFinite() && axis.norm() > 0.0))
    throw std::invalid_argument(where + "axis (" + str(axis(0)) + ", " + str(axis(1)) + ", " +
                                str(axis(2)) + "), allowed finite and nonzero");
  m_axis.normalize();
  // e_1: the coordinate axis after the one nearest to a, made normal to a;
  // e_2 = a x e_1 (header).
  int nearest = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(m_axis(k)) > std::abs(m_axis(nearest))) nearest = k;
  const Eigen::Vector3d next = Eigen::Vector3d::Unit((nearest + 1) % 3);
  const Eigen::Vector3d e1 = (next - next.dot(m_axis) * m_axis).normalized();
  const Eigen::Vector3d e2 = m_axis.cross(e1);
  if (m_nodes.empty())
    throw std::invalid_argument(where + "nodes is empty, allowed at least one contact node");
  if (gap.kind == ImposedGap::Kind::constant) {
    if (!std::isfinite(gap.value))
      throw std::invalid_argument(where + "constant gap = " + str(gap.value) + ", allowed finite");
  } else {
    if (!(std::isfinite(gap.value) && gap.value > 0.0))
      throw std::invalid_argument(where + "oval gap g_m = " + str(gap.value) +
                                  ", allowed (0, inf)");
    if (!(std::isfinite(gap.width) && gap.width > 0.0))
      throw std::invalid_argument(where + "oval gap width = " + str(gap.width) +
                                  ", allowed (0, inf)");
  }
  if (!std::isfinite(omega))
    throw std::invalid_argument(where + "omega = " + str(omega) + ", allowed finite");
  if (!std::isfinite(sliding_omega))
    throw std::invalid_argument(where + "sliding omega = " + str(sliding_omega) +
                                ", allowed finite");
  if (!(std::isfinite(mu) && mu >= 0.0))
    throw std::invalid_argument(where + "mu = " + str(mu) + ", allowed [0, inf)");
  std::set<int> seen;
  for (std::size_t c = 0; c < m_nodes.size(); ++c) {
    const RigidSurfaceNode& node = m_nodes[c];
    for (int dof : node.dofs) {
      if (dof < 0)
        throw std::invalid_argument(where + "node " + std::to_string(c) + " dof " +
                                    std::to_string(dof) + ", allowed [0, n_dofs)");
      if (!seen.insert(dof).second)
        throw std::invalid_argument(where + "node " + std::to_string(c) + " dof " +
                                    std::to_string(dof) +
                                    " used twice, allowed: distinct dofs for all nodes");
    }
    if (!std::isfinite(node.growth))
      throw std::invalid_argument(where + "node " + std::to_string(c) + " growth must be finite");
    const Eigen::Vector3d& x = node.position;
    if (!x.allFinite())
      throw std::invalid_argument(where + "node " + std::to_string(c) + " position must be finite");
    const double p1 = e1.dot(x);
    const double p2 = e2.dot(x);
    const double r = std::hypot(p1, p2);
    if (!(r > 0.0))
      throw std::invalid_argument(where + "node " + std::to_string(c) +
                                  " lies on the rotation axis (r = 0), allowed r > 0");
    ContactFrame f;
    f.radius = r;
    f.angle = std::atan2(p2, p1);
    // Adding +0.0 turns the -0 of a component along the axis into +0: a
    // model about z keeps its frames bit for bit.
    f.normal = ((-(p1 / r) * e1 - (p2 / r) * e2).array() + 0.0).matrix();
    f.tangent1 = m_axis;
    f.tangent2 = f.normal.cross(f.tangent1);
    m_frames.push_back(f);
  }
}

double RigidSurfaceContact::imposed_gap(int contact, double t) const {
  return m_gap(m_omega * t + m_frames.at(contact).angle) - m_nodes[contact].growth;
}

Eigen::Vector3d RigidSurfaceContact::casing_velocity(int contact) const {
  const ContactFrame& f = m_frames.at(contact);
  return (-f.radius * m_sliding_omega) * f.tangent2;
}

std::vector<int> RigidSurfaceContact::dofs_read(int n_dofs) const {
  std::vector<int> dofs;
  for (const RigidSurfaceNode& node : m_nodes)
    for (int dof : node.dofs) {
      if (dof >= n_dofs)
        throw std::invalid_argument("RigidSurfaceContact: dof " + std::to_string(dof) +
                                    " outside a system of " + std::to_string(n_dofs) +
                                    " dofs, allowed [0, " + std::to_string(n_dofs) + ")");
      dofs.push_back(dof);
    }
  return dofs;
}

void RigidSurfaceContact::evaluate(const Eigen::Ref<const Eigen::VectorXd>& current,
                                   const Eigen::Ref<const Eigen::VectorXd>& predicted,
                                   double t_next, double dt, FrictionalContactGeometry& out) const {
  const std::string where = "RigidSurfaceContact::evaluate: ";
  if (current.size() != predicted.size())
    throw std::invalid_argument(where + "current has " + std::to_string(current.size()) +
                                " entries and predicted " + std::to_string(predicted.size()) +
                                ", allowed equal sizes");
  if (!std::isfinite(t_next))
    throw std::invalid_argument(where + "t_next = " + str(t_next) + ", allowed finite");
  if (!(std::isfinite(dt) && dt > 0.0))
    throw std::invalid_argument(where + "dt = " + str(dt) + ", allowed (0, inf)");
  const int nc = n_contacts();
  out.normal_gap.resize(nc);
  out.slip.resize(2 * nc);
  out.rows.resize(3 * nc);
  for (int c = 0; c < nc; ++c) {
    const RigidSurfaceNode& node = m_nodes[c];
    const ContactFrame& f = m_frames[c];
    Eigen::Vector3d u_next, increment;
    for (int k = 0; k < 3; ++k) {
      const int dof = node.dofs[k];
      if (dof >= predicted.size())
        throw std::invalid_argument(where + "node dof " + std::to_string(dof) +
                                    " outside vectors of " + std::to_string(predicted.size()) +
                                    " entries");
      u_next(k) = predicted(dof);
      increment(k) = predicted(dof) - current(dof);
    }
    out.normal_gap(c) = imposed_gap(c, t_next) + f.normal.dot(u_next);
    out.slip(2 * c) = f.tangent1.dot(increment);
    out.slip(2 * c + 1) = f.tangent2.dot(increment) + f.radius * m_sliding_omega * dt;
    const Eigen::Vector3d* directions[3] = {&f.normal, &f.tangent1, &f.tangent2};
    for (int i = 0; i < 3; ++i) {
      SparseRow& row = out.rows[3 * c + i];
      row.clear();
      for (int k = 0; k < 3; ++k)
        if ((*directions[i])(k) != 0.0) row.emplace_back(node.dofs[k], (*directions[i])(k));
    }
  }
}

std::vector<RigidSurfaceNode> rigid_surface_nodes(const Component& component,
                                                  const std::vector<int>& node_ids, int offset) {
  const std::string where = "rigid_surface_nodes: ";
  if (offset < 0)
    throw std::invalid_argument(where + "offset = " + std::to_string(offset) +
                                ", allowed [0, inf)");
  const char* kinds[3] = {"ux", "uy", "uz"};
  std::vector<RigidSurfaceNode> nodes;
  for (int id : node_ids) {
    RigidSurfaceNode node;
    const auto at =
        std::lower_bound(component.nodes.begin(), component.nodes.end(), id,
                         [](const ComponentNode& n, int value) { return n.id < value; });
    if (at == component.nodes.end() || at->id != id)
      throw std::invalid_argument(where + "node " + std::to_string(id) + " not in component '" +
                                  component.name + "'");
    node.position = at->x;
    for (int i = 0; i < component.n_dofs(); ++i)
      if (component.dofs[i].node == id)
        for (int k = 0; k < 3; ++k)
          if (component.dofs[i].kind == kinds[k]) node.dofs[k] = offset + i;
    for (int k = 0; k < 3; ++k)
      if (node.dofs[k] < 0)
        throw std::invalid_argument(where + "node " + std::to_string(id) + " of component '" +
                                    component.name + "' has no " + kinds[k] + " dof");
    nodes.push_back(node);
  }
  return nodes;
}

} // namespace rsi
