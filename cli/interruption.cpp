#include "interruption.hpp"

#include <csignal>
#include <cstring>

namespace rsi {
namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void record_signal(int signal) {
  received = signal;
}

} // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") +
                         (signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal") +
                         ": the run was abandoned and none of its output kept")
    , m_signal(signal) {}

void install_interruption_handlers() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0; // no SA_RESTART: waits return EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int pending_signal() {
  return received;
}

void throw_if_interrupted() {
  if (const int signal = received; signal != 0) throw Interrupted(signal);
}

} // namespace rsi
