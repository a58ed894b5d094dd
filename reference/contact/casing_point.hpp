#pragma once
// The point of the casing ring a blade tip faces (SPEC §2, §3): the ring
// element under the tip's polar angle, the Hermite values N(xi) of its
// radial and tangential fields there (ring_element), and its unclamped
// nodes. Shared by the 2D tip/ring laws (tip_casing_contact: sliding sign;
// tip_ring_frictional_contact: Coulomb), which differ only in what they
// build from it.

#include <vector>

#include <Eigen/Core>

namespace rsi {

struct CasingPoint {
  Eigen::Vector4d shape;        ///< N(xi) for (1, 1_s, 2, 2_s) of the element's two nodes
  int n_nodes = 0;              ///< unclamped nodes of the element (0 to 2)
  int first[2] = {-1, -1};      ///< system index of each unclamped node's u (u, u_s, v, v_s follow)
  int shape_offset[2] = {0, 0}; ///< where its two values sit in `shape` (0 or 2)
};

/// For a finite polar angle alpha [rad] (any turn) on a ring of
/// `n_elements` equal elements of radius `radius`, whose node j has its
/// first dof at node_dof[j] (-1: clamped). A node past the last is node 0;
/// alpha within round-off of 2 pi is the end of the last element.
CasingPoint casing_point(double alpha, int n_elements, double radius,
                         const std::vector<int>& node_dof);

} // namespace rsi
