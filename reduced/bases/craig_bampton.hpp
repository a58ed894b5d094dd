#pragma once
// Craig-Bampton (paper eqs. 3-7): eta fixed-interface modes (the lowest
// modes of K_II phi = omega^2 M_II phi, boundary clamped) and the n_B
// constraint modes (guyan.hpp). q = (u_eta, q_B):
//   u_I = Phi_fixed u_eta + Psi_I q_B,   u_B = q_B.
// The fixed-interface modes are M_II-normalised, so K^ is block diagonal:
// diag(omega_i^2) and the Guyan stiffness (SPEC V3).
// Valid range: 0 <= eta <= n_I (ReductionError otherwise).

#include <Eigen/SparseCore>

#include "partition.hpp"
#include "reduced_basis.hpp"

namespace rsi {

ReducedBasis craig_bampton(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const Partition& p, int eta);

} // namespace rsi
