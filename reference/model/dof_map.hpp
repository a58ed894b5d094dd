#pragma once
// What each degree of freedom of an assembled part is.

#include <array>
#include <map>
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

/// Each node's translation dofs by node id: the indices in `dofs` of its
/// "ux", "uy", "uz", -1 for one it lacks (a clamped direction). Nodes with
/// none are absent.
inline std::map<int, std::array<int, 3>> node_translations(const DofMap& dofs) {
  std::map<int, std::array<int, 3>> out;
  for (int i = 0; i < static_cast<int>(dofs.size()); ++i) {
    const DofInfo& d = dofs[static_cast<size_t>(i)];
    const int k = d.kind == "ux" ? 0 : d.kind == "uy" ? 1 : d.kind == "uz" ? 2 : -1;
    if (k >= 0) out.emplace(d.node, std::array<int, 3>{-1, -1, -1}).first->second[static_cast<size_t>(k)] = i;
  }
  return out;
}

} // namespace rsi
