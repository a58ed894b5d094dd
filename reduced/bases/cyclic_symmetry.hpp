#pragma once
// The turn of an N-fold cyclic component onto itself (issue 27: the bladed
// disk's bases from one sector's solves).
//
// Turning the disk by alpha = 2 pi / N about its axis carries the node at x
// to the node at R(alpha) x, and a displacement field u to P u with
// (P u)(R x) = R u(x). A disk of N identical sectors has P^T K P = K and
// P^T M P = M: a turned field has the field's strain and kinetic energy.
// ccx integrates each sector's elements at turned coordinates, so the
// assembled K and M keep this up to the rounding of the element integration
// (relative_asymmetry measures it).
//
// What follows for the constraint modes (guyan.hpp): the mode of boundary
// node P^k(r), direction e_c, is P^k sum_d (R^k)_cd psi_(r,d), the turned
// combination of the modes of the representative node r (a unit
// displacement along R^k R^-k e_c = e_c there, zero at every other boundary
// node, no interior load). One sector's boundary nodes are solved for; the
// others are turned.

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "component.hpp"
#include "partition.hpp"

namespace rsi {

struct CyclicSymmetry {
  int sectors = 0;                                 ///< N
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); ///< unit
  std::vector<std::array<int, 3>> triples;         ///< the ux, uy, uz dofs of each node with dofs
  std::vector<int> turned;                         ///< the triple at R(alpha) x of triple t's node
};

/// The turn of component `c` about its rotation axis by 2 pi / sectors.
/// Throws ReductionError for sectors < 2, a dof other than ux, uy, uz, and,
/// naming the node, a node with dofs that lacks one of ux, uy, uz, lies on
/// another, or whose turned position holds no node with dofs within 1e-6
/// of the model's size (not `sectors`-fold cyclic), or when N turns do not
/// bring every node back.
CyclicSymmetry cyclic_symmetry(const Component& c, int sectors);

/// R(k alpha), exactly I at k = 0.
Eigen::Matrix3d turn_rotation(const CyclicSymmetry& s, int k);

/// P^k u for the n x m fields u (rows the component's dofs).
Eigen::MatrixXd turn_fields(const CyclicSymmetry& s, int k, const Eigen::MatrixXd& u);

/// P^k as a sparse n x n matrix (for checks: P^T K P - K).
Eigen::SparseMatrix<double> turn_matrix(const CyclicSymmetry& s, int k, int n_dofs);

/// max |(P^T A P - A)_ij| / max |A_ij|: how far the model is from its
/// symmetry (0 for an exactly cyclic A).
double relative_asymmetry(const CyclicSymmetry& s, const Eigen::SparseMatrix<double>& a);

/// The boundary grouped by turns: boundary position j (p.boundary[j]) is
/// component `component[j]` of the triple of representative `rep[j]`
/// turned `turns[j]` times; position[r][k][c] inverts it.
struct BoundaryOrbits {
  int sectors = 0;
  std::vector<int> rep, turns, component;
  std::vector<std::vector<std::array<int, 3>>> position;
  int n_representatives() const { return static_cast<int>(position.size()); }
  /// The boundary positions of the representatives' dofs, r by r, c by c.
  std::vector<int> representative_positions() const;
};

/// Throws ReductionError when a turned boundary node is not a whole
/// boundary triple, or comes back in fewer than N turns (on the axis);
/// std::invalid_argument for a partition of another size.
BoundaryOrbits boundary_orbits(const CyclicSymmetry& s, const Partition& p);

} // namespace rsi
