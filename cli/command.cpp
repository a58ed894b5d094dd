#include "command.hpp"

#include <CLI/CLI.hpp>

namespace rsi {

bool Command::chosen() const {
  return m_command.parsed();
}

} // namespace rsi
