#include "sweep_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace rsi {

std::vector<int> balance_tasks(const std::vector<double>& cost, int ranks) {
  if (ranks < 1) throw std::invalid_argument("balance_tasks: ranks must be >= 1");
  for (double c : cost)
    if (!std::isfinite(c) || c < 0.0)
      throw std::invalid_argument("balance_tasks: costs must be finite and >= 0");
  std::vector<size_t> order(cost.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return cost[a] > cost[b]; });
  std::vector<double> load(static_cast<size_t>(ranks), 0.0);
  std::vector<int> rank(cost.size(), 0);
  for (size_t task : order) {
    const auto least = std::min_element(load.begin(), load.end()); // first of equals
    rank[task] = static_cast<int>(least - load.begin());
    *least += cost[task];
  }
  return rank;
}

} // namespace rsi
