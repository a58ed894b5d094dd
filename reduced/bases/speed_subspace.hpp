#pragma once
// Reduced models at any rotation speed without a basis build per speed
// (issue 26): one subspace for the whole speed range, and the method's own
// reduction done inside it at each speed.
//
// The subspace: the method's bases (CB, CCM, Guyan or MacNeal with the
// requested mode count) built once at a few basis speeds on the parametric
// K(Omega) of rotation_fit.hpp, every column split as u = Psi_0 u_B + w
// (Psi_0: the boundary columns of the first basis, the identity on the
// boundary dofs; w zero on the boundary) and the w orthonormalised:
//   T_g = [Psi_0, Q],  Q^T Q = I,  Q zero on the boundary rows,
// so the first n_B coordinates of the subspace are the physical boundary
// dofs. Since K(Omega) = K0 + sum_q f_q(Omega) C_q (rotation_fit.hpp),
//   T_g^T K(Omega) T_g = T_g^T K0 T_g + sum_q f_q(Omega) T_g^T C_q T_g,
// projected once. At a speed: the subspace model (r_g dofs, dense) is
// reduced by reduce() with its first n_B dofs as boundary, and
// T = T_g T_s. Where the subspace holds the direct basis (at a basis speed
// for CB: its constraint and fixed-interface modes), the Rayleigh-Ritz
// solutions inside the subspace are the exact ones, so the result is the
// direct basis's model to rounding; between basis speeds it is the
// method's reduction of a Ritz model of K(Omega) (its eigenvalues upper
// bounds of the full model's, Rayleigh-Ritz).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "reduced_basis.hpp"
#include "rotation_fit.hpp"

namespace rsi {

struct SpeedSubspace {
  std::string method;
  int modes = 0;
  std::vector<double> basis_speeds; ///< where the method's bases were built [rad/s]
  Eigen::MatrixXd transformation;   ///< T_g, n x r_g: boundary columns first
  int n_boundary = 0;
  Eigen::MatrixXd rest_stiffness;     ///< T_g^T K0 T_g
  std::vector<Eigen::MatrixXd> terms; ///< T_g^T C_q T_g, the fit's order
  Eigen::MatrixXd mass;               ///< T_g^T M T_g
  double build_seconds = 0.0;         ///< the bases, the orthonormalisation, the projections
  int n_subspace() const { return static_cast<int>(transformation.cols()); }
};

/// Builds the subspace from the method's bases at `basis_speeds` (each at
/// most the fit's highest speed) on `fit`'s K(Omega) and mass, boundary =
/// the fit's component's boundary dofs. The bases are built on up to
/// `threads` threads (one basis a thread at a time, so two builds of a
/// 61,098-dof Rotor 37 model hold two factorisations at once); the result
/// does not depend on `threads`. Throws ReductionError as reduce().
SpeedSubspace speed_subspace(const RotationFit& fit, const std::string& method, int modes,
                             const std::vector<double>& basis_speeds, int threads = 1);

/// T_g^T K(speed) T_g (r_g x r_g) by the fit's features at `speed`.
Eigen::MatrixXd subspace_stiffness(const SpeedSubspace& subspace, const RotationFit& fit,
                                   double speed);

/// The `count` lowest eigenvalues [rad^2/s^2] of the subspace model
/// (T_g^T K(speed) T_g, T_g^T M T_g), boundary free: Rayleigh-Ritz upper
/// bounds of the full K(speed)'s. Throws std::runtime_error if the dense
/// solver fails.
Eigen::VectorXd subspace_eigenvalues(const SpeedSubspace& subspace, const RotationFit& fit,
                                     double speed, int count);

/// The method's reduced model at `speed` (|speed| at most the fit's highest
/// speed) from the subspace: its T (n x r), K^, M^ and boundary positions
/// as reduce() gives them, build_seconds the time at this speed.
ReducedBasis reduce_at_speed(const SpeedSubspace& subspace, const RotationFit& fit, double speed);

} // namespace rsi
