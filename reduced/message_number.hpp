#pragma once
// A number in an error message of the reduced solver: six significant
// digits, enough to recognize a value, short enough to read.

#include <sstream>
#include <string>

namespace rsi {

inline std::string message_number(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

} // namespace rsi
