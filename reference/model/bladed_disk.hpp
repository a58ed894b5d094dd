#pragma once
// The assembled bladed disk (rotating frame), SPEC §2.
//
// Sector k (k = 0..N-1) lies along phi_k = 2 pi k / N; all of its frame
// dofs are expressed in its own sector frame, so every sector has the same
// matrices and the dof vector is N identical blocks of dofs_per_sector
// (cyclic symmetry is exact, block k at angle phi_k).
// Block layout: rim node (u, u_s, v, v_s) of the rim ring; blade nodes 1..n-1
// (ux, uy, theta); tip node (u, v, theta) in the tip polar frame (u along the
// tip radius, v counter-clockwise); then, only for a free hub, the hub node
// (ux, uy, theta). The rim frame dofs are tied to the ring by
// ux = u, uy = v, theta = v/r_r - u_s (ring kinematics, a transformation).

#include <vector>

#include <Eigen/SparseCore>

#include "blade_geometry.hpp"
#include "case_file.hpp"
#include "dof_map.hpp"

namespace rsi {

enum class HubSupport { clamped, free };

struct BladedDisk {
  Eigen::SparseMatrix<double> stiffness;
  Eigen::SparseMatrix<double> mass;
  DofMap dofs;
  BladeGeometry geometry;
  int n_sectors = 0;
  int dofs_per_sector = 0;
  int nodes_per_sector = 0;        ///< hub, rim, blade nodes: node id = k * this + local
  std::vector<int> tip_radial;     ///< global index of tip u of blade k
  std::vector<int> tip_tangential; ///< global index of tip v of blade k
  std::vector<int> boundary;       ///< (u_0, v_0, u_1, v_1, ...): the contact dofs

  int n_dofs() const { return static_cast<int>(dofs.size()); }
};

BladedDisk assemble_bladed_disk(const Case& c, HubSupport hub = HubSupport::clamped);

} // namespace rsi
