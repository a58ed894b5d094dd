#include "rubbing_points.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace rsi {
namespace {

/// Every contact node once, a node of the model with its ux, uy, uz among
/// the boundary dofs (every run's casing law acts there, and every
/// reduction keeps them): CaseError naming `key` otherwise.
void check_contact_nodes(const ComponentCase& c, const Component& comp,
                         const std::vector<int>& contact_nodes, const std::string& key) {
  const std::string where = c.case_path + ": key '" + key + "': ";
  std::set<int> seen;
  std::map<int, std::array<bool, 3>> on_boundary; // node -> ux, uy, uz on the boundary
  for (int d : comp.boundary) {
    const std::string& kind = comp.dofs[d].kind;
    const int axis = kind == "ux" ? 0 : kind == "uy" ? 1 : kind == "uz" ? 2 : -1;
    if (axis >= 0) on_boundary[comp.dofs[d].node][axis] = true;
  }
  for (int id : contact_nodes) {
    if (!seen.insert(id).second)
      throw CaseError(where + "contact node " + std::to_string(id) +
                      " is listed twice (each contact node once)");
    const auto at =
        std::lower_bound(comp.nodes.begin(), comp.nodes.end(), id,
                         [](const ComponentNode& node, int value) { return node.id < value; });
    const bool has_node = at != comp.nodes.end() && at->id == id;
    bool has_dofs = false;
    for (const DofInfo& d : comp.dofs)
      has_dofs = has_dofs || d.node == id;
    if (!has_node || !has_dofs)
      throw CaseError(where + "contact node " + std::to_string(id) + " is not a node of " +
                      comp.name + " with degrees of freedom (its " +
                      std::to_string(comp.nodes.size()) + " nodes; a clamped node has none)");
    const auto found = on_boundary.find(id);
    if (found == on_boundary.end() || !found->second[0] || !found->second[1] || !found->second[2])
      throw CaseError(where + "contact node " + std::to_string(id) +
                      ": its ux, uy and uz must be boundary dofs (component.boundary), so that "
                      "every reduction keeps them");
  }
}

} // namespace

void require_rubbing(const ComponentCase& c) {
  if (!c.rubbing)
    throw CaseError(c.case_path + ": key 'rubbing': missing (a contact run of a component needs "
                                  "its casing, friction, speed and length; data/README.md)");
}

RubbingPoints resolve_rubbing_points(const ComponentCase& c, const Component& comp) {
  require_rubbing(c);
  const RubbingSetup& setup = *c.rubbing;
  RubbingPoints points;
  points.contact_nodes = setup.contact_nodes;
  if (points.contact_nodes.empty())
    for (int d : comp.boundary)
      if (points.contact_nodes.empty() || points.contact_nodes.back() != comp.dofs[d].node)
        points.contact_nodes.push_back(comp.dofs[d].node);
  const std::string contact_key =
      setup.contact_nodes.empty() ? "component.boundary" : "rubbing.contact_nodes";
  check_contact_nodes(c, comp, points.contact_nodes, contact_key);
  // A contact or response node is one point with one dof per direction: a
  // node ccx created, or a beam, shell or plane node it expanded into
  // several (a row per expanded node and direction), is not.
  const auto rows_of = [&comp](int node, const std::string& kind) {
    int rows = 0;
    for (const DofInfo& d : comp.dofs)
      rows += d.node == node && d.kind == kind;
    return rows;
  };
  const auto check_point = [&](int node, const std::string& key) {
    const auto at = std::find_if(comp.nodes.begin(), comp.nodes.end(),
                                 [node](const ComponentNode& n) { return n.id == node; });
    if (at != comp.nodes.end() && at->generated)
      throw CaseError(c.case_path + ": key '" + key + "': node " + std::to_string(node) +
                      " is a node ccx created (no position in the deck); name a node of the deck");
    for (const char* kind : {"ux", "uy", "uz"})
      if (rows_of(node, kind) > 1)
        throw CaseError(c.case_path + ": key '" + key + "': node " + std::to_string(node) +
                        " has " + std::to_string(rows_of(node, kind)) + " rows of " + kind +
                        ": ccx expanded it (a node of a beam, shell or plane element) into as "
                        "many nodes; a contact or response node must be a node of a solid "
                        "element (one row per direction)");
  };
  for (int node : points.contact_nodes)
    check_point(node, contact_key);
  check_point(setup.response_node, "rubbing.response");
  const std::string kind = direction_kind(setup.response_direction);
  for (int i = 0; i < comp.n_dofs(); ++i)
    if (comp.dofs[i].node == setup.response_node && comp.dofs[i].kind == kind)
      points.response_dof = i;
  if (points.response_dof < 0)
    throw CaseError(c.case_path + ": key 'rubbing.response': node " +
                    std::to_string(setup.response_node) + " direction " +
                    std::to_string(setup.response_direction) +
                    " is not a dof of the model (a free node and direction 1..3)");
  points.response_name = "u_" + std::to_string(setup.response_node) + "_" +
                         std::to_string(setup.response_direction);
  return points;
}

} // namespace rsi
