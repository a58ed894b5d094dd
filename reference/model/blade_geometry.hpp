#pragma once
// Geometry of one sector of the bladed disk, in the sector frame (x along
// the sector's radial axis through the hub node, y counter-clockwise).
//
// Blade element i (i = 0..n-1) points along the angle -i a: each kink turns
// the blade clockwise, against the rotation, so the tip trails the root
// (SPEC §2). The common element length is the root of |tip(L)| = R_t,
// found with GSL's Brent solver.

#include <vector>

#include <Eigen/Core>

#include "case_file.hpp"

namespace rsi {

struct BladeGeometry {
  double disk_length = 0.0;    ///< r_r - r_h [m]
  double element_length = 0.0; ///< common blade element length [m]
  double tip_angle = 0.0;      ///< polar angle of the tip in the sector frame [rad]
  /// Nodes in the sector frame: hub, rim, then the blade nodes to the tip.
  std::vector<Eigen::Vector2d> nodes;
  /// Direction of blade element i in the sector frame [rad].
  std::vector<double> element_angles;
};

/// Throws CaseError if no element length puts the tip at tip_radius.
BladeGeometry blade_geometry(const BladedDiskSpec& spec);

} // namespace rsi
