#pragma once
// Progress of a long run on stderr (issue 13, class 9): the fraction done
// and the elapsed and estimated remaining time, only when stderr is a
// terminal (logs and pipes stay clean) and once the run has lasted a second.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace rsi {

/// A callback taking the fraction done in [0, 1]; empty when stderr is not
/// a terminal. `what` prefixes the line (e.g. "full"). The caller ends the
/// line (finish_terminal_progress) when the run returns.
std::function<void(double)> terminal_progress(const std::string& what = "");

/// Ends the progress line if one was drawn.
void finish_terminal_progress(const std::function<void(double)>& progress);

/// A stage with no step count of its own (loading, assembly, an
/// eigensolver, a basis build: minutes of Lanczos on a large casing) shown
/// on a terminal as "<what>: <elapsed> s", redrawn every second from the
/// first second on by a thread of its own, until done() or destruction,
/// which end the line; nothing when stderr is not a terminal.
class TerminalStage {
public:
  explicit TerminalStage(std::string what);
  ~TerminalStage();
  TerminalStage(const TerminalStage&) = delete;
  TerminalStage& operator=(const TerminalStage&) = delete;
  /// Stops the redraw and ends the line if one was drawn; idempotent.
  void done();

private:
  std::string m_what;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  bool m_done = false;
  bool m_drawn = false;
  std::thread m_thread;
};

} // namespace rsi
