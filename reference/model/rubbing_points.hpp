#pragma once
// The points of a component where its rubbing run acts and is watched: the
// contact nodes (rubbing.contact_nodes, or the boundary's nodes in boundary
// order) and the response dof (rubbing.response: node and direction 1..3).
// Each is one point with one dof a direction: a node of the deck (not one
// ccx created), of a solid element (ccx expands beam, shell and plane nodes
// into several rows a direction); every contact node once, with its ux, uy,
// uz among the boundary dofs, so that every reduction keeps them.

#include <string>
#include <vector>

#include "component.hpp"
#include "component_case.hpp"

namespace rsi {

struct RubbingPoints {
  std::vector<int> contact_nodes; ///< node ids, the casing's contact order
  int response_dof = -1;          ///< dof index in the component
  std::string response_name;      ///< "u_NODE_DIR", the history column
};

/// CaseError naming the case file unless it has a "rubbing" object.
void require_rubbing(const ComponentCase& c);

/// Throws CaseError naming the case file and the key (rubbing, its
/// contact_nodes or component.boundary, rubbing.response) when a point is
/// not one of the component's as above.
RubbingPoints resolve_rubbing_points(const ComponentCase& c, const Component& component);

} // namespace rsi
