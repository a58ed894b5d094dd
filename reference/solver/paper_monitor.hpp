#pragma once
// What the paper's kind (bladed disk and flexible casing, SPEC §2-3) watches
// beyond RunMonitor's common bookkeeping, in both solvers:
// - runaway: a tip gap non-finite or beyond 1000 clearances (R_c - R_t):
//   nothing physical, a blow-up; the step is counted and a row written
//   before the run stops;
// - the blade-1 contact intervals: [first, last] times of each run of steps
//   with lambda_1 > 0 (RunSummary::contact_intervals_blade_1);
// - the casing's radial and tangential displacement of every node at the
//   first contact (paper Fig. 9; zeros at the clamp).

#include "run_monitor.hpp"

namespace rsi {

class PaperMonitor : public KindMonitor {
public:
  /// `casing` must outlive the monitor (not owned).
  PaperMonitor(const Case& c, const Casing& casing);
  Runaway runaway(const StepState& state) const override;
  void after_step(const StepReport& report, const StepState& state, bool first_contact,
                  RunResult& result) override;
  bool needs_casing(const StepReport& report, const RunSummary& summary) const override {
    return summary.first_contact_step < 0 && report.n_active > 0;
  }

private:
  const Casing& m_casing;
  double m_runaway_gap; ///< 1000 clearances [m]
  bool m_in_contact = false;
};

} // namespace rsi
