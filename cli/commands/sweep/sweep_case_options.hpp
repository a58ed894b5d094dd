#pragma once
// rsi sweep's options applied to each kind of case, and checked before
// anything is written: --speeds and --method (with its run options) in
// place of the case's sweep.speeds and sweep.runs, the runs against the
// model, then the sweep points of that kind (campaign/paper_sweep_points,
// campaign/component_sweep_points). Throws UsageError, CaseError,
// ImportError or ReductionError (exit 2).

#include <memory>

#include "case_file.hpp"
#include "component_case.hpp"
#include "sweep_options.hpp"
#include "sweep_points.hpp"

namespace rsi {

/// The paper's case; `jobs`: the runs a process holds at once (memory checks).
std::unique_ptr<SweepPoints> case_sweep(const Case& c, const SweepOptions& options, int jobs);

/// A component case with its "rubbing" object (one run at a time a thread:
/// `jobs` sets no memory check).
std::unique_ptr<SweepPoints> case_sweep(const ComponentCase& c, const SweepOptions& options,
                                        int jobs);

} // namespace rsi
