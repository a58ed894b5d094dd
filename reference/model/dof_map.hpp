#pragma once
// What each degree of freedom of an assembled part is.

#include <string>
#include <vector>

namespace rsi {

/// One dof: the node it belongs to, its kind (see data/README.md for the
/// frames: "u", "u_s", "v", "v_s" polar ring dofs; "ux", "uy", "theta" frame
/// dofs in the sector frame; tip "u", "v" in the tip polar frame) and whether
/// it is a boundary (contact) dof.
struct DofInfo {
  int node = -1;
  std::string kind;
  bool boundary = false;
};

using DofMap = std::vector<DofInfo>;

} // namespace rsi
