#pragma once
// Runs an external program (gmsh, ccx) as a child process: posix_spawnp
// with the standard output and error of the child written to a log file,
// the parent waiting for its exit status. No shell is involved, so file
// names need no quoting.
//
// The child leads a process group of its own, so that a signal meant for
// rsi stops it and everything it started (ccx's and gmsh's own threads and
// children), and nothing else: while it runs, the parent polls the
// interruption flag (interruption_flag.hpp) every 20 ms; a SIGINT or
// SIGTERM recorded there is forwarded to the child's group, the child is
// waited for (SIGKILL to the group after 5 s) and Interrupted thrown.
// Ctrl-C on a terminal reaches rsi's group only; it reaches the child
// through this forwarding.

#include <string>
#include <vector>

namespace rsi {

struct ChildResult {
  bool started = false; ///< false: the program could not be executed (missing, not executable)
  int exit_status = -1; ///< exit code when the child exited normally, else -1
  int signal = 0;       ///< signal number when the child was killed by a signal, else 0
  std::string output;   ///< everything the child wrote to stdout and stderr
  std::string error;    ///< why it did not start or could not be waited for

  bool succeeded() const { return started && exit_status == 0; }
};

/// Runs argv[0] (looked up on PATH when it has no '/') with arguments
/// argv[1..], in `working_dir` (empty: the caller's), its stdout and stderr
/// both written to `log_path` (truncated), which is then read back into
/// ChildResult::output. Never throws for a failing child: the result says
/// what happened. Throws std::invalid_argument for an empty argv, and
/// Interrupted (the child stopped and reaped first) when a signal is
/// recorded while it runs.
ChildResult run_child(const std::vector<std::string>& argv, const std::string& working_dir,
                      const std::string& log_path);

/// The command line as one string, for messages (arguments separated by spaces).
std::string command_text(const std::vector<std::string>& argv);

/// True when `program` names an executable file, directly (with a '/') or on PATH.
bool executable_on_path(const std::string& program);

} // namespace rsi
