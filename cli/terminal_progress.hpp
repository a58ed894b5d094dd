#pragma once
// Progress of a long run on stderr (issue 13, class 9): the fraction done
// and the elapsed and estimated remaining time, only when stderr is a
// terminal (logs and pipes stay clean) and once the run has lasted a second.

#include <functional>
#include <string>

namespace rsi {

/// A callback taking the fraction done in [0, 1]; empty when stderr is not
/// a terminal. `what` prefixes the line (e.g. "full"). The caller ends the
/// line (finish_terminal_progress) when the run returns.
std::function<void(double)> terminal_progress(const std::string& what = "");

/// Ends the progress line if one was drawn.
void finish_terminal_progress(const std::function<void(double)>& progress);

} // namespace rsi
