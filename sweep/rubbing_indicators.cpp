#include "rubbing_indicators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rsi {

RubbingIndicatorAccumulator::RubbingIndicatorAccumulator(const RigidSurfaceContact& casing,
                                                         double transient, double output_interval)
    : RubbingIndicatorAccumulator(transient, output_interval) {
  m_casing = &casing;
}

RubbingIndicatorAccumulator::RubbingIndicatorAccumulator(double transient, double output_interval)
    : m_casing(nullptr)
    , m_transient(transient)
    , m_interval(output_interval) {
  if (!(output_interval > 0.0) || !(transient >= 0.0))
    throw std::invalid_argument("RubbingIndicatorAccumulator: transient >= 0 and interval > 0");
}

void RubbingIndicatorAccumulator::add(const HistoryRow& row, double response) {
  // As sweep_indicators.cpp: a row meant to fall on the transient may sit a
  // few ulps below it.
  if (row.time < m_transient - 1e-6 * m_interval) return;
  const Eigen::Index nc = row.gap.size();
  if ((m_casing && nc != m_casing->n_contacts()) || row.lambda.size() != nc)
    throw std::invalid_argument("RubbingIndicatorAccumulator: a gap and a lambda_n a contact expected");
  bool closed = false;
  for (Eigen::Index c = 0; c < nc; ++c) {
    if (m_casing) {
      const double radial = m_casing->imposed_gap(static_cast<int>(c), row.time) - row.gap(c);
      m_out.max_tip_radial = std::max(m_out.max_tip_radial, std::abs(radial));
    }
    m_out.max_contact_force = std::max(m_out.max_contact_force, row.lambda(c));
    closed = closed || row.lambda(c) > 0.0;
  }
  m_contact_rows += closed;
  if (m_out.rows == 0) m_first_energy = row.energy;
  m_last_energy = row.energy;
  m_out.max_abs_response = std::max(m_out.max_abs_response, std::abs(response));
  m_response.push_back(response);
  ++m_out.rows;
}

RubbingIndicators RubbingIndicatorAccumulator::finish() const {
  RubbingIndicators out = m_out;
  if (out.rows == 0) return out;
  out.contact_fraction = static_cast<double>(m_contact_rows) / static_cast<double>(out.rows);
  out.energy_ratio = m_first_energy > 0.0 ? m_last_energy / m_first_energy
                                          : std::numeric_limits<double>::quiet_NaN();
  bool finite = true;
  for (double x : m_response)
    finite = finite && std::isfinite(x);
  if (out.rows >= 4 && finite) out.peaks = dominant_frequencies(m_response, m_interval, 3);
  return out;
}

} // namespace rsi
