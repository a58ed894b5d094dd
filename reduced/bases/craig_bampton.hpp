#pragma once
// Craig-Bampton (paper eqs. 3-7): eta fixed-interface modes (modes of
// K_II phi = omega^2 M_II phi, boundary clamped) and the n_B constraint
// modes (guyan.hpp). q = (u_eta, q_B):
//   u_I = Phi_fixed u_eta + Psi_I q_B,   u_B = q_B.
// The fixed-interface modes are M_II-normalised, so K^ is block diagonal:
// diag(omega_i^2) and the Guyan stiffness (SPEC V3).
// By count: the eta lowest modes. By selection (mode_selection.hpp): any
// eta of a pool of the lowest modes, in ascending order.
// Valid range: 0 <= eta <= n_I (ReductionError otherwise).

#include <chrono>
#include <vector>

#include <Eigen/SparseCore>

#include "modal_analysis.hpp"
#include "partition.hpp"
#include "reduced_basis.hpp"
#include "turned_constraint_modes.hpp"

namespace rsi {

/// ReductionError unless 0 <= eta <= n_I.
void check_fixed_interface_count(const Partition& p, int eta);

/// The candidates of a Craig-Bampton basis: the constraint modes and the
/// `count` lowest fixed-interface modes, computed as the count-based
/// builder computes them (one solver choice, few_modes(count, n_I)).
struct FixedInterfacePool {
  Eigen::MatrixXd constraint; ///< Psi_I = -K_II^-1 K_IB, n_I x n_B
  Modes modes;                ///< shapes n_I x count, ascending (empty for count 0)
};

/// Throws ReductionError for a count out of range or a singular K_II.
/// With `cyclic`, the constraint modes by the turns (guyan.hpp).
FixedInterfacePool fixed_interface_pool(const Eigen::SparseMatrix<double>& stiffness,
                                        const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                        int count, const CyclicBoundary* cyclic = nullptr);

/// The basis keeping the pool's modes `kept` (ascending indices into the
/// pool), in that order; `start` is when the work began (build_seconds).
/// ReducedBasis::mode_index = kept, n_modes = kept.size(). With `cyclic`
/// (the pool's too), K^ and M^ by the turns (finish_basis).
ReducedBasis craig_bampton(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const Partition& p,
                           const FixedInterfacePool& pool, const std::vector<int>& kept,
                           std::chrono::steady_clock::time_point start,
                           const CyclicBoundary* cyclic = nullptr);

/// The eta lowest fixed-interface modes.
ReducedBasis craig_bampton(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const Partition& p, int eta,
                           const CyclicBoundary* cyclic = nullptr);

} // namespace rsi
