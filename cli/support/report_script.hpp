#pragma once
// The report generators of reports/ (Python with matplotlib), run by the
// commands that end with a report, with Debian's /usr/bin/python3 (where
// python3-matplotlib installs; the python3 first on PATH may be another).

#include <string>

namespace rsi {

/// Runs /usr/bin/python3 RSI_REPORTS_DIR/`script` `dir` (its stdout
/// discarded, its stderr kept); its exit status (127 if it cannot be started).
int run_report_script(const std::string& script, const std::string& dir);

} // namespace rsi
