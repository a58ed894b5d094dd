#include "rigid_casing_part.hpp"

#include <stdexcept>
#include <string>

namespace rsi {

namespace {
const std::string kWhere = "ComponentIntegrator: ";
} // namespace

RigidCasingPart::RigidCasingPart(const RigidCasing& casing, int n_boundary, double dt)
    : m_casing(casing)
    , m_dt(dt)
    , m_nc(casing.n_contacts()) {
  // B_B: the frame rows of each contact node on its ux, uy, uz.
  m_b = Eigen::MatrixXd::Zero(3 * m_nc, n_boundary);
  for (int c = 0; c < m_nc; ++c)
    for (int a = 0; a < 3; ++a) {
      const int k = casing.boundary_index(c)[a];
      if (k >= n_boundary)
        throw std::invalid_argument(kWhere + "contact node " + std::to_string(c) +
                                    ": boundary index " + std::to_string(k) + " >= the basis' " +
                                    std::to_string(n_boundary) + " boundary coordinates");
      m_b.block(3 * c, k, 3, 1) = casing.frame(c).col(a);
    }
  m_pred.setZero(3 * m_nc);
  m_gap.setZero(m_nc);
}

Eigen::Vector3d RigidCasingPart::node_of(const Eigen::VectorXd& u_boundary, int c) const {
  const std::array<int, 3>& k = m_casing.boundary_index(c);
  return Eigen::Vector3d(u_boundary(k[0]), u_boundary(k[1]), u_boundary(k[2]));
}

void RigidCasingPart::gaps_at(const Eigen::VectorXd& u_boundary, double t) {
  for (int c = 0; c < m_nc; ++c)
    m_gap(c) = m_casing.imposed_gap(c, t) + m_casing.frame(c).row(0).dot(node_of(u_boundary, c));
}

void RigidCasingPart::predict(const Eigen::VectorXd& u_trial, const Eigen::VectorXd& u_now,
                              double /*t_n*/, double t_next) {
  // [g~; s~] per contact: g(t_{n+1}) + e_n.u~, [e_t1; e_t2](u~ - u_n) + (0, r Omega dt).
  for (int c = 0; c < m_nc; ++c) {
    const Eigen::Matrix3d& f = m_casing.frame(c);
    const Eigen::Vector3d now = node_of(u_now, c);
    const Eigen::Vector3d y = f * (node_of(u_trial, c) - now);
    m_pred(3 * c) = y(0) + f.row(0).dot(now) + m_casing.imposed_gap(c, t_next);
    m_pred(3 * c + 1) = y(1);
    m_pred(3 * c + 2) = y(2) + m_casing.casing_slip(c, m_dt);
  }
}

} // namespace rsi
