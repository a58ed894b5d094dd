#include "component_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rsi {

namespace {

/// The first contact whose normal displacement exceeds its radius (-1: none).
int runaway_contact(const ComponentIntegrator& integrator) {
  const RigidCasing& casing = integrator.casing();
  for (int c = 0; c < casing.n_contacts(); ++c)
    if (!(std::abs(integrator.gap()(c) - casing.imposed_gap(c, integrator.time())) <=
          casing.radius(c)))
      return c;
  return -1;
}

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
  if (!started) integrator.start();
  ComponentRunSummary s;
  s.steps_requested = options.steps;
  s.dt = integrator.dt();
  s.omega_max = integrator.omega_max();
  s.critical_dt = integrator.critical_dt();
  s.initial_energy = integrator.initial_energy();
  s.energy_scale = std::abs(s.initial_energy);
  const auto record = [&](double energy) {
    const ComponentSample row{integrator.time(),
                              integrator.response(response_row),
                              integrator.gap(),
                              integrator.lambda(),
                              energy,
                              integrator.contact_work(),
                              integrator.damping_work(),
                              integrator.external_work()};
    sink(row);
  };
  record(integrator.energy());
  s.status = "completed";
  s.completed = true;
  bool first_contact = true;
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  for (std::int64_t n = 1; n <= options.steps; ++n) {
    if (n % 1000 == 0 && options.checkpoint) options.checkpoint();
    StepReport r;
    try {
      r = integrator.step();
    } catch (const ComponentIntegrationError& e) {
      s.completed = false;
      s.status = e.what();
      break;
    }
    s.steps = n;
    const int runaway = runaway_contact(integrator);
    if (runaway >= 0) {
      std::ostringstream m;
      m.precision(6);
      const RigidCasing& casing = integrator.casing();
      m << "runaway at step " << n << " (t = " << integrator.time() << " s): contact node "
        << runaway + 1 << " moved "
        << integrator.gap()(runaway) - casing.imposed_gap(runaway, integrator.time())
        << " along its normal, more than its radius " << casing.radius(runaway)
        << " (the small-displacement model is left: an unstable step or a blow-up)";
      s.completed = false;
      s.status = m.str();
      break;
    }
    if (r.n_active > 0) {
      s.max_penetration = std::max(s.max_penetration, r.max_penetration);
      s.min_lambda = first_contact ? r.min_lambda : std::min(s.min_lambda, r.min_lambda);
      first_contact = false;
    }
    s.max_complementarity = std::max(s.max_complementarity, r.max_complementarity);
    s.max_cone_violation = std::max(s.max_cone_violation, r.max_cone_violation);
    s.max_stick_slip_residual = std::max(s.max_stick_slip_residual, r.max_stick_slip_residual);
    s.stick_slip_transitions += r.stick_slip_transitions;
    s.stick_contact_steps += r.n_stick;
    s.slip_contact_steps += r.n_slip;
    const bool sample = n % options.output_every == 0;
    const bool check = n % options.energy_every == 0 || n == options.steps;
    if (sample && !check) record(std::numeric_limits<double>::quiet_NaN());
    if (check) {
      const double e = integrator.energy();
      const double wc = integrator.contact_work(), wd = integrator.damping_work();
      const double we = integrator.external_work(); // 0 without a force: the same arithmetic
      s.energy_scale = std::max({s.energy_scale, std::abs(e), std::abs(wc), wd, std::abs(we)});
      const double error = std::abs(e - s.initial_energy - we - wc + wd);
      s.energy_balance_error = std::max(s.energy_balance_error, error);
      if (sample) record(e);
      if (!(error <= options.balance_tolerance * s.energy_scale)) {
        std::ostringstream m;
        m.precision(6);
        m << "energy balance broken at step " << n << " (t = " << integrator.time()
          << " s): |E - E0 - W_ext - W_contact + W_damp| = " << error << " > "
          << options.balance_tolerance << " x scale " << s.energy_scale
          << " (instability or solver trouble)";
        s.completed = false;
        s.status = m.str();
        break;
      }
    }
  }
  s.integration_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.integration_cpu_seconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  s.final_contact_work = integrator.contact_work();
  s.final_damping_work = integrator.damping_work();
  s.final_external_work = integrator.external_work();
  s.sweeps = integrator.sweeps();
  return s;
}

} // namespace rsi
