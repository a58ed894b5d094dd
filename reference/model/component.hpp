#pragma once
// A linear structural component (SPEC §8): sparse symmetric K and M, what
// each dof is (node, direction), node coordinates, and a boundary, the dofs
// kept as physical coordinates by every reduction (the contact dofs).
//
// The builders of components are the paper's 2D parts
// (paper_components.hpp), CalculiX decks (calculix_matrices.hpp) and Matrix
// Market folders in the layout `rsi export` writes (matrix_market.hpp);
// component_case.hpp reads the case file that names one. Units are those of
// the source (SI for the paper's parts; N, mm, t, s for Rotor 37): a
// component only keeps them as text for messages and reports.

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "dof_map.hpp"
#include "failure_kinds.hpp"

namespace rsi {

/// Bad input in an imported model (file and line named), or a model that is
/// not a component (K or M not symmetric, M with a non-positive diagonal).
/// Exit status 2 in the CLI.
class ImportError : public BadInput {
public:
  using BadInput::BadInput;
};

struct ComponentNode {
  int id = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero(); ///< coordinates, in the component's length unit
  /// A node the model's generator created, not the user (ccx: the
  /// incompatible modes of a C3D8I element, the rotations of a beam or
  /// shell knot, calculix_matrices.hpp): it has no position (x is NaN) and
  /// is never a boundary, contact or response node.
  bool generated = false;
};

/// n_sectors identical blocks of dofs_per_sector dofs, block k at angle
/// 2 pi k / n_sectors (the bladed disk); n_sectors = 0: no cyclic structure.
struct CyclicLayout {
  int n_sectors = 0;
  int dofs_per_sector = 0;
};

struct Component {
  std::string name;                       ///< folder name in `rsi export`
  Eigen::SparseMatrix<double> stiffness;  ///< K, both triangles stored
  Eigen::SparseMatrix<double> mass;       ///< M, both triangles stored
  DofMap dofs;                            ///< what row i of K and M is
  std::vector<ComponentNode> nodes;       ///< every node a dof refers to, ascending id
  std::vector<int> boundary;              ///< dof indices kept physical, in order
  CyclicLayout cyclic;
  /// N > 0: the case's "cyclic_bases" (an N-sector bladed disk): CB, CC,
  /// Guyan, CCM and MacNeal bases solve one sector's constraint modes and
  /// turn them (reduced/bases/turned_constraint_modes.hpp,
  /// turned_residual_flexibility.hpp); 0: each one solved.
  int cyclic_bases = 0;
  std::string units;                      ///< e.g. "N, mm, t, s"
  Eigen::Vector3d rotation_axis = Eigen::Vector3d::UnitZ();

  int n_dofs() const { return static_cast<int>(dofs.size()); }
};

/// The direction kind of dof `direction` (1..6) of a 3D node: ux, uy, uz,
/// rx, ry, rz (CalculiX's node.direction numbering).
std::string direction_kind(int direction);

/// Every dof of each node of `node_ids`, node by node, in dof order; marks
/// them as boundary in `dofs`. Throws ImportError naming `what` (where the
/// set came from) for a node that has no dof in the model or is repeated.
std::vector<int> boundary_of_nodes(const std::vector<int>& node_ids, DofMap& dofs,
                                   const std::string& what);

/// The dofs flagged `boundary` in the dof map, in dof order.
std::vector<int> flagged_boundary(const DofMap& dofs);

/// Checks what every builder must deliver: K and M square of the dof map's
/// size, finite, symmetric within 1e-12 relative to their largest entry,
/// M with a positive diagonal. Throws ImportError naming `source`.
void check_component(const Component& component, const std::string& source);

} // namespace rsi
