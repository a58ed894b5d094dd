#pragma once
// Craig-Chang-Martinez's and MacNeal's transformation (eq. 20) of a cyclic
// component from its constraint modes, turned from one sector's boundary
// (turned_constraint_modes.hpp; issue 27: the default 3D system's bases in
// 60 s), instead of K^-1 on every boundary column and the dense solve
// R_B^T A_I^T = R_I^T over every interior row (926 s on the default disk).
//
// With Psi the constraint modes (boundary rows the identity) and
// G = (K^-1)_BB, K^-1 E_B = Psi G: K X = E_B gives K_II X_I + K_IB X_B = 0,
// so X_I = Psi_I X_B, X_B = G. Then, with D = Omega_1^-2 Phi_1B^T,
//   R(:, B) = Psi G - Phi_1 D,     R_B = G - Phi_1B D,
// and, since G = R_B + Phi_1B D,
//   A = R(:, B) R_B^-1 = Psi - Y C,   Y = Phi_1 - Psi Phi_1B,  C = D R_B^-1,
//   Phi_1 - A Phi_1B = Y (I + C Phi_1B):
// T = [Psi, 0] + Y W with W = [-C, I + C Phi_1B] (psi x (n_B + psi)), a
// rank-psi change of Guyan's basis (Y vanishes on the boundary rows: T's
// boundary rows are [I, 0] exactly). Its projections
//   T^T A T = [Psi^T A Psi, 0; 0, 0] + E X W + W^T X^T E^T + W^T (Y^T A Y) W,
// X = Psi^T A Y, E = [I; 0], need Psi^T A Psi (Guyan's, by the turns) and
// products with the psi columns of Y only. G is turned from one sector's
// columns K^-1 e_r (refined solves; on the factor the modes use from
// block_method_min_dofs on): G = S^-1 from S = Psi^T K Psi would multiply
// S's turn error by cond(S) (1.6e6 on the CI disk). Nothing asks the kept
// modes to be a turn-invariant set: they enter through Y and
// D, never turned.
//
// Accuracy: Psi, S and G carry the model's asymmetry under the turn (about
// 1e-10 of max |K| for ccx's turned elements, relative_asymmetry); R_B
// then loses what the kept modes cancel of G, and C what cond(R_B)
// amplifies (Bladh et al. 2003), as on the direct path. test_cyclic_bases
// measures the difference to the direct basis.

#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "craig_chang_martinez.hpp"
#include "partition.hpp"
#include "reduced_basis.hpp"
#include "turned_constraint_modes.hpp"

namespace rsi {

/// T (eq. 20), cond(R_B), the kept modes' omega and K^ = T^T K T,
/// M^ = T^T M T (symmetric), keeping every mode of `pool`, whose
/// flexibility holds K^-1 on the representatives' boundary columns only
/// (free_interface_pool with cyclic.orbits.representative_positions()). The other fields of
/// the returned basis: n_modes, requested_modes, candidate_modes,
/// mode_index, boundary_position; the caller names the method and times
/// the build. Throws ReductionError, its message starting with `name`, for
/// a numerically singular R_B (a singular K is the pool's);
/// std::invalid_argument for a complete pool or one whose flexibility is
/// not the representatives' 3 n_r columns.
/// With `pieces`, Psi (n x n_B, boundary rows the identity), Y and W of
/// T = [Psi, 0] + Y W (Y, W empty without modes) and G = (K^-1)_BB as
/// turned (before R_B symmetrizes it), for a caller's checks.
struct TurnedResidualPieces {
  Eigen::MatrixXd psi, y, w, g;
};
ReducedBasis turned_residual_flexibility(const Eigen::SparseMatrix<double>& stiffness,
                                         const Eigen::SparseMatrix<double>& mass,
                                         const Partition& p, const FreeInterfacePool& pool,
                                         const CyclicBoundary& cyclic, const std::string& name,
                                         TurnedResidualPieces* pieces = nullptr);

} // namespace rsi
