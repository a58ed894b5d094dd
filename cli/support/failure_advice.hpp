#pragma once
// The one place that words a failure's advice in the CLI's terms: the
// option or case key behind the input a kernel names (failure_kinds.hpp),
// and what to change. The kernels (reference/, reduced/) never name an
// option or a key; every `rsi: error:` line, and every failed run's reason a
// campaign or a sweep records, is rendered here from the kernel's text and
// its FailureAdvice.

#include <exception>
#include <string>

#include "failure_kinds.hpp"
#include "history.hpp"
#include "run_monitor.hpp"

namespace rsi {

/// CONTEXT + "NAME: " (the failed input's option or key) + `what` + the
/// remedies' words, in the order the kernel gave them.
std::string with_advice(const std::string& what, const FailureAdvice& advice);

/// What the user reads for `e`: with_advice(e.what(), its advice) for the
/// two kinds of failure, e.what() for any other exception.
std::string failure_message(const std::exception& e);

/// What the user reads for the status of run `s`: "completed", or what
/// stopped it with the advice of the failure that did (with_advice).
std::string run_status(const RunSummary& s);

// A step at or above the stability limit: `rsi simulate` offers --force;
// `rsi campaign` and `rsi sweep` have none, so their messages name the keys
// they read the step from instead.

/// `what` with its trailing " or --force" (the remedy of simulate) replaced
/// by " (" + remedy + ")"; `what` unchanged without it.
std::string without_force(const std::string& what, const std::string& remedy);

/// The same, as the StabilityError a command without --force throws.
StabilityError without_force(const StabilityError& e, const std::string& remedy);

/// What to change after the paper's case run of `s` was stopped by the
/// monitor (a blow-up): the step when it was at or above 2/omega_max
/// (--force), else the contact's friction and the blades' lean.
std::string stopped_run_remedy(const RunSummary& s);

} // namespace rsi
