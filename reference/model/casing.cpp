#include "casing.hpp"

#include <cmath>

#include "assembler.hpp"
#include "part_definiteness.hpp"
#include "ring_element.hpp"

namespace rsi {
namespace {

Casing assemble_ring(const Material& material, const Section& section, double radius,
                     int n_elements, int clamped_node) {
  Casing casing;
  casing.radius = radius;
  casing.n_elements = n_elements;
  casing.clamped_node = clamped_node;
  for (int j = 0; j < n_elements; ++j) {
    if (j == clamped_node) {
      casing.node_first_dof.push_back(-1);
      continue;
    }
    casing.node_first_dof.push_back(casing.n_dofs());
    for (const char* kind : {"u", "u_s", "v", "v_s"})
      casing.dofs.push_back({j, kind, false});
  }
  const BeamProperties p = beam_properties(material, section);
  const double arc = 2.0 * M_PI * radius / n_elements;
  const Matrix8d ke = ring_stiffness(p, radius, arc);
  const Matrix8d me = ring_mass(p, arc);
  Assembler assembler(casing.n_dofs());
  for (int e = 0; e < n_elements; ++e) {
    std::vector<DofCombination> map;
    for (int j : {e, (e + 1) % n_elements}) {
      const int first = casing.node_first_dof[j];
      for (int d = 0; d < 4; ++d)
        map.push_back(first < 0 ? DofCombination{} : DofCombination{{first + d, 1.0}});
    }
    assembler.add(ke, me, map);
  }
  casing.stiffness = assembler.stiffness();
  casing.mass = assembler.mass();
  return casing;
}

} // namespace

Casing assemble_casing(const Case& c) {
  const int clamped =
      static_cast<int>(std::lround(c.casing.clamp_angle * c.casing.n_elements / (2.0 * M_PI))) %
      c.casing.n_elements;
  Casing casing =
      assemble_ring(c.material, c.casing.section, c.casing.radius, c.casing.n_elements, clamped);
  check_casing_definite(casing, c); // K and M positive definite to working precision
  return casing;
}

Eigen::VectorXd on_all_nodes(const Casing& casing, const Eigen::Ref<const Eigen::VectorXd>& x) {
  Eigen::VectorXd all = Eigen::VectorXd::Zero(4 * casing.n_elements);
  for (int j = 0; j < casing.n_elements; ++j)
    if (casing.node_first_dof[j] >= 0)
      all.segment<4>(4 * j) = x.segment<4>(casing.node_first_dof[j]);
  return all;
}

Casing assemble_free_ring(const Material& material, const Section& section, double radius,
                          int n_elements) {
  return assemble_ring(material, section, radius, n_elements, -1);
}

} // namespace rsi
