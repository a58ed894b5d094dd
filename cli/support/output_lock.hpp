#pragma once
// The lock that keeps two rsi runs from writing one --out at once (issue
// 13, class 4): an exclusive flock(2) on DIR/.rsi-lock, a file holding the
// owner's pid (for the refusal message only).
//
// flock rather than an O_EXCL file: the kernel drops the lock when its
// process ends, however it ends (SIGKILL, a crash), so a lock file left by
// a dead run is simply taken over; an O_EXCL file would need a guess that
// its pid is dead (fooled by pid reuse, and racy when two runs find it
// stale at once). The file is unlinked while still locked, and a run that
// locked a file that was unlinked meanwhile (the path now names another
// file or none) tries again, so two runs never both hold "the" lock.

#include <string>

namespace rsi {

class OutputLock {
public:
  /// Locks `dir` (which must exist). Throws OutputError naming `option`:
  /// "OPTION DIR: another rsi run (pid N) is writing it" when another run
  /// holds it, or when the lock file cannot be created.
  OutputLock(const std::string& dir, const std::string& option);
  /// Removes the lock file, then releases the lock.
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

private:
  std::string m_path;
  int m_fd = -1; ///< owned; the descriptor holding the flock
};

} // namespace rsi
