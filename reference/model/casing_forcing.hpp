#pragma once
// External forcing of the casing (SPEC §2): radial nodal forces
// F0 cos(n theta_j) on every (unclamped) casing node j for 0 <= t <= T.

#include <Eigen/Core>

#include "casing.hpp"

namespace rsi {

/// The force vector on the casing dofs while the forcing acts [N].
Eigen::VectorXd casing_forcing(const Casing& casing, const Forcing& forcing);

/// Whether the forcing acts at time t (0 <= t <= duration, with a
/// tolerance of a millionth of a step for t = n dt).
inline bool forcing_active(const Forcing& forcing, double t, double dt) {
  return t <= forcing.duration + 1e-6 * dt;
}

/// The forcing's discrete history for a run at dt = I / k, I = time.step *
/// output_every the case's output interval (issue 14: each reduced system at
/// its own step). Central differences apply the force of step n over its
/// dual cell [t_n - dt/2, t_n + dt/2] (the velocity jumps by dt M^-1 F_n
/// between half steps), step 0 from rest over [0, dt/2]. A run at the
/// case's step (k = output_every) applies F on steps 0..N (forcing_active:
/// t_N the last time <= duration), an impulse F (N + 1/2) time.step = F T_imp.
/// A run at another step gets the same impulse history: step n carries the
/// share |cell_n intersect [0, T_imp]| / |cell_n| of F. In units of
/// time.step / (2k), with o = output_every, cell_n = [(2n-1) o, (2n+1) o]
/// (cell_0 = [0, o]) and T_imp = (2N+1) k: integers, so the shares are exact
/// and a run at the case's step gets 1 on steps 0..N and 0 after, its
/// first-round force bit for bit.
class ForcingSchedule {
public:
  /// k >= 1; throws std::invalid_argument otherwise.
  ForcingSchedule(const Forcing& forcing, const TimeStepping& case_time, long k);
  /// Share in [0, 1] of the force on step n >= 0.
  double share(long n) const;

private:
  long m_o;       ///< output_every
  long m_t_imp;   ///< T_imp in units of time.step / (2k)
};

} // namespace rsi
