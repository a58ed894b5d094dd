#include "terminal_progress.hpp"

#include <chrono>
#include <cstdio>
#include <unistd.h>

namespace rsi {

std::function<void(double)> terminal_progress(const std::string& what) {
  if (!::isatty(STDERR_FILENO)) return {};
  const auto start = std::chrono::steady_clock::now();
  const std::string prefix = what.empty() ? "" : what + ": ";
  return [start, prefix](double fraction) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed <= 1.0) return;
    if (fraction > 0.0)
      std::fprintf(stderr, "\r%s%5.1f%% (%.1f s, about %.0f s left)   ", prefix.c_str(),
                   100.0 * fraction, elapsed, elapsed * (1.0 - fraction) / fraction);
    else
      std::fprintf(stderr, "\r%s%.1f s", prefix.c_str(), elapsed);
  };
}

void finish_terminal_progress(const std::function<void(double)>& progress) {
  if (progress) std::fprintf(stderr, "\n");
}

} // namespace rsi
