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

namespace rsi {

/// CONTEXT + "NAME: " (the failed input's option or key) + `what` + the
/// remedies' words, in the order the kernel gave them.
std::string with_advice(const std::string& what, const FailureAdvice& advice);

/// What the user reads for `e`: with_advice(e.what(), its advice) for the
/// two kinds of failure, e.what() for any other exception.
std::string failure_message(const std::exception& e);

} // namespace rsi
