#pragma once
// A component from CalculiX's matrix storage: JOB.sti (K), JOB.mas (M), one
// entry a line "row col value", 1-based, upper triangle, and JOB.dof, the
// meaning of each row as "node.direction" (direction 1..3: x, y, z), all
// written by `ccx` 2.20 for a step `*FREQUENCY, SOLVER=MATRIXSTORAGE` with
// the deck's constraints already removed. Node coordinates and node sets
// come from the deck (calculix_deck.hpp).
//
// The nodes ccx creates: ccx expands beams (B31, B32), shells (S3 ... S8R)
// and plane and axisymmetric elements (CPS*, CPE*, CAX*) into solid
// elements with new nodes, and writes each row of an expanded node with
// the deck node it expands (src/gennactdofinv.f): such a deck node has
// several rows of one direction, all its own, all on the boundary when it
// is. The nodes ccx adds above the deck's largest node id (the three
// incompatible-mode nodes of each C3D8I element, B31's expansion included;
// the rotation and expansion nodes of a beam or shell knot) are interior
// dofs: generated nodes without a position (ComponentNode::generated).
//
// Throws ImportError naming file and line for a truncated or non-numeric
// line, an index beyond the .dof count, NaN/Inf, an entry given twice, and
// through check_component for K or M not symmetric within 1e-12 or a
// non-positive mass diagonal; a .dof count different from the matrices'
// size (largest index) is named too.

#include <string>
#include <vector>

#include "calculix_deck.hpp"
#include "component.hpp"

namespace rsi {

/// JOB.dof: one DofInfo per line (node, kind ux/uy/uz/rx/ry/rz).
DofMap read_calculix_dofs(const std::string& path);

/// The component of `deck` from the files `prefix`.sti, .mas and .dof; the
/// boundary is every dof of `boundary_nodes` (ImportError if one is not a
/// node with dofs). `name` and `units` are kept as given.
Component read_calculix_component(const std::string& prefix, const CalculixDeck& deck,
                                  const std::vector<int>& boundary_nodes, const std::string& name);

} // namespace rsi
