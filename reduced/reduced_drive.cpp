#include "reduced_drive.hpp"

namespace rsi {

std::int64_t drive_reduced(ReducedStepper& integrator, std::int64_t steps, DriveMonitor& monitor,
                           bool started) {
  if (!started) integrator.start();
  monitor.started();
  std::int64_t n = 0;
  while (n < steps) {
    monitor.before_step(n);
    StepReport report;
    try {
      report = integrator.step();
    } catch (const NumericalFailure& failure) {
      if (monitor.stops_on(failure, n + 1)) return n;
      throw;
    }
    ++n;
    if (!monitor.after_step(n, report)) break;
  }
  return n;
}

} // namespace rsi
