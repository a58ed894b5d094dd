#pragma once
// Gap-history error norms of SPEC §4 V6, on the blade-1 gap:
//   e_2   = || g_red - g_ref ||_2 / || g_ref ||_2
//   e_inf = max | g_red - g_ref | / max | g_ref |
// over the history rows (the same sampling in both runs).

#include <stdexcept>

#include "history.hpp"

namespace rsi {

struct GapErrors {
  double e2 = 0.0;
  double e_inf = 0.0;
};

/// Throws std::invalid_argument if the two histories have different rows.
inline GapErrors blade1_gap_errors(const History& reduced, const History& reference) {
  if (reduced.n_rows() != reference.n_rows())
    throw std::invalid_argument("blade1_gap_errors: the histories have " +
                                std::to_string(reduced.n_rows()) + " and " +
                                std::to_string(reference.n_rows()) + " rows");
  double diff2 = 0.0, ref2 = 0.0, diff_max = 0.0, ref_max = 0.0;
  for (int i = 0; i < reference.n_rows(); ++i) {
    const double d = reduced.gap[i](0) - reference.gap[i](0);
    diff2 += d * d;
    ref2 += reference.gap[i](0) * reference.gap[i](0);
    diff_max = std::max(diff_max, std::abs(d));
    ref_max = std::max(ref_max, std::abs(reference.gap[i](0)));
  }
  return {std::sqrt(diff2 / ref2), diff_max / ref_max};
}

} // namespace rsi
