#pragma once
// The reduced solver's one time loop: every reduced run (the paper's bladed
// disk and casing, a component on a rigid casing) is this loop over a
// ReducedStepper, with what differs per kind of run (the loads that change,
// the history rows, the blow-up and energy-balance tests, the summary)
// plugged in as a DriveMonitor. The loop holds no physics.

#include <cstdint>
#include <exception>

#include "failure_kinds.hpp"
#include "reduced_stepper.hpp"

namespace rsi {

class DriveMonitor {
public:
  virtual ~DriveMonitor() = default;
  /// After start (the state at t = 0: the first history row).
  virtual void started() = 0;
  /// Before the step n -> n+1 (n = 0, 1, ...): loads that change between
  /// steps, checkpoints that may throw to abandon the run.
  virtual void before_step(std::int64_t /*n*/) {}
  /// The step n -> n+1 threw `failure`: true stops the run there as
  /// recorded by the monitor, false lets the failure through to the caller.
  virtual bool stops_on(const NumericalFailure& /*failure*/, std::int64_t /*n_next*/) {
    return false;
  }
  /// After the step to n_next = n + 1 with its report: false stops the run.
  virtual bool after_step(std::int64_t n_next, const StepReport& report) = 0;
};

/// Starts `integrator` from rest unless `started` (a run that continues),
/// then takes up to `steps` steps, stopped early by the monitor. Returns the
/// steps taken (a step that threw and was stopped on is not counted).
std::int64_t drive_reduced(ReducedStepper& integrator, std::int64_t steps, DriveMonitor& monitor,
                           bool started = false);

} // namespace rsi
