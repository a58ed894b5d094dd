#include "speeds_option.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "usage_error.hpp"

namespace rsi {

std::vector<double> parse_speeds_option(const std::string& text, SpeedSign sign) {
  const double lowest = sign == SpeedSign::non_negative ? 0.0 : -1e5;
  const std::string range =
      sign == SpeedSign::non_negative ? "[0, 100000)" : "(-100000, 100000)";
  const auto number = [&](const std::string& s) {
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(x) || x < lowest ||
        (sign == SpeedSign::any && x == lowest) || x >= 1e5)
      throw UsageError("--speeds: each speed must be a number in " + range + " rad/s, got '" + s +
                       "' in '" + text + "'");
    return x;
  };
  std::vector<std::string> parts;
  const char separator = text.find(':') != std::string::npos ? ':' : ',';
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);)
    parts.push_back(part);
  if (separator == ',') {
    if (parts.empty() || parts.size() > 100000)
      throw UsageError("--speeds: 1 to 100000 speeds, got '" + text + "'");
    std::vector<double> speeds;
    for (const std::string& p : parts)
      speeds.push_back(number(p));
    return speeds;
  }
  if (parts.size() != 3)
    throw UsageError("--speeds: FROM:TO:COUNT or W1,W2,... [rad/s], got '" + text + "'");
  const double from = number(parts[0]);
  const double to = number(parts[1]);
  char* end = nullptr;
  const long count = std::strtol(parts[2].c_str(), &end, 10);
  if (parts[2].empty() || *end != '\0' || count < 1 || count > 100000)
    throw UsageError("--speeds: COUNT must be an integer in [1, 100000], got '" + parts[2] + "'");
  if (count > 1 && !(to > from))
    throw UsageError("--speeds: TO must be above FROM when COUNT > 1, got '" + text + "'");
  std::vector<double> speeds;
  for (long i = 0; i < count; ++i) // the case file's formula (case_file.cpp read_speeds)
    speeds.push_back(count == 1 ? from : from + (to - from) * static_cast<double>(i) / (count - 1));
  return speeds;
}

} // namespace rsi
