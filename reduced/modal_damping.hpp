#pragma once
// Modal damping of a reduced bladed disk (SPEC §8): a ratio zeta on each
// kept mode, none on the boundary coordinates. C^ is diagonal in q:
//   C^_jj = 2 zeta omega_i  on the coordinate j of kept mode i,
//   C^_jj = 0               on every boundary coordinate,
// with omega_i the mode's own frequency (ReducedBasis::mode_omega).
//
// What it damps, method by method (M^ is not diagonal: the modes are
// coupled to the boundary through the mass):
// - Craig-Bampton, q = (u_eta, q_B): the fixed-interface modes are
//   M_II-normalised, M^_etaeta = I and K^_etaeta = diag(omega_i^2), so C^ is
//   2 zeta omega_i on the mass-normalised modal coordinates: each
//   fixed-interface mode, boundary held, is a damped oscillator of ratio
//   zeta. They are not modes of the coupled reduced system (M^_etaB != 0),
//   so a free mode of the reduced model gets a ratio near zeta, not zeta.
// - Craig-Chang-Martinez and MacNeal, q = (q_B, u_1): the free mode i of
//   the whole part lies in the basis, at q_i = (Phi_1B e_i, e_i), and since
//   Phi_1^T M R = 0 (the residual flexibility is M-orthogonal to the kept
//   modes) M^ q_i = e_i (u_1 part; MacNeal's M^ = diag(0, I) gives the same).
//   Hence C^ q_i = 2 zeta omega_i e_i = 2 zeta omega_i M^ q_i and
//   K^ q_i = omega_i^2 M^ q_i: each kept free mode is an exact damped mode
//   of the reduced model with ratio zeta, and the attachment (boundary)
//   motions, M^-orthogonal to them, are undamped.
// - Guyan: no modes, C^ = 0.
// The integrator (reduced_integrator.hpp) takes the diagonal.

#include <Eigen/Core>

#include "reduced_basis.hpp"

namespace rsi {

/// diag(C^) [N s/m in q's units] for the ratio zeta in [0, 1) on every kept
/// mode. Throws std::invalid_argument for zeta outside [0, 1) or not finite,
/// and for a basis with modes whose mode_omega is missing (a basis built
/// by hand).
Eigen::VectorXd modal_damping(const ReducedBasis& basis, double zeta);

} // namespace rsi
