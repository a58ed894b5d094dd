#pragma once
// Guyan static condensation: the constraint modes of the boundary
// (paper §4.2): for a unit displacement of boundary dof b, the others held
// at zero and no interior load, u_I = -K_II^-1 K_IB e_b. Coordinates q = q_B.
// Equal to Craig-Bampton with eta = 0 and to Craig-Chang-Martinez with
// psi = 0 (SPEC V4). Assumes K_II positive definite (the hub is clamped).

#include <chrono>
#include <memory>
#include <string>

#include <Eigen/SparseCore>

#include "accurate_solve.hpp"
#include "cholmod_shift_invert.hpp"
#include "energy_resolution.hpp"
#include "modal_analysis.hpp"
#include "partition.hpp"
#include "reduced_basis.hpp"
#include "turned_constraint_modes.hpp"

namespace rsi {

/// X = A^-1 B for a matrix A that must be symmetric positive definite, by a
/// sparse Cholesky factorization (CHOLMOD) and iterative refinement to the
/// last bit (accurate_solve). CHOLMOD's simplicial LDL^T does
/// not stop at a negative or zero pivot, and a singular A factorizes with
/// round-off pivots, so the factor is checked: a pivot d <= 0 (A indefinite)
/// or a lowest mode (inverse iteration on the factor) whose energy is not
/// resolved (A not positive definite to working precision, unresolved())
/// throws ReductionError "`name` is singular or indefinite (...);
/// `remedy`", with the column of A and the pivot, or the energy and its
/// rounding.
AccurateMatrix solve_positive_definite(const Eigen::SparseMatrix<double>& a,
                                       const Eigen::MatrixXd& b, const std::string& name,
                                       const std::string& remedy);

/// Why the factor's lowest mode shows its matrix not positive definite to
/// working precision (linalg/energy_resolution): its energy not above its
/// rounding; empty if it is resolved.
std::string unresolved(const DefinitenessCheck& lowest);

/// The large-model path: from block_method_min_dofs dofs on, one CHOLMOD
/// factor of A serves both the static solves (accurate_solve with it) and
/// the modes (lowest_modes on the factor), instead of a factorization each
/// (1.5 s apiece for Rotor 37's K_II). True if A (n x n) takes it.
inline bool shares_factor(int n) {
  return n >= block_method_min_dofs;
}

/// A's factor (shift-invert operator at shift 0, with `mass` for the
/// modes), checked as solve_positive_definite checks its own (not positive
/// definite, or its lowest mode against `mass` not resolved):
/// ReductionError "`name` is singular or indefinite (...); `remedy`".
std::unique_ptr<CholmodShiftInvert> factor_positive_definite(const Eigen::SparseMatrix<double>& a,
                                                             const Eigen::SparseMatrix<double>& mass,
                                                             const std::string& name,
                                                             const std::string& remedy);

/// X = A^-1 B refined to the last bit (accurate_solve) on a checked factor of A.
AccurateMatrix solve_with(const CholmodShiftInvert& factor, const Eigen::SparseMatrix<double>& a,
                          const Eigen::MatrixXd& b, const std::string& name);

/// Psi_I = -K_II^-1 K_IB (n_I x n_B), by solve_positive_definite: rounded
/// to the last bit, so it does not depend on the factor's round-off. Throws
/// ReductionError naming K_II if it is singular or indefinite (the boundary
/// does not hold the part against every rigid motion). With `cyclic`, one
/// sector's solved so and the others turned (turned_constraint_modes.hpp):
/// those carry the turn's rounding and the model's own asymmetry (about
/// 1e-10 of max |K| for ccx's turned elements), not the last bit.
Eigen::MatrixXd constraint_modes(const Eigen::SparseMatrix<double>& stiffness, const Partition& p,
                                 const CyclicBoundary* cyclic = nullptr);

/// The same on K_II's factor (k_ii = K_II, as factorized).
Eigen::MatrixXd constraint_modes(const Eigen::SparseMatrix<double>& stiffness, const Partition& p,
                                 const CholmodShiftInvert& k_ii_factor,
                                 const Eigen::SparseMatrix<double>& k_ii,
                                 const CyclicBoundary* cyclic = nullptr);

/// The name and remedy of K_II in the messages of constraint_modes.
std::string interior_stiffness_name(const Partition& p);
extern const char* const interior_stiffness_remedy;

/// Completes a basis whose transformation is set: the n_boundary boundary
/// coordinates sit at q[first_boundary_position ...], K^ = T^T K T and
/// M^ = T^T M T (symmetrized: the products are symmetric up to round-off),
/// and the build time since `start`. With `cyclic` (T a CB basis of its
/// boundary, first_boundary_position its eta modes), the products by the
/// turns (cyclic_projection).
void finish_basis(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int n_boundary,
                  int first_boundary_position, std::chrono::steady_clock::time_point start,
                  ReducedBasis& basis, const CyclicBoundary* cyclic = nullptr);

ReducedBasis guyan(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, const Partition& p,
                   const CyclicBoundary* cyclic = nullptr);

} // namespace rsi
