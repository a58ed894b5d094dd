#include "terminal_progress.hpp"

#include <chrono>
#include <cstdio>
#include <utility>
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

TerminalStage::TerminalStage(std::string what) : m_what(std::move(what)) {
  if (!::isatty(STDERR_FILENO)) {
    m_done = true;
    return;
  }
  m_thread = std::thread([this] {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(m_mutex);
    while (!m_wake.wait_for(lock, std::chrono::seconds(1), [this] { return m_done; })) {
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "\r%s: %.0f s", m_what.c_str(), elapsed);
      std::fflush(stderr);
      m_drawn = true;
    }
  });
}

TerminalStage::~TerminalStage() {
  done();
}

void TerminalStage::done() {
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    if (m_done && !m_thread.joinable()) return;
    m_done = true;
  }
  m_wake.notify_all();
  if (m_thread.joinable()) m_thread.join();
  if (m_drawn) std::fprintf(stderr, "\n");
  m_drawn = false;
}

} // namespace rsi
