#pragma once
// A run of ComponentIntegrator (component_integrator.hpp), stepped by the
// reduced time loop (reduced_drive.hpp) with the monitor below: the sampled
// histories issue 12 asks for (time, a response dof, per contact node the
// gap, lambda_n, lambda_t1, lambda_t2, energy and works) and a summary with
// the worst certificate over every step (not only the sampled ones).
//
// Monitors, checked every step: the integrator's own (a contact solve that
// fails, a non-finite state: ComponentIntegrationError, caught here and
// reported as the status with its step); and the energy balance
// |E - E_0 - W_ext - W_contact + W_damp| <= balance_tolerance * scale, scale
// the largest of E, |W_ext|, |W_contact|, W_damp so far (checked every
// energy_every steps: E costs 2 r^2; W_ext = 0 without an external force);
// (with an abradable liner, E = E0 + W_ext + W_contact - W_damp - W_plastic,
// ComponentIntegrator::contact_work) and every step the runaway test: a contact node whose normal displacement
// |g_c - g0_c(t)| exceeds its radius r_c has left the small-displacement
// model (a blow-up: an unstable step grows while the balance still closes,
// the moving casing's work growing with it; measured on the gmsh blade,
// MacNeal-50 past its held-boundary limit: 3e38 mm, balance 5e-16 of its
// scale). A run that breaks a monitor stops at that step, completed =
// false, status says which and when.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "component_integrator.hpp"

namespace rsi {

/// One sampled row as run_component produces it; the references are valid
/// only during the call of the sink that receives it.
struct ComponentSample {
  double time = 0.0;
  double response = 0.0;         ///< the response dof [length]
  const Eigen::VectorXd& gap;    ///< nc [length]
  const Eigen::VectorXd& lambda; ///< 3 nc: n, t1, t2 per contact [force]
  double energy = 0.0;           ///< E at an energy check, NaN between
  double contact_work = 0.0, damping_work = 0.0;
  double external_work = 0.0; ///< W_ext (0 without an external force)
  /// With an abradable liner: W_plastic up to the row; nullptr without.
  const double* plastic_work = nullptr;
};

/// Receives every sampled row in order (a history file streams them; a
/// ComponentHistory keeps them).
using ComponentSampleSink = std::function<void(const ComponentSample&)>;

struct ComponentHistory {
  std::vector<double> time;
  std::vector<double> response;        ///< the response dof [length]
  std::vector<Eigen::VectorXd> gap;    ///< nc per row [length]
  std::vector<Eigen::VectorXd> lambda; ///< 3 nc per row: n, t1, t2 per contact [force]
  std::vector<double> energy;          ///< E at the rows that are energy checks, NaN at the others
  std::vector<double> contact_work, damping_work;
  std::vector<double> external_work; ///< W_ext (0 without an external force)
  std::vector<double> plastic_work;  ///< W_plastic (empty without a liner)
  int n_rows() const { return static_cast<int>(time.size()); }
  /// Keeps a copy of `row`.
  void append(const ComponentSample& row);
};

struct ComponentRunSummary {
  std::int64_t steps_requested = 0;
  std::int64_t steps = 0;
  bool completed = false;
  std::string status;
  FailureAdvice status_advice; ///< what to change, when a failure stopped the run
  double dt = 0.0, omega_max = 0.0, critical_dt = 0.0;
  double integration_seconds = 0.0;     ///< wall time of the step loop
  double integration_cpu_seconds = 0.0; ///< the process's CPU time over it (std::clock)
  double max_penetration = 0.0, min_lambda = 0.0, max_complementarity = 0.0;
  double max_cone_violation = 0.0, max_stick_slip_residual = 0.0;
  long stick_slip_transitions = 0, stick_contact_steps = 0, slip_contact_steps = 0;
  double initial_energy = 0.0, energy_balance_error = 0.0, energy_scale = 0.0;
  double final_contact_work = 0.0, final_damping_work = 0.0;
  double final_external_work = 0.0; ///< W_ext at the end (0 without an external force)
  long sweeps = 0;
  /// With an abradable liner (liner_contact_solve.hpp): W_plastic at the end,
  /// the unmatched work (ComponentIntegrator::liner_unmatched_work) and the
  /// largest relative bar-law residual of any step.
  bool liner = false;
  double final_plastic_work = 0.0, liner_unmatched_work = 0.0, max_law_residual = 0.0;
};

struct ComponentRunOptions {
  std::int64_t steps = 0;           ///< >= 1 (64-bit: a count derived from a case)
  std::int64_t output_every = 1;    ///< >= 1
  std::int64_t energy_every = 1;    ///< >= 1; rows between energy checks carry energy NaN
  double balance_tolerance = 1e-8;  ///< relative, in (0, 1)
  std::function<void()> checkpoint; ///< called every 1000 steps (may throw: an interruption)
};

/// Starts `integrator` from zero initial conditions unless `started`, runs,
/// and hands every sampled row to `sink` as it is produced (nothing is
/// kept: the memory of a run does not grow with its length).
/// `response_row`: a row of T (r entries). Throws std::invalid_argument for
/// bad options.
ComponentRunSummary run_component(ComponentIntegrator& integrator,
                                  const Eigen::Ref<const Eigen::RowVectorXd>& response_row,
                                  const ComponentRunOptions& options,
                                  const ComponentSampleSink& sink, bool started = false);

/// The same, keeping every row in `history`.
ComponentRunSummary run_component(ComponentIntegrator& integrator,
                                  const Eigen::Ref<const Eigen::RowVectorXd>& response_row,
                                  const ComponentRunOptions& options, ComponentHistory& history,
                                  bool started = false);

} // namespace rsi
