#pragma once
// --speeds of rsi sweep and rsi modes: "FROM:TO:COUNT" (COUNT equally spaced speeds, both
// ends, the case file's formula) or "W1,W2,..." [rad/s], 1 to 100000 speeds.

#include <string>
#include <vector>

namespace rsi {

/// The paper's case takes speeds in [0, 1e5); a component case signed
/// speeds in (-1e5, 1e5) (its sign is the rotation's direction; the
/// component's own checks refuse 0 and a change of sign).
enum class SpeedSign { non_negative, any };

/// Throws UsageError naming --speeds and the allowed form and range.
std::vector<double> parse_speeds_option(const std::string& text, SpeedSign sign);

} // namespace rsi
