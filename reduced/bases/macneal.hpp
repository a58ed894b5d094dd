#pragma once
// MacNeal's method (MacNeal, Computers & Structures 1, 1971; as the 'MCN'
// CMS_ROM of NLvib and NLstep: Monjaraz-Tec, Gross, Krack, Computers &
// Structures 260 (2022) 106698): psi free-interface modes Phi_1 (the
// lowest modes of the whole part, M-normalised) plus the residual
// flexibility of the boundary, with the boundary made massless.
//
// With R = K^-1 - Phi_1 Omega_1^-2 Phi_1^T (Phi_1^T M R = 0, Phi_1^T K R = 0,
// R K R = R) and u = Phi_1 q + R(:, B) f, the energies are exactly
//   u^T K u = q^T Omega_1^2 q + f^T R_B f,
//   u^T M u = q^T q + f^T R(:, B)^T M R(:, B) f,
// and MacNeal neglects the residual mass R(:, B)^T M R(:, B). Changed to the
// coordinates q = (q_B, u_1) of Craig-Chang-Martinez (craig_chang_martinez.hpp,
// eq. 20) by f = R_B^-1 (u_B - Phi_1B u_1), the transformation T is CCM's,
// K^ = T^T K T (as CCM), and
//   M^ = [0 0; 0 I_psi]:
// the boundary block and the coupling of M^ are exact zeros. Statically
// condensing the massless u_B leaves K^ = Omega_1^2 on u_1, so without
// contact the finite eigenvalues of (K^, M^) are the kept omega_1^2 ...
// omega_psi^2, omega_max = omega_psi and the critical step of central
// differences is 2 / omega_psi (reduced_omega_max in critical_step.hpp).
// Condensing u_1 instead leaves K^ on u_B equal to ((K^-1)_BB)^-1: a static
// boundary load gives the full model's static response.
//
// Integrating it in time needs a static balance of the boundary with the
// contact forces at every step (SPEC §8); the reduced integrator of this
// suite inverts M^ and refuses such a basis (ReducedBasis::massless_boundary).
//
// Assumptions and errors as Craig-Chang-Martinez: K positive definite, R_B
// invertible (cond(R_B) reported, >= 1/(n eps) refused), ReductionError
// otherwise. Valid range: 1 <= psi <= n - n_B (psi = 0 would leave no mass).

#include <chrono>
#include <vector>

#include <Eigen/SparseCore>

#include "craig_chang_martinez.hpp"
#include "partition.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// The basis keeping the pool's modes `kept` (ascending, at least one), as
/// Craig-Chang-Martinez's overload of that name: several bases from one
/// pool's Lanczos and K^-1 E_B; `start` is when the work began
/// (build_seconds). With the pool of psi modes, every one kept, the bases
/// of the count-based builder below, bit for bit.
ReducedBasis macneal(const Eigen::SparseMatrix<double>& stiffness,
                     const Eigen::SparseMatrix<double>& mass, const Partition& p,
                     const FreeInterfacePool& pool, const std::vector<int>& kept,
                     std::chrono::steady_clock::time_point start);

/// The psi lowest free-interface modes; `cyclic` as craig_chang_martinez's.
ReducedBasis macneal(const Eigen::SparseMatrix<double>& stiffness,
                     const Eigen::SparseMatrix<double>& mass, const Partition& p, int psi,
                     const CyclicBoundary* cyclic = nullptr);

} // namespace rsi
