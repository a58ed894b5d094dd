#pragma once
// Nodal diameter of a mode of a cyclic structure.
//
// The vector is n_blocks identical blocks of block_size dofs, block k at the
// angle 2 pi k / n_blocks with its dofs in its own rotating frame (sector
// frame, polar frame). For each dof j of the block, the discrete Fourier
// transform over k gives X_j(n); a mode of nodal diameter n has energy only
// in harmonics n and N - n. Returned: the n in [0, N/2] with the largest
// sum_j (|X_j(n)|^2 + |X_j(N-n)|^2).

#include <Eigen/Core>

namespace rsi {

int nodal_diameter(const Eigen::Ref<const Eigen::VectorXd>& mode, int n_blocks, int block_size);

/// Share of the mode's sum of squares that lies in its dominant harmonic
/// (1 for a mode of a perfectly cyclic structure).
double nodal_diameter_purity(const Eigen::Ref<const Eigen::VectorXd>& mode, int n_blocks,
                             int block_size);

} // namespace rsi
