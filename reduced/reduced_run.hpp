#pragma once
// A contact run of the reduced bladed disk (CB, CCM or Guyan) with the full
// casing (SPEC §3): same outputs as the reference run, stepped by the
// reduced time loop (reduced_drive.hpp).

#include <functional>
#include <string>

#include <Eigen/Core>

#include "case_file.hpp"
#include "casing_basis.hpp"
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
  /// The run's time step (run_step.hpp): the case's (default), the reduced
  /// system's own stable step, or a given one; rows at the case's output
  /// times in every case.
  StepRule step;
  /// Where a bad step is reported (CaseError's key).
  std::string step_key = "time_step";
  /// Where the mode count came from, for a basis too large for the memory:
  /// empty when the caller's own mode count (FailedInput::mode_count), else
  /// shown as it is (a campaign's run list entry).
  std::string modes_key;
  /// 0: the full casing; N_c >= 1: the casing in its lowest N_c modes plus
  /// the static correction for the forcing (casing_basis.hpp).
  int casing_modes = 0;
  /// How the kept modes are chosen (mode_selection.hpp): "lowest" (the
  /// first round's bases), "families", "forced" or "participation".
  std::string selection = "lowest";
  /// Reduced runs in progress at once in this process (a campaign's
  /// threads), for the memory check of their dense casing matrices.
  int runs_at_once = 1;
};

struct ReducedRunResult {
  RunResult run;
  ReducedBasis basis;
  CasingBasis casing_basis; ///< empty (size 0) with the full casing
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

/// The bladed-disk basis run_reduced builds for (method, modes, selection):
/// one basis serves every run of a sweep (the rotation enters only through
/// contact). Throws ReductionError.
ReducedBasis build_reduced_basis(const Case& c, const std::string& method, int modes,
                                 const std::string& selection);

/// The same with a basis built (or altered) by the caller.
ReducedRunResult run_reduced(const Case& c, const ReducedBasis& basis,
                             const ReducedRunOptions& options);

} // namespace rsi
