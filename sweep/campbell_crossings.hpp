#pragma once
// Where the engine orders cross the modes of a rotating blade: the Campbell
// diagram's coincidences. A blade of rotating-frame frequency f_i(Omega)
// [Hz] is excited by a stationary disturbance with k lobes (engine order k)
// at k Omega / 2 pi; the coincidence speed solves
//   d(Omega) = f_i(Omega) - k Omega / (2 pi) = 0.
// The frequencies are known on a grid of speeds (ascending); between two
// grid speeds where d changes sign (or vanishes) the crossing is located by
// linear interpolation of d, exact when f_i is linear there, otherwise off
// by at most the chord error of f_i over the interval, (dOmega^2 / 8)
// max |f_i''| / |f_i' - k / 2 pi|. Mode i is the i-th lowest frequency at
// each speed (no tracking through veerings).

#include <vector>

#include <Eigen/Core>

namespace rsi {

struct CampbellCrossing {
  int mode = 0;         ///< i >= 1, the i-th lowest frequency
  int engine_order = 0; ///< k >= 1
  double speed_rad_s = 0.0;
  double frequency_hz = 0.0; ///< k Omega / 2 pi at the crossing
};

/// `speeds` ascending [rad/s] (>= 0); `frequencies_hz`(s, i): mode i + 1 at
/// speeds[s]. Every crossing of engine orders 1..max_order with every
/// mode, ordered by mode, engine order, speed. Throws std::invalid_argument
/// for fewer than two speeds, unsorted speeds or a size mismatch.
std::vector<CampbellCrossing> campbell_crossings(const std::vector<double>& speeds,
                                                 const Eigen::MatrixXd& frequencies_hz,
                                                 int max_order);

} // namespace rsi
