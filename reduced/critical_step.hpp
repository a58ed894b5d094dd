#pragma once
// The stable step of central differences on a reduced model: 2 / omega_max,
// omega_max^2 the largest finite eigenvalue of K^ x = omega^2 M^ x (SPEC §3:
// reduced runs report their own omega_max and critical step).
//
// A basis with mass on every coordinate (CB, CCM, Guyan): the dense
// generalized eigenproblem of (K^, M^).
// A massless boundary (MacNeal, ReducedBasis::massless_boundary: M^ zero on
// the boundary coordinates b, r the others): the boundary rows carry no
// inertia, K^_bb x_b + K^_br x_r = 0, so x_b = -K^_bb^-1 K^_br x_r and the
// finite eigenvalues are those of the statically condensed problem
//   (K^_rr - K^_rb K^_bb^-1 K^_br) x_r = omega^2 M^_rr x_r,
// solved densely (r x r); the n_b others are infinite and do not limit an
// integrator that keeps the boundary in static balance (SPEC §8). For
// MacNeal the condensed stiffness is Omega_1^2 in exact arithmetic
// (macneal.hpp): omega_max = omega_psi.
// Assumes K^ symmetric, M^_rr positive definite, K^_bb positive definite.

#include <Eigen/Core>

#include "reduced_basis.hpp"

namespace rsi {

/// The finite eigenvalues omega^2 [rad^2/s^2] of (K^, M^), ascending, the
/// massless boundary condensed first. Throws ReducedIntegrationError if the
/// dense eigensolver or the Cholesky factorization of K^_bb fails.
Eigen::VectorXd reduced_eigenvalues(const ReducedBasis& basis);

/// omega_max [rad/s] of the reduced model, as above; the critical step is
/// 2 / omega_max.
double reduced_omega_max(const ReducedBasis& basis);

/// The modes of a reduced model with mass on every coordinate: K^ Psi =
/// M^ Psi diag(omega^2), Psi^T M^ Psi = I (the integrator's modal
/// coordinates, reduced_integrator.hpp).
struct ReducedModes {
  Eigen::MatrixXd shapes;        ///< Psi, r x r
  Eigen::VectorXd omega_squared; ///< ascending [rad^2/s^2]
  double omega_max() const;
};

/// Throws ReducedIntegrationError for a massless boundary or a failed
/// eigensolver (M^ not positive definite).
ReducedModes reduced_modes(const ReducedBasis& basis);

} // namespace rsi
