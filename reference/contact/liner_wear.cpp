#include "liner_wear.hpp"

#include <algorithm>
#include <cstddef>

namespace rsi {

int ring_lobes(const std::vector<double>& ring, double deepest) {
  const std::size_t n = ring.size();
  if (n == 0) return 0;
  const double half = 0.5 * deepest;
  // A cell where the depth changes from the previous one starts a run;
  // none: the ring is flat.
  std::size_t start = n;
  for (std::size_t i = 0; i < n; ++i)
    if (ring[i] != ring[(i + n - 1) % n]) {
      start = i;
      break;
    }
  if (start == n) return ring[0] > half && deepest > 0.0 ? 1 : 0;
  int lobes = 0;
  std::size_t i = start;
  std::size_t walked = 0;
  while (walked < n) {
    std::size_t length = 1;
    while (length < n && ring[(i + length) % n] == ring[i]) ++length;
    const double before = ring[(i + n - 1) % n];
    const double after = ring[(i + length) % n];
    if (ring[i] > before && ring[i] > after && ring[i] > half) ++lobes;
    i = (i + length) % n;
    walked += length;
  }
  return lobes;
}

int wear_lobes(const std::vector<double>& depth, int n_theta, int n_axial) {
  const double deepest = depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end());
  int lobes = 0;
  for (int j = 0; j < n_axial; ++j) {
    const std::vector<double> ring(depth.begin() + static_cast<std::ptrdiff_t>(j) * n_theta,
                                   depth.begin() + static_cast<std::ptrdiff_t>(j + 1) * n_theta);
    lobes = std::max(lobes, ring_lobes(ring, deepest));
  }
  return lobes;
}

} // namespace rsi
