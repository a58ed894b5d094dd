#include "reduced_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "full_casing_part.hpp"
#include "modal_disk_part.hpp"
#include "modal_casing_part.hpp"
#include "physical_disk_part.hpp"

namespace rsi {

namespace {

bool finite_non_negative(double x) {
  return std::isfinite(x) && x >= 0.0;
}

// What to change, for the messages of ReducedIntegrationError.
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
    : m_dt(dt)
    , m_mu(contact.friction_coefficient())
    , m_contact(contact)
    , m_law(contact.friction_law())
    , m_coulomb(1, contact.friction_coefficient()) {
  const Eigen::Index r = basis.n_reduced();
  bool disk_damped = false;
  if (damping.bladed_disk.size() != 0) {
    if (damping.bladed_disk.size() != r ||
        !damping.bladed_disk.unaryExpr(&finite_non_negative).all())
      throw std::invalid_argument("ReducedIntegrator: the bladed-disk damping must have " +
                                  std::to_string(r) + " finite entries >= 0");
    disk_damped = (damping.bladed_disk.array() != 0.0).any();
  }
  Eigen::MatrixXd disk_damping_matrix;
  if (damping.bladed_disk_matrix.size() != 0) {
    if (damping.bladed_disk.size() != 0 || damping.bladed_disk_matrix.rows() != r ||
        damping.bladed_disk_matrix.cols() != r || !damping.bladed_disk_matrix.allFinite())
      throw std::invalid_argument("ReducedIntegrator: a full bladed-disk damping must be " +
                                  std::to_string(r) + " x " + std::to_string(r) +
                                  ", finite, and given without the diagonal one");
    disk_damping_matrix = damping.bladed_disk_matrix;
    disk_damped = (disk_damping_matrix.array() != 0.0).any();
    if (!disk_damped) disk_damping_matrix.resize(0, 0);
  }
  if (!finite_non_negative(damping.casing.alpha) || !finite_non_negative(damping.casing.beta))
    throw std::invalid_argument(
        "ReducedIntegrator: the casing's Rayleigh alpha and beta must be finite and >= 0");

  // The disk in its modes when undamped and given them (modal_disk_part.hpp).
  m_modal_disk = disk_modes != nullptr && !disk_damped;
  if (m_modal_disk)
    m_disk = std::make_unique<ModalDiskPart>(basis, dt, *disk_modes);
  else
    m_disk = std::make_unique<PhysicalDiskPart>(basis, dt, disk_damped, damping.bladed_disk,
                                                disk_damping_matrix);
  if (casing_basis != nullptr)
    m_casing = std::make_unique<ModalCasingPart>(casing, *casing_basis, dt, damping.casing);
  else
    m_casing = std::make_unique<FullCasingPart>(casing, dt, damping.casing);
}

double ReducedIntegrator::flops_per_step() const {
  return m_disk->flops_per_step() + 64.0 * m_contact.n_tips() + casing_flops_per_step();
}

double ReducedIntegrator::energy() const {
  return m_casing->energy() + m_disk->energy();
}

void ReducedIntegrator::set_force(const Eigen::Ref<const Eigen::VectorXd>& casing_force) {
  if (casing_force.size() != m_casing->n_dofs())
    throw std::invalid_argument("ReducedIntegrator::set_force: the force has " +
                                std::to_string(casing_force.size()) + " entries, the casing " +
                                std::to_string(m_casing->n_dofs()) + " dofs");
  m_casing->set_force(casing_force);
}

void ReducedIntegrator::start(const Eigen::Ref<const Eigen::VectorXd>& casing_force) {
  start(casing_force, Eigen::VectorXd::Zero(m_disk->n_reduced()));
}

void ReducedIntegrator::start() {
  start_at(Eigen::VectorXd::Zero(m_disk->n_reduced()));
}

void ReducedIntegrator::start(const Eigen::Ref<const Eigen::VectorXd>& casing_force,
                              const Eigen::Ref<const Eigen::VectorXd>& q0) {
  if (q0.size() != m_disk->n_reduced())
    throw std::invalid_argument("ReducedIntegrator::start: q0 has " + std::to_string(q0.size()) +
                                " entries, the reduced model " +
                                std::to_string(m_disk->n_reduced()));
  set_force(casing_force);
  start_at(q0);
}

void ReducedIntegrator::start_at(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  m_n = 0;
  m_disk->start(q0);
  m_casing->start();
  m_contact.evaluate(m_disk->now(), m_disk->now(), m_casing->now(), m_casing->now(), m_dt, 0.0,
                     m_tips);
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
  const Eigen::MatrixXd& disk_flexibility = m_disk->flexibility();
  double w =
      disk_flexibility(i.q_u, j.q_u) + m_mu * j.sign * disk_flexibility(i.q_u, j.q_v);
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
  const Eigen::MatrixXd& disk_flexibility = m_disk->flexibility();
  double nn = disk_flexibility(i.q_u, j.q_u);
  double nt = -disk_flexibility(i.q_u, j.q_v);
  double tn = -disk_flexibility(i.q_v, j.q_u);
  double tt = disk_flexibility(i.q_v, j.q_v);
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
    m_disk->add_coulomb_correction(tip, f, ft);
    m_casing->add_correction(tip, f, -ft);
  }
  apply_corrections();
}

void ReducedIntegrator::clear_corrections() {
  m_disk->clear_correction();
  m_casing->clear_correction();
}

void ReducedIntegrator::apply_corrections() {
  m_disk->apply_correction();
  m_casing->apply_correction();
}

double ReducedIntegrator::step_damping_work() {
  double work = 0.0;
  if (m_disk->damped()) work += m_disk->step_damping_product();
  if (m_casing->damped()) work += m_casing->step_damping_product();
  return work / (4.0 * m_dt);
}

StepReport ReducedIntegrator::step() {
  const double dt2 = m_dt * m_dt;
  m_disk->predict();
  m_casing->predict();
  const double t_next = (m_n + 1) * m_dt;
  m_contact.evaluate(m_disk->next(), m_disk->now(), m_casing->next(), m_casing->now(), m_dt,
                     t_next, m_predicted);
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
      m_disk->add_sliding_correction(tip, f, m_mu);
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
        const Eigen::VectorXd& q_next = m_disk->next();
        const Eigen::VectorXd& q_prev = m_disk->previous();
        const Eigen::VectorXd& c_next = m_casing->next();
        const Eigen::VectorXd& c_prev = m_casing->previous();
        double normal = -(q_next(tip.q_u) - q_prev(tip.q_u));
        double tangential = q_next(tip.q_v) - q_prev(tip.q_v);
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
                          direction_dot(m_predicted[j], m_disk->next(), m_disk->previous(),
                                        m_casing->next(), m_casing->previous());
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

  if (m_disk->damped() || m_casing->damped()) m_damping_work += step_damping_work();

  m_disk->advance();
  m_casing->advance();
  ++m_n;

  // The tips at the new state: those predicted unless a correction moved it
  // (then m_predicted keeps the predicted signs compared below).
  if (corrected)
    m_contact.evaluate(m_disk->now(), m_disk->previous(), m_casing->now(), m_casing->previous(),
                       m_dt, t_next, m_tips);
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
