#pragma once
// Straight two-node 2D Euler-Bernoulli frame element.
//
// Dofs, in the frame in which `angle` is measured: (u_x1, u_y1, theta_1,
// u_x2, u_y2, theta_2), theta counter-clockwise. Axial displacement linear,
// transverse displacement cubic Hermite; consistent mass without rotary
// inertia (Przemieniecki, Theory of Matrix Structural Analysis, ch. 5 and 11):
//   K_axial = EA/L [1 -1; -1 1],  K_bend = EI/L^3 [12 6L -12 6L; ...],
//   M_axial = rhoA L/6 [2 1; 1 2], M_bend = rhoA L/420 [156 22L 54 -13L; ...].
// The element axis makes the angle `angle` [rad] with the x axis.
// Valid for length > 0 and positive properties.

#include <Eigen/Core>

#include "beam_properties.hpp"

namespace rsi {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Stiffness in local (axial, transverse, rotation) coordinates.
Matrix6d frame_stiffness_local(const BeamProperties& p, double length);
/// Consistent mass in local coordinates.
Matrix6d frame_mass_local(const BeamProperties& p, double length);
/// R with u_local = R u_global, for an axis at `angle` to x.
Matrix6d frame_rotation(double angle);

Matrix6d frame_stiffness(const BeamProperties& p, double length, double angle);
Matrix6d frame_mass(const BeamProperties& p, double length, double angle);

} // namespace rsi
