#pragma once
// The signal a process was asked to stop by (SIGINT, SIGTERM), recorded by
// the CLI's handlers (cli/support/interruption.hpp) and polled by long work: the
// runs' checkpoint every 1000 steps, the eigensolvers' operators at every
// product (cholmod_shift_invert.hpp, block_shift_invert.hpp), a child
// process's wait (child_process.hpp: gmsh, ccx), the CLI's loops between
// runs. Work that cannot poll (one CHOLMOD factorisation, one dense LAPACK
// call) is interrupted when it returns.
//
// The recorded signal is the one piece of process-wide state of rsi: a
// signal handler can reach nothing else (async-signal-safe: one volatile
// std::sig_atomic_t store). It sits in the library, below the CLI, so that
// the library's long loops can poll it without a callback threaded through
// every call; a program that installs no handler (the tests) never sees it
// set.

#include <stdexcept>

namespace rsi {

/// Thrown where a poll finds a signal: its unwinding removes temporary
/// files and stops child processes; the CLI exits 128 + signal (130, 143)
/// with one `rsi: error:` line.
class Interrupted : public std::runtime_error {
public:
  explicit Interrupted(int signal);
  int signal() const { return m_signal; }
  int exit_status() const { return 128 + m_signal; }

private:
  int m_signal;
};

/// Records `signal` (from a signal handler: async-signal-safe).
void record_interruption(int signal) noexcept;
/// The signal recorded, 0 if none.
int pending_interruption() noexcept;
/// Throws Interrupted if a signal was recorded.
void throw_if_interrupted();

} // namespace rsi
