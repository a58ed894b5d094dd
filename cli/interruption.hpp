#pragma once
// SIGINT and SIGTERM in the CLI (issue 13, class 6): the handlers only
// record the signal; long work polls it (the runs' checkpoint every 1000
// steps, the campaigns between runs, modal-campaign between bases, the wait
// for the report script) and throws Interrupted, whose unwinding removes
// every temporary file (StreamedTextFile), stops a child process, and ends
// in exit 128 + signal (130, 143) with one `rsi: error:` line. Work that
// polls nothing (an eigensolver, a ccx child) is interrupted when it ends:
// main treats a command that returns or throws with a signal pending as
// interrupted. Nothing of the interrupted run is committed: no file claims
// a finished run.
//
// The recorded signal is the one piece of process-wide state here: a
// signal handler can reach nothing else (async-signal-safe: one
// volatile std::sig_atomic_t store).

#include <stdexcept>
#include <string>

namespace rsi {

class Interrupted : public std::runtime_error {
public:
  explicit Interrupted(int signal);
  int signal() const { return m_signal; }
  int exit_status() const { return 128 + m_signal; }

private:
  int m_signal;
};

/// Installs the handlers of SIGINT and SIGTERM (without SA_RESTART, so a
/// blocking wait returns EINTR and can look).
void install_interruption_handlers();
/// The signal received, 0 if none.
int pending_signal();
/// Throws Interrupted if a signal was received.
void throw_if_interrupted();

} // namespace rsi
