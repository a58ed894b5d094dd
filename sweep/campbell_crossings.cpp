#include "campbell_crossings.hpp"

#include <cmath>
#include <stdexcept>

namespace rsi {

std::vector<CampbellCrossing> campbell_crossings(const std::vector<double>& speeds,
                                                 const Eigen::MatrixXd& frequencies_hz,
                                                 int max_order) {
  const int n = static_cast<int>(speeds.size());
  if (n < 2 || frequencies_hz.rows() != n)
    throw std::invalid_argument("campbell_crossings: at least two speeds, one row of "
                                "frequencies each");
  for (int s = 1; s < n; ++s)
    if (!(speeds[s] > speeds[s - 1]))
      throw std::invalid_argument("campbell_crossings: speeds must ascend");
  std::vector<CampbellCrossing> crossings;
  for (int i = 0; i < frequencies_hz.cols(); ++i)
    for (int k = 1; k <= max_order; ++k) {
      const auto d = [&](int s) { return frequencies_hz(s, i) - k * speeds[s] / (2.0 * M_PI); };
      for (int s = 1; s < n; ++s) {
        const double a = d(s - 1);
        const double b = d(s);
        // A root on a grid speed belongs to the interval it closes (b == 0),
        // so it is listed once; the first speed's own root is kept too.
        const bool crosses = (a > 0.0 && b <= 0.0) || (a < 0.0 && b >= 0.0) ||
                             (s == 1 && a == 0.0);
        if (!crosses) continue;
        const double t = a == b ? 0.0 : a / (a - b);
        const double speed = speeds[s - 1] + t * (speeds[s] - speeds[s - 1]);
        crossings.push_back({i + 1, k, speed, k * speed / (2.0 * M_PI)});
      }
    }
  return crossings;
}

} // namespace rsi
