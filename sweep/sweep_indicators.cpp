#include "sweep_indicators.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rsi {

SweepIndicatorAccumulator::SweepIndicatorAccumulator(double transient, double output_interval)
    : m_transient(transient)
    , m_interval(output_interval) {
  if (!(output_interval > 0.0) || !(transient >= 0.0))
    throw std::invalid_argument("SweepIndicatorAccumulator: transient >= 0 and interval > 0");
}

void SweepIndicatorAccumulator::add(const HistoryRow& row) {
  if (row.tip_displacement == nullptr)
    throw std::invalid_argument(
        "SweepIndicatorAccumulator: the history rows carry no tip displacement");
  // Row times are n dt; a row meant to fall on the transient may sit a few
  // ulps below it: a millionth of the output interval absorbs that.
  if (row.time < m_transient - 1e-6 * m_interval) return;
  const Eigen::VectorXd& tips = *row.tip_displacement;
  const Eigen::Index n_blades = row.lambda.size();
  if (tips.size() != 2 * n_blades)
    throw std::invalid_argument("SweepIndicatorAccumulator: 2 tip displacements a blade expected");
  for (Eigen::Index k = 0; k < n_blades; ++k) {
    m_out.max_tip_radial = std::max(m_out.max_tip_radial, std::abs(tips(2 * k)));
    m_out.max_tip_tangential = std::max(m_out.max_tip_tangential, std::abs(tips(2 * k + 1)));
    m_out.max_contact_force = std::max(m_out.max_contact_force, row.lambda(k));
    m_contact_pairs += row.lambda(k) > 0.0;
  }
  m_pairs += n_blades;
  if (m_out.rows == 0) m_first_energy = row.energy;
  m_last_energy = row.energy;
  m_blade1_radial.push_back(tips(0));
  ++m_out.rows;
}

SweepIndicators SweepIndicatorAccumulator::finish() const {
  SweepIndicators out = m_out;
  if (out.rows == 0) return out;
  out.contact_fraction = static_cast<double>(m_contact_pairs) / static_cast<double>(m_pairs);
  out.energy_ratio = m_last_energy / m_first_energy;
  bool finite = true;
  for (double x : m_blade1_radial)
    finite = finite && std::isfinite(x);
  if (out.rows >= 4 && finite) out.peaks = dominant_frequencies(m_blade1_radial, m_interval, 3);
  return out;
}

} // namespace rsi
