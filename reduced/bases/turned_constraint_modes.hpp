#pragma once
// Constraint modes and projections of a cyclic component's CB basis from one
// sector's boundary (issue 27: the default 3D system's bases in 60 s).
//
// Constraint modes (cyclic_symmetry.hpp): only the representatives'
// (one sector's boundary nodes: 48 of the default disk's 1,056 boundary
// dofs) are solved; boundary node t = P^k(r) takes psi_(t,c) = P^k sum_d
// (R^k)_cd psi_(r,d), interior rows only (its boundary rows are the
// identity's, as every constraint mode's).
//
// Projections: with P^T A P = A, the block of T^T A T between boundary
// triples t = P^k(r) and t' is
//     (T^T A T)_(t,t') = R^k (T^T A T)_(r, P^-k(t')) (R^k)^T,
// the pair turned back by k so that its first node is the representative
// (the pair's energy does not depend on the frame). So only the rows of
// the fixed-interface modes and of the representatives are formed, W^T A T
// with W = [Phi, the representatives' columns]: (eta + 3 n_r) n r
// multiply-adds instead of n r^2 (68 of 1,076 rows on the default disk).
// The rows of the boundary against the modes are the modes' rows
// transposed (A symmetric). For a model whose P^T A P differs from A by
// round-off delta (relative_asymmetry), the result differs from the direct
// product by about delta |T|^T |A| |T| entrywise.

#include <functional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "component.hpp"
#include "cyclic_symmetry.hpp"
#include "partition.hpp"

namespace rsi {

struct CyclicBoundary {
  CyclicSymmetry symmetry;
  BoundaryOrbits orbits;
};

/// The turn and the boundary's orbits of component `c` with partition `p`.
/// Throws ReductionError as cyclic_symmetry and boundary_orbits.
CyclicBoundary cyclic_boundary(const Component& c, int sectors, const Partition& p);

/// K_II^-1 applied to the columns of its argument.
using InteriorSolve = std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>;

/// The constraint modes -K_II^-1 K_IB (n_I x n_B, p.boundary's order):
/// the representatives' through `solve`, the others turned.
Eigen::MatrixXd turned_constraint_modes(const Eigen::SparseMatrix<double>& stiffness,
                                        const Partition& p, const CyclicBoundary& cyclic,
                                        const InteriorSolve& solve);

/// T^T A T by the turns, for T = [eta fixed-interface modes, the constraint
/// modes of p.boundary] (craig_bampton.hpp's): not yet symmetrised.
Eigen::MatrixXd cyclic_projection(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& t,
                                  int eta, const CyclicBoundary& cyclic);

/// An n_B x n_B matrix G of the boundary with P^T G P = G (a projection
/// T^T A T's boundary block, (K^-1)_BB) from the representatives' rows
/// `rows` (3 n_r x n_B: representative, direction; columns in p.boundary's
/// order): block (t, t') = R^k G_(r, P^-k t') R^kT for t = P^k r.
Eigen::MatrixXd turned_boundary_block(const Eigen::MatrixXd& rows, const CyclicBoundary& cyclic);

} // namespace rsi
