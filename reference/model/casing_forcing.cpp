#include "casing_forcing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rsi {

Eigen::VectorXd casing_forcing(const Casing& casing, const Forcing& forcing) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(casing.n_dofs());
  for (int j = 0; j < casing.n_elements; ++j) {
    const int first = casing.node_first_dof[j];
    if (first >= 0)
      f(first) = forcing.amplitude * std::cos(forcing.nodal_diameter * casing.node_angle(j));
  }
  return f;
}

ForcingSchedule::ForcingSchedule(const Forcing& forcing, const TimeStepping& case_time, long k)
    : m_o(case_time.output_every) {
  if (k < 1) throw std::invalid_argument("ForcingSchedule: k must be >= 1, got " + std::to_string(k));
  // N: the last step of the case's own run with the force on (forcing_active).
  const double dt = case_time.step;
  long last = static_cast<long>(std::floor(forcing.duration / dt));
  while (forcing_active(forcing, static_cast<double>(last + 1) * dt, dt))
    ++last;
  while (last > 0 && !forcing_active(forcing, static_cast<double>(last) * dt, dt))
    --last;
  m_t_imp = (2 * last + 1) * k;
}

double ForcingSchedule::share(long n) const {
  const long low = n == 0 ? 0 : (2 * n - 1) * m_o;
  const long high = (2 * n + 1) * m_o;
  const long overlap = std::max(0L, std::min(high, m_t_imp) - low);
  return static_cast<double>(overlap) / static_cast<double>(high - low);
}

} // namespace rsi
