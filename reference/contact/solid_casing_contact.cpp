#include "solid_casing_contact.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rsi {
namespace {

std::string str(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

Eigen::Vector3d radial(double a) {
  return {std::cos(a), std::sin(a), 0.0};
}
Eigen::Vector3d circumferential(double a) {
  return {-std::sin(a), std::cos(a), 0.0};
}

} // namespace

SolidCasingContact::SolidCasingContact(std::vector<RigidSurfaceNode> tips, CasingSurface surface,
                                       std::map<int, std::array<int, 3>> casing_dofs, double omega,
                                       double mu)
    : m_surface(std::move(surface))
    , m_casing_dofs(std::move(casing_dofs))
    , m_omega(omega)
    , m_mu(mu) {
  const std::string where = "SolidCasingContact: ";
  if (tips.empty()) throw std::invalid_argument(where + "no tip, allowed at least one");
  if (!std::isfinite(omega))
    throw std::invalid_argument(where + "omega = " + str(omega) + ", allowed finite");
  if (!(std::isfinite(mu) && mu >= 0.0))
    throw std::invalid_argument(where + "mu = " + str(mu) + ", allowed [0, inf)");
  std::set<int> seen;
  const auto claim = [&](int dof, const std::string& whose) {
    if (dof < 0)
      throw std::invalid_argument(where + whose + " dof " + std::to_string(dof) + ", allowed >= 0");
    if (!seen.insert(dof).second)
      throw std::invalid_argument(where + whose + " dof " + std::to_string(dof) +
                                  " used twice, allowed: distinct dofs");
  };
  for (const auto& [id, dofs] : m_casing_dofs)
    for (const int dof : dofs)
      claim(dof, "casing node " + std::to_string(id));
  for (size_t c = 0; c < tips.size(); ++c) {
    const RigidSurfaceNode& node = tips[c];
    const std::string which = "tip " + std::to_string(c);
    for (const int dof : node.dofs)
      claim(dof, which);
    if (!node.position.allFinite() || !std::isfinite(node.growth))
      throw std::invalid_argument(where + which + ": position and growth must be finite");
    Tip tip{node, std::hypot(node.position.x(), node.position.y()),
            std::atan2(node.position.y(), node.position.x())};
    if (!(tip.radius > 0.0))
      throw std::invalid_argument(where + which + " lies on the axis (r = 0), allowed r > 0");
    if (!m_surface.locate(tip.angle, node.position.z()))
      throw std::invalid_argument(where + which + " at height z = " + str(node.position.z()) +
                                  " is not above the casing's surface (its axial extent)");
    m_tips.push_back(tip);
  }
}

SurfacePoint SolidCasingContact::point(int contact, double t) const {
  const Tip& tip = m_tips.at(static_cast<size_t>(contact));
  const double theta = tip.angle + m_omega * t;
  const std::optional<SurfacePoint> p = m_surface.locate(theta, tip.node.position.z());
  if (!p)
    throw std::runtime_error("SolidCasingContact: tip " + std::to_string(contact) + " at angle " +
                             str(theta) + " rad: no casing face under it");
  return *p;
}

double SolidCasingContact::rest_gap(int contact, double t) const {
  const Tip& tip = m_tips.at(static_cast<size_t>(contact));
  return point(contact, t).rho - tip.radius - tip.node.growth;
}

void SolidCasingContact::evaluate(const Eigen::Ref<const Eigen::VectorXd>& current,
                                  const Eigen::Ref<const Eigen::VectorXd>& predicted, double t_next,
                                  double dt, FrictionalContactGeometry& out) const {
  const std::string where = "SolidCasingContact::evaluate: ";
  if (current.size() != predicted.size())
    throw std::invalid_argument(where + "current and predicted differ in size");
  if (!std::isfinite(t_next))
    throw std::invalid_argument(where + "t_next = " + str(t_next) + ", allowed finite");
  if (!(std::isfinite(dt) && dt > 0.0))
    throw std::invalid_argument(where + "dt = " + str(dt) + ", allowed (0, inf)");
  const auto value = [&](const Eigen::Ref<const Eigen::VectorXd>& u, int dof) {
    if (dof >= u.size())
      throw std::invalid_argument(where + "dof " + std::to_string(dof) + " outside vectors of " +
                                  std::to_string(u.size()) + " entries");
    return u(dof);
  };
  const int nc = n_contacts();
  out.normal_gap.resize(nc);
  out.slip.resize(2 * nc);
  out.rows.resize(3 * static_cast<size_t>(nc));
  const Eigen::Vector3d axial = Eigen::Vector3d::UnitZ();
  for (int c = 0; c < nc; ++c) {
    const Tip& tip = m_tips[static_cast<size_t>(c)];
    const SurfacePoint p = point(c, t_next);
    const double theta = tip.angle + m_omega * t_next;
    // Directions: the tip's in the rotor's frame, the casing's at theta.
    const std::array<Eigen::Vector3d, 3> on_tip = {-radial(tip.angle), axial,
                                                   circumferential(tip.angle)};
    const std::array<Eigen::Vector3d, 3> on_casing = {-radial(theta), axial,
                                                      circumferential(theta)};
    Eigen::Vector3d u_tip, du_tip;
    for (int k = 0; k < 3; ++k) {
      u_tip(k) = value(predicted, tip.node.dofs[k]);
      du_tip(k) = u_tip(k) - value(current, tip.node.dofs[k]);
    }
    const std::array<double, 6> n = triangle6_shape_functions(p.xi, p.eta);
    const std::array<int, 6>& face = m_surface.face_nodes(p.face);
    Eigen::Vector3d u_face = Eigen::Vector3d::Zero(), du_face = Eigen::Vector3d::Zero();
    for (int i = 0; i < 6; ++i) {
      const auto dofs = m_casing_dofs.find(face[i]);
      if (dofs == m_casing_dofs.end()) continue; // clamped
      for (int k = 0; k < 3; ++k) {
        const double u = value(predicted, dofs->second[k]);
        u_face(k) += n[i] * u;
        du_face(k) += n[i] * (u - value(current, dofs->second[k]));
      }
    }
    out.normal_gap(c) =
        p.rho - tip.radius - tip.node.growth + on_tip[0].dot(u_tip) - on_casing[0].dot(u_face);
    out.slip(2 * c) = on_tip[1].dot(du_tip) - on_casing[1].dot(du_face);
    out.slip(2 * c + 1) =
        on_tip[2].dot(du_tip) - on_casing[2].dot(du_face) + tip.radius * m_omega * dt;
    for (int r = 0; r < 3; ++r) {
      SparseRow& row = out.rows[3 * static_cast<size_t>(c) + static_cast<size_t>(r)];
      row.clear();
      for (int k = 0; k < 3; ++k)
        if (on_tip[r](k) != 0.0) row.emplace_back(tip.node.dofs[k], on_tip[r](k));
      for (int i = 0; i < 6; ++i) {
        const auto dofs = m_casing_dofs.find(face[i]);
        if (dofs == m_casing_dofs.end() || n[i] == 0.0) continue;
        for (int k = 0; k < 3; ++k)
          if (on_casing[r](k) != 0.0) row.emplace_back(dofs->second[k], -n[i] * on_casing[r](k));
      }
    }
  }
}

std::vector<int> SolidCasingContact::dofs_read(int n_dofs) const {
  std::vector<int> dofs;
  const auto add = [&](int dof) {
    if (dof >= n_dofs)
      throw std::invalid_argument("SolidCasingContact: dof " + std::to_string(dof) +
                                  " outside a system of " + std::to_string(n_dofs) +
                                  " dofs, allowed [0, " + std::to_string(n_dofs) + ")");
    dofs.push_back(dof);
  };
  for (const Tip& tip : m_tips)
    for (const int dof : tip.node.dofs)
      add(dof);
  for (const auto& [id, three] : m_casing_dofs)
    for (const int dof : three)
      add(dof);
  return dofs;
}

} // namespace rsi
