#include "paper_monitor.hpp"

#include <sstream>
#include <stdexcept>

namespace rsi {

PaperMonitor::PaperMonitor(const Case& c, const Casing& casing)
    : m_casing(casing)
    // Tips moved by a thousand clearances: nothing physical, a blow-up.
    , m_runaway_gap(1000.0 * (c.casing.radius - c.bladed_disk.tip_radius)) {}

KindMonitor::Runaway PaperMonitor::runaway(const StepState& state) const {
  // Every step: a blow-up shows first in the gaps.
  if (state.gap.allFinite() && !(state.gap.cwiseAbs().maxCoeff() > m_runaway_gap)) return {};
  std::ostringstream message;
  message << "blow-up: a blade tip gap is non-finite or beyond " << m_runaway_gap
          << " m (1000 clearances) at step " << state.step << " (t = " << state.time << " s)";
  return {message.str(), true};
}

void PaperMonitor::after_step(const StepReport&, const StepState& state, bool first_contact,
                              RunResult& result) {
  if (first_contact) {
    if (state.casing.size() != m_casing.n_dofs())
      throw std::logic_error("RunMonitor: the casing displacement is needed at the first contact");
    const Eigen::VectorXd all = on_all_nodes(m_casing, state.casing);
    const int n = m_casing.n_elements;
    result.casing_u_at_first_contact =
        Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<4>>(all.data(), n);
    result.casing_v_at_first_contact =
        Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<4>>(all.data() + 2, n);
  }
  const bool contact = state.lambda(0) > 0.0;
  if (contact) {
    if (!m_in_contact) result.summary.contact_intervals_blade_1.emplace_back(state.time, state.time);
    result.summary.contact_intervals_blade_1.back().second = state.time;
  }
  m_in_contact = contact;
}

} // namespace rsi
