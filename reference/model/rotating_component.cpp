#include "rotating_component.hpp"

#include <cmath>

#include "calculix_matrices.hpp"
#include "calculix_run.hpp"
#include "case_file.hpp"
#include "mass_lumping.hpp"

namespace rsi {
namespace {

/// The static deflection table of ccx onto the component's dofs; a dof of a
/// node ccx generated (not printed) or a rotation keeps 0.
Eigen::VectorXd deflection_at_dofs(const Component& component,
                                   const std::map<int, Eigen::Vector3d>& table) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(component.n_dofs());
  for (int i = 0; i < component.n_dofs(); ++i) {
    const DofInfo& dof = component.dofs[i];
    const int axis = dof.kind == "ux" ? 0 : dof.kind == "uy" ? 1 : dof.kind == "uz" ? 2 : -1;
    const auto node = table.find(dof.node);
    if (axis >= 0 && node != table.end()) u(i) = node->second(axis);
  }
  return u;
}

} // namespace

RotatingComponent rotating_component(const ComponentCase& c, const ComponentLoadOptions& options,
                                     double speed) {
  if (!std::isfinite(speed) || std::abs(speed) >= 1e5)
    throw CaseError(c.case_path + ": rotation speed " + std::to_string(speed) +
                    " rad/s: allowed |Omega| < 1e5 rad/s");
  RotatingComponent rotating;
  rotating.speed = speed;
  if (speed == 0.0) {
    rotating.component = load_component(c, options);
    rotating.deflection = Eigen::VectorXd::Zero(rotating.component.n_dofs());
    return rotating;
  }
  if (!c.calculix_matrices.empty())
    throw CaseError(c.case_path + ": key 'component.source.calculix_matrices': rotation "
                    "effects need ccx to run the deck under the centrifugal load, and the case "
                    "names matrices already written; drop calculix_matrices");
  const ComponentDeck model = component_deck(c, options);
  CentrifugalLoad load;
  load.omega = std::abs(speed);
  load.axis = c.rotation_axis.normalized();
  const std::string job = calculix_prestressed_matrices(model.deck, load, options.ccx_cache,
                                                        options.ccx_cache_named());
  Component& component = rotating.component;
  component = read_calculix_component(job, model.deck, model.boundary, c.name);
  component.units = c.units;
  component.rotation_axis = c.rotation_axis;
  if (c.lumped_mass) component.mass = hrz_lumped_mass(component);
  rotating.deflection = deflection_at_dofs(component, read_calculix_displacements(job + ".dat"));
  return rotating;
}

double radial_growth(const Component& component, const Eigen::VectorXd& deflection, int node) {
  const Eigen::Vector3d axis = component.rotation_axis.normalized();
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  Eigen::Vector3d x = Eigen::Vector3d::Constant(std::nan(""));
  for (const ComponentNode& n : component.nodes)
    if (n.id == node) x = n.x;
  for (int i = 0; i < component.n_dofs(); ++i) {
    const DofInfo& dof = component.dofs[i];
    if (dof.node != node) continue;
    if (dof.kind == "ux") u.x() = deflection(i);
    if (dof.kind == "uy") u.y() = deflection(i);
    if (dof.kind == "uz") u.z() = deflection(i);
  }
  const Eigen::Vector3d radial = x - axis * axis.dot(x);
  if (!radial.allFinite() || radial.norm() == 0.0)
    throw CaseError("node " + std::to_string(node) + " is on the rotation axis or has no "
                    "position: no radial direction");
  return u.dot(radial.normalized());
}

} // namespace rsi
