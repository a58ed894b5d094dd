#pragma once
// The options of `rsi sweep`, read by the command and by the sweep points
// of each kind of case (paper_sweep_points.hpp, component_sweep_points.hpp).

#include <string>
#include <vector>

#include "component_case.hpp"

namespace rsi {

struct SweepOptions {
  std::string case_path;
  std::string out = "out/sweep";
  /// --speeds: "FROM:TO:COUNT" or "W1,W2,..." [rad/s]; empty: the case's sweep.speeds.
  std::string speeds;
  /// --method: one run in place of the case's sweep.runs (empty: the case's).
  std::string method;
  int modes = 0;
  /// --boundary-modes: with --method cc, n_c (--modes its eta).
  int boundary_modes = 0;
  std::string selection = "lowest";
  int casing_modes = 0;
  std::string time_step = "case";
  double step_safety = 0.9;
  int jobs = 0;              ///< threads a process; 0: 2 alone, 1 a rank under mpirun
  bool quiet = false;        ///< no progress lines on stderr
  bool report = true;        ///< run the case's report generator (reports/) at the end
  ComponentLoadOptions load; ///< component cases: --source, --ccx-cache
  /// The paper-case run options given (--casing-modes, --selection,
  /// --time-step, --step-safety): a component case refuses them.
  std::vector<std::string> paper_run_options;
};

} // namespace rsi
