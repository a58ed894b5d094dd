#include "interruption.hpp"

#include <csignal>
#include <cstring>

namespace rsi {
namespace {

extern "C" void record_signal(int signal) {
  record_interruption(signal);
}

} // namespace

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
  return pending_interruption();
}

} // namespace rsi
