#pragma once
// What the user of a command can change after a failure that the library
// reports in its own terms (issue 13, class 8: every non-zero exit prints one
// `rsi: error:` line saying what failed and what to change).
//
// The library's StabilityError ends with "use a smaller step or --force",
// the remedy of `rsi simulate`; `rsi campaign` and `rsi sweep` have no
// --force, so their messages name the keys they read instead. A run that
// the monitor stopped (a blow-up, exit 3) gets the remedy that fits its
// step: above the stability limit (only with --force) or not.

#include <string>

#include "history.hpp"
#include "run_monitor.hpp"

namespace rsi {

/// `what` with its trailing " or --force" (StabilityError's remedy for
/// simulate) replaced by " (" + remedy + ")"; `what` unchanged without it.
std::string without_force(const std::string& what, const std::string& remedy);

/// The same, as the StabilityError a command without --force throws.
StabilityError without_force(const StabilityError& e, const std::string& remedy);

/// What to change after the paper's case run of `s` was stopped by the
/// monitor (a blow-up): the step when it was at or above 2/omega_max
/// (--force), else the contact's friction and the blades' lean.
std::string stopped_run_remedy(const RunSummary& s);

} // namespace rsi
