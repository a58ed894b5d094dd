#pragma once
// Which rank runs which task of a sweep (issue 15): the longest-processing-
// time rule on the expected costs. Tasks are taken by decreasing cost (ties:
// lower index first) and each goes to the rank with the least cost so far
// (ties: lower rank). Every rank computes the same assignment from the same
// costs, so no message is needed to agree on it. Graham (1969): the
// makespan is at most 4/3 - 1/(3 ranks) of the optimum, and with many
// tasks of similar cost the ranks' totals differ by at most one task.

#include <vector>

namespace rsi {

/// rank of each task (size of `cost`), for `ranks` >= 1 ranks. Throws
/// std::invalid_argument for ranks < 1 or a negative or non-finite cost.
std::vector<int> balance_tasks(const std::vector<double>& cost, int ranks);

} // namespace rsi
