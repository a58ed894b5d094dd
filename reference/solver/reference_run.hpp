#pragma once
// The full finite-element reference run (SPEC §2-3): the bladed disk and the
// casing, both full, integrated by central differences and coupled only
// through blade-tip contact with friction: the paper's case as a problem
// (problem.hpp) through the one full-order loop (full_order_run.hpp).

#include "case_file.hpp"
#include "run_monitor.hpp"

namespace rsi {

/// run_full_order(paper_problem(c), options). Throws StabilityError (dt too
/// large, not forced), IntegrationError or ModalError (numerical failure).
/// A blow-up is not an exception: the run stops, summary.completed is false
/// and summary.status says where.
RunResult run_reference(const Case& c, const RunOptions& options);

} // namespace rsi
