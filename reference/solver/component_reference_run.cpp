#include "component_reference_run.hpp"

#include <limits>
#include <memory>
#include <stdexcept>

#include "full_order_run.hpp"
#include "modal_analysis.hpp"
#include "rubbing_monitor.hpp"
#include "run_monitor.hpp"

namespace rsi {

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
  const Clock::time_point start = Clock::now();
  RunResult result;
  RunSummary& s = result.summary;
  s.method = "full";
  s.n_dofs = static_cast<int>(stiffness.rows());
  check_time_step(options.dt,
                  options.omega_max > 0.0 ? options.omega_max
                                          : max_angular_frequency(stiffness, mass),
                  options.force, s);
  s.bladed_disk_critical_dt = s.critical_dt;

  // The response dof rides in the rows as the one "tip" gathered on output
  // steps; the caller's sink gets it beside the row.
  RunOptions run;
  run.checkpoint = options.checkpoint;
  run.progress = options.progress;
  run.tip_displacement = true;
  run.history_sink = [&sink](const HistoryRow& row) {
    const double response = (*row.tip_displacement)(0);
    const HistoryRow out{row.time,          row.gap,           row.lambda,
                         row.energy,        row.external_work, row.contact_work,
                         row.damping_work,  row.lambda_tangential};
    sink(out, response);
  };
  MonitorRules rules;
  rules.steps_requested = static_cast<int>(options.steps);
  rules.output_every = options.output_every;
  rules.energy_every = options.energy_every;
  rules.row_at_last_step = false;
  rules.balance_tolerance = options.balance_tolerance;
  RunMonitor monitor(rules, std::make_unique<RubbingMonitor>(law), run, result);

  const StructureContact contact(law);
  FullOrderSystem system;
  system.stiffness = &stiffness;
  system.mass = &mass;
  system.dt = options.dt;
  system.damping = options.damping;
  system.contact = &contact;
  system.tip_dofs = {response_dof};
  system.failure_is_status = true;
  drive_full_order(system, monitor, s, start);
  // A component run's clocks include its rows' output (as its reduced runs'
  // do: cli/rubbing_run.hpp compares them).
  s.integration_seconds += s.output_seconds;
  s.wall_seconds += s.output_seconds;
  s.output_seconds = 0.0;
  return s;
}

} // namespace rsi
