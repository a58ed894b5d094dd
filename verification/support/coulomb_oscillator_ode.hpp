#pragma once
// An independent second computation of the Coulomb oscillator of
// coulomb_oscillator.hpp (same equation, same event logic, same grazing
// decisions), for the tests: slip segments integrated numerically by GSL
// odeiv2 (rk8pd, local error control D_i = eps_abs + eps_rel |y_i|), events
// x' = 0 located by Brent's method on the one-step map tau -> x'(after one
// rk8pd step of size tau from the start of the step where s x' changed
// sign); stick ends located by scanning g(t) = F(t) - k x_s on a grid of
// 64 points per forcing period and Brent's method on g -+ mu N. It shares
// with coulomb_oscillator.cpp only the parameter and segment types.
//
// Error bound (error_bound()): in the energy norm ||(e_x, e_v)|| =
// sqrt(k e_x^2 + m e_v^2) the exact flow of a slip segment is an isometry on
// differences (same linear ODE, same constant friction), a stick keeps e_x
// and sets e_v to 0, and at an event the first-order effect of the shifted
// event time on the state is: reversal, e_v multiplied by
// |a + s mu N| / |a - s mu N| <= 1; stick start, e_v dropped; stick end,
// nothing (the slip starts from rest with zero acceleration). So the global
// error is at most the sum over accepted steps of the local errors, which
// GSL's control keeps <= 1.1 D_i per component (assuming the embedded
// estimate bounds the error of the 8th-order solution, which it
// overestimates): error_bound() = sum over steps of 1.1 ||(D_x, D_v)||.
// Then |e_x| <= error_bound()/sqrt(k), |e_v| <= error_bound()/sqrt(m);
// second-order terms in the event-time shifts are neglected.

#include <string>
#include <vector>

#include "coulomb_oscillator.hpp"

namespace rsi::coulomb {

struct OdeTolerances {
  double eps_abs = 1e-12; ///< > 0, [m] and [m/s]
  double eps_rel = 1e-12; ///< >= 0
};

class OdeSolution {
public:
  /// window_end: T > 0 finite; sample_times: sorted, in [0, T].
  OdeSolution(const Oscillator& oscillator, double window_end,
              const std::vector<double>& sample_times, const OdeTolerances& tolerances);

  const std::vector<double>& x() const { return m_x; } ///< at the sample times
  const std::vector<double>& v() const { return m_v; }
  const std::vector<Segment>& segments() const { return m_segments; }
  Transitions transitions() const { return count_transitions(m_segments); }
  /// Sum of the per-step local error tolerances in the energy norm [sqrt(J)].
  double error_bound() const { return m_error_bound; }
  long n_steps() const { return m_n_steps; }
  bool ok() const { return m_failure.empty(); }
  const std::string& failure() const { return m_failure; }

private:
  std::vector<double> m_x, m_v;
  std::vector<Segment> m_segments;
  double m_error_bound = 0.0;
  long m_n_steps = 0;
  std::string m_failure;
};

} // namespace rsi::coulomb
