#pragma once
// The report generators of reports/ (Python with matplotlib), run by the
// commands that end with a report, with Debian's /usr/bin/python3 (where
// python3-matplotlib installs; the python3 first on PATH may be another).

#include <string>

namespace rsi {

/// Runs /usr/bin/python3 RSI_REPORTS_DIR/`script` `dir` (its stdout
/// discarded, its stderr kept); its exit status (127 if it cannot be started).
int run_report_script(const std::string& script, const std::string& dir);

/// Runs `script` on the staged folder `stage` of a command's --out `out`;
/// false if it fails, with the one `rsi: error:` line printed: the command
/// then exits 1 and publishes nothing (staged_output.hpp), --out stays as it was.
bool write_report(const std::string& script, const std::string& stage, const std::string& out);

} // namespace rsi
