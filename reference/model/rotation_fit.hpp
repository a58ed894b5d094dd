#pragma once
// A parametric K(Omega) between speeds where ccx ran (SPEC §9, rotation
// effects; docs/decisions.md, "Rotation effects"): the tangent stiffness as
// a polynomial in the static deflection's coordinates, not in Omega^2.
//
// Why this form: ccx's NLGEOM solid elements are St Venant-Kirchhoff, so
// the tangent stiffness at a deflection u is exactly quadratic in u (the
// initial-displacement matrices are linear and quadratic in u, the
// initial-stress matrix linear in the second Piola-Kirchhoff stress, itself
// quadratic in u), and the spin softening and centrifugal load stiffness
// are linear in s = Omega^2. With u on m deflection shapes V (n x m,
// orthonormal: ccx's deflections at the m highest fit speeds), u = V a,
//   K(Omega) = K0 + sum_k a_k L_k + sum_{k<=l} a_k a_l Q_kl + s R,   (1)
// p = m + m(m+1)/2 + 1 unknown matrices, fitted exactly at p fit speeds
// (a p x p solve, entry by entry; a minimum-norm one over the singular
// values kept when the features are nearly dependent, as for a stiff part
// whose deflection is linear in s). What (1) leaves out is the deflection's
// part outside V and the error of a(Omega) between fit speeds; a(Omega) is
// a natural cubic spline in s through (0, 0) and the fit speeds' a, and so
// is the whole deflection u(Omega) (the same cardinal weights, so
// a = V^T u holds at every speed). The Omega^2 polynomial
// K0 + s K1 + s^2 K2 fails by 6-70 % on both 3D blades (the deflection
// saturates as the blade stiffens); (1) holds to 1.2e-3 on the gmsh blade
// (reports/rotation-fit).
//
// The mass is the model's at rest (ccx's total-Lagrangian mass does not
// change with the prestress; HRZ-lumped when the case says so).

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "component.hpp"
#include "component_case.hpp"
#include "rotating_component.hpp"

namespace rsi {

struct RotationFit {
  Component rest;                     ///< the model at rest: K0, M, nodes, dofs
  std::vector<double> fit_speeds;     ///< ascending, > 0 [rad/s]
  Eigen::MatrixXd shapes;             ///< V, n x m, orthonormal columns
  /// u at 0 and at each fit speed (n x (p + 1)), the spline's nodes.
  Eigen::MatrixXd node_deflections;
  /// L_1..L_m, Q_11, Q_12, .., Q_mm, R: the order of features().
  std::vector<Eigen::SparseMatrix<double>> terms;
  /// cond_2 of the p x p feature matrix, columns scaled to 1, over the
  /// singular values kept (those above 1e-8 of the largest).
  double feature_condition = 0.0;
  int feature_rank = 0; ///< p, or fewer for a part whose deflection is ~ linear in s
  int n_shapes() const { return static_cast<int>(shapes.cols()); }
};

/// The number of fit speeds `shapes` deflection shapes need: m + m(m+1)/2 + 1.
int rotation_fit_speed_count(int shapes);

/// The features of (1) at coordinates `a` and s = speed^2: a_1..a_m, then
/// a_k a_l for k <= l in row order, then s.
Eigen::VectorXd rotation_fit_features(const Eigen::VectorXd& a, double speed);

/// Runs ccx (cached) at each fit speed (rotating_component) and fits (1).
/// Throws CaseError for a speed count other than rotation_fit_speed_count,
/// speeds not ascending or not in (0, 1e5), fit speeds whose deflections
/// do not span m shapes, or no deflection at all; ImportError as
/// rotating_component.
RotationFit fit_rotation(const ComponentCase& c, const ComponentLoadOptions& options,
                         const std::vector<double>& fit_speeds, int shapes);

/// The natural cubic spline's weights w_j(s) of the nodes s_j = 0, fit
/// speeds^2 at s = speed^2: u(speed) = sum_j w_j u_j. Throws CaseError for
/// |speed| above the highest fit speed (no extrapolation).
Eigen::VectorXd rotation_fit_weights(const RotationFit& fit, double speed);

/// u(speed) by the spline (zero at 0), without K: what the growth needs.
Eigen::VectorXd rotation_fit_deflection(const RotationFit& fit, double speed);

/// K(speed) by (1), the mass at rest, and u(speed) by the spline; at a fit
/// speed ccx's K to the solve's rounding, at 0 the model at rest bit for bit.
RotatingComponent rotating_component_at(const RotationFit& fit, double speed);

} // namespace rsi
