#pragma once
// The sweep of the paper's case: the bladed disk in its flexible casing at
// each speed, over sweep.duration with sweep.damping, the full model and
// the reduced runs of sweep.runs; each history reduced to a row of
// indicators (sweep/sweep_indicators.hpp) and the model's interaction lines
// (sweep/interaction_lines.hpp) written beside them.

#include <functional>
#include <memory>
#include <string>

#include "case_file.hpp"
#include "run_monitor.hpp"
#include "sweep_points.hpp"

namespace rsi {

/// The message of a run whose step its run refuses at a speed (the
/// StabilityError `e`): the caller says what sets the step.
using RefusedStepMessage =
    std::function<std::string(const CampaignRun& run, const StabilityError& e)>;

/// The run's name in sweep.csv: "full", or the campaign's "cb-44-dt-own".
std::string sweep_run_name(const CampaignRun& run);

/// The runs of `c.sweep` (its speeds and runs: the case's, or the caller's
/// in place of them) at each of its speeds. The caller has checked them
/// against the model (run_list_checks.hpp); `disk_dofs`: the bladed disk's.
std::unique_ptr<SweepPoints> paper_sweep_points(Case c, int disk_dofs,
                                                RefusedStepMessage refused_step);

} // namespace rsi
