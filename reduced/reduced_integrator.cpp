#include "reduced_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "full_casing_part.hpp"
#include "modal_disk_part.hpp"
#include "modal_casing_part.hpp"
#include "physical_disk_part.hpp"
#include "coulomb_tip_solve.hpp"
#include "sliding_sign_solve.hpp"

namespace rsi {

namespace {

bool finite_non_negative(double x) {
  return std::isfinite(x) && x >= 0.0;
}

} // namespace

ReducedIntegrator::ReducedIntegrator(const ReducedBasis& basis, const Casing& casing, double dt,
                                     const ReducedTipContact& contact,
                                     const ReducedDamping& damping,
                                     const CasingBasis* casing_basis,
                                     const ReducedModes* disk_modes)
    : m_dt(dt)
    , m_mu(contact.friction_coefficient())
    , m_contact(contact)
    , m_law(contact.friction_law()) {
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
  // The contact solve of the case's friction law, over both parts.
  if (m_law == FrictionLaw::coulomb)
    m_solve = std::make_unique<CoulombTipSolve>(*m_disk, *m_casing, dt, m_mu);
  else
    m_solve = std::make_unique<SlidingSignSolve>(*m_disk, *m_casing, dt, m_mu);
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
  m_solve->start(m_contact.n_tips());
  m_initial_energy = energy();
  m_external_work = m_contact_work = m_damping_work = 0.0;
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
  m_disk->predict();
  m_casing->predict();
  const double t_next = (m_n + 1) * m_dt;
  m_contact.evaluate(m_disk->next(), m_disk->now(), m_casing->next(), m_casing->now(), m_dt,
                     t_next, m_predicted);
  StepReport report;
  m_solve->solve(m_predicted, m_n + 1, report);
  const Eigen::VectorXd& lambda = m_solve->lambda();
  const bool corrected = lambda.any();
  if (corrected) {
    clear_corrections();
    m_solve->gather_correction(m_predicted, *m_disk, *m_casing);
    apply_corrections();
  }
  // Works of step n: (F_n + R_n)^T (x_{n+1} - x_{n-1}) / 2.
  if (!m_casing->force_zero()) m_external_work += m_casing->step_external_work();
  m_solve->add_contact_work(m_predicted, corrected, m_contact_work);

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
  for (int k = 0; k < lambda.size(); ++k) {
    const double g = m_tips[k].gap;
    const double l = lambda(k);
    m_gap(k) = g;
    report.max_penetration = std::max(report.max_penetration, -g);
    report.min_lambda = std::min(report.min_lambda, l);
    report.max_complementarity = std::max(report.max_complementarity, std::abs(l * g));
    if (l == 0.0) continue;
    ++report.n_active;
    m_solve->report_tip(m_tips[k], m_predicted[k], l, report);
  }
  return report;
}

} // namespace rsi
