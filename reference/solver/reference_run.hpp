#pragma once
// The full finite-element reference run (SPEC §2-3): the bladed disk and the
// casing, both full, integrated by central differences and coupled only
// through blade-tip contact with friction.

#include "case_file.hpp"
#include "run_monitor.hpp"

namespace rsi {

/// Throws StabilityError (dt too large, not forced), IntegrationError or
/// ModalError (numerical failure). A blow-up is not an exception: the run
/// stops, summary.completed is false and summary.status says where.
RunResult run_reference(const Case& c, const RunOptions& options);

} // namespace rsi
