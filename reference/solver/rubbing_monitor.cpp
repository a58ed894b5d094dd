#include "rubbing_monitor.hpp"

#include <cmath>
#include <sstream>

namespace rsi {

RubbingMonitor::RubbingMonitor(const RigidSurfaceContact& law)
    : m_rest_gap([&law](int c, double t) { return law.imposed_gap(c, t); }) {
  for (int c = 0; c < law.n_contacts(); ++c)
    m_radius.push_back(law.frame(c).radius);
}

RubbingMonitor::RubbingMonitor(const SolidCasingContact& law)
    : m_rest_gap([&law](int c, double t) { return law.rest_gap(c, t); }) {
  for (int c = 0; c < law.n_contacts(); ++c)
    m_radius.push_back(law.radius(c));
}

KindMonitor::Runaway RubbingMonitor::runaway(const StepState& state) const {
  for (int c = 0; c < static_cast<int>(m_radius.size()); ++c) {
    const double normal = state.gap(c) - m_rest_gap(c, state.time);
    if (std::abs(normal) <= m_radius[static_cast<size_t>(c)]) continue;
    std::ostringstream m;
    m.precision(6);
    m << "runaway at step " << state.step << " (t = " << state.time << " s): contact node "
      << c + 1 << " moved " << normal << " along its normal, more than its radius "
      << m_radius[static_cast<size_t>(c)]
      << " (the small-displacement model is left: an unstable step or a blow-up)";
    return {m.str(), false};
  }
  return {};
}

} // namespace rsi
