#include "reduced_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "full_casing_part.hpp"
#include "modal_casing_part.hpp"

namespace rsi {

namespace {

bool finite_non_negative(double x) {
  return std::isfinite(x) && x >= 0.0;
}

// What to change, for the messages of ReducedIntegrationError (issue 13,
// class 8). The case's M is positive definite (checked when it loads) and
// so is T^T M T for a basis T of full rank: a mass that fails here is a
// basis that lost its rank in rounding.
const std::string kReducedMassRemedy =
    "; the case's M passed its check when it loaded, so the basis T lost its rank in rounding: "
    "keep fewer modes (--modes, or the campaign's modes) or use another --method";
const std::string kStepRemedy =
    "; use a smaller step (time.step, or --time-step and the campaign's time_step of a reduced "
    "run)";
const std::string kContactRemedy =
    "; change operating_point.friction_coefficient (friction that cancels the contacts' normal "
    "flexibility) or use a smaller step (time.step, --time-step)";

} // namespace

ReducedIntegrator::ReducedIntegrator(const ReducedBasis& basis, const Casing& casing, double dt,
                                     const ReducedTipContact& contact,
                                     const ReducedDamping& damping,
                                     const CasingBasis* casing_basis,
                                     const ReducedModes* disk_modes)
    : m_kq(basis.stiffness)
    , m_mq(basis.mass)
    , m_dt(dt)
    , m_mu(contact.friction_coefficient())
    , m_contact(contact)
    , m_law(contact.friction_law())
    , m_coulomb(1, contact.friction_coefficient()) {
  const Eigen::Index r = m_kq.rows();
  if (damping.bladed_disk.size() != 0) {
    if (damping.bladed_disk.size() != r ||
        !damping.bladed_disk.unaryExpr(&finite_non_negative).all())
      throw std::invalid_argument("ReducedIntegrator: the bladed-disk damping must have " +
                                  std::to_string(r) + " finite entries >= 0");
    m_q_damped = (damping.bladed_disk.array() != 0.0).any();
  }
  if (damping.bladed_disk_matrix.size() != 0) {
    if (damping.bladed_disk.size() != 0 || damping.bladed_disk_matrix.rows() != r ||
        damping.bladed_disk_matrix.cols() != r || !damping.bladed_disk_matrix.allFinite())
      throw std::invalid_argument("ReducedIntegrator: a full bladed-disk damping must be " +
                                  std::to_string(r) + " x " + std::to_string(r) +
                                  ", finite, and given without the diagonal one");
    m_cq_matrix = damping.bladed_disk_matrix;
    m_q_damped = (m_cq_matrix.array() != 0.0).any();
    if (!m_q_damped) m_cq_matrix.resize(0, 0);
  }
  if (!finite_non_negative(damping.casing.alpha) || !finite_non_negative(damping.casing.beta))
    throw std::invalid_argument(
        "ReducedIntegrator: the casing's Rayleigh alpha and beta must be finite and >= 0");

  // A = M^ + dt/2 C^ (M^ undamped), factorized once.
  Eigen::MatrixXd a_q = m_mq;
  if (m_q_damped && m_cq_matrix.size() != 0) {
    a_q += 0.5 * dt * m_cq_matrix;
  } else if (m_q_damped) {
    m_cq = damping.bladed_disk;
    a_q.diagonal() += 0.5 * dt * m_cq;
  }
  const Eigen::LLT<Eigen::MatrixXd> mq_factor(a_q);
  if (mq_factor.info() != Eigen::Success)
    throw ReducedIntegrationError(std::string("reduced integrator: the reduced mass matrix") +
                                  (m_q_damped ? " plus dt/2 C^" : "") +
                                  " is not positive definite" + kReducedMassRemedy);
  m_mq_inverse = mq_factor.solve(Eigen::MatrixXd::Identity(m_mq.rows(), m_mq.cols()));
  m_tip_position = basis.boundary_position;
  const bool modal = disk_modes != nullptr && !m_q_damped;
  if (!modal) m_aq = mq_factor.solve(m_kq); // the physical predictor's M^-1 K^ only
  if (m_q_damped)
    m_bq = m_cq_matrix.size() != 0 ? Eigen::MatrixXd(dt * (m_mq_inverse * m_cq_matrix))
                                   : Eigen::MatrixXd(dt * (m_mq_inverse * m_cq.asDiagonal()));
  if (modal) {
    if (disk_modes->shapes.rows() != r || disk_modes->shapes.cols() != r ||
        disk_modes->omega_squared.size() != r)
      throw std::invalid_argument("ReducedIntegrator: the reduced modes must be " +
                                  std::to_string(r) + " x " + std::to_string(r));
    m_modal_disk = true;
    m_psi = disk_modes->shapes;
    m_lambda_disk = disk_modes->omega_squared;
    m_boundary = basis.boundary_position;
    m_psi_boundary.resize(static_cast<Eigen::Index>(m_boundary.size()), r);
    m_boundary_index.assign(static_cast<size_t>(r), -1);
    for (size_t i = 0; i < m_boundary.size(); ++i) {
      m_psi_boundary.row(static_cast<Eigen::Index>(i)) = m_psi.row(m_boundary[i]);
      m_boundary_index[static_cast<size_t>(m_boundary[i])] = static_cast<int>(i);
    }
    m_boundary_flexibility = m_psi_boundary * m_psi_boundary.transpose();
    m_eta = m_eta_prev = m_eta_next = m_deta = Eigen::VectorXd::Zero(r);
    m_q_boundary = m_dq_boundary =
        Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m_boundary.size()));
  }

  m_q_next = m_dq = Eigen::VectorXd::Zero(m_kq.rows());
  if (casing_basis != nullptr)
    m_casing = std::make_unique<ModalCasingPart>(casing, *casing_basis, dt, damping.casing);
  else
    m_casing = std::make_unique<FullCasingPart>(casing, dt, damping.casing);
}

double ReducedIntegrator::flops_per_step() const {
  const auto r = static_cast<double>(m_kq.rows());
  const double disk = m_modal_disk ? 2.0 * static_cast<double>(m_boundary.size()) * r + 5.0 * r
                                   : 2.0 * r * r + 4.0 * r;
  double flops = disk + 64.0 * m_contact.n_tips() + casing_flops_per_step();
  if (m_q_damped) flops += 2.0 * r * r + 5.0 * r;
  if (m_cq_matrix.size() != 0) flops += 2.0 * r * r; // C^ dq of W_damp
  return flops;
}

double ReducedIntegrator::energy() const {
  return m_casing->energy() + (m_modal_disk ? 0.5 * ((m_eta - m_eta_prev) / m_dt).squaredNorm() +
                                               0.5 * m_eta_prev.dot(m_lambda_disk.cwiseProduct(m_eta))
                                         : disk_energy());
}

double ReducedIntegrator::disk_energy() const {
  const Eigen::VectorXd vq = (m_q - m_q_prev) / m_dt;
  return 0.5 * vq.dot(m_mq * vq) + 0.5 * m_q_prev.dot(m_kq * m_q);
}

void ReducedIntegrator::tip_displacement(Eigen::VectorXd& out) const {
  // On the modal path q_n's boundary entries are kept (form_boundary).
  out.resize(static_cast<Eigen::Index>(m_tip_position.size()));
  for (size_t i = 0; i < m_tip_position.size(); ++i)
    out(static_cast<Eigen::Index>(i)) = m_q(m_tip_position[i]);
}

Eigen::VectorXd ReducedIntegrator::q() const {
  if (m_modal_disk) return m_psi * m_eta;
  return m_q;
}

void ReducedIntegrator::form_boundary(const Eigen::VectorXd& eta, Eigen::VectorXd& q) {
  m_q_boundary.noalias() = m_psi_boundary * eta;
  for (size_t i = 0; i < m_boundary.size(); ++i)
    q(m_boundary[i]) = m_q_boundary(static_cast<Eigen::Index>(i));
}

void ReducedIntegrator::set_force(const Eigen::Ref<const Eigen::VectorXd>& casing_force) {
  if (casing_force.size() != m_casing->n_dofs())
    throw std::invalid_argument("ReducedIntegrator::set_force: the force has " +
                                std::to_string(casing_force.size()) + " entries, the casing " +
                                std::to_string(m_casing->n_dofs()) + " dofs");
  m_casing->set_force(casing_force);
}

void ReducedIntegrator::start(const Eigen::Ref<const Eigen::VectorXd>& casing_force) {
  start(casing_force, Eigen::VectorXd::Zero(m_kq.rows()));
}

void ReducedIntegrator::start() {
  start_at(Eigen::VectorXd::Zero(m_kq.rows()));
}

void ReducedIntegrator::start(const Eigen::Ref<const Eigen::VectorXd>& casing_force,
                              const Eigen::Ref<const Eigen::VectorXd>& q0) {
  if (q0.size() != m_kq.rows())
    throw std::invalid_argument("ReducedIntegrator::start: q0 has " + std::to_string(q0.size()) +
                                " entries, the reduced model " + std::to_string(m_kq.rows()));
  set_force(casing_force);
  start_at(q0);
}

void ReducedIntegrator::start_at(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  m_n = 0;
  m_q = q0;
  if (q0.isZero(0.0)) {
    m_q_prev = m_q;
  } else {
    // q_{-1} = q0 + dt^2/2 M^-1 (-K^ q0): at rest, with M^ itself (not A).
    const Eigen::LLT<Eigen::MatrixXd> mass(m_mq);
    if (mass.info() != Eigen::Success)
      throw ReducedIntegrationError(
          "reduced integrator: the reduced mass matrix is not positive definite" +
          kReducedMassRemedy);
    m_q_prev = m_q - 0.5 * m_dt * m_dt * mass.solve(m_kq * m_q);
  }
  if (m_modal_disk) {
    // eta = Psi^T M^ q, the same start in modal coordinates; q, q_prev whole.
    m_eta.noalias() = m_psi.transpose() * (m_mq * m_q);
    m_eta_prev = m_eta - (0.5 * m_dt * m_dt) * m_lambda_disk.cwiseProduct(m_eta);
    if (q0.isZero(0.0)) m_eta_prev = m_eta;
    m_q.noalias() = m_psi * m_eta;
    m_q_prev.noalias() = m_psi * m_eta_prev;
  }
  m_casing->start();
  m_contact.evaluate(m_q, m_q, m_casing->now(), m_casing->now(), m_dt, 0.0, m_tips);
  m_predicted = m_tips;
  m_gap.resize(m_contact.n_tips());
  for (int k = 0; k < m_contact.n_tips(); ++k)
    m_gap(k) = m_tips[k].gap;
  m_lambda = Eigen::VectorXd::Zero(m_contact.n_tips());
  m_lambda_t = Eigen::VectorXd::Zero(m_contact.n_tips());
  m_lambda_t_zero = true;
  m_state.assign(m_contact.n_tips(), ReducedContactState::open);
  m_state_before = m_state;
  m_warm = Eigen::VectorXd::Zero(2 * m_contact.n_tips());
  m_certificate = ReducedCoulombCertificate{};
  m_initial_energy = energy();
  m_external_work = m_contact_work = m_damping_work = 0.0;
}

double ReducedIntegrator::flexibility(const TipContact& i, const TipContact& j) const {
  // G_i^q = -e(u_i), D_j^q = -e(u_j) - mu s_j e(v_j).
  double w = m_mq_inverse(i.q_u, j.q_u) + m_mu * j.sign * m_mq_inverse(i.q_u, j.q_v);
  // G_i^c = sum_a N_a e(cu_a), D_j^c = sum_b N_b (e(cu_b) + mu s_j e(cv_b)).
  const Eigen::MatrixXd& casing_flexibility = m_casing->flexibility();
  for (int a = 0; a < 4; ++a) {
    if (i.c_u[a] < 0) continue;
    for (int b = 0; b < 4; ++b) {
      if (j.c_u[b] < 0) continue;
      w += i.shape[a] * j.shape[b] *
           (casing_flexibility(i.c_u[a], j.c_u[b]) +
            m_mu * j.sign * casing_flexibility(i.c_u[a], j.c_v[b]));
    }
  }
  return m_dt * m_dt * w;
}

double ReducedIntegrator::direction_dot(const TipContact& j, const Eigen::VectorXd& q_a,
                                        const Eigen::VectorXd& q_b, const Eigen::VectorXd& c_a,
                                        const Eigen::VectorXd& c_b) const {
  double sum = -(q_a(j.q_u) - q_b(j.q_u)) - m_mu * j.sign * (q_a(j.q_v) - q_b(j.q_v));
  for (int b = 0; b < 4; ++b)
    if (j.c_u[b] >= 0)
      sum += j.shape[b] *
             ((c_a(j.c_u[b]) - c_b(j.c_u[b])) + m_mu * j.sign * (c_a(j.c_v[b]) - c_b(j.c_v[b])));
  return sum;
}

void ReducedIntegrator::solve_contact(const std::vector<TipContact>& tips) {
  const int nt = static_cast<int>(tips.size());
  m_lambda.setZero(nt);
  int n_active = 0;
  for (int k = 0; k < nt; ++k)
    n_active += tips[k].gap < 0.0;
  if (n_active == 0) return;
  m_active.resize(nt);
  for (int k = 0; k < nt; ++k)
    m_active[k] = tips[k].gap < 0.0;
  m_w_all.resize(nt, nt);
  m_known.assign(static_cast<size_t>(nt) * nt, 0);
  auto w = [&](int i, int j) {
    if (!m_known[i * nt + j]) {
      m_w_all(i, j) = flexibility(tips[i], tips[j]);
      m_known[i * nt + j] = 1;
    }
    return m_w_all(i, j);
  };
  for (int round = 0; round < 2 * nt + 2; ++round) {
    m_set.clear();
    for (int k = 0; k < nt; ++k)
      if (m_active[k]) m_set.push_back(k);
    const int m = static_cast<int>(m_set.size());
    m_lambda.setZero(nt);
    if (m == 0) return;
    m_wa.resize(m, m);
    m_minus_gap.resize(m);
    for (int a = 0; a < m; ++a) {
      m_minus_gap(a) = -tips[m_set[a]].gap;
      for (int b = 0; b < m; ++b)
        m_wa(a, b) = w(m_set[a], m_set[b]);
    }
    m_lu.compute(m_wa);
    m_la = m_lu.solve(m_minus_gap);
    m_residual.noalias() = m_wa * m_la;
    m_residual -= m_minus_gap;
    if (!m_la.allFinite() || m_residual.norm() > 1e-8 * m_minus_gap.norm())
      throw ReducedIntegrationError("reduced integrator: singular contact matrix W at step " +
                                    std::to_string(m_n + 1) + " (" + std::to_string(m) +
                                    " active tips)" + kContactRemedy);
    bool changed = false;
    for (int a = 0; a < m; ++a)
      if (m_la(a) < 0.0) m_active[m_set[a]] = 0, changed = true; // drop every negative multiplier
    if (changed) continue;
    for (int a = 0; a < m; ++a)
      m_lambda(m_set[a]) = m_la(a);
    for (int k = 0; k < nt; ++k) { // constraints the correction would close
      if (m_active[k]) continue;
      double g = tips[k].gap;
      for (int a = 0; a < m; ++a)
        g += w(k, m_set[a]) * m_la(a);
      if (g < 0.0) m_active[k] = 1, changed = true;
    }
    if (!changed) return;
  }
  throw ReducedIntegrationError("reduced integrator: the active set did not settle at step " +
                                std::to_string(m_n + 1) + kStepRemedy);
}

Eigen::Matrix2d ReducedIntegrator::coulomb_block(const TipContact& i, const TipContact& j) const {
  // Rows B_n,i = (-e(u_i); +N_i on c_u), B_t,i = (+e(v_i); -N_i on c_v); the
  // same for the columns of j.
  double nn = m_mq_inverse(i.q_u, j.q_u);
  double nt = -m_mq_inverse(i.q_u, j.q_v);
  double tn = -m_mq_inverse(i.q_v, j.q_u);
  double tt = m_mq_inverse(i.q_v, j.q_v);
  const Eigen::MatrixXd& casing_flexibility = m_casing->flexibility();
  for (int a = 0; a < 4; ++a) {
    if (i.c_u[a] < 0) continue;
    for (int b = 0; b < 4; ++b) {
      if (j.c_u[b] < 0) continue;
      const double nab = i.shape[a] * j.shape[b];
      nn += nab * casing_flexibility(i.c_u[a], j.c_u[b]);
      nt -= nab * casing_flexibility(i.c_u[a], j.c_v[b]);
      tn -= nab * casing_flexibility(i.c_v[a], j.c_u[b]);
      tt += nab * casing_flexibility(i.c_v[a], j.c_v[b]);
    }
  }
  const double dt2 = m_dt * m_dt;
  Eigen::Matrix2d w;
  w << dt2 * nn, dt2 * nt, dt2 * tn, dt2 * tt;
  return w;
}

void ReducedIntegrator::solve_coulomb(const std::vector<TipContact>& tips, StepReport& report) {
  const int nt = static_cast<int>(tips.size());
  m_state_before.swap(m_state);
  m_state.assign(nt, ReducedContactState::open);
  m_lambda.setZero(nt);
  m_lambda_t.setZero(nt);
  m_certificate = ReducedCoulombCertificate{};
  m_active.assign(nt, 0);
  m_set.clear();
  m_w.resize(0, 0);
  m_rows.resize(0);
  int n_active = 0;
  for (int k = 0; k < nt; ++k) {
    if (!std::isfinite(tips[k].gap) || !std::isfinite(tips[k].slip))
      throw ReducedIntegrationError("reduced integrator: non-finite predicted gap or slip of tip " +
                                    std::to_string(k + 1) + " at step " + std::to_string(m_n + 1) +
                                    " (the state blew up)" + kStepRemedy);
    if (tips[k].gap < 0.0) m_active[k] = 1, ++n_active;
  }
  if (n_active > 0) {
    for (int round = 0;; ++round) {
      m_set.clear();
      for (int k = 0; k < nt; ++k)
        if (m_active[k]) m_set.push_back(k);
      const int m = static_cast<int>(m_set.size());
      m_w.resize(2 * m, 2 * m);
      m_rows.resize(2 * m);
      m_rows_lambda.resize(2 * m);
      for (int a = 0; a < m; ++a) {
        const TipContact& tip = tips[m_set[a]];
        m_rows(2 * a) = tip.gap;
        m_rows(2 * a + 1) = tip.slip;
        m_rows_lambda.segment<2>(2 * a) = m_warm.segment<2>(2 * m_set[a]);
        for (int b = 0; b < m; ++b)
          m_w.block<2, 2>(2 * a, 2 * b) = coulomb_block(tip, tips[m_set[b]]);
      }
      const CoulombGaussSeidelReport solved = m_coulomb.solve(m_w, m_rows, m_rows_lambda);
      if (!solved.converged())
        throw ReducedIntegrationError("reduced integrator: Coulomb contact problem at step " +
                                      std::to_string(m_n + 1) + ": " + solved.message +
                                      kContactRemedy);
      for (int a = 0; a < m; ++a)
        m_warm.segment<2>(2 * m_set[a]) = m_rows_lambda.segment<2>(2 * a);
      bool joined = false; // tips left out whose gap the correction would close
      for (int k = 0; k < nt; ++k) {
        if (m_active[k]) continue;
        double g = tips[k].gap;
        for (int a = 0; a < m; ++a) {
          const Eigen::Matrix2d w = coulomb_block(tips[k], tips[m_set[a]]);
          g += w(0, 0) * m_rows_lambda(2 * a) + w(0, 1) * m_rows_lambda(2 * a + 1);
        }
        if (g < 0.0) m_active[k] = 1, joined = true;
      }
      if (!joined) break;
      if (round >= nt)
        throw ReducedIntegrationError(
            "reduced integrator: the set of closing tips did not settle at step " +
            std::to_string(m_n + 1) + kStepRemedy);
    }
    m_predicted_kept = tips;
    const std::vector<ReducedContactState>& states = m_coulomb.states();
    const int m = static_cast<int>(m_set.size());
    for (int a = 0; a < m; ++a) {
      m_lambda(m_set[a]) = m_rows_lambda(2 * a);
      m_lambda_t(m_set[a]) = m_rows_lambda(2 * a + 1);
      m_state[m_set[a]] = states[a];
    }
    m_certificate = reduced_coulomb_certificate(m_w, m_rows, 1, m_mu, m_rows_lambda, states);
    // The scaled stick/slip residual (reduced_integrator.hpp).
    m_rows_y = m_rows;
    m_rows_y.noalias() += m_w * m_rows_lambda;
    const double largest = m_rows_lambda.cwiseAbs().maxCoeff();
    double scaled = largest > 0.0 ? m_certificate.max_open_residual / largest : 0.0;
    for (int a = 0; a < m; ++a) {
      const double ln = m_rows_lambda(2 * a);
      const double lt = m_rows_lambda(2 * a + 1);
      const double slip = m_rows_y(2 * a + 1);
      const double sigma =
          std::abs(m_rows(2 * a + 1)) + m_w.row(2 * a + 1).cwiseAbs().sum() * largest;
      if (states[a] == ReducedContactState::stick) {
        if (sigma > 0.0) scaled = std::max(scaled, std::abs(slip) / sigma);
      } else if (states[a] == ReducedContactState::slip) {
        if (lt != 0.0 && sigma > 0.0) {
          const double e = lt > 0.0 ? -1.0 : 1.0; // the slip direction lambda_t opposes
          scaled = std::max(scaled, std::max(-slip * e, 0.0) / sigma);
        }
        if (m_mu * ln > 0.0)
          scaled = std::max(scaled, std::abs(std::abs(lt) - m_mu * ln) / (m_mu * ln));
      }
    }
    report.max_cone_violation = m_certificate.max_cone_violation;
    report.max_stick_slip_residual = scaled;
  }
  // Tips outside the solved set stay open with lambda = 0: their start is 0.
  for (int k = 0; k < nt; ++k) {
    if (!m_active[k]) m_warm.segment<2>(2 * k).setZero();
    if (m_state[k] != m_state_before[k]) ++report.stick_slip_transitions;
    report.n_stick += m_state[k] == ReducedContactState::stick;
    report.n_slip += m_state[k] == ReducedContactState::slip;
  }
}

void ReducedIntegrator::correct_coulomb(const std::vector<TipContact>& tips) {
  const double dt2 = m_dt * m_dt;
  clear_corrections();
  for (int j = 0; j < m_lambda.size(); ++j) {
    if (m_lambda(j) == 0.0 && m_lambda_t(j) == 0.0) continue;
    const TipContact& tip = tips[j];
    const double f = dt2 * m_lambda(j);
    const double ft = dt2 * m_lambda_t(j);
    if (m_modal_disk) {
      add_disk_correction(tip.q_u, -f);
      if (ft != 0.0) add_disk_correction(tip.q_v, ft);
    } else {
      m_dq -= f * m_mq_inverse.col(tip.q_u);
      if (ft != 0.0) m_dq += ft * m_mq_inverse.col(tip.q_v);
    }
    m_casing->add_correction(tip, f, -ft);
  }
  apply_corrections();
}

void ReducedIntegrator::clear_corrections() {
  m_dq.setZero();
  m_casing->clear_correction();
  if (m_modal_disk) {
    m_deta.setZero();
    m_dq_boundary.setZero();
  }
}

void ReducedIntegrator::apply_corrections() {
  if (m_modal_disk) {
    // q_B = Psi_B (eta~ + d eta) = q~_B + Psi_B Psi_B^T (sum of f e): the
    // predictor's q~_B plus the corrections' columns (add_disk_correction).
    m_eta_next += m_deta;
    m_q_boundary += m_dq_boundary;
    for (size_t i = 0; i < m_boundary.size(); ++i)
      m_q_next(m_boundary[i]) = m_q_boundary(static_cast<Eigen::Index>(i));
  } else {
    m_q_next += m_dq;
  }
  m_casing->apply_correction();
}

double ReducedIntegrator::step_damping_work() {
  double work = 0.0;
  if (m_q_damped) {
    m_dq = m_q_next - m_q_prev;
    if (m_cq_matrix.size() != 0) {
      m_cq_dq.noalias() = m_cq_matrix * m_dq;
      work += m_dq.dot(m_cq_dq);
    } else {
      work += m_dq.dot(m_cq.cwiseProduct(m_dq));
    }
  }
  if (m_casing->damped()) work += m_casing->step_damping_product();
  return work / (4.0 * m_dt);
}

StepReport ReducedIntegrator::step() {
  const double dt2 = m_dt * m_dt;
  if (m_modal_disk) {
    m_eta_next = 2.0 * m_eta - m_eta_prev;
    m_eta_next -= dt2 * m_lambda_disk.cwiseProduct(m_eta);
    form_boundary(m_eta_next, m_q_next);
  } else {
    m_q_next = 2.0 * m_q - m_q_prev;
    m_q_next.noalias() -= dt2 * (m_aq * m_q);
    if (m_q_damped) { // - dt A^-1 C^ (q_n - q_{n-1})
      m_dq = m_q - m_q_prev;
      m_q_next.noalias() -= m_bq * m_dq;
    }
  }
  m_casing->predict();
  const double t_next = (m_n + 1) * m_dt;
  m_contact.evaluate(m_q_next, m_q, m_casing->next(), m_casing->now(), m_dt, t_next, m_predicted);
  StepReport report;
  const bool coulomb = m_law == FrictionLaw::coulomb;
  if (coulomb)
    solve_coulomb(m_predicted, report);
  else
    solve_contact(m_predicted);

  const bool corrected = m_lambda.any();
  if (coulomb) {
    if (corrected) correct_coulomb(m_predicted);
  } else if (corrected) {
    clear_corrections();
    for (int j = 0; j < m_lambda.size(); ++j) {
      if (m_lambda(j) == 0.0) continue;
      const TipContact& tip = m_predicted[j];
      const double f = dt2 * m_lambda(j);
      if (m_modal_disk) {
        add_disk_correction(tip.q_u, -f);
        if (m_mu * tip.sign != 0.0) add_disk_correction(tip.q_v, -f * m_mu * tip.sign);
      } else {
        m_dq -= f * (m_mq_inverse.col(tip.q_u) + m_mu * tip.sign * m_mq_inverse.col(tip.q_v));
      }
      m_casing->add_sliding_correction(tip, f, m_mu);
    }
    apply_corrections();
  }
  // Works of step n: (F_n + R_n)^T (x_{n+1} - x_{n-1}) / 2.
  if (!m_casing->force_zero()) m_external_work += m_casing->step_external_work();
  if (coulomb) {
    for (int j = 0; j < m_lambda.size(); ++j)
      if (m_lambda(j) != 0.0) {
        // B_n . dx and B_t . dx over dx = x_{n+1} - x_{n-1}, at tip j's entries.
        const TipContact& tip = m_predicted[j];
        const Eigen::VectorXd& c_next = m_casing->next();
        const Eigen::VectorXd& c_prev = m_casing->previous();
        double normal = -(m_q_next(tip.q_u) - m_q_prev(tip.q_u));
        double tangential = m_q_next(tip.q_v) - m_q_prev(tip.q_v);
        for (int b = 0; b < 4; ++b)
          if (tip.c_u[b] >= 0) {
            normal += tip.shape[b] * (c_next(tip.c_u[b]) - c_prev(tip.c_u[b]));
            tangential -= tip.shape[b] * (c_next(tip.c_v[b]) - c_prev(tip.c_v[b]));
          }
        m_contact_work += 0.5 * (m_lambda(j) * normal + m_lambda_t(j) * tangential);
      }
  } else {
    for (int j = 0; j < m_lambda.size(); ++j)
      if (m_lambda(j) != 0.0)
        m_contact_work += 0.5 * m_lambda(j) *
                          direction_dot(m_predicted[j], m_q_next, m_q_prev, m_casing->next(),
                                        m_casing->previous());
    // The tangential force the law applied, -mu sign lambda (tangential_lambda()).
    if (corrected) {
      for (int j = 0; j < m_lambda.size(); ++j)
        m_lambda_t(j) = m_lambda(j) != 0.0 ? -m_mu * m_predicted[j].sign * m_lambda(j) : 0.0;
      m_lambda_t_zero = false;
    } else if (!m_lambda_t_zero) {
      m_lambda_t.setZero();
      m_lambda_t_zero = true;
    }
  }

  if (m_q_damped || m_casing->damped()) m_damping_work += step_damping_work();

  m_q_prev.swap(m_q);
  m_q.swap(m_q_next);
  m_casing->advance();
  if (m_modal_disk) {
    m_eta_prev.swap(m_eta);
    m_eta.swap(m_eta_next);
  }
  ++m_n;

  // The tips at the new state: those predicted unless a correction moved it
  // (then m_predicted keeps the predicted signs compared below).
  if (corrected)
    m_contact.evaluate(m_q, m_q_prev, m_casing->now(), m_casing->previous(), m_dt, t_next, m_tips);
  else
    m_tips.swap(m_predicted);
  for (int k = 0; k < m_lambda.size(); ++k) {
    const double g = m_tips[k].gap;
    const double l = m_lambda(k);
    m_gap(k) = g;
    report.max_penetration = std::max(report.max_penetration, -g);
    report.min_lambda = std::min(report.min_lambda, l);
    report.max_complementarity = std::max(report.max_complementarity, std::abs(l * g));
    if (l == 0.0) continue;
    ++report.n_active;
    if (!coulomb && m_mu > 0.0 && m_tips[k].sign != m_predicted[k].sign) {
      ++report.sliding_reversals;
      report.max_friction_residual = std::max(
          report.max_friction_residual, m_mu * l * std::abs(m_tips[k].sign - m_predicted[k].sign));
    }
  }
  return report;
}

} // namespace rsi
