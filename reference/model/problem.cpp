#include "problem.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "assembler.hpp"
#include "casing_forcing.hpp"
#include "paper_components.hpp"
#include "rotating_component.hpp"
#include "rubbing_points.hpp"

namespace rsi {

int ProblemContact::n_contacts() const {
  switch (kind) {
  case ContactKind::none: return 0;
  case ContactKind::tip_ring: return static_cast<int>(rotor_dofs.size()) / 2; // u, v a tip
  case ContactKind::rigid_surface: return static_cast<int>(contact_nodes.size());
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
    if (deflection.size() > 0)
      for (int node : p.contact.contact_nodes)
        p.casing.tip_growth.push_back(radial_growth(comp, deflection, node));
    p.steps.rule = ProblemSteps::Rule::per_revolution;
    p.steps.revolutions = r.revolutions;
    p.steps.steps_per_revolution = r.steps_per_revolution;
    p.steps.step_safety = r.step_safety;
    p.outputs.output_every = r.output_every;
    p.outputs.response_dof = points.response_dof;
    p.outputs.response_name = std::move(points.response_name);
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
