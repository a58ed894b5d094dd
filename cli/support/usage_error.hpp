#pragma once
// A command-line value outside its allowed range, or an option the chosen
// command or method does not take: bad input (exit status 2), its message
// naming the option and what is allowed.

#include "failure_kinds.hpp"

namespace rsi {

class UsageError : public BadInput {
public:
  using BadInput::BadInput;
};

} // namespace rsi
