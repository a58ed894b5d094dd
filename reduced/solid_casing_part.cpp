#include "solid_casing_part.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "component_integration_error.hpp"
#include "message_number.hpp"

namespace rsi {

namespace {
const std::string kWhere = "SolidCasingPart: ";
} // namespace

SolidCasingPart::SolidCasingPart(const RigidCasing& tips, int n_boundary, double dt,
                                 CasingSurface surface,
                                 std::map<int, std::array<int, 3>> casing_dofs,
                                 const CasingBasis& basis, SolidCasingLoad load)
    : m_tips(tips, n_boundary, dt)
    , m_dt(dt)
    , m_omega(tips.omega())
    , m_nc(tips.n_contacts())
    , m_m(basis.size())
    , m_surface(std::move(surface))
    , m_casing_dofs(std::move(casing_dofs))
    , m_phi(basis.shapes)
    , m_omega_squared(basis.omega_squared) {
  if (tips.gap_law().kind != CasingGapKind::constant || tips.gap_law().g0 != 0.0 ||
      tips.sliding_omega() != tips.omega())
    throw std::invalid_argument(kWhere + "the tips' RigidCasing must have a constant zero gap "
                                         "and sliding omega = omega (the casing's own geometry "
                                         "gives the gap)");
  if (m_m < 1 || m_omega_squared.size() != m_m || !m_phi.allFinite() ||
      !m_omega_squared.allFinite())
    throw std::invalid_argument(kWhere + "the casing basis has " + std::to_string(m_m) +
                                " columns and " + std::to_string(m_omega_squared.size()) +
                                " eigenvalues, allowed >= 1 finite columns with one each");
  const auto rows = static_cast<int>(m_phi.rows());
  for (const auto& [node, dofs] : m_casing_dofs)
    for (int d : dofs)
      if (d < -1 || d >= rows)
        throw std::invalid_argument(kWhere + "casing node " + std::to_string(node) + ": dof " +
                                    std::to_string(d) + " outside the basis' " +
                                    std::to_string(rows) + " rows (allowed -1 for clamped)");
  if (load.force.size() != 0) {
    if (load.force.size() != rows || !load.force.allFinite())
      throw std::invalid_argument(kWhere + "load: " + std::to_string(load.force.size()) +
                                  " entries, allowed " + std::to_string(rows) +
                                  " finite entries (or none)");
    if (!(load.duration >= 0.0) || !std::isfinite(load.duration))
      throw std::invalid_argument(kWhere + "load duration = " + message_number(load.duration) +
                                  " s, allowed a finite value >= 0");
    m_force_modal = m_phi.transpose() * load.force;
    m_duration = load.duration;
  }
  m_p = m_p_prev = m_p_trial = m_p_next = Eigen::VectorXd::Zero(m_m);
  m_rho.assign(static_cast<size_t>(m_nc), 0.0);
  m_face.assign(static_cast<size_t>(m_nc), -1);
  m_h = Eigen::MatrixXd::Zero(3 * m_nc, m_m);
  m_pred.setZero(3 * m_nc);
  m_gap.setZero(m_nc);
  locate(0.0);
}

double SolidCasingPart::load_share(long n) const {
  // The full-order run's rule (problem.hpp, ProblemForcing): the load on
  // every step with t_n <= duration, a millionth of a step allowed.
  if (m_force_modal.size() == 0) return 0.0;
  return static_cast<double>(n) * m_dt <= m_duration + 1e-6 * m_dt ? 1.0 : 0.0;
}

Eigen::Matrix3d SolidCasingPart::casing_directions(int c, double t) const {
  const double theta = m_tips.tips().polar_angle(c) + m_omega * t;
  Eigen::Matrix3d d;
  d << std::cos(theta), std::sin(theta), 0.0, //
      0.0, 0.0, -1.0,                         //
      std::sin(theta), -std::cos(theta), 0.0;
  return d;
}

void SolidCasingPart::locate(double t) {
  if (t == m_located_t) return;
  const RigidCasing& tips = m_tips.tips();
  m_h.setZero();
  for (int c = 0; c < m_nc; ++c) {
    const double theta = tips.polar_angle(c) + m_omega * t;
    const std::optional<SurfacePoint> point =
        m_surface.locate(theta, tips.axial_coordinate(c), m_face[static_cast<size_t>(c)]);
    if (!point)
      throw ComponentIntegrationError(kWhere + "t = " + message_number(t) + " s: tip " +
                                      std::to_string(c + 1) + " (height " +
                                      message_number(tips.axial_coordinate(c)) +
                                      ") is above no face of the casing's contact surface");
    m_rho[static_cast<size_t>(c)] = point->rho;
    m_face[static_cast<size_t>(c)] = point->face;
    const std::array<double, 6> n = triangle6_shape_functions(point->xi, point->eta);
    const Eigen::Matrix3d d = casing_directions(c, t);
    const std::array<int, 6>& nodes = m_surface.face_nodes(point->face);
    for (int i = 0; i < 6; ++i) {
      const auto it = m_casing_dofs.find(nodes[static_cast<size_t>(i)]);
      if (it == m_casing_dofs.end()) continue; // clamped
      for (int a = 0; a < 3; ++a) {
        const int k = it->second[static_cast<size_t>(a)];
        if (k < 0) continue;
        // Row k of Phi along direction a, weighted N_i, into the three rows.
        m_h.middleRows(3 * c, 3).noalias() += (n[static_cast<size_t>(i)] * d.col(a)) * m_phi.row(k);
      }
    }
  }
  m_located_t = t;
}

void SolidCasingPart::start() {
  m_n = 0;
  m_p.setZero();
  m_p_prev.setZero();
  if (m_force_modal.size() > 0) m_p_prev = 0.5 * m_dt * m_dt * load_share(0) * m_force_modal;
  m_p_trial = m_p;
  m_external_work = m_contact_work = 0.0;
}

void SolidCasingPart::predict(const Eigen::VectorXd& u_trial, const Eigen::VectorXd& u_now,
                              double t_n, double t_next) {
  m_tips.predict(u_trial, u_now, t_n, t_next);
  m_held = !(t_next > t_n);
  if (!m_held) {
    m_p_trial = 2.0 * m_p - m_p_prev - m_dt * m_dt * m_omega_squared.cwiseProduct(m_p);
    if (m_force_modal.size() > 0)
      m_p_trial.noalias() += (m_dt * m_dt * load_share(m_n)) * m_force_modal;
  } else {
    m_p_trial = m_p; // the contact at t = 0: the casing held where it is
  }
  locate(t_next);
  m_pred = m_tips.prediction();
  const Eigen::VectorXd dp = m_p_trial - m_p;
  for (int c = 0; c < m_nc; ++c) {
    const auto h = m_h.middleRows(3 * c, 3);
    m_pred(3 * c) +=
        m_rho[static_cast<size_t>(c)] - m_tips.tips().radius(c) + h.row(0).dot(m_p_trial);
    m_pred(3 * c + 1) += h.row(1).dot(dp);
    m_pred(3 * c + 2) += h.row(2).dot(dp);
  }
}

void SolidCasingPart::add_flexibility(Eigen::MatrixXd& w) const {
  if (m_held) return;
  // The lower triangle by a rank update (half the flops of H H^T), mirrored.
  w.selfadjointView<Eigen::Lower>().rankUpdate(m_h, m_dt * m_dt);
  w.triangularView<Eigen::StrictlyUpper>() = w.transpose().eval();
}

void SolidCasingPart::correct(const Eigen::VectorXd& lambda) {
  if (m_held) return;
  m_p_next = m_p_trial;
  if (lambda.any()) m_p_next.noalias() += (m_dt * m_dt) * (m_h.transpose() * lambda);
  const Eigen::VectorXd increment = m_p_next - m_p_prev;
  if (m_force_modal.size() > 0)
    m_external_work += 0.5 * load_share(m_n) * m_force_modal.dot(increment);
  if (lambda.any()) m_contact_work += 0.5 * lambda.dot(m_h * increment);
}

void SolidCasingPart::advance() {
  m_p_prev = m_p;
  m_p = m_p_next;
  ++m_n;
}

void SolidCasingPart::gaps_at(const Eigen::VectorXd& u_boundary, double t) {
  m_tips.gaps_at(u_boundary, t);
  locate(t);
  m_gap = m_tips.gap();
  for (int c = 0; c < m_nc; ++c)
    m_gap(c) += m_rho[static_cast<size_t>(c)] - m_tips.tips().radius(c) + m_h.row(3 * c).dot(m_p);
}

double SolidCasingPart::rest_gap(int c, double t) const {
  if (t == m_located_t) return m_rho.at(static_cast<size_t>(c)) - m_tips.tips().radius(c);
  const RigidCasing& tips = m_tips.tips();
  const std::optional<SurfacePoint> point =
      m_surface.locate(tips.polar_angle(c) + m_omega * t, tips.axial_coordinate(c));
  if (!point)
    throw ComponentIntegrationError(kWhere + "t = " + message_number(t) + " s: tip " +
                                    std::to_string(c + 1) + " is above no face of the casing");
  return point->rho - tips.radius(c);
}

double SolidCasingPart::omega_max() const {
  return std::sqrt(m_omega_squared.maxCoeff());
}

double SolidCasingPart::energy() const {
  return 0.5 * ((m_p - m_p_prev) / m_dt).squaredNorm() +
         0.5 * m_p_prev.dot(m_omega_squared.cwiseProduct(m_p));
}

} // namespace rsi
