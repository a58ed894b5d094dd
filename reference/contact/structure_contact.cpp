#include "structure_contact.hpp"

#include <array>
#include <map>
#include <stdexcept>

#include "tip_casing_contact.hpp"
#include "tip_ring_frictional_contact.hpp"

namespace rsi {

StructureContact::StructureContact(const Problem& problem)
    : StructureContact(problem, problem.contact.rotation_speed) {}

StructureContact::StructureContact(const Problem& problem, double rotation_speed) {
  const ProblemContact& c = problem.contact;
  if (c.kind != ContactKind::rigid_surface && c.kind != ContactKind::solid_casing &&
      rotation_speed != c.rotation_speed)
    throw std::invalid_argument(problem.source +
                                ": only a 3D casing's contact runs at another speed");
  switch (c.kind) {
  case ContactKind::none:
    throw std::invalid_argument(problem.source + ": the problem has no contact to run");
  case ContactKind::tip_ring: {
    if (!problem.paper) throw std::logic_error("StructureContact: tip_ring without the 2D parts");
    const PaperParts& parts = *problem.paper;
    if (c.friction_law == FrictionLaw::coulomb) {
      auto law = std::make_shared<const TipRingFrictionalContact>(parts.bladed_disk, parts.casing,
                                                                  parts.case_file);
      m_frictional = law.get();
      m_owned = law;
    } else {
      auto law =
          std::make_shared<const TipCasingContact>(parts.bladed_disk, parts.casing, parts.case_file);
      m_law = law.get();
      m_owned = law;
    }
    return;
  }
  case ContactKind::rigid_surface: {
    const Component& rotor = problem.structures.front();
    const ImposedGap gap = problem.casing.oval_gap
                               ? ImposedGap::oval(problem.casing.gap, problem.casing.gap_width)
                               : ImposedGap::constant(problem.casing.gap);
    std::vector<RigidSurfaceNode> nodes = rigid_surface_nodes(rotor, c.contact_nodes);
    if (!problem.casing.tip_growth.empty()) {
      if (rotation_speed != c.rotation_speed)
        throw std::invalid_argument(problem.source +
                                    ": with rotation effects the model holds K(Omega) at the "
                                    "case's speed only");
      for (size_t k = 0; k < nodes.size(); ++k) nodes[k].growth = problem.casing.tip_growth.at(k);
    }
    auto law = std::make_shared<const RigidSurfaceContact>(
        std::move(nodes), gap, rotation_speed, c.friction_coefficient,
        c.sliding_speed_at(rotation_speed), rotor.rotation_axis);
    m_frictional = law.get();
    m_rigid_surface = law.get();
    m_owned = law;
    return;
  }
  case ContactKind::solid_casing: {
    if (!problem.casing.surface || problem.casing.structure != 1)
      throw std::logic_error("StructureContact: solid_casing without the casing's surface");
    const Component& casing = problem.structures.at(1);
    const int offset = problem.offset(1);
    // Each casing node's ux, uy, uz (a clamped node has none: not in the map).
    std::map<int, std::array<int, 3>> casing_dofs = node_translations(casing.dofs);
    for (auto& [node, dofs] : casing_dofs)
      for (int& dof : dofs) {
        if (dof < 0)
          throw std::invalid_argument(problem.source + ": casing node " + std::to_string(node) +
                                      " lacks one of its three translations (a partly clamped "
                                      "contact node is not taken)");
        dof += offset;
      }
    auto law = std::make_shared<const SolidCasingContact>(
        rigid_surface_nodes(problem.structures.front(), c.contact_nodes), *problem.casing.surface,
        std::move(casing_dofs), rotation_speed, c.friction_coefficient);
    m_frictional = law.get();
    m_solid_casing = law.get();
    m_owned = law;
    return;
  }
  }
}

int StructureContact::n_contacts() const {
  if (m_law) return m_law->n_constraints();
  if (m_frictional) return m_frictional->n_contacts();
  return 0;
}

} // namespace rsi
