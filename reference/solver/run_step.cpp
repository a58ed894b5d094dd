#include "run_step.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <sstream>

namespace rsi {

namespace {

[[noreturn]] void refuse(const std::string& key, const std::string& what) {
  throw CaseError(key + ": " + what);
}

} // namespace

RunStep run_step(const StepRule& rule, const TimeStepping& case_time, double omega_max,
                 const std::string& key) {
  const double interval = case_time.step * case_time.output_every;
  double k = 0.0;
  switch (rule.kind) {
  case StepRule::Kind::case_step: k = case_time.output_every; break;
  case StepRule::Kind::own: {
    const double limit = rule.safety * 2.0 / omega_max;
    if (!(limit > 0.0) || !std::isfinite(limit))
      refuse(key, "the run's own step needs a finite omega_max, got " + std::to_string(omega_max));
    k = std::ceil(interval / limit);
    break;
  }
  case StepRule::Kind::given: {
    const double ratio = interval / rule.step;
    k = std::round(ratio);
    // I / dt is formed from two decimal inputs: an integer to a few ulps.
    if (k < 1.0 || std::abs(ratio - k) > 1e-9 * k) {
      std::ostringstream what;
      what.precision(10);
      what << "a step of " << rule.step << " s must divide the output interval time.step * "
           << "output_every = " << interval << " s (an integer number of steps per history row), "
           << "got " << ratio << " steps";
      refuse(key, what.str());
    }
    break;
  }
  }
  if (!(k <= static_cast<double>(INT_MAX)))
    refuse(key, "the step " + std::to_string(interval / k) + " s would need more than 2^31 - 1 "
                "steps per history row");
  RunStep out;
  out.k = static_cast<long>(std::max(1.0, k));
  out.dt = out.k == case_time.output_every ? case_time.step
                                           : interval / static_cast<double>(out.k);
  return out;
}

Case with_run_step(const Case& c, const RunStep& step) {
  Case out = c;
  out.time.step = step.dt;
  out.time.output_every = static_cast<int>(step.k);
  return out;
}

} // namespace rsi
