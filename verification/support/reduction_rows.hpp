#pragma once
// The rows V3 / V4 of SPEC §4, and MacNeal's (macneal.hpp), on ANY component
// (K, M, boundary dofs): each function measures and returns numbers, each
// with its worst ratio to a round-off bound; the caller prints them and
// asserts ratio <= 1. Written for large 3D components too (Rotor 37,
// 61,098 dofs): no dense n x n matrix anywhere, only sparse products, one
// CHOLMOD factor of K per component (and one of K_II for the zero-mode
// row), the lowest modes (lowest_modes: dense up to dense_limit dofs,
// Spectra's Lanczos above) and dense r x r reduced matrices.
//
// Every reference quantity is computed independently of reduced/ (which
// supplies only the bases and, for MacNeal, the functions under test,
// reduced_eigenvalues and reduced_omega_max): the static reference is a CHOLMOD supernodal
// factorization of K (reduced/ solves K_II or K against other right-hand
// sides and refines them), cond(K) and the extreme eigenvalues come from
// Lanczos on K and on K^-1, the reduced eigenvalues from Eigen's dense
// generalized solver with eigenvectors (for their bounds; LAPACK's dsygvd
// for the complete basis, r = n).
//
// Bounds (first order in eps, worst case, the convention of
// test_reduction_bases), n the order of the matrices involved:
// - a product x^T A y formed in floating point: n eps |x|^T |A| |y|, or
//   n eps ||A||_inf ||x|| ||y||;
// - an eigenvalue w2 of a backward-stable dense solve, eigenvector x
//   B-normalised: n eps (||A|| + |w2| ||B||) ||x||^2;
// - an eigenvalue of Spectra's Lanczos (relative residual tol = 1e-12 of
//   the shift-inverted operator, lanczos_tol): tol w2 on top of the above;
//   its Ritz vectors are K-orthogonal up to tol^2 lambda_max;
// - a linear solve with A: relative error n eps cond(A) (normwise).
// Ratios far below 1 are the rule: the bounds are worst-case.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal_analysis.hpp"
#include "partition.hpp"
#include "reduced_basis.hpp"

namespace rsi::rows {

/// Spectra's convergence tolerance in lowest_modes (modal_analysis.cpp).
constexpr double lanczos_tol = 1e-12;

/// A measured error and its worst ratio to the round-off bound (over the
/// entries, eigenvalues or loads measured): ratio <= 1 must hold.
struct Measure {
  double error = 0.0; ///< worst measured value, in the units the field states
  double ratio = 0.0; ///< worst error / bound
};

/// A component as the rows see it: K, M and the boundary, and what every
/// row reuses. K must be positive definite (a supported part), M positive
/// definite.
class Component {
public:
  /// `stiffness` and `mass` are not owned and must outlive the component.
  /// Factorizes K (CHOLMOD); throws std::runtime_error if it fails.
  Component(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
            const std::vector<int>& boundary);
  ~Component();
  Component(const Component&) = delete;
  Component& operator=(const Component&) = delete;

  const Eigen::SparseMatrix<double>& k() const { return m_k; }
  const Eigen::SparseMatrix<double>& m() const { return m_m; }
  const Eigen::SparseMatrix<double>& k_abs() const { return m_k_abs; } ///< |K|
  const Eigen::SparseMatrix<double>& m_abs() const { return m_m_abs; } ///< |M|
  const Partition& partition() const { return m_p; }
  int n() const { return m_p.n(); }
  int n_boundary() const { return m_p.n_boundary(); }
  double k_norm() const { return m_k_norm; } ///< ||K||_inf
  double m_norm() const { return m_m_norm; } ///< ||M||_inf

  /// K^-1 F (n x c), by the CHOLMOD factor; throws if the solve fails.
  Eigen::MatrixXd solve(const Eigen::Ref<const Eigen::MatrixXd>& f) const;
  /// G = (K^-1)_BB, the boundary flexibility (n_B x n_B), on first use.
  const Eigen::MatrixXd& boundary_flexibility() const;
  /// cond_2(K) = lambda_max(K) / lambda_min(K), by Lanczos on K and on
  /// K^-1 (the factor), on first use.
  double cond_k() const;
  /// omega_max^2 of (K, M), by lowest_modes' Lanczos (max_angular_frequency),
  /// on first use; relative accuracy lanczos_tol.
  double lambda_max() const;

private:
  struct Factor;
  const Eigen::SparseMatrix<double>& m_k;
  const Eigen::SparseMatrix<double>& m_m;
  Eigen::SparseMatrix<double> m_k_abs, m_m_abs;
  Partition m_p;
  double m_k_norm = 0.0, m_m_norm = 0.0;
  std::unique_ptr<Factor> m_factor;
  mutable Eigen::MatrixXd m_boundary_flexibility;
  mutable double m_cond_k = 0.0;
  mutable double m_lambda_max = 0.0;
};

// ------------------------------------------------- precondition: M > 0

/// M positive definite to working precision: the assumption of every row
/// that computes modes (lowest_modes' sparse path factors M for omega_max,
/// Component::lambda_max likewise). The lowest eigenvalues of M by Lanczos
/// on (M + c I)^-1, c = sqrt(eps) lambda_max(M) (CHOLMOD factor of the
/// shifted matrix, positive definite for any M >= 0): lambda = 1/mu - c.
/// A backward-stable factor resolves the eigenvalues of M only to about
/// n eps lambda_max(M) (absolute): an eigenvalue below that is zero to
/// working precision and M is singular (a mass matrix integrated with too
/// few points, a node without mass).
struct MassRow {
  bool cholesky = false;   ///< CHOLMOD's supernodal LL^T of M succeeded
  double lambda_max = 0.0; ///< lambda_max(M), Lanczos
  double floor = 0.0;      ///< n eps lambda_max(M): the resolution
  Eigen::VectorXd lowest;  ///< the `count` lowest eigenvalues of M, ascending
  int n_below_floor = 0;   ///< how many of them are below the floor
};
/// `count` = 0: CHOLMOD's attempt and lambda_max(M) only (a few seconds on
/// 61,098 dofs; the shifted Lanczos takes ten more).
MassRow mass_definiteness(const Component& c, int count);

// ------------------------------------------------------------- V3: modes

/// Orthogonality of a set of modes of (K, M) (the full ones, or the
/// fixed-interface ones of (K_II, M_II)): Phi^T M Phi = I,
/// Phi^T K Phi = diag(omega^2).
struct ModeRow {
  int n_modes = 0;
  bool lanczos = false; ///< computed by Lanczos (else dense dsygvd)
  /// |Phi^T M Phi - I|_ij; bound n eps ||M|| |phi_i| |phi_j|.
  Measure mass;
  /// |phi_i^T K phi_j| / omega_m^2, i != j (omega_m: the highest of the set);
  /// bound n eps ||K|| |phi_i| |phi_j| + tol^2 lambda_max (Lanczos).
  Measure stiffness_off;
  /// |phi_i^T K phi_i - omega_i^2| / omega_i^2 (omega_i^2 as the solver
  /// returned it); bound 2 n eps (||K|| + omega_i^2 ||M||) |phi_i|^2 (solve
  /// and product) + tol omega_i^2 (Lanczos).
  Measure stiffness_diag;
  /// max_i ||K phi_i - omega_i^2 M phi_i|| / ||K phi_i|| (information).
  double residual = 0.0;
};

/// The row for modes of (k, m) (n x n, positive definite), computed by
/// Lanczos or not; lambda_max bounds the largest eigenvalue of (k, m).
ModeRow mode_orthogonality(const Eigen::SparseMatrix<double>& k,
                           const Eigen::SparseMatrix<double>& m, const Modes& modes, bool lanczos,
                           double lambda_max);

/// The `count` lowest modes of the whole component (lowest_modes, automatic
/// solver: dense up to dense_limit dofs, Lanczos above).
Modes full_modes(const Component& c, int count);
/// Whether full_modes uses Lanczos (n > dense_limit) or dsygvd.
bool full_modes_by_lanczos(const Component& c);

/// Row of the full modes.
ModeRow full_mode_row(const Component& c, const Modes& full);

/// Row of the eta lowest fixed-interface modes (K_II, M_II), computed as
/// craig_bampton computes them (solver few_modes(eta, n_I)).
ModeRow fixed_interface_row(const Component& c, int eta);

/// Free-interface modes as craig_chang_martinez / macneal compute them
/// (solver few_modes(psi, n)): their row, and their eigenvalues against the
/// full modes' (an independent solve when the solvers differ).
struct FreeModeRow {
  ModeRow modes;
  /// |omega_i^2(free) - omega_i^2(full)| / omega_i^2(full); bound: the sum
  /// of both eigenvalue bounds (eigenvalue_bounds).
  Measure eigenvalues;
};
FreeModeRow free_mode_row(const Component& c, int psi, const Modes& full);

/// Per-eigenvalue bound of a solve of (K, M): n eps (||K|| + w2 ||M||)
/// ||phi||^2, plus tol w2 for Lanczos.
Eigen::VectorXd eigenvalue_bounds(const Component& c, const Modes& modes, bool lanczos);

// ------------------------------------------------------ V3: CB structure

/// Craig-Bampton's K^ block diagonal (SPEC V3): the fixed-interface modes
/// are K-orthogonal to the constraint modes and M-orthonormal.
struct BlockRow {
  /// |K^(modal, B)| / ||K^||_inf; bound 2 n eps ||K|| |t_i| |t_b| (the
  /// residual of Psi and the product).
  Measure coupling;
  /// |M^(modal, modal) - I|; bound n eps ||M|| |t_i| |t_j|.
  Measure modal_mass;
  /// |K^(i, j)| / ||K^||_inf, modal i != j; bound n eps ||K|| |t_i| |t_j| +
  /// tol^2 lambda_max(K, M) (interlacing: lambda_max(K_II, M_II) below it).
  Measure modal_stiffness_off;
};
BlockRow cb_block_diagonal(const Component& c, const ReducedBasis& cb);

// ------------------------------------------------------ V4: static loads

/// Exact static response to boundary loads (any CB, CCM, MacNeal basis:
/// span T contains K^-1 E_B).
struct StaticRow {
  /// ||T K^-1 T^T f - K^-1 f|| / ||K^-1 f||, worst load; bound
  /// 2 n eps cond(K) + n_B eps cond(R_B) (both backward-stable solutions of
  /// K u = f; CCM and MacNeal add R_B^-1).
  Measure response;
  /// ||S G - I||_2 with S = K^ statically condensed onto the boundary
  /// coordinates and G = (K^-1)_BB: S = G^-1, the boundary stiffness of the
  /// full model; bound cond_2(G) (the response bound + n_B eps cond_2(S)).
  Measure boundary_stiffness;
  double cond_g = 0.0; ///< cond_2(G) (information)
};
/// `boundary_loads`: n_B x L, one load per column [N].
StaticRow static_response(const Component& c, const ReducedBasis& basis,
                          const Eigen::Ref<const Eigen::MatrixXd>& boundary_loads);

/// Four boundary loads, entries uniform in [-1, 1] N (mt19937, seed 2007):
/// the static row's loads on every component.
Eigen::MatrixXd random_boundary_loads(int n_boundary);

// ------------------------------------------- V4: CB(0) = CCM(0) = Guyan

/// One of CB(0), CCM(0) against Guyan, in the same coordinates q_B.
struct ZeroModeRow {
  std::string method;
  double t_ulps = 0.0; ///< max |dT_ij| in ulps of Guyan's T_ij (information)
  /// ||dT||_2; bound 2 dPsi + n_B eps cond(R_B) (1 + ||Psi||), with
  /// dPsi = n eps ||K|| / lambda_min(K_II) (1 + ||Psi||) per method.
  Measure transformation;
  /// ||dK^||_2 / ||K^||_2; bound (2 n eps ||K|| ||T||^2 + 2 ||dT|| n eps
  /// ||K|| (1 + ||Psi||) + ||K|| ||dT||^2) / ||K^||_2 (K^ stationary in dPsi).
  Measure stiffness;
  /// ||dM^||_2 / ||M^||_2; bound (2 n eps ||M|| ||T||^2 + 2 ||M|| ||T|| ||dT||
  /// + ||M|| ||dT||^2) / ||M^||_2.
  Measure mass;
};
/// cb0 and ccm0 against guyan; factorizes K_II for lambda_min(K_II).
std::vector<ZeroModeRow> zero_mode_limits(const Component& c, const ReducedBasis& guyan,
                                          const ReducedBasis& cb0, const ReducedBasis& ccm0);

// ------------------------------------------------- V4: Rayleigh-Ritz

/// One basis of a nested sequence against the full modes.
struct RitzRow {
  std::string method;
  int n_modes = 0;
  int n_reduced = 0;
  /// max over the compared eigenvalues of |lambda_i(red) - lambda_i(full)| / lambda_i(full)
  /// (information: the accuracy of the basis).
  double lowest_error = 0.0;
  /// (lambda_i(full) - lambda_i(red)) / lambda_i(full), i below r and the
  /// full modes computed: <= 0 by Courant-Fischer; bound the two eigenvalue bounds.
  Measure below;
  /// (lambda_r(red) - lambda_max(full)) / lambda_max(full): <= 0; bound the
  /// reduced eigenvalue bound + lanczos_tol lambda_max(full).
  Measure top;
  /// (lambda_i - lambda_i(previous basis)) / lambda_i(previous), i < lowest:
  /// <= 0 for nested bases; bound the two reduced eigenvalue bounds. Zero
  /// for the first basis.
  Measure rise;
  double omega_max = 0.0; ///< reduced omega_max [rad/s] (information)
};
/// `nested`: bases of one method with growing mode counts (each span
/// containing the previous); `lowest`: how many eigenvalues the rise and
/// lowest_error compare (at most full.n_modes() and every basis' r).
std::vector<RitzRow> rayleigh_ritz(const Component& c,
                                   const std::vector<const ReducedBasis*>& nested,
                                   const Modes& full, bool full_by_lanczos, int lowest);

// ------------------------------------------ V4: a complete basis = full

/// A basis spanning the whole space (Craig-Bampton with every
/// fixed-interface mode: r = n, T square and nonsingular): (K^, M^) =
/// T^T (K, M) T is congruent to (K, M), so its eigenvalues are the full ones
/// exactly, whatever the accuracy of the modes inside T; only the rounding
/// of K^, M^ and of the two dense solves separates them. Dense n x n:
/// for components of a few thousand dofs.
struct CompleteRow {
  int n_reduced = 0;
  /// |lambda_i(red) - lambda_i(full)| / lambda_i(full), every i; bound per
  /// i: the reduced eigenvalue's (forming K^ and M^: n eps ((|T||x_i|)^T |K|
  /// (|T||x_i|) + lambda_i (|T||x_i|)^T |M| (|T||x_i|)), and the dense solve
  /// of the pencil scaled by powers of two D (D M^ D with a unit-order
  /// diagonal): r eps (||D K^ D|| + lambda_i ||D M^ D||) ||D^-1 x_i||^2, x_i
  /// M^-normalised) + the full one (eigenvalue_bounds, dsygvd). The dense
  /// solve's term is about r eps lambda_max for every i: the lowest
  /// eigenvalues are bounded only to r eps lambda_max / lambda_i (relative),
  /// the absolute accuracy of any backward-stable dense solver.
  Measure eigenvalues;
  double lowest_error = 0.0;   ///< the same error over the lowest `lowest` (information)
  double lowest_bound = 0.0;   ///< the largest relative bound over the lowest `lowest`
  double omega_max = 0.0;      ///< reduced omega_max [rad/s], from this solve
  double omega_max_full = 0.0; ///< the full dense omega_max [rad/s]
  double seconds = 0.0;        ///< the dense reduced solve and the bounds
};
/// `full_dense`: every mode of (K, M) (lowest_modes, ModalSolver::dense,
/// count n); the reduced eigenpairs by LAPACK's dsygvd (Eigen's dense
/// solver takes minutes at r = 4,000).
CompleteRow complete_basis_row(const Component& c, const ReducedBasis& basis,
                               const Modes& full_dense, int lowest);

// ------------------------------------------------------------- MacNeal

/// MacNeal's basis against CCM's and CB's with the same mode count
/// (macneal.hpp).
struct MacNealRow {
  double boundary_mass = 0.0; ///< max |M^(b, :)|, |M^(:, b)|: exactly 0
  double modal_mass = 0.0;    ///< max |M^(q, q) - I|: exactly 0
  double t_vs_ccm = 0.0;      ///< max |T - T_CCM|: exactly 0 (the same code)
  /// |K^ - T^T K T|_ij recomputed here column by column; bound
  /// 2 n eps (|T|^T |K| |T|)_ij (both roundings).
  Measure stiffness;
  /// |omega_i^2(MacNeal) - omega_i^2(full)| / omega_i^2(full), the finite
  /// eigenvalues (critical_step.hpp's condensation) against the lowest psi
  /// full ones; bound per i: n eps (|T||z_i|)^T |K| (|T||z_i|) (forming K^;
  /// z_i the reduced eigenvector, T z_i = phi_i, the condensation being
  /// stationary) + n_B eps cond(K^_bb) |x_b|^T |K^_bb| |x_b| (the
  /// condensation's solve) + psi eps ||K_c||_inf (dense solve) + the kept
  /// free modes' own error (lanczos_tol omega_i^2 when computed by Lanczos,
  /// plus their rounding, taken as the full eigenvalue bound again) + the
  /// full eigenvalue bound.
  Measure eigenvalues;
  double omega_max = 0.0;     ///< MacNeal's reduced omega_max [rad/s]
  double omega_psi = 0.0;     ///< the psi-th full omega [rad/s]
  double omega_max_ccm = 0.0; ///< CCM(psi)'s reduced omega_max
  double omega_max_cb = 0.0;  ///< CB(psi)'s reduced omega_max
  /// (omega_max^2 - omega_max_ccm^2) / omega_max_ccm^2: <= 0, since span
  /// T_CCM contains Phi_1 whose largest Rayleigh quotient is omega_psi^2;
  /// bound: MacNeal's eigenvalue bound of omega_psi^2 + CCM's dense solve.
  Measure below_ccm;
};
MacNealRow macneal_row(const Component& c, const ReducedBasis& macneal, const ReducedBasis& ccm,
                       const ReducedBasis& cb, const Modes& full, bool full_by_lanczos);

} // namespace rsi::rows
