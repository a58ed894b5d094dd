#include "interruption_flag.hpp"

#include <csignal>
#include <string>

namespace rsi {
namespace {

volatile std::sig_atomic_t received = 0;

} // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") +
                         (signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal") +
                         ": the run was abandoned and none of its output kept")
    , m_signal(signal) {}

void record_interruption(int signal) noexcept {
  received = signal;
}

int pending_interruption() noexcept {
  return received;
}

void throw_if_interrupted() {
  if (const int signal = received; signal != 0) throw Interrupted(signal);
}

} // namespace rsi
