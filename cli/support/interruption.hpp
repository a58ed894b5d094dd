#pragma once
// SIGINT and SIGTERM in the CLI: the handlers only record the signal
// (interruption_flag.hpp, the library's flag); long work polls it (the runs'
// checkpoint every 1000 steps, the campaigns between runs, modal-campaign
// between bases, the eigensolvers' operator products, the wait for a child
// process: gmsh, ccx, the report script, each stopped by the signal
// forwarded to its process group) and throws Interrupted, whose unwinding
// removes every temporary file (StreamedTextFile), and ends in exit 128 +
// signal (130, 143) with one `rsi: error:` line. Work that polls nothing
// (one CHOLMOD factorisation, one dense LAPACK call) is interrupted when it
// ends: main treats a command that returns or throws with a signal pending
// as interrupted. Nothing of the interrupted run is committed: no file
// claims a finished run.

#include "interruption_flag.hpp"

namespace rsi {

/// Installs the handlers of SIGINT and SIGTERM (without SA_RESTART, so a
/// blocking wait returns EINTR and can look).
void install_interruption_handlers();
/// The signal received, 0 if none.
int pending_signal();

} // namespace rsi
