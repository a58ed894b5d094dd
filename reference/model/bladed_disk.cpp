#include "bladed_disk.hpp"

#include <cmath>

#include "assembler.hpp"
#include "frame_element.hpp"
#include "part_definiteness.hpp"
#include "ring_element.hpp"

namespace rsi {
namespace {

using NodeDofs = std::vector<DofCombination>;

DofCombination single(int dof) {
  return {{dof, 1.0}};
}

/// Frame view (ux, uy, theta) of a node whose dofs are plain frame dofs.
NodeDofs frame_node(int first) {
  return {single(first), single(first + 1), single(first + 2)};
}

/// Frame view of the rim node from its ring dofs (u, u_s, v, v_s) at `first`:
/// ux = u, uy = v, theta = v/R - u_s (SPEC §2 ring kinematics).
NodeDofs rim_frame_view(int first, double radius) {
  return {single(first), single(first + 2), {{first + 2, 1.0 / radius}, {first + 1, -1.0}}};
}

/// Frame view of the tip node from its polar dofs (u, v, theta) at `first`.
NodeDofs tip_frame_view(int first, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {{{first, c}, {first + 1, -s}}, {{first, s}, {first + 1, c}}, single(first + 2)};
}

NodeDofs clamped_node() {
  return NodeDofs(3);
}

NodeDofs ring_node(int first) {
  return {single(first), single(first + 1), single(first + 2), single(first + 3)};
}

NodeDofs join(const NodeDofs& a, const NodeDofs& b) {
  NodeDofs out = a;
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

} // namespace

BladedDisk assemble_bladed_disk(const Case& c, HubSupport hub) {
  const BladedDiskSpec& spec = c.bladed_disk;
  BladedDisk bd;
  bd.geometry = blade_geometry(spec);
  bd.n_sectors = spec.n_blades;
  const int n_be = spec.n_blade_elements;
  const bool free_hub = hub == HubSupport::free;
  bd.dofs_per_sector = 4 + 3 * n_be + (free_hub ? 3 : 0);
  bd.nodes_per_sector = n_be + 2;

  const int tip_local = 4 + 3 * (n_be - 1);
  const int hub_local = 4 + 3 * n_be;
  for (int k = 0; k < bd.n_sectors; ++k) {
    const int node0 = k * bd.nodes_per_sector;
    for (const char* kind : {"u", "u_s", "v", "v_s"})
      bd.dofs.push_back({node0 + 1, kind, false});
    for (int i = 1; i < n_be; ++i)
      for (const char* kind : {"ux", "uy", "theta"})
        bd.dofs.push_back({node0 + 1 + i, kind, false});
    bd.dofs.push_back({node0 + 1 + n_be, "u", true});
    bd.dofs.push_back({node0 + 1 + n_be, "v", true});
    bd.dofs.push_back({node0 + 1 + n_be, "theta", false});
    if (free_hub)
      for (const char* kind : {"ux", "uy", "theta"})
        bd.dofs.push_back({node0, kind, false});
    const int first = k * bd.dofs_per_sector;
    bd.tip_radial.push_back(first + tip_local);
    bd.tip_tangential.push_back(first + tip_local + 1);
    bd.boundary.push_back(first + tip_local);
    bd.boundary.push_back(first + tip_local + 1);
  }

  const BeamProperties blade = beam_properties(c.material, spec.blade);
  const BeamProperties disk = beam_properties(c.material, spec.disk);
  const BeamProperties ring = beam_properties(c.material, spec.rim_ring);
  const double ring_arc = 2.0 * M_PI * spec.rim_radius / bd.n_sectors;
  const Matrix6d k_disk = frame_stiffness(disk, bd.geometry.disk_length, 0.0);
  const Matrix6d m_disk = frame_mass(disk, bd.geometry.disk_length, 0.0);
  const Matrix8d k_ring = ring_stiffness(ring, spec.rim_radius, ring_arc);
  const Matrix8d m_ring = ring_mass(ring, ring_arc);

  Assembler assembler(bd.n_dofs());
  for (int k = 0; k < bd.n_sectors; ++k) {
    const int first = k * bd.dofs_per_sector;
    // Frame view of blade node i (0 = rim, n_be = tip).
    auto blade_node = [&](int i) -> NodeDofs {
      if (i == 0) return rim_frame_view(first, spec.rim_radius);
      if (i == n_be) return tip_frame_view(first + tip_local, bd.geometry.tip_angle);
      return frame_node(first + 4 + 3 * (i - 1));
    };
    const NodeDofs hub_node = free_hub ? frame_node(first + hub_local) : clamped_node();
    assembler.add(k_disk, m_disk, join(hub_node, blade_node(0)));
    for (int i = 0; i < n_be; ++i) {
      const double angle = bd.geometry.element_angles[i];
      assembler.add(frame_stiffness(blade, bd.geometry.element_length, angle),
                    frame_mass(blade, bd.geometry.element_length, angle),
                    join(blade_node(i), blade_node(i + 1)));
    }
    const int next = ((k + 1) % bd.n_sectors) * bd.dofs_per_sector;
    assembler.add(k_ring, m_ring, join(ring_node(first), ring_node(next)));
  }
  bd.stiffness = assembler.stiffness();
  bd.mass = assembler.mass();
  // The parts as a whole: K and M positive definite to working precision
  // (a free hub leaves K its rigid rotation on purpose, for the tests).
  if (hub == HubSupport::clamped) check_bladed_disk_definite(bd, c);
  return bd;
}

} // namespace rsi
