#pragma once
// A contact run of the reduced bladed disk (CB, CCM or Guyan) with the full
// casing (SPEC §3): same outputs as the reference run.

#include <functional>
#include <string>

#include <Eigen/Core>

#include "case_file.hpp"
#include "critical_step.hpp"
#include "reduced_basis.hpp"
#include "run_monitor.hpp"

namespace rsi {

/// Receives the bladed-disk field u = T q at time t [s] of a history row;
/// `u` is valid only during the call (not owned).
using FieldSink = std::function<void(double t, const Eigen::VectorXd& u)>;

struct ReducedRunOptions {
  RunOptions run; ///< its history_sink, if set, streams the history rows
  /// Recover the physical displacement u = T q of every bladed-disk dof on
  /// each output step (for stresses and animations).
  bool full_field = false;
  /// With full_field: when set, each field row is handed to it as it is
  /// produced and ReducedRunResult::field stays empty (streamed output).
  FieldSink field_sink;
  /// Reduced runs in progress at once in this process (a campaign's
  /// threads), for the memory check of their dense casing matrices.
  int runs_at_once = 1;
};

struct ReducedRunResult {
  RunResult run;
  ReducedBasis basis;
  /// Row i: the bladed-disk dofs at history row i (empty unless asked, or
  /// when streamed through ReducedRunOptions::field_sink).
  Eigen::MatrixXd field;
};

/// Throws ReductionError (method, mode count, R_B, a massless boundary),
/// StabilityError (dt at or above the reduced model's 2/omega_max, not
/// forced) or ReducedIntegrationError. A blow-up stops the run
/// (summary.completed false).
ReducedRunResult run_reduced(const Case& c, const std::string& method, int modes,
                             const ReducedRunOptions& options);

/// The same with a basis built (or altered) by the caller.
ReducedRunResult run_reduced(const Case& c, const ReducedBasis& basis,
                             const ReducedRunOptions& options);

} // namespace rsi
