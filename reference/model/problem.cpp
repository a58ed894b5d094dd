#include "problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "assembler.hpp"
#include "casing_forcing.hpp"
#include "casing_pressure.hpp"
#include "paper_components.hpp"
#include "rotating_component.hpp"
#include "rubbing_points.hpp"

namespace rsi {

int ProblemContact::n_contacts() const {
  switch (kind) {
  case ContactKind::none: return 0;
  case ContactKind::tip_ring: return static_cast<int>(rotor_dofs.size()) / 2; // u, v a tip
  case ContactKind::rigid_surface:
  case ContactKind::solid_casing: return static_cast<int>(contact_nodes.size());
  }
  return 0;
}

long ProblemSteps::fixed_steps() const {
  return rule == Rule::fixed ? std::lround(duration / step) : 0;
}

double ProblemSteps::samples(double revolutions) const {
  return std::max(1.0, std::round(revolutions * steps_per_revolution));
}

double ProblemSteps::sample_step(double omega) const {
  return 2.0 * M_PI / std::abs(omega) / steps_per_revolution;
}

double ProblemSteps::steps_per_sample(double sample_dt, double critical_dt) const {
  return std::max(1.0, std::ceil(sample_dt / (step_safety * critical_dt)));
}

int Problem::n_dofs() const {
  int n = 0;
  for (const Component& s : structures)
    n += s.n_dofs();
  return n;
}

int Problem::offset(int structure) const {
  int n = 0;
  for (int s = 0; s < structure; ++s)
    n += structures[static_cast<size_t>(s)].n_dofs();
  return n;
}

namespace {

/// diag(A_0, A_1, ...) of the structures' `which` matrix.
Eigen::SparseMatrix<double>
system_matrix(const std::vector<Component>& structures,
              Eigen::SparseMatrix<double> Component::*which) {
  if (structures.empty()) return {};
  Eigen::SparseMatrix<double> out = structures.front().*which;
  for (size_t s = 1; s < structures.size(); ++s)
    out = block_diagonal(out, structures[s].*which);
  return out;
}

} // namespace

Eigen::SparseMatrix<double> Problem::stiffness() const {
  return system_matrix(structures, &Component::stiffness);
}

Eigen::SparseMatrix<double> Problem::mass() const {
  return system_matrix(structures, &Component::mass);
}

Problem paper_problem(const Case& c) {
  Problem p;
  p.kind = ProblemKind::paper;
  p.source = c.source;
  PaperParts parts{c, assemble_bladed_disk(c), assemble_casing(c)};
  p.structures.push_back(bladed_disk_component(parts.bladed_disk));
  p.structures.push_back(casing_component(parts.casing));

  p.contact.kind = ContactKind::tip_ring;
  p.contact.friction_law = c.operating_point.friction_law;
  p.contact.friction_coefficient = c.operating_point.friction_coefficient;
  p.contact.rotation_speed = c.operating_point.rotation_speed;
  p.contact.sliding_speed = c.operating_point.rotation_speed;
  p.contact.rotor_dofs = parts.bladed_disk.boundary;

  p.casing.rigid = false;
  p.casing.structure = 1;
  p.casing.clearance = c.casing.radius - c.bladed_disk.tip_radius;

  // F0 cos(ND theta_j) on the casing's radial dofs, the bladed disk unloaded.
  p.forcing.force = Eigen::VectorXd::Zero(parts.bladed_disk.n_dofs() + parts.casing.n_dofs());
  p.forcing.force.tail(parts.casing.n_dofs()) = casing_forcing(parts.casing, c.forcing);
  p.forcing.until = c.forcing.duration;

  p.damping = c.damping;
  p.steps.rule = ProblemSteps::Rule::fixed;
  p.steps.step = c.time.step;
  p.steps.duration = c.time.duration;
  p.outputs.output_every = c.time.output_every;
  p.paper = std::move(parts);
  return p;
}

namespace {

/// The liner of a rubbing case (ProblemLiner): radius and default axial
/// extent from the contact nodes about the component's rotation axis.
ProblemLiner problem_liner(const ComponentCase& c, const LinerSetup& setup, const Component& comp,
                           const std::vector<int>& contact_nodes) {
  const Eigen::Vector3d a = comp.rotation_axis.normalized();
  double radius = 0.0;
  double z_low = std::numeric_limits<double>::infinity();
  double z_high = -z_low;
  for (int id : contact_nodes)
    for (const ComponentNode& node : comp.nodes)
      if (node.id == id) {
        const double z = a.dot(node.x);
        radius = std::max(radius, (node.x - z * a).norm());
        z_low = std::min(z_low, z);
        z_high = std::max(z_high, z);
      }
  ProblemLiner l;
  l.radius = radius;
  l.thickness = setup.thickness;
  l.young = setup.young_modulus;
  l.yield = setup.yield_stress;
  l.hardening = setup.hardening_modulus;
  l.n_theta = setup.cells_around;
  l.n_axial = setup.rows;
  l.patch_circumferential = setup.patch_circumferential;
  l.patch_axial = setup.patch_axial;
  if (!(setup.thickness < radius))
    throw CaseError(c.case_path + ": the abradable liner's thickness must be less than the contact "
                                  "nodes' largest radius about the rotation axis, " +
                    std::to_string(radius) + ", got " + std::to_string(setup.thickness));
  if (setup.axial_extent) {
    if (z_low < setup.z_min || z_high > setup.z_max)
      throw CaseError(c.case_path + ": the abradable liner's axial extent (z_min, z_max) must cover "
                                    "the contact nodes' axial coordinates [" + std::to_string(z_low) + ", " +
                      std::to_string(z_high) + "], got [" + std::to_string(setup.z_min) + ", " +
                      std::to_string(setup.z_max) + "]");
    l.z_min = setup.z_min;
    l.z_max = setup.z_max;
  } else {
    const double margin = z_high > z_low ? 0.05 * (z_high - z_low) : setup.thickness;
    l.z_min = z_low - margin;
    l.z_max = z_high + margin;
  }
  return l;
}

} // namespace

namespace {

/// The flexible casing of rubbing.casing beside the rotor: structure 1, its
/// contact surface, the solid-casing law, the load on it.
void add_flexible_casing(const ComponentCase& c, const ComponentLoadOptions& load, Problem& p) {
  const RubbingSetup& r = *c.rubbing;
  FlexibleCasing casing = load_flexible_casing(c, load);
  p.structures.push_back(std::move(casing.component));
  p.casing.surface.emplace(std::move(casing.surface));
  p.casing.rigid = false;
  p.casing.structure = 1;
  p.contact.kind = ContactKind::solid_casing;
  if (r.casing_forcing) {
    const RubbingSetup::CasingForcing& f = *r.casing_forcing;
    p.forcing.force = Eigen::VectorXd::Zero(p.n_dofs());
    p.forcing.force.tail(p.structures[1].n_dofs()) = casing_pressure_forces(
        *p.casing.surface, p.structures[1], f.pressure, f.nodal_diameters);
    p.forcing.until = f.duration;
  }
}

} // namespace

Problem component_problem(const ComponentCase& c, const ComponentLoadOptions& load) {
  Problem p;
  p.kind = ProblemKind::component;
  p.source = c.case_path;
  Eigen::VectorXd deflection;
  if (c.rotation_effects && c.rubbing) {
    RotatingComponent rotating = rotating_component(c, load, c.rubbing->rotation_speed);
    p.structures.push_back(std::move(rotating.component));
    deflection = std::move(rotating.deflection);
  } else {
    p.structures.push_back(load_component(c, load));
  }
  p.damping = c.damping;
  p.casing.rigid = true;
  if (c.rubbing) {
    const RubbingSetup& r = *c.rubbing;
    const Component& comp = p.structures.front();
    RubbingPoints points = resolve_rubbing_points(c, comp);
    p.contact.kind = ContactKind::rigid_surface;
    p.contact.friction_law = FrictionLaw::coulomb;
    p.contact.friction_coefficient = r.friction_coefficient;
    p.contact.rotation_speed = r.rotation_speed;
    p.contact.sliding_speed = r.sliding_speed();
    p.contact.sliding_against_rotation = r.sliding_against_rotation;
    p.contact.contact_nodes = std::move(points.contact_nodes);
    // ux, uy, uz of each contact node, the order rigid_surface_nodes reads them.
    for (int node : p.contact.contact_nodes)
      for (const char* kind : {"ux", "uy", "uz"})
        for (int i = 0; i < comp.n_dofs(); ++i)
          if (comp.dofs[i].node == node && comp.dofs[i].kind == kind)
            p.contact.rotor_dofs.push_back(i);
    p.casing.oval_gap = r.oval_gap;
    p.casing.gap = r.gap;
    p.casing.gap_width = r.gap_width;
    if (deflection.size() > 0) {
      // The gap is the clearance at clearance_speed: the growth from there.
      Eigen::VectorXd reference = Eigen::VectorXd::Zero(deflection.size());
      if (r.clearance_speed == std::abs(r.rotation_speed))
        reference = deflection;
      else if (r.clearance_speed != 0.0)
        reference = rotating_component(c, load, r.clearance_speed).deflection;
      for (int node : p.contact.contact_nodes)
        p.casing.tip_growth.push_back(radial_growth(comp, deflection, node) -
                                      radial_growth(comp, reference, node));
    }
    if (r.liner) p.casing.liner = problem_liner(c, *r.liner, comp, p.contact.contact_nodes);
    p.steps.rule = ProblemSteps::Rule::per_revolution;
    p.steps.revolutions = r.revolutions;
    p.steps.steps_per_revolution = r.steps_per_revolution;
    p.steps.step_safety = r.step_safety;
    p.outputs.output_every = r.output_every;
    p.outputs.response_dof = points.response_dof;
    p.outputs.response_name = std::move(points.response_name);
    // Last: the casing joins `structures`, which moves the rotor (`comp`).
    if (r.casing) add_flexible_casing(c, load, p);
  }
  p.component_case = c;
  return p;
}

Problem load_problem(const std::string& path, const ComponentLoadOptions& load) {
  const nlohmann::json document = read_case_document(path);
  if (is_component_case(document))
    return component_problem(parse_component_case(document, path), load);
  return paper_problem(parse_case(document, path));
}

} // namespace rsi
