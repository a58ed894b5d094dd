#pragma once
// The casing in modal coordinates (issue 14, SPEC §8 "reduced casing"):
// c = Phi p, Phi the lowest clamped-ring modes plus one static correction
// for the case's forcing, mass-normalised, Phi^T M_c Phi = I,
// Phi^T K_c Phi = diag(omega^2).
//
// Why modes and not a fixed-interface basis: the contact point of every tip
// travels round the whole ring (alpha_k = alpha_k0 + Omega t), so there is
// no fixed boundary set to keep physical; the clamped ring's own modes are
// the basis that does not depend on where the tips are.
// Why the static correction: the forcing F0 cos(n theta) acts on every node
// for 0.2 ms; its quasi-static part K_c^-1 F spreads over all modes of the
// right pattern (the clamp breaks the ring's symmetry), and the lowest
// modes alone miss the share of the truncated ones (the mode-acceleration
// argument, Craig and Kurdila, Fundamentals of Structural Dynamics, 2006,
// §14.7). x = K_c^-1 F is made M-orthogonal to the modes (twice, classical
// Gram-Schmidt), normalised, and [Phi x] diagonalised once more (a
// Rayleigh-Ritz step), so the basis stays modal: the integrator's casing
// step costs O(N_c) plus the reconstruction c = Phi p (2 n_c N_c flops).
// The correction is left out when the forcing's static response already
// lies in the span of the modes: its M-orthogonal part below
// sqrt(eps) ||x||_M (what a twice-orthogonalised vector keeps of round-off,
// Giraud et al., Numer. Math. 2005) is noise, not a direction.
// With every mode kept (N_c = n_c) the basis spans the whole casing and
// the reduced run is the full-casing run up to round-off (test_casing_basis).

#include <string>

#include <Eigen/Core>

#include "casing.hpp"
#include "component.hpp"

namespace rsi {

struct CasingBasis {
  Eigen::MatrixXd shapes;        ///< Phi, n_c x m, mass-normalised
  Eigen::VectorXd omega_squared; ///< diag(Phi^T K_c Phi), ascending [rad^2/s^2]
  int n_modes = 0;               ///< N_c: clamped-ring modes asked for
  bool static_correction = false;
  double build_seconds = 0.0;

  int size() const { return static_cast<int>(shapes.cols()); }
  /// 2 / omega_max of the casing in these coordinates [s].
  double critical_time_step() const;
  /// "full" or "modal-N" (with "+s" when the static correction is kept):
  /// the casing-basis name of campaign runs and summaries.
  std::string name() const;
};

/// The lowest `modes` modes of the clamped casing (1 <= modes <= n_c) plus
/// the static correction for `forcing` (the force vector on the casing
/// dofs; zero: none). Throws std::invalid_argument for a count out of
/// range and ModalError when the eigensolver fails.
CasingBasis reduce_casing(const Casing& casing, int modes, const Eigen::VectorXd& forcing);

/// The same for a 3D casing (issue 27: the flexible casing of
/// reference/model/gmsh_casing, or one's own deck): its lowest `modes`
/// modes by the sparse eigensolver (1 <= modes < its dofs) plus the static
/// correction for `forcing` (its dofs; empty or zero: none), K_c x = F by
/// CHOLMOD. Throws std::invalid_argument for a count or size out of range
/// and ModalError when the eigensolver or the factorization fails.
CasingBasis reduce_solid_casing(const Component& casing, int modes, const Eigen::VectorXd& forcing);

} // namespace rsi
