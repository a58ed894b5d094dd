#include "liner_wear.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace rsi {

namespace {

// Cell a ranks above cell b: deeper, or as deep and earlier (header).
bool ranks_above(const std::vector<double>& ring, std::size_t a, std::size_t b) {
  return ring[a] > ring[b] || (ring[a] == ring[b] && a < b);
}

std::size_t root_of(std::vector<std::size_t>& parent, std::size_t c) {
  while (parent[c] != c) {
    parent[c] = parent[parent[c]];
    c = parent[c];
  }
  return c;
}

} // namespace

int ring_lobes(const std::vector<double>& ring, double deepest) {
  const std::size_t n = ring.size();
  if (n == 0) return 0;
  const double least = kLobeProminence * deepest;
  const auto is_lobe = [&](double prominence) { return prominence > 0.0 && prominence >= least; };
  // The superlevel sets' merge tree: cells join in rank order; a component's
  // root is its top, and where two components meet (at the joining cell's
  // depth, their saddle) the one with the lower-ranked top ends there, its
  // prominence its top's depth less the saddle's.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return ranks_above(ring, a, b); });
  constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
  std::vector<std::size_t> parent(n, kAbsent);
  int lobes = 0;
  for (const std::size_t c : order) {
    parent[c] = c;
    for (const std::size_t side : {(c + n - 1) % n, (c + 1) % n}) {
      if (side == c || parent[side] == kAbsent) continue;
      const std::size_t mine = root_of(parent, c);
      const std::size_t theirs = root_of(parent, side);
      if (mine == theirs) continue;
      const bool mine_above = ranks_above(ring, mine, theirs);
      const std::size_t ends = mine_above ? theirs : mine;
      if (ends != c && is_lobe(ring[ends] - ring[c])) ++lobes;
      parent[ends] = mine_above ? mine : theirs;
    }
  }
  // The last component is the ring's top peak: its prominence is the range.
  const std::size_t top = order.front();
  if (is_lobe(ring[top] - ring[order.back()])) ++lobes;
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
