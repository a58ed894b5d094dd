#include "component_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "reduced_drive.hpp"

namespace rsi {

namespace {

/// The first contact whose normal displacement exceeds its radius (-1: none).
int runaway_contact(const ComponentIntegrator& integrator) {
  const RigidCasing& casing = integrator.casing();
  for (int c = 0; c < casing.n_contacts(); ++c)
    if (!(std::abs(integrator.gap()(c) - integrator.rest_gap(c, integrator.time())) <=
          casing.radius(c)))
      return c;
  return -1;
}

/// The component run's monitor (component_run.hpp): the sampled rows, the
/// certificate maxima of every step, the runaway and energy-balance tests.
class ComponentMonitor final : public DriveMonitor {
public:
  /// Every argument must outlive the monitor (not owned).
  ComponentMonitor(const ComponentIntegrator& integrator,
                   const Eigen::Ref<const Eigen::RowVectorXd>& response_row,
                   const ComponentRunOptions& options, const ComponentSampleSink& sink,
                   ComponentRunSummary& summary)
      : m_integrator(integrator)
      , m_response_row(response_row)
      , m_options(options)
      , m_sink(sink)
      , m_s(summary) {}

  void started() override {
    ComponentRunSummary& s = m_s;
    s.steps_requested = m_options.steps;
    s.dt = m_integrator.dt();
    s.omega_max = m_integrator.omega_max();
    s.critical_dt = m_integrator.critical_dt();
    s.initial_energy = m_integrator.initial_energy();
    s.energy_scale = std::abs(s.initial_energy);
    record(m_integrator.energy());
    s.status = "completed";
    s.completed = true;
    m_t0 = std::chrono::steady_clock::now();
    m_c0 = std::clock();
  }

  void before_step(std::int64_t n) override {
    if ((n + 1) % 1000 == 0 && m_options.checkpoint) m_options.checkpoint();
  }

  bool stops_on(const NumericalFailure& failure, std::int64_t /*n_next*/) override {
    if (dynamic_cast<const ComponentIntegrationError*>(&failure) == nullptr) return false;
    m_s.completed = false;
    m_s.status = failure.what();
    m_s.status_advice = failure.advice();
    return true;
  }

  bool after_step(std::int64_t n, const StepReport& r) override {
    ComponentRunSummary& s = m_s;
    const ComponentIntegrator& integrator = m_integrator;
    s.steps = n;
    const int runaway = runaway_contact(integrator);
    if (runaway >= 0) {
      std::ostringstream m;
      m.precision(6);
      const RigidCasing& casing = integrator.casing();
      m << "runaway at step " << n << " (t = " << integrator.time() << " s): contact node "
        << runaway + 1 << " moved "
        << integrator.gap()(runaway) - integrator.rest_gap(runaway, integrator.time())
        << " along its normal, more than its radius " << casing.radius(runaway)
        << " (the small-displacement model is left: an unstable step or a blow-up)";
      s.completed = false;
      s.status = m.str();
      return false;
    }
    if (r.n_active > 0) {
      s.max_penetration = std::max(s.max_penetration, r.max_penetration);
      s.min_lambda = m_first_contact ? r.min_lambda : std::min(s.min_lambda, r.min_lambda);
      m_first_contact = false;
    }
    s.max_complementarity = std::max(s.max_complementarity, r.max_complementarity);
    s.max_cone_violation = std::max(s.max_cone_violation, r.max_cone_violation);
    s.max_stick_slip_residual = std::max(s.max_stick_slip_residual, r.max_stick_slip_residual);
    s.stick_slip_transitions += r.stick_slip_transitions;
    s.stick_contact_steps += r.n_stick;
    s.slip_contact_steps += r.n_slip;
    const bool sample = n % m_options.output_every == 0;
    const bool check = n % m_options.energy_every == 0 || n == m_options.steps;
    if (sample && !check) record(std::numeric_limits<double>::quiet_NaN());
    if (check) {
      const double e = integrator.energy();
      const double wc = integrator.contact_work(), wd = integrator.damping_work();
      const double we = integrator.external_work(); // 0 without a force: the same arithmetic
      const double wp = integrator.plastic_work();  // 0 without a liner: the same arithmetic
      s.energy_scale = std::max({s.energy_scale, std::abs(e), std::abs(wc), wd, std::abs(we), wp});
      const double error = std::abs(e - s.initial_energy - we - wc + wd + wp);
      s.energy_balance_error = std::max(s.energy_balance_error, error);
      if (sample) record(e);
      if (!(error <= m_options.balance_tolerance * s.energy_scale)) {
        std::ostringstream m;
        m.precision(6);
        m << "energy balance broken at step " << n << " (t = " << integrator.time()
          << " s): |E - E0 - W_ext - W_contact + W_damp"
          << (integrator.liner() ? " + W_plastic" : "") << "| = " << error << " > "
          << m_options.balance_tolerance << " x scale " << s.energy_scale
          << " (instability or solver trouble)";
        s.completed = false;
        s.status = m.str();
        return false;
      }
    }
    return true;
  }

  /// The clocks and the final works, after the loop.
  void finish() {
    ComponentRunSummary& s = m_s;
    s.integration_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_t0).count();
    s.integration_cpu_seconds = static_cast<double>(std::clock() - m_c0) / CLOCKS_PER_SEC;
    s.final_contact_work = m_integrator.contact_work();
    s.final_damping_work = m_integrator.damping_work();
    s.final_external_work = m_integrator.external_work();
    s.sweeps = m_integrator.sweeps();
    if (const LinerContactSolve* liner = m_integrator.liner()) {
      s.liner = true;
      s.final_plastic_work = liner->plastic_work();
      s.liner_unmatched_work = m_integrator.liner_unmatched_work();
      s.max_law_residual = liner->max_law_residual();
    }
  }

private:
  void record(double energy) {
    const double plastic = m_integrator.plastic_work();
    const ComponentSample row{m_integrator.time(),
                              m_integrator.response(m_response_row),
                              m_integrator.gap(),
                              m_integrator.lambda(),
                              energy,
                              m_integrator.contact_work(),
                              m_integrator.damping_work(),
                              m_integrator.external_work(),
                              m_integrator.liner() ? &plastic : nullptr};
    m_sink(row);
  }

  const ComponentIntegrator& m_integrator;
  const Eigen::Ref<const Eigen::RowVectorXd>& m_response_row;
  const ComponentRunOptions& m_options;
  const ComponentSampleSink& m_sink;
  ComponentRunSummary& m_s;
  bool m_first_contact = true;
  std::chrono::steady_clock::time_point m_t0;
  std::clock_t m_c0 = 0;
};

} // namespace

void ComponentHistory::append(const ComponentSample& row) {
  time.push_back(row.time);
  response.push_back(row.response);
  gap.push_back(row.gap);
  lambda.push_back(row.lambda);
  energy.push_back(row.energy);
  contact_work.push_back(row.contact_work);
  damping_work.push_back(row.damping_work);
  external_work.push_back(row.external_work);
  if (row.plastic_work) plastic_work.push_back(*row.plastic_work);
}

ComponentRunSummary run_component(ComponentIntegrator& integrator,
                                  const Eigen::Ref<const Eigen::RowVectorXd>& response_row,
                                  const ComponentRunOptions& options, ComponentHistory& history,
                                  bool started) {
  return run_component(
      integrator, response_row, options,
      [&history](const ComponentSample& row) { history.append(row); }, started);
}

ComponentRunSummary run_component(ComponentIntegrator& integrator,
                                  const Eigen::Ref<const Eigen::RowVectorXd>& response_row,
                                  const ComponentRunOptions& options,
                                  const ComponentSampleSink& sink, bool started) {
  const std::string where = "run_component: ";
  if (options.steps < 1)
    throw std::invalid_argument(where + "steps = " + std::to_string(options.steps) +
                                ", allowed >= 1");
  if (options.output_every < 1 || options.energy_every < 1)
    throw std::invalid_argument(where + "output_every and energy_every must be >= 1");
  if (!(options.balance_tolerance > 0.0 && options.balance_tolerance < 1.0))
    throw std::invalid_argument(where + "balance_tolerance must be in (0, 1)");
  ComponentRunSummary s;
  ComponentMonitor monitor(integrator, response_row, options, sink, s);
  drive_reduced(integrator, options.steps, monitor, started);
  monitor.finish();
  return s;
}

} // namespace rsi
