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

} // namespace rsi
