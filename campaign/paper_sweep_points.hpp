#pragma once
// The sweep of the paper's case (issue 15): the bladed disk in its flexible
// casing at each speed, over sweep.duration with sweep.damping, the full
// model and the reduced runs of sweep.runs; each history reduced to a row of
// indicators (sweep/sweep_indicators.hpp) and the model's interaction lines
// (sweep/interaction_lines.hpp) written beside them.

#include <memory>

#include "sweep_options.hpp"
#include "sweep_points.hpp"

namespace rsi {

/// Checks `c` (its "sweep" object, or the options in place of it) against
/// the model; throws UsageError or CaseError (exit 2) before anything is
/// written. `jobs`: the runs a process holds at once (memory checks).
std::unique_ptr<SweepPoints> paper_sweep_points(Case c, const SweepOptions& options, int jobs);

} // namespace rsi
