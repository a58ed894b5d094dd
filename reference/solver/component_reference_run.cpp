#include "component_reference_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "central_difference.hpp"
#include "modal_analysis.hpp"
#include "run_monitor.hpp"

namespace rsi {

namespace {

/// The first contact whose normal displacement exceeds its radius, or whose
/// gap is not finite (-1: none).
int runaway_contact(const CentralDifference& cd, const RigidSurfaceContact& law) {
  for (int c = 0; c < law.n_contacts(); ++c)
    if (!(std::abs(cd.gap()(c) - law.imposed_gap(c, cd.time())) <= law.frame(c).radius))
      return c;
  return -1;
}

} // namespace

RunSummary run_component_reference(const Eigen::SparseMatrix<double>& stiffness,
                                   const Eigen::SparseMatrix<double>& mass,
                                   const RigidSurfaceContact& law, int response_dof,
                                   const ComponentReferenceOptions& options,
                                   const ComponentRowSink& sink) {
  const std::string where = "run_component_reference: ";
  if (options.steps < 1 || options.steps > std::numeric_limits<int>::max())
    throw std::invalid_argument(where + "steps = " + std::to_string(options.steps) +
                                ", allowed [1, " + std::to_string(std::numeric_limits<int>::max()) +
                                "]");
  if (options.output_every < 1 || options.energy_every < 1)
    throw std::invalid_argument(where + "output_every and energy_every must be >= 1");
  if (!(options.balance_tolerance > 0.0 && options.balance_tolerance < 1.0))
    throw std::invalid_argument(where + "balance_tolerance must be in (0, 1)");
  if (response_dof < 0 || response_dof >= stiffness.rows())
    throw std::invalid_argument(where + "response dof " + std::to_string(response_dof) +
                                " outside [0, " + std::to_string(stiffness.rows()) + ")");
  const auto start = std::chrono::steady_clock::now();
  RunSummary s;
  s.method = "full";
  s.n_dofs = static_cast<int>(stiffness.rows());
  s.steps_requested = static_cast<int>(options.steps);
  check_time_step(options.dt,
                  options.omega_max > 0.0 ? options.omega_max
                                          : max_angular_frequency(stiffness, mass),
                  options.force, s);
  s.bladed_disk_critical_dt = s.critical_dt;

  CentralDifference cd(stiffness, mass, options.dt, law, options.damping);
  s.flops_per_step = cd.flops_per_step();
  cd.start(Eigen::VectorXd::Zero(stiffness.rows()));
  s.initial_energy = cd.initial_energy();
  s.max_energy = s.initial_energy;
  s.energy_scale = std::abs(s.initial_energy);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto emit = [&](double energy) {
    const HistoryRow row{cd.time(),           cd.gap(),           cd.lambda(),
                         energy,              cd.external_work(), cd.contact_work(),
                         cd.damping_work(),   &cd.lambda_tangential()};
    sink(row, cd.displacement()(response_dof));
  };
  emit(cd.energy());
  s.status = "completed";
  s.completed = true;
  bool any_contact = false;
  const auto integration_start = std::chrono::steady_clock::now();
  for (std::int64_t n = 1; n <= options.steps; ++n) {
    if (n % 1000 == 0) {
      if (options.checkpoint) options.checkpoint();
      if (options.progress) options.progress(static_cast<double>(n) / options.steps);
    }
    StepReport r;
    try {
      r = cd.step();
    } catch (const IntegrationError& e) {
      s.completed = false;
      s.status = e.what();
      break;
    }
    s.steps = static_cast<int>(n);
    const int runaway = runaway_contact(cd, law);
    if (runaway >= 0) {
      std::ostringstream m;
      m.precision(6);
      m << "runaway at step " << n << " (t = " << cd.time() << " s): contact node " << runaway + 1
        << " moved " << cd.gap()(runaway) - law.imposed_gap(runaway, cd.time())
        << " along its normal, more than its radius " << law.frame(runaway).radius
        << " (the small-displacement model is left: an unstable step or a blow-up)";
      s.completed = false;
      s.status = m.str();
      break;
    }
    if (r.n_active > 0) {
      s.max_penetration = std::max(s.max_penetration, r.max_penetration);
      s.min_lambda = any_contact ? std::min(s.min_lambda, r.min_lambda) : r.min_lambda;
      if (!any_contact) s.first_contact_step = static_cast<int>(n);
      any_contact = true;
    }
    s.max_lambda = std::max(s.max_lambda, cd.lambda().maxCoeff());
    s.max_active = std::max(s.max_active, r.n_active);
    s.max_complementarity = std::max(s.max_complementarity, r.max_complementarity);
    s.max_friction_residual = std::max(s.max_friction_residual, r.max_friction_residual);
    s.sliding_reversals += r.sliding_reversals;
    s.max_cone_violation = std::max(s.max_cone_violation, r.max_cone_violation);
    s.max_stick_slip_residual = std::max(s.max_stick_slip_residual, r.max_stick_slip_residual);
    s.stick_slip_transitions += r.stick_slip_transitions;
    s.stick_contact_steps += r.n_stick;
    s.slip_contact_steps += r.n_slip;
    const bool sample = n % options.output_every == 0;
    const bool check = n % options.energy_every == 0 || n == options.steps;
    double energy = nan;
    if (check) {
      energy = cd.energy();
      const double wc = cd.contact_work(), wd = cd.damping_work();
      s.max_energy = std::max(s.max_energy, energy);
      s.energy_scale = std::max({s.energy_scale, std::abs(energy), std::abs(wc), wd});
      const double error = std::abs(energy - s.initial_energy - wc + wd);
      s.energy_balance_error = std::max(s.energy_balance_error, error);
      if (!(error <= options.balance_tolerance * s.energy_scale)) {
        std::ostringstream m;
        m.precision(6);
        m << "energy balance broken at step " << n << " (t = " << cd.time()
          << " s): |E - E0 - W_contact + W_damp| = " << error << " > "
          << options.balance_tolerance << " x scale " << s.energy_scale
          << " (instability or solver trouble)";
        s.completed = false;
        s.status = m.str();
        if (sample) emit(energy);
        break;
      }
    }
    if (sample) emit(energy);
  }
  const auto now = std::chrono::steady_clock::now();
  s.integration_seconds = std::chrono::duration<double>(now - integration_start).count();
  s.wall_seconds = std::chrono::duration<double>(now - start).count();
  s.final_contact_work = cd.contact_work();
  s.final_damping_work = cd.damping_work();
  return s;
}

} // namespace rsi
