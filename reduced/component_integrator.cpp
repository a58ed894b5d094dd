#include "component_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "critical_step.hpp"
#include "mass_carrying_boundary_part.hpp"
#include "massless_boundary_part.hpp"
#include "message_number.hpp"

namespace rsi {

namespace {

const std::string kWhere = "ComponentIntegrator: ";

/// The step's contact law: the liner's bars, or Signorini on the rigid surface.
std::unique_ptr<ComponentContactSolve> contact_solve_of(const RigidCasing& casing,
                                                        const ComponentIntegratorOptions& options) {
  if (!options.liner)
    return std::make_unique<CoulombNodeSolve>(casing.n_contacts(), options.dt, options.mu,
                                              options.coulomb, options.closing_subset);
  LinerContactLayout layout;
  layout.omega = casing.omega();
  layout.patch = options.liner->patch;
  for (int c = 0; c < casing.n_contacts(); ++c) {
    layout.polar_angle.push_back(casing.polar_angle(c));
    layout.axial.push_back(casing.axial_coordinate(c));
  }
  return std::make_unique<LinerContactSolve>(
      casing.n_contacts(), options.dt, options.mu,
      AbradableCells(options.liner->geometry, options.liner->material), layout,
      options.liner->solve);
}

/// options.dt, checked: finite and > 0 (std::invalid_argument otherwise).
double checked_dt(const ComponentIntegratorOptions& options) {
  if (!(options.dt > 0.0) || !std::isfinite(options.dt))
    throw std::invalid_argument(kWhere + "dt = " + message_number(options.dt) +
                                ", allowed a finite value > 0");
  return options.dt;
}

} // namespace

ComponentIntegrator::ComponentIntegrator(const ReducedBasis& basis, const RigidCasing& casing,
                                         const ComponentIntegratorOptions& options)
    : m_contact(contact_solve_of(casing, options))
    , m_liner(dynamic_cast<LinerContactSolve*>(m_contact.get())) {
  m_casing = std::make_unique<RigidCasingPart>(casing, basis.n_boundary(), checked_dt(options));
  init(basis, options);
}

ComponentIntegrator::ComponentIntegrator(const ReducedBasis& basis,
                                         std::unique_ptr<ComponentCasingPart> casing,
                                         const ComponentIntegratorOptions& options) {
  if (!casing) throw std::invalid_argument(kWhere + "no casing part");
  if (options.liner)
    throw std::invalid_argument(kWhere + "a liner is the rigid casing's; allowed none here");
  checked_dt(options);
  auto coulomb = std::make_unique<CoulombNodeSolve>(casing->n_contacts(), options.dt, options.mu,
                                                    options.coulomb, options.closing_subset);
  m_coulomb = coulomb.get();
  m_contact = std::move(coulomb);
  m_casing = std::move(casing);
  init(basis, options);
}

void ComponentIntegrator::init(const ReducedBasis& basis,
                               const ComponentIntegratorOptions& options) {
  m_dt = options.dt;
  m_r = basis.n_reduced();
  // With every boundary mode (n_c = n_B) W has CB's rank: no note.
  m_boundary_rank = basis.boundary_shapes.cols() < basis.boundary_shapes.rows()
                        ? static_cast<int>(basis.boundary_shapes.cols())
                        : 0;
  const int nb = basis.n_boundary();
  for (int b : basis.boundary_position)
    if (b < 0 || b >= m_r)
      throw std::invalid_argument(kWhere + "boundary position " + std::to_string(b) +
                                  " outside the basis' " + std::to_string(m_r) + " coordinates");
  m_nc = m_casing->n_contacts();
  if (m_nc < 1)
    throw std::invalid_argument(kWhere + "the casing has no contact node, allowed >= 1");
  if (options.damping.size() != 0) {
    if (options.damping.size() != m_r || !options.damping.allFinite() ||
        options.damping.minCoeff() < 0.0)
      throw std::invalid_argument(kWhere + "damping: " + std::to_string(options.damping.size()) +
                                  " entries, allowed " + std::to_string(m_r) +
                                  " finite entries >= 0 (or none)");
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

  for (int c = 0; c < m_nc; ++c)
    for (int k : m_casing->tips().boundary_index(c))
      if (k >= nb)
        throw std::invalid_argument(kWhere + "contact node " + std::to_string(c) +
                                    ": boundary index " + std::to_string(k) + " >= the basis' " +
                                    std::to_string(nb) + " boundary coordinates");

  m_omega_max = std::max(reduced_omega_max(basis), m_casing->omega_max());
  if (!(m_omega_max > 0.0) || !std::isfinite(m_omega_max))
    throw ComponentIntegrationError(kWhere + "omega_max of the reduced model is " +
                                    message_number(m_omega_max) + ", allowed a finite value > 0");
  if (m_dt >= critical_dt() && !options.force_step)
    throw ComponentIntegrationError(
        kWhere + "dt = " + message_number(m_dt) +
        " s is at or above the critical step 2/omega_max = " + message_number(critical_dt()) +
        " s of the " + basis.method + " model (omega_max = " + message_number(m_omega_max) +
        " rad/s" + (basis.massless_boundary ? ", massless boundary condensed" : "") +
        "); allowed dt < critical step unless forced");

  // The one choice of scheme: the basis' boundary carries mass or not.
  if (basis.massless_boundary)
    m_rotor = std::make_unique<MasslessBoundaryPart>(basis, options, m_casing->rows());
  else
    m_rotor = std::make_unique<MassCarryingBoundaryPart>(basis, options, m_casing->rows());
  m_contact->set_contact_matrix(m_rotor->contact_matrix());
  m_lambda.setZero(3 * m_nc);
}

void ComponentIntegrator::solve_contact(StepReport& report) {
  // The flexible casing's share dt^2 H H^T of this prediction's W (none
  // while it is held at t = 0).
  if (m_coulomb != nullptr) m_coulomb->set_flexibility(m_casing->flexibility_rows(), m_dt * m_dt);
  if (m_boundary_rank == 0 || m_liner != nullptr)
    return m_contact->solve(m_casing->prediction(), m_n + 1, report);
  try {
    m_contact->solve(m_casing->prediction(), m_n + 1, report);
  } catch (const ComponentIntegrationError& e) {
    // u_B = Psi_c q_c: B_q = B_B [0 Psi_c] has rank <= n_c, and so has the
    // rotor's share of W (a flexible casing adds dt^2 H H^T, rank <= its
    // modes). More closed contact directions than that make W's active
    // block singular, its multipliers not unique: the boundary too coarse.
    FailureAdvice advice = e.advice();
    advice.remedies.insert(advice.remedies.begin(), Remedy::more_boundary_modes);
    throw ComponentIntegrationError(std::string(e.what()) + " (the boundary in " +
                                        std::to_string(m_boundary_rank) +
                                        " characteristic constraint modes: the rotor's share of "
                                        "W has rank at most " +
                                        std::to_string(m_boundary_rank) + ")",
                                    advice);
  }
}

void ComponentIntegrator::start() {
  start(Eigen::VectorXd::Zero(m_r));
}

void ComponentIntegrator::start(const Eigen::Ref<const Eigen::VectorXd>& q0) {
  if (q0.size() != m_r || !q0.allFinite())
    throw std::invalid_argument(kWhere + "start: q0 has " + std::to_string(q0.size()) +
                                " entries, allowed " + std::to_string(m_r) + " finite entries");
  m_n = 0;
  m_lambda.setZero();
  m_wall_work = 0.0;
  m_contact->start();
  m_casing->start();
  m_rotor->start(q0);
  if (m_rotor->contact_at_next_level()) {
    // The contact at t = 0 on the trial boundary, its slip relative to the
    // structure at rest: the casing's own increment over the step before
    // (a flexible casing held where it is: W the rotor's).
    m_casing->predict(m_rotor->trial_boundary(), m_rotor->boundary(), 0.0, 0.0);
    StepReport unused;
    solve_contact(unused);
    m_lambda = m_contact->lambda_next();
    m_rotor->start_balance(m_lambda);
  }
  m_casing->gaps_at(m_rotor->boundary(), 0.0);
  // A massless boundary in contact at t = 0 (a tip grown into the liner)
  // starts with loaded bars: their energy is in E0, and W_contact counts the
  // bars' work from there.
  m_initial_bar_energy = m_liner ? m_liner->elastic_energy() : 0.0;
  m_initial_energy = energy();
}

StepReport ComponentIntegrator::step() {
  StepReport report;
  const double t_next = (m_n + 1) * m_dt;
  m_rotor->predict(m_lambda, time(), t_next);
  m_casing->predict(m_rotor->trial_boundary(), m_rotor->boundary(), time(), t_next);
  solve_contact(report);
  const Eigen::VectorXd& solved = m_contact->lambda_next();
  m_rotor->correct(solved);
  m_casing->correct(solved);
  // Work of (*) at time n: lambda_n . B (x_{n+1} - x_{n-1}) / 2, lambda_n the
  // solved multipliers when they enforce the contact at x_{n+1}, the previous
  // ones when the step's balance is at the new level.
  const Eigen::VectorXd& lambda_n = m_rotor->contact_at_next_level() ? m_lambda : solved;
  if (lambda_n.any()) {
    m_contact->add_contact_work(lambda_n, m_casing->rows(), m_rotor->boundary_increment());
    if (m_liner) {
      // The casing surface's own move under the normal forces, for the
      // unmatched work (liner_unmatched_work()).
      const RigidCasing& casing = m_casing->tips();
      for (int c = 0; c < m_nc; ++c)
        m_wall_work -= 0.5 * lambda_n(3 * c) *
                       (casing.imposed_gap(c, t_next) - casing.imposed_gap(c, t_next - 2.0 * m_dt));
    }
  }
  m_rotor->add_step_work();
  m_lambda = solved;
  m_rotor->advance();
  m_casing->advance();
  m_casing->gaps_at(m_rotor->boundary(), t_next);
  ++m_n;
  if (!m_rotor->finite() || !m_casing->finite() || !m_casing->gap().allFinite())
    throw ComponentIntegrationError(kWhere + "step " + std::to_string(m_n) +
                                        " (t = " + message_number(time()) +
                                        " s): the state is not finite (blow-up)",
                                    remedied_by({Remedy::smaller_step_safety_unforced}));
  return report;
}

double ComponentIntegrator::energy() const {
  if (m_casing->flexible()) return m_rotor->energy() + m_casing->energy();
  return m_liner ? m_rotor->energy() + m_liner->elastic_energy() : m_rotor->energy();
}

double ComponentIntegrator::contact_work() const {
  if (m_casing->flexible()) return m_contact->contact_work() + m_casing->contact_work();
  return m_liner ? m_contact->contact_work() + (m_liner->elastic_energy() - m_initial_bar_energy) +
                       m_liner->plastic_work()
                 : m_contact->contact_work();
}

double ComponentIntegrator::external_work() const {
  if (m_casing->flexible()) return m_rotor->external_work() + m_casing->external_work();
  return m_rotor->external_work();
}

double ComponentIntegrator::plastic_work() const {
  return m_liner ? m_liner->plastic_work() : 0.0;
}

double ComponentIntegrator::liner_unmatched_work() const {
  return m_liner ? (m_wall_work - m_liner->normal_work()) -
                       (m_liner->elastic_energy() - m_initial_bar_energy + m_liner->plastic_work())
                 : 0.0;
}

double ComponentIntegrator::response(const Eigen::Ref<const Eigen::RowVectorXd>& row) const {
  if (row.size() != m_r)
    throw std::invalid_argument(kWhere + "response: the row has " + std::to_string(row.size()) +
                                " entries, allowed " + std::to_string(m_r));
  return row.dot(q());
}

} // namespace rsi
