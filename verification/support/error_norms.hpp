#pragma once
// Gap-history error norms of SPEC §4 V6, on the blade-1 gap:
//   e_2   = || g_red - g_ref ||_2 / || g_ref ||_2
//   e_inf = max | g_red - g_ref | / max | g_ref |
// over the history rows (the same sampling in both runs).

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "history.hpp"

namespace rsi {

struct GapErrors {
  double e2 = 0.0;
  double e_inf = 0.0;
};

/// The sums behind e2 and e_inf, taken row by row in order (a series read
/// in chunks gives the same bits as a whole one).
class GapErrorSums {
public:
  void add(double reduced, double reference) {
    const double d = reduced - reference;
    m_diff2 += d * d;
    m_ref2 += reference * reference;
    m_diff_max = std::max(m_diff_max, std::abs(d));
    m_ref_max = std::max(m_ref_max, std::abs(reference));
  }
  GapErrors errors() const { return {std::sqrt(m_diff2 / m_ref2), m_diff_max / m_ref_max}; }

private:
  double m_diff2 = 0.0, m_ref2 = 0.0, m_diff_max = 0.0, m_ref_max = 0.0;
};

/// e2 and e_inf of the blade-1 gap series `reduced` against `reference`
/// (one entry per history row). Throws std::invalid_argument if their
/// lengths differ.
inline GapErrors gap_errors(const std::vector<double>& reduced,
                            const std::vector<double>& reference) {
  if (reduced.size() != reference.size())
    throw std::invalid_argument("blade1_gap_errors: the histories have " +
                                std::to_string(reduced.size()) + " and " +
                                std::to_string(reference.size()) + " rows");
  GapErrorSums sums;
  for (size_t i = 0; i < reference.size(); ++i)
    sums.add(reduced[i], reference[i]);
  return sums.errors();
}

/// The blade-1 gap of every row of a history.
inline std::vector<double> blade1_gap(const History& h) {
  std::vector<double> gap;
  for (const Eigen::VectorXd& g : h.gap)
    gap.push_back(g(0));
  return gap;
}

/// Throws std::invalid_argument if the two histories have different rows.
inline GapErrors blade1_gap_errors(const History& reduced, const History& reference) {
  return gap_errors(blade1_gap(reduced), blade1_gap(reference));
}

} // namespace rsi
