#pragma once
// Two-node curved beam (ring) element of radius R and arc length l (SPEC §2).
//
// Dofs per node (u, u_s, v, v_s): u radial (outward), v tangential
// (counter-clockwise), s = R theta the arc length; u and v both cubic
// Hermite in s. With eps = v_s + u/R and kappa = u_ss - v_s/R,
//   U = 1/2 int (EA eps^2 + EI kappa^2) ds,  T = 1/2 int rhoA (u'^2 + v'^2) ds,
// integrated by 4-point Gauss-Legendre (GSL), exact for these degree-6
// polynomial integrands. Element dof order: (u1, u1_s, v1, v1_s, u2, u2_s,
// v2, v2_s). Rigid translations are represented only approximately (cubics
// cannot hold cos and sin), rigid rotation (v = const) exactly.
// Valid for radius > 0, arc_length > 0.

#include <Eigen/Core>

#include "beam_properties.hpp"

namespace rsi {

using Matrix8d = Eigen::Matrix<double, 8, 8>;

Matrix8d ring_stiffness(const BeamProperties& p, double radius, double arc_length);
Matrix8d ring_mass(const BeamProperties& p, double arc_length);

/// Cubic Hermite shape values at xi in [0, 1] on an element of length l,
/// for the nodal values (f1, f1_s, f2, f2_s). Shared with the contact code,
/// which interpolates the casing radial displacement with them (SPEC §2).
Eigen::Vector4d hermite_values(double xi, double l);

} // namespace rsi
