#include "paper_components.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace rsi {
namespace {

/// The nodes of `dofs`, ascending, coordinates from `position(node)`.
template <typename Position>
std::vector<ComponentNode> nodes_of(const DofMap& dofs, Position position) {
  std::vector<int> ids;
  for (const DofInfo& d : dofs)
    ids.push_back(d.node);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<ComponentNode> nodes;
  for (int id : ids)
    nodes.push_back({id, position(id)});
  return nodes;
}

} // namespace

Component bladed_disk_component(const BladedDisk& bd) {
  Component c;
  c.name = "bladed-disk";
  c.stiffness = bd.stiffness;
  c.mass = bd.mass;
  c.dofs = bd.dofs;
  c.boundary = bd.boundary;
  c.cyclic = {bd.n_sectors, bd.dofs_per_sector};
  c.units = "N, m, kg, s";
  // Node k * nodes_per_sector + j is geometry node j of sector k, turned by 2 pi k / N.
  c.nodes = nodes_of(bd.dofs, [&](int id) {
    const int k = id / bd.nodes_per_sector;
    const Eigen::Vector2d local = bd.geometry.nodes[id % bd.nodes_per_sector];
    const Eigen::Vector2d x = Eigen::Rotation2Dd(2.0 * M_PI * k / bd.n_sectors) * local;
    return Eigen::Vector3d(x(0), x(1), 0.0);
  });
  return c;
}

Component casing_component(const Casing& casing) {
  Component c;
  c.name = "casing";
  c.stiffness = casing.stiffness;
  c.mass = casing.mass;
  c.dofs = casing.dofs;
  c.units = "N, m, kg, s";
  c.nodes = nodes_of(casing.dofs, [&](int j) {
    return Eigen::Vector3d(casing.radius * std::cos(casing.node_angle(j)),
                           casing.radius * std::sin(casing.node_angle(j)), 0.0);
  });
  return c;
}

} // namespace rsi
