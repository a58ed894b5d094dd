#pragma once
// What a component rubbing on a casing (rigid, or the flexible solid one)
// watches beyond RunMonitor's common bookkeeping: the runaway test. A
// contact node whose normal displacement |g_c - g0_c(t)| (g0_c the gap at
// zero displacement) exceeds its distance r from the axis, or
// whose gap is not finite, has left the small-displacement model (a blow-up
// the energy balance may not see: an unstable run's energy grows with the
// moving casing's work and the balance closes). That step is outside the
// model: it is not counted and no row is written; the run stops there.

#include <functional>
#include <vector>

#include "rigid_surface_contact.hpp"
#include "run_monitor.hpp"
#include "solid_casing_contact.hpp"

namespace rsi {

class RubbingMonitor : public KindMonitor {
public:
  /// `law` must outlive the monitor (not owned).
  explicit RubbingMonitor(const RigidSurfaceContact& law);
  explicit RubbingMonitor(const SolidCasingContact& law);
  Runaway runaway(const StepState& state) const override;
  void after_step(const StepReport&, const StepState&, bool, RunResult&) override {}
  bool needs_casing(const StepReport&, const RunSummary&) const override { return false; }

private:
  std::function<double(int, double)> m_rest_gap; ///< g0_c(t)
  std::vector<double> m_radius;                  ///< r_c
};

} // namespace rsi
