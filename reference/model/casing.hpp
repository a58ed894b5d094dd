#pragma once
// The assembled casing (fixed frame), SPEC §2: a ring of n curved beam
// elements of radius R_c, node j at theta_j = 2 pi j / n, 4 dofs per node
// (u, u_s, v, v_s), all 4 dofs of the node at clamp_angle removed.

#include <vector>

#include <Eigen/SparseCore>

#include "case_file.hpp"
#include "dof_map.hpp"

namespace rsi {

struct Casing {
  Eigen::SparseMatrix<double> stiffness;
  Eigen::SparseMatrix<double> mass;
  DofMap dofs;
  double radius = 0.0;
  int n_elements = 0;
  int clamped_node = -1;
  /// First of the 4 dofs of node j, or -1 for the clamped node.
  std::vector<int> node_first_dof;

  int n_dofs() const { return static_cast<int>(dofs.size()); }
  double node_angle(int j) const { return 2.0 * M_PI * j / n_elements; }
};

Casing assemble_casing(const Case& c);

/// The dof vector x of the casing laid out on all n nodes (4 dofs each),
/// zeros at the clamped node: the cyclic layout nodal_diameter() expects.
Eigen::VectorXd on_all_nodes(const Casing& casing, const Eigen::Ref<const Eigen::VectorXd>& x);

/// A free (unclamped) ring of n elements: the same element, no supports.
/// Used by the verification suites against the exact ring solution.
Casing assemble_free_ring(const Material& material, const Section& section, double radius,
                          int n_elements);

} // namespace rsi
