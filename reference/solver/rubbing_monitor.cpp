#include "rubbing_monitor.hpp"

#include <cmath>
#include <sstream>

namespace rsi {

KindMonitor::Runaway RubbingMonitor::runaway(const StepState& state) const {
  for (int c = 0; c < m_law.n_contacts(); ++c) {
    const double normal = state.gap(c) - m_law.imposed_gap(c, state.time);
    if (std::abs(normal) <= m_law.frame(c).radius) continue;
    std::ostringstream m;
    m.precision(6);
    m << "runaway at step " << state.step << " (t = " << state.time << " s): contact node "
      << c + 1 << " moved " << normal << " along its normal, more than its radius "
      << m_law.frame(c).radius
      << " (the small-displacement model is left: an unstable step or a blow-up)";
    return {m.str(), false};
  }
  return {};
}

} // namespace rsi
