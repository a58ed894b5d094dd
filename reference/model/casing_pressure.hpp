#pragma once
// The paper's forcing on the flexible 3D casing (issue 27 item 2; SPEC §2's
// F0 cos(n theta_j) in 3D): a radial traction on the casing's contact
// surface, p(theta) e_r(theta), p(theta) = p0 cos(n theta) (> 0 outward;
// n = 2 the two-nodal-diameter load of the paper), held for t <= duration.
// Its consistent nodal forces f_i = sum over the faces of the integral of
// N_i p(theta) e_r(theta) dA over the face, by the 6-point Gauss rule of
// degree 4 on the triangle (Dunavant 1985) at the face's points X(xi,
// eta) (casing_surface.hpp), with dA = |dX/dxi x dX/deta| dxi deta. A
// clamped node takes no force (its share goes to the support).

#include <Eigen/Core>

#include "casing_surface.hpp"
#include "component.hpp"

namespace rsi {

/// The nodal forces of p0 cos(n theta) e_r on `surface` as a vector of the
/// casing component's dofs (ux, uy, uz of each node the component keeps).
/// p0 finite [force/length^2], n >= 0. Throws std::invalid_argument
/// otherwise, or when a face node lacks one of its translations in the
/// component without lacking all three (a partly clamped node).
Eigen::VectorXd casing_pressure_forces(const CasingSurface& surface, const Component& casing,
                                       double p0, int nodal_diameters);

} // namespace rsi
