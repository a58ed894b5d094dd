#pragma once
// The options of `rsi simulate`, and its run on a component case
// (component_simulation.cpp); the paper's case runs in simulate_command.cpp.

#include <string>

#include "component_case.hpp"

namespace rsi {

class StagedOutput;

struct SimulateOptions {
  std::string case_path;
  std::string method = "full";
  int modes = 0;
  int boundary_modes = 0; ///< --boundary-modes: n_c of --method cc (component cases)
  std::string out = "out/simulate";
  bool force = false;
  bool full_field = false;
  std::string time_step = "case"; ///< --time-step: case, own or a step in seconds (reduced methods)
  double step_safety = 0.9;       ///< --step-safety: of --time-step own
  int casing_modes = 0;           ///< --casing-modes: 0 the full casing (reduced methods)
  std::string selection = "lowest"; ///< --selection: mode selection (reduced methods)
  ComponentLoadOptions load;        ///< component cases: --source, --ccx-cache
};

/// rsi simulate on a component case with a "rubbing" object: its rubbing
/// run (rubbing_run.hpp) -> history.csv, summary.json.
int simulate_component_case(const SimulateOptions& options, const ComponentCase& c,
                            StagedOutput& output);

} // namespace rsi
