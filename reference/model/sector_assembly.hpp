#pragma once
// A bladed disk assembled from one sector's matrices (issue 27: bringing
// one's own sector deck): the sector's K_s and M_s (ccx's, of a deck the
// user meshed, its hub clamped by the deck's own *BOUNDARY) turned N times
// about the rotation axis by k alpha, alpha = 2 pi / N, and summed with the
// nodes of the two sector faces shared.
//
// Why the matrices turn: an element turned rigidly by R has the stiffness
// R^ K_e R^T and the mass R^ M_e R^T in the global frame (R^ = R on each
// node's translation triple: the strain energy and the kinetic energy do not
// depend on the frame), so the copy k of the sector is Q_k K_s Q_k^T with Q_k
// block-diagonal of R(k alpha), and the assembly is the sum of the N copies
// over the shared dofs (the direct stiffness method). ccx meshing the whole
// disk would integrate each copy's elements at turned coordinates: the same
// matrices up to the rounding of its element integration
// (test_sector_assembly measures it against the gmsh bladed disk).
//
// Faces: each node of LEFT (the face at -alpha/2) with dofs turned by alpha
// must land within `tolerance` on a node of RIGHT with dofs (the next
// sector's copy of it): sector k's LEFT node j is sector k-1's (mod N)
// RIGHT partner, as gmsh_bladed_disk.hpp numbers it. A RIGHT node with dofs
// that no LEFT node lands on is refused (the two faces are not one node
// pattern); face nodes without dofs (clamped) need no partner, so the node
// sets of ccx's cyclic symmetry tie (NLEFT without the clamped nodes) serve.
//
// Numbering: sector k's node j is k * stride + j (a LEFT node: its partner's
// number in sector k-1); dofs are numbered sector by sector in the sector's
// dof order, a shared node's where it first appears. The boundary is the
// sector's boundary nodes in each sector, sector 0's first.
//
// Only solid models: every dof a translation (ux, uy, uz), every node with
// all three or none (a node clamped in one direction only would not stay
// clamped in that direction once turned); no generated nodes. Anything else
// is refused with ImportError naming the node.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "component.hpp"

namespace rsi {

struct SectorPattern {
  int sectors = 0;                                 ///< N >= 3
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); ///< unit, through the origin
  std::vector<int> left;                           ///< node ids of the face at -alpha/2
  std::vector<int> right;                          ///< node ids of the face at +alpha/2
  std::vector<int> boundary;                       ///< the sector's boundary node ids, in order
  int stride = 0;                                  ///< > the sector's largest node id
  double tolerance = 0.0;                          ///< face pairing distance, > 0 [length]
};

/// The assembled bladed disk (name, units and rotation axis copied from the
/// sector). Throws ImportError naming `what` (the case's key) for faces
/// that do not pair, a node that is not a whole translation triple, or a
/// boundary node without dofs; std::invalid_argument for N < 3 or a stride
/// not above every node id.
Component assemble_sectors(const Component& sector, const SectorPattern& pattern,
                           const std::string& what);

/// R(angle) about the unit `axis` (Rodrigues): exactly I at angle 0.
Eigen::Matrix3d axis_rotation(const Eigen::Vector3d& axis, double angle);

} // namespace rsi
