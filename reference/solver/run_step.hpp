#pragma once
// The time step of one run under a StepRule (case_file.hpp, issue 14):
// dt = I / k with I = time.step * output_every the case's output interval,
// so every run writes its history rows at the reference's output times.

#include "case_file.hpp"
#include "history.hpp"

namespace rsi {

struct RunStep {
  double dt = 0.0;  ///< [s]
  long k = 0;       ///< steps per output interval: the run's output_every
};

/// case_step: (time.step, output_every). own: k the smallest integer with
/// I / k <= safety * 2 / omega_max (omega_max of the system the run
/// integrates). given: k = I / step, which must be an integer to 1e-9
/// relative (else CaseError naming `key`, e.g. "campaign[2].time_step").
/// Whenever k == output_every the step is time.step itself (bit for bit
/// the first round's runs). Throws CaseError when k exceeds what an int
/// holds (a step below I / 2^31).
RunStep run_step(const StepRule& rule, const TimeStepping& case_time, double omega_max,
                 const std::string& key);

/// The case with time.step and output_every of `step` (the run's own).
Case with_run_step(const Case& c, const RunStep& step);

} // namespace rsi
