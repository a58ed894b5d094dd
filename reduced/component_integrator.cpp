#include "component_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "critical_step.hpp"
#include "message_number.hpp"
#include "reduced_coulomb_certificate.hpp"

namespace rsi {

namespace {

const std::string kWhere = "ComponentIntegrator: ";
/// What to change when the reduced mass fails (issue 13, class 8): a
/// consistent mass may be singular (Rotor 37's C3D15), T^T M T with it.
const std::string kMassRemedy =
    "; set component.mass to \"lumped\" (HRZ, positive definite) or keep fewer modes";

Eigen::MatrixXd block(const Eigen::MatrixXd& a, const std::vector<int>& rows,
                      const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j)
      out(i, j) = a(rows[i], cols[j]);
  return out;
}

Eigen::VectorXd take(const Eigen::VectorXd& a, const std::vector<int>& rows) {
  Eigen::VectorXd out(rows.size());
  for (size_t i = 0; i < rows.size(); ++i)
    out(i) = a(rows[i]);
  return out;
}

} // namespace

ComponentIntegrator::ComponentIntegrator(const ReducedBasis& basis, const RigidCasing& casing,
                                         const ComponentIntegratorOptions& options)
    : m_casing(casing)
    , m_solver(2, options.mu, options.coulomb) {
  if (!(options.dt > 0.0) || !std::isfinite(options.dt))
    throw std::invalid_argument(kWhere + "dt = " + message_number(options.dt) +
                                ", allowed a finite value > 0");
  m_dt = options.dt;
  m_mu = options.mu;
  m_subset = options.closing_subset;
  m_r = basis.n_reduced();
  m_massless = basis.massless_boundary;
  m_boundary = basis.boundary_position;
  m_nb = static_cast<int>(m_boundary.size());
  std::vector<char> is_b(m_r, 0);
  for (int b : m_boundary) {
    if (b < 0 || b >= m_r)
      throw std::invalid_argument(kWhere + "boundary position " + std::to_string(b) +
                                  " outside the basis' " + std::to_string(m_r) + " coordinates");
    is_b[b] = 1;
  }
  for (int i = 0; i < m_r; ++i)
    if (!is_b[i]) m_interior.push_back(i);
  m_ni = static_cast<int>(m_interior.size());
  m_nc = casing.n_contacts();
  if (m_nc < 1)
    throw std::invalid_argument(kWhere + "the casing has no contact node, allowed >= 1");
  if (options.damping.size() != 0) {
    if (options.damping.size() != m_r || !options.damping.allFinite() ||
        options.damping.minCoeff() < 0.0)
      throw std::invalid_argument(kWhere + "damping: " + std::to_string(options.damping.size()) +
                                  " entries, allowed " + std::to_string(m_r) +
                                  " finite entries >= 0 (or none)");
    if (options.damping.any()) m_c = options.damping;
  }
  const auto check_force = [&](const Eigen::VectorXd& f, const char* name) {
    if (f.size() != 0 && (f.size() != m_r || !f.allFinite()))
      throw std::invalid_argument(kWhere + name + ": " + std::to_string(f.size()) +
                                  " entries, allowed " + std::to_string(m_r) +
                                  " finite entries (or none)");
  };
  check_force(options.force_constant, "force_constant");
  check_force(options.force_harmonic, "force_harmonic");
  if (!std::isfinite(options.force_frequency) || !std::isfinite(options.force_phase))
    throw std::invalid_argument(
        kWhere + "force_frequency = " + message_number(options.force_frequency) +
        ", force_phase = " + message_number(options.force_phase) + ", allowed finite values");
  m_force = options.force_constant.size() != 0 || options.force_harmonic.size() != 0;
  if (m_force) {
    m_f0 = options.force_constant.size() ? options.force_constant : Eigen::VectorXd::Zero(m_r);
    m_f1 = options.force_harmonic.size() ? options.force_harmonic : Eigen::VectorXd::Zero(m_r);
    m_omega_f = options.force_frequency;
    m_phi_f = options.force_phase;
  }
  m_k = basis.stiffness;
  m_m = basis.mass;

  // B_B: the frame rows of each contact node on its ux, uy, uz.
  m_b = Eigen::MatrixXd::Zero(3 * m_nc, m_nb);
  for (int c = 0; c < m_nc; ++c)
    for (int a = 0; a < 3; ++a) {
      const int k = casing.boundary_index(c)[a];
      if (k >= m_nb)
        throw std::invalid_argument(kWhere + "contact node " + std::to_string(c) +
                                    ": boundary index " + std::to_string(k) + " >= the basis' " +
                                    std::to_string(m_nb) + " boundary coordinates");
      m_b.block(3 * c, k, 3, 1) = casing.frame(c).col(a);
    }

  m_omega_max = reduced_omega_max(basis);
  if (!(m_omega_max > 0.0) || !std::isfinite(m_omega_max))
    throw ComponentIntegrationError(kWhere + "omega_max of the reduced model is " +
                                    message_number(m_omega_max) + ", allowed a finite value > 0");
  if (m_dt >= critical_dt() && !options.force_step)
    throw ComponentIntegrationError(
        kWhere + "dt = " + message_number(m_dt) +
        " s is at or above the critical step 2/omega_max = " + message_number(critical_dt()) +
        " s of the " + basis.method + " model (omega_max = " + message_number(m_omega_max) +
        " rad/s" + (m_massless ? ", massless boundary condensed" : "") +
        "); allowed dt < critical step unless forced");

  if (!m_massless) {
    Eigen::MatrixXd a = m_m;
    if (m_c.size()) a.diagonal() += 0.5 * m_dt * m_c;
    const Eigen::LLT<Eigen::MatrixXd> llt(a);
    if (llt.info() != Eigen::Success)
      throw ComponentIntegrationError(kWhere + "M^ + dt/2 C^ of the " + basis.method +
                                      " model is not positive definite (Cholesky failed)" +
                                      kMassRemedy);
    m_p = (m_dt * m_dt) * llt.solve(m_k);
    if (m_c.size()) m_d = m_dt * llt.solve(Eigen::MatrixXd(m_c.asDiagonal()));
    Eigen::MatrixXd bt = Eigen::MatrixXd::Zero(m_r, 3 * m_nc);
    for (int k = 0; k < m_nb; ++k)
      bt.row(m_boundary[k]) = m_b.col(k).transpose();
    m_g = (m_dt * m_dt) * llt.solve(bt);
    m_w = bt.transpose() * m_g;
    if (m_force) {
      m_gf0 = (m_dt * m_dt) * llt.solve(m_f0);
      m_gf1 = (m_dt * m_dt) * llt.solve(m_f1);
    }
  } else {
    const Eigen::MatrixXd mbb = block(m_m, m_boundary, m_boundary);
    const Eigen::MatrixXd mbi = block(m_m, m_boundary, m_interior);
    if (mbb.cwiseAbs().maxCoeff() != 0.0 || (m_ni && mbi.cwiseAbs().maxCoeff() != 0.0))
      throw std::invalid_argument(kWhere + "the basis is flagged massless_boundary but M^_BB or "
                                           "M^_BI is not exactly zero");
    if (m_c.size() && take(m_c, m_boundary).any())
      throw std::invalid_argument(kWhere + "damping on a massless boundary coordinate, allowed 0");
    const Eigen::LLT<Eigen::MatrixXd> kbb(block(m_k, m_boundary, m_boundary));
    if (kbb.info() != Eigen::Success)
      throw ComponentIntegrationError(kWhere + "K^_BB of the massless boundary is not positive "
                                               "definite (static condensation failed); use a "
                                               "method with a massed boundary (cb, ccm)");
    const Eigen::MatrixXd kbi = block(m_k, m_boundary, m_interior);
    m_z = -kbb.solve(kbi);
    m_g = kbb.solve(Eigen::MatrixXd(m_b.transpose()));
    m_w = m_b * m_g;
    Eigen::MatrixXd ai = block(m_m, m_interior, m_interior);
    if (m_c.size()) ai.diagonal() += 0.5 * m_dt * take(m_c, m_interior);
    const Eigen::LLT<Eigen::MatrixXd> llt(ai);
    if (llt.info() != Eigen::Success)
      throw ComponentIntegrationError(kWhere +
                                      "M^_II + dt/2 C^_I is not positive definite "
                                      "(Cholesky failed)" +
                                      kMassRemedy);
    // With u_B^n = Z q_I^n + S B_B^T lambda_n (the balance (B)), the force of
    // (I) is K^_II q + K^_IB u_B = K_c q + K^_IB S B_B^T lambda_n, K_c the
    // condensed stiffness K^_II - K^_IB S K^_BI (Omega_1^2 for MacNeal): a
    // contact-free step applies K_c and Z only (2 (psi^2 + psi n_B) flops),
    // the contact adds the columns of the contacts that carry a force.
    Eigen::MatrixXd kc = block(m_k, m_interior, m_interior) + kbi.transpose() * m_z;
    kc = 0.5 * (kc + kc.transpose()).eval();
    m_p = (m_dt * m_dt) * llt.solve(kc);
    m_pb = (m_dt * m_dt) * llt.solve(Eigen::MatrixXd(kbi.transpose() * m_g));
    if (m_force) {
      // (B): u_B = Z q_I + S B_B^T lambda + S f_B; (I) sees f_I - K^_IB S f_B.
      m_sf0 = kbb.solve(take(m_f0, m_boundary));
      m_sf1 = kbb.solve(take(m_f1, m_boundary));
      m_gf0 = (m_dt * m_dt) *
              llt.solve(Eigen::VectorXd(take(m_f0, m_interior) - kbi.transpose() * m_sf0));
      m_gf1 = (m_dt * m_dt) *
              llt.solve(Eigen::VectorXd(take(m_f1, m_interior) - kbi.transpose() * m_sf1));
    }
    if (m_c.size()) {
      m_ci = take(m_c, m_interior);
      const Eigen::MatrixXd mii = block(m_m, m_interior, m_interior);
      if (Eigen::MatrixXd(mii.diagonal().asDiagonal()) == mii) {
        // Diagonal M^_II (MacNeal: I): dt A^-1 C^ is the diagonal dt c/(m + dt/2 c).
        m_d_diagonal = (m_dt * m_ci).cwiseQuotient(mii.diagonal() + 0.5 * m_dt * m_ci);
      } else {
        m_d = m_dt * llt.solve(Eigen::MatrixXd(m_ci.asDiagonal()));
      }
    }
  }
  m_w = 0.5 * (m_w + m_w.transpose()).eval();
  m_pred.setZero(3 * m_nc);
  m_gap.setZero(m_nc);
  m_lambda.setZero(3 * m_nc);
  m_lambda_next.setZero(3 * m_nc);
  m_state.assign(m_nc, ReducedContactState::open);
}

Eigen::VectorXd ComponentIntegrator::external_force(double t) const {
  if (!m_force) return Eigen::VectorXd::Zero(m_r);
  return m_f0 + std::cos(m_omega_f * t + m_phi_f) * m_f1;
}

Eigen::VectorXd ComponentIntegrator::boundary_of(const Eigen::VectorXd& x) const {
  return take(x, m_boundary);
}

Eigen::Vector3d ComponentIntegrator::node_of(const Eigen::VectorXd& u_boundary, int c) const {
  const std::array<int, 3>& k = m_casing.boundary_index(c);
  return Eigen::Vector3d(u_boundary(k[0]), u_boundary(k[1]), u_boundary(k[2]));
}

void ComponentIntegrator::gaps_at(const Eigen::VectorXd& u_boundary, double t) {
  // B_B is 3 x 3 blocks (the frames) on each node's ux, uy, uz: applied block by block.
  for (int c = 0; c < m_nc; ++c)
    m_gap(c) = m_casing.imposed_gap(c, t) + m_casing.frame(c).row(0).dot(node_of(u_boundary, c));
}

void ComponentIntegrator::predict_contact(const Eigen::VectorXd& u_trial,
                                          const Eigen::VectorXd& u_now, double t_next) {
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

void ComponentIntegrator::solve_contact(StepReport& report) {
  const std::vector<ReducedContactState> before = m_state;
  bool closing = false;
  for (int c = 0; c < m_nc; ++c)
    closing = closing || m_pred(3 * c) < 0.0;
  if (!closing) {
    // lambda = 0 solves the step's problem: g = g~ >= 0 for every contact.
    m_lambda_next.setZero();
    m_state.assign(m_nc, ReducedContactState::open);
  } else {
    // The solve on the contacts that may carry a force: A = the closing ones
    // (g~ < 0) and those that carried a force at the previous step (fewer
    // re-solves), grown by every contact that the others' forces close
    // (g~_c + W_cA lambda_A < 0), until none does. A lambda that vanishes off
    // A, with those gaps >= 0, satisfies the whole problem's law (open
    // contacts: lambda_c = 0, g_c >= 0); the certificate below checks it on
    // the whole W. Most steps close few of the contacts: the Gauss-Seidel
    // works on 3 |A| rows instead of 3 nc.
    std::vector<int> active;
    std::vector<char> in(m_nc, 0);
    for (int c = 0; c < m_nc; ++c)
      if (m_pred(3 * c) < 0.0 || m_lambda_next(3 * c) > 0.0 || !m_subset) {
        active.push_back(c);
        in[c] = 1;
      }
    for (;;) {
      const int na = static_cast<int>(active.size());
      m_wa.resize(3 * na, 3 * na);
      m_pa.resize(3 * na);
      m_la.resize(3 * na);
      for (int i = 0; i < na; ++i) {
        m_pa.segment(3 * i, 3) = m_pred.segment(3 * active[i], 3);
        m_la.segment(3 * i, 3) = m_lambda_next.segment(3 * active[i], 3); // warm start
        for (int j = 0; j < na; ++j)
          m_wa.block(3 * i, 3 * j, 3, 3) = m_w.block(3 * active[i], 3 * active[j], 3, 3);
      }
      const CoulombGaussSeidelReport r = m_solver.solve(m_wa, m_pa, m_la);
      m_sweeps += r.sweeps;
      if (!r.converged())
        throw ComponentIntegrationError(kWhere + "step " + std::to_string(m_n + 1) +
                                        " (t = " + message_number((m_n + 1) * m_dt) +
                                        " s): contact solve failed: " + r.message +
                                        "; use a smaller rubbing.step_safety or "
                                        "rubbing.friction_coefficient");
      m_lambda_next.setZero();
      m_state.assign(m_nc, ReducedContactState::open);
      for (int i = 0; i < na; ++i) {
        m_lambda_next.segment(3 * active[i], 3) = m_la.segment(3 * i, 3);
        m_state[active[i]] = m_solver.states()[i];
      }
      bool grown = false;
      for (int c = 0; c < m_nc; ++c) {
        if (in[c]) continue;
        double g = m_pred(3 * c);
        for (int i = 0; i < na; ++i)
          g += m_w.row(3 * c).segment(3 * active[i], 3).dot(m_la.segment(3 * i, 3));
        if (g < 0.0) {
          active.push_back(c);
          in[c] = 1;
          grown = true;
        }
      }
      if (!grown) break;
    }
    const ReducedCoulombCertificate cert =
        reduced_coulomb_certificate(m_w, m_pred, 2, m_mu, m_lambda_next, m_state);
    report.max_penetration = cert.max_penetration;
    report.min_lambda = cert.min_normal;
    report.max_complementarity = cert.max_complementarity;
    report.max_cone_violation = cert.max_cone_violation;
    // Scaled: stick residual per the largest predicted slip, slip residual
    // per the largest friction bound mu lambda_n (0 when the step has none).
    double slip_scale = 0.0, force_scale = 0.0;
    for (int c = 0; c < m_nc; ++c) {
      slip_scale = std::max(slip_scale, m_pred.segment(3 * c + 1, 2).norm());
      force_scale = std::max(force_scale, m_mu * m_lambda_next(3 * c));
    }
    const double stick = slip_scale > 0.0 ? cert.max_stick_residual / slip_scale : 0.0;
    const double slip = force_scale > 0.0 ? cert.max_slip_residual / force_scale : 0.0;
    report.max_stick_slip_residual =
        std::max({stick, slip, force_scale > 0.0 ? cert.max_open_residual / force_scale : 0.0});
    report.n_stick = cert.n_stick;
    report.n_slip = cert.n_slip;
  }
  report.n_active = report.n_stick + report.n_slip;
  for (int c = 0; c < m_nc; ++c)
    if (m_state[c] != before[c]) ++report.stick_slip_transitions;
}

void ComponentIntegrator::start() {
  start(Eigen::VectorXd::Zero(m_r));
}

void ComponentIntegrator::start(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  if (q0.size() != m_r || !q0.allFinite())
    throw std::invalid_argument(kWhere + "start: q0 has " + std::to_string(q0.size()) +
                                " entries, allowed " + std::to_string(m_r) + " finite entries");
  m_n = 0;
  m_contact_work = 0.0;
  m_damping_work = 0.0;
  m_external_work = 0.0;
  m_sweeps = 0;
  m_lambda.setZero();
  m_lambda_next.setZero();
  m_state.assign(m_nc, ReducedContactState::open);
  const double h2 = 0.5 * m_dt * m_dt;
  if (!m_massless) {
    // At rest: x_{-1} = x_0 - dt^2/2 M^-1 K^ x_0, so (x_1 - x_{-1})/(2 dt) = 0 without contact.
    // With a force: x_{-1} = x_0 - dt^2/2 M^-1 (K^ x_0 - f(0)), at rest under the load of t = 0.
    m_x = q0;
    const Eigen::LLT<Eigen::MatrixXd> llt(m_m);
    if (!m_force)
      m_xp = m_x - h2 * llt.solve(m_k * m_x);
    else
      m_xp = m_x - h2 * llt.solve(Eigen::VectorXd(m_k * m_x - m_f0 - std::cos(m_phi_f) * m_f1));
    gaps_at(boundary_of(m_x), 0.0);
  } else {
    // The boundary at rest before t = 0: u_B^{-1} = -S K^_BI q_I^0 (contact free);
    // at t = 0 the contact is solved on the condensed boundary, lambda_0 with u_B^0.
    // With a force, the load of t = 0 acts on the boundary from t = 0 on:
    // u~_B^0 = u_B^{-1} + S f_B(0), its slip relative to u_B^{-1}.
    m_x = take(Eigen::VectorXd(q0), m_interior);
    m_up = m_z * m_x;
    const double c0 = std::cos(m_phi_f);
    if (!m_force)
      predict_contact(m_up, m_up, 0.0);
    else
      predict_contact(Eigen::VectorXd(m_up + m_sf0 + c0 * m_sf1), m_up, 0.0);
    // Slip at t = 0 relative to the structure at rest: the casing's own
    // increment over the step before (the r Omega dt already in m_pred).
    StepReport unused;
    solve_contact(unused);
    m_lambda = m_lambda_next;
    m_u = m_up + m_g * m_lambda;
    if (m_force) m_u += m_sf0 + c0 * m_sf1;
    const Eigen::MatrixXd mii = block(m_m, m_interior, m_interior);
    const Eigen::LLT<Eigen::MatrixXd> llt(mii);
    Eigen::VectorXd force =
        block(m_k, m_interior, m_interior) * m_x + block(m_k, m_interior, m_boundary) * m_u;
    if (m_force) force -= take(Eigen::VectorXd(m_f0 + c0 * m_f1), m_interior);
    m_xp = m_x - h2 * llt.solve(force);
    gaps_at(m_u, 0.0);
  }
  m_initial_energy = energy();
}

StepReport ComponentIntegrator::step() {
  StepReport report;
  const double t_next = (m_n + 1) * m_dt;
  if (!m_massless) {
    m_xn = 2.0 * m_x - m_xp;
    m_xn.noalias() -= m_p * m_x;
    if (m_d.size()) m_xn.noalias() -= m_d * (m_x - m_xp);
    double cn = 0.0; // cos(omega_f t_n + phi_f)
    if (m_force) {
      cn = std::cos(m_omega_f * time() + m_phi_f);
      m_xn += m_gf0 + cn * m_gf1;
    }
    const Eigen::VectorXd ut = boundary_of(m_xn);
    predict_contact(ut, boundary_of(m_x), t_next);
    solve_contact(report);
    m_lambda = m_lambda_next; // lambda_n of (*), enforcing the contact at x_{n+1}
    if (m_lambda.any()) m_xn.noalias() += m_g * m_lambda;
    const Eigen::VectorXd dx = m_xn - m_xp;
    if (m_lambda.any()) m_contact_work += 0.5 * m_lambda.dot(m_b * boundary_of(dx));
    if (m_force) m_external_work += 0.5 * (m_f0.dot(dx) + cn * m_f1.dot(dx));
    if (m_c.size()) m_damping_work += dx.dot(m_c.cwiseProduct(dx)) / (4.0 * m_dt);
    m_xp.swap(m_x);
    m_x.swap(m_xn);
    gaps_at(boundary_of(m_x), t_next);
  } else {
    // (I): q_I^{n+1} with u_B^n in balance with lambda_n.
    m_xn = 2.0 * m_x - m_xp;
    m_xn.noalias() -= m_p * m_x;
    for (int c = 0; c < m_nc; ++c)
      if (m_lambda.segment(3 * c, 3).any())
        m_xn.noalias() -= m_pb.middleCols(3 * c, 3) * m_lambda.segment(3 * c, 3);
    if (m_d.size()) m_xn.noalias() -= m_d * (m_x - m_xp);
    if (m_d_diagonal.size()) m_xn -= m_d_diagonal.cwiseProduct(m_x - m_xp);
    double cn = 0.0; // cos(omega_f t_n + phi_f)
    if (m_force) {
      cn = std::cos(m_omega_f * time() + m_phi_f);
      m_xn += m_gf0 + cn * m_gf1;
    }
    // (B) at n+1 with the contact on the condensed boundary.
    m_un.noalias() = m_z * m_xn;
    if (m_force) m_un += m_sf0 + std::cos(m_omega_f * t_next + m_phi_f) * m_sf1;
    predict_contact(m_un, m_u, t_next);
    solve_contact(report);
    if (m_lambda_next.any()) m_un.noalias() += m_g * m_lambda_next;
    // Work of (*) at time n: lambda_n . B (x_{n+1} - x_{n-1}) / 2.
    if (m_lambda.any()) m_contact_work += 0.5 * m_lambda.dot(m_b * (m_un - m_up));
    if (m_force) {
      // f(t_n)^T (x_{n+1} - x_{n-1})/2 over the boundary and the interior rows.
      double w = 0.0;
      for (int k = 0; k < m_nb; ++k)
        w += (m_f0(m_boundary[k]) + cn * m_f1(m_boundary[k])) * (m_un(k) - m_up(k));
      for (int k = 0; k < m_ni; ++k)
        w += (m_f0(m_interior[k]) + cn * m_f1(m_interior[k])) * (m_xn(k) - m_xp(k));
      m_external_work += 0.5 * w;
    }
    if (m_c.size()) {
      m_work_b = m_xn - m_xp;
      m_damping_work += m_work_b.dot(m_ci.cwiseProduct(m_work_b)) / (4.0 * m_dt);
    }
    m_lambda = m_lambda_next;
    m_xp.swap(m_x);
    m_x.swap(m_xn);
    m_up.swap(m_u);
    m_u.swap(m_un);
    gaps_at(m_u, t_next);
  }
  ++m_n;
  if (!m_x.allFinite() || !m_gap.allFinite())
    throw ComponentIntegrationError(kWhere + "step " + std::to_string(m_n) +
                                    " (t = " + message_number(time()) +
                                    " s): the state is not finite (blow-up); use a smaller "
                                    "rubbing.step_safety, without --force");
  return report;
}

Eigen::VectorXd ComponentIntegrator::q() const {
  if (!m_massless) return m_x;
  Eigen::VectorXd x(m_r);
  for (int k = 0; k < m_nb; ++k)
    x(m_boundary[k]) = m_u(k);
  for (int k = 0; k < m_ni; ++k)
    x(m_interior[k]) = m_x(k);
  return x;
}

double ComponentIntegrator::response(const Eigen::Ref<const Eigen::RowVectorXd>& row) const {
  if (row.size() != m_r)
    throw std::invalid_argument(kWhere + "response: the row has " + std::to_string(row.size()) +
                                " entries, allowed " + std::to_string(m_r));
  return row.dot(q());
}

void ComponentIntegrator::state_in_basis(Eigen::VectorXd& x, Eigen::VectorXd& xp) const {
  if (!m_massless) {
    x = m_x;
    xp = m_xp;
    return;
  }
  x.resize(m_r);
  xp.resize(m_r);
  for (int k = 0; k < m_nb; ++k) {
    x(m_boundary[k]) = m_u(k);
    xp(m_boundary[k]) = m_up(k);
  }
  for (int k = 0; k < m_ni; ++k) {
    x(m_interior[k]) = m_x(k);
    xp(m_interior[k]) = m_xp(k);
  }
}

double ComponentIntegrator::energy() const {
  // E_{n-1/2} = 1/2 v^T M^ v + 1/2 x_{n-1}^T K^ x_n, v = (x_n - x_{n-1})/dt.
  Eigen::VectorXd x, xp;
  state_in_basis(x, xp);
  const Eigen::VectorXd v = (x - xp) / m_dt;
  return 0.5 * v.dot(m_m * v) + 0.5 * xp.dot(m_k * x);
}

} // namespace rsi
