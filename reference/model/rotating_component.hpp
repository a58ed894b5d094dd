#pragma once
// A component at rotation speed Omega (SPEC §9, rotation effects): the
// tangent stiffness K(Omega) = K_e + K_sigma(Omega) - Omega^2 M_s (stress
// stiffening from the centrifugal prestress, spin softening, the deformed
// geometry) and the mass, both written by ccx after a nonlinear static step
// under the centrifugal load (calculix_prestressed_matrices), with the
// static centrifugal deflection as the operating point. Each speed is one
// ccx run, cached; nothing is interpolated between speeds.
//
// Why no parametric fit (K0 + Omega^2 K1 + Omega^4 K2 from three speeds):
// measured on both 3D blades, the interpolated matrices put the first
// eigenvalues 6-70 % off at speeds between the fit speeds (docs/decisions.md,
// "Rotation effects"): the static deflection saturates as the blade
// stiffens (rational in Omega^2, a pole near Omega^2 = -5e5 rad^2/s^2 on
// Rotor 37), so no low-order polynomial in Omega^2 holds the tangent
// stiffness over an engine's speed range.
//
// The axis passes through the deck's origin along the case's rotation_axis
// (the polar angle of the rubbing gap is measured there too). The sign of
// Omega does not matter: the load is Omega^2 (no Coriolis term here).
// Omega = 0 is the component load_component builds, bit for bit (no ccx
// run). Sources: a CalculiX deck or the gmsh blade (CaseError for a Matrix
// Market folder or matrices named in the case: there is no deck to load).

#include <Eigen/Core>

#include "component.hpp"
#include "component_case.hpp"

namespace rsi {

struct RotatingComponent {
  double speed = 0.0;        ///< Omega [rad/s]
  Component component;       ///< K(Omega), M (HRZ-lumped when the case says so)
  /// Static centrifugal deflection at every dof of `component` (zero at
  /// Omega = 0), from ccx's printed table: 7 significant digits.
  Eigen::VectorXd deflection;
};

RotatingComponent rotating_component(const ComponentCase& c, const ComponentLoadOptions& options,
                                     double speed);

/// The radial growth (along the outward radius from the axis, in the plane
/// normal to it) of node `node` of `component` under `deflection`.
double radial_growth(const Component& component, const Eigen::VectorXd& deflection, int node);

} // namespace rsi
