#include "liner_patch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rsi {

namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("abradable liner tip patch: " + what);
}

/// The first and last integer i with centre (i + 1/2) w in [x - width/2, x + width/2].
std::pair<long long, long long> centres_within(double x, double width, double pitch) {
  const double lo = std::ceil((x - 0.5 * width) / pitch - 0.5);
  const double hi = std::floor((x + 0.5 * width) / pitch - 0.5);
  if (!(std::isfinite(lo) && std::isfinite(hi) && std::abs(lo) < 1e15 && std::abs(hi) < 1e15))
    refuse("window centre " + std::to_string(x) + " and width " + std::to_string(width) +
           " must be finite and of the liner's scale");
  return {static_cast<long long>(lo), static_cast<long long>(hi)};
}

} // namespace

std::vector<int> patch_sectors(const AbradableLiner& liner, double theta, double angular_width) {
  if (!(std::isfinite(angular_width) && angular_width >= 0.0))
    refuse("angular width " + std::to_string(angular_width) + " must be finite and >= 0");
  const long long n = liner.n_theta();
  const auto [lo, hi] = centres_within(theta, angular_width, liner.pitch());
  std::vector<int> sectors;
  if (hi < lo) {
    sectors.push_back(liner.angular_cell(theta));
  } else if (hi - lo + 1 >= n) {
    for (int i = 0; i < n; ++i) sectors.push_back(i);
  } else {
    for (long long i = lo; i <= hi; ++i) sectors.push_back(static_cast<int>(((i % n) + n) % n));
  }
  return sectors;
}

std::vector<int> patch_rows(const AbradableLiner& liner, double z, double width) {
  if (!(std::isfinite(width) && width >= 0.0))
    refuse("axial width " + std::to_string(width) + " must be finite and >= 0");
  const int own = liner.axial_row(z);
  const auto [lo, hi] = centres_within(z - liner.geometry().z_min, width, liner.row_width());
  std::vector<int> rows;
  for (long long j = std::max(lo, 0LL); j <= std::min(hi, liner.n_axial() - 1LL); ++j)
    rows.push_back(static_cast<int>(j));
  if (rows.empty()) rows.push_back(own);
  return rows;
}

LinerPatchResponse patch_compliant_force(const AbradableLiner& liner,
                                         const std::vector<LinerCellState>& states,
                                         double depth_pred, double compliance) {
  if (states.empty()) refuse("a patch needs at least one cell");
  if (!(std::isfinite(compliance) && compliance >= 0.0))
    refuse("compliance c = " + std::to_string(compliance) + " must be finite and >= 0");
  if (!std::isfinite(depth_pred))
    refuse("predicted depth = " + std::to_string(depth_pred) + " must be finite");
  const double k = liner.stiffness();
  const double kt = liner.tangent_stiffness();
  const std::size_t n = states.size();
  std::vector<double> wear(n), force_yield(n), delta_yield(n), breaks;
  breaks.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    wear[i] = states[i].wear;
    force_yield[i] = liner.yield_force(states[i]);
    delta_yield[i] = force_yield[i] / k;
    breaks.push_back(wear[i]);
    breaks.push_back(wear[i] + delta_yield[i]);
  }
  std::sort(breaks.begin(), breaks.end());
  // G(x) = x + c S(x), S the bars' force at the common depth x.
  const auto g_of = [&](double x) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double delta = x - wear[i];
      if (delta <= 0.0) continue;
      s += delta <= delta_yield[i] ? k * delta
                                   : force_yield[i] + kt * (delta - delta_yield[i]);
    }
    return x + compliance * s;
  };
  const auto first_above =
      std::partition_point(breaks.begin(), breaks.end(), [&](double x) { return g_of(x) <= depth_pred; });
  LinerPatchResponse out;
  if (first_above != breaks.begin()) {
    // The piece (left, right) holding the root; a breakpoint is either
    // <= left or >= right, so each bar's branch on it is exact.
    const double left = *(first_above - 1);
    double numerator = 0.0;
    double slope = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double delta_pred = depth_pred - wear[i];
      if (wear[i] + delta_yield[i] <= left) {
        numerator += force_yield[i] + kt * (delta_pred - delta_yield[i]);
        slope += kt;
      } else if (wear[i] <= left) {
        numerator += k * delta_pred;
        slope += k;
      }
    }
    out.force = numerator / (1.0 + compliance * slope);
  }
  for (std::size_t i = 0; i < n; ++i)
    out.bars.push_back(liner.bar_force(states[i], (depth_pred - wear[i]) - compliance * out.force));
  // c = 0: the law itself, the bars' own forces summed (as the one-bar solve).
  if (compliance == 0.0) {
    out.force = 0.0;
    for (const LinerBarResponse& b : out.bars) out.force += b.force;
  }
  return out;
}

} // namespace rsi
