#pragma once
// Characteristic constraint modes (Castanier, Tan, Pierre, AIAA J. 39(6),
// 2001): Craig-Bampton (craig_bampton.hpp) with its boundary coordinates
// reduced in turn. The Guyan boundary problem of the CB basis,
//   K^_BB psi = lambda M^_BB psi,   Psi_c^T M^_BB Psi_c = I,
// (K^_BB the Schur complement, M^_BB = Psi^T M Psi of the constraint modes
// Psi), gives n_c modes of the whole boundary, and
//   u = Phi_fixed u_eta + Psi Psi_c q_c,   u_B = Psi_c q_c,
// i.e. T_cc = T_cb S with S = diag(I_eta, Psi_c), K^ = S^T K^_cb S,
// M^ = S^T M^_cb S (a congruence of the CB matrices: the span of T_cc is a
// subspace of CB's, equal to it for n_c = n_B). K^ is diagonal:
// diag(omega_i^2, lambda_c); M^'s boundary block is I.
// The boundary is no longer a set of coordinates of q
// (ReducedBasis::boundary_position is empty, boundary_shapes = Psi_c): the
// component integrator reads u_B = Psi_c q_c (component_rotor_part.hpp);
// the paper's 2D integrator keeps u_B as coordinates and does not take it.
// Valid range: 0 <= eta <= n_I, 1 <= n_c <= n_B (ReductionError otherwise).

#include <Eigen/SparseCore>

#include "partition.hpp"
#include "reduced_basis.hpp"
#include "turned_constraint_modes.hpp"

namespace rsi {

/// CB with eta fixed-interface modes and its boundary reduced to the n_c
/// lowest characteristic constraint modes. Throws ReductionError for counts
/// out of range or a boundary mass M^_BB that is not positive definite.
/// With `cyclic`, its CB basis by the turns (craig_bampton.hpp).
ReducedBasis characteristic_constraint(const Eigen::SparseMatrix<double>& stiffness,
                                       const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                       int eta, int n_c, const CyclicBoundary* cyclic = nullptr);

} // namespace rsi
