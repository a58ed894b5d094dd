#include "rubbing_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "component_integrator.hpp"
#include "component_run.hpp"
#include "modal_analysis.hpp"
#include "modal_damping.hpp"
#include "reduction.hpp"
#include "rigid_casing.hpp"
#include "rigid_surface_contact.hpp"

namespace rsi {
namespace {

/// k of the header: samples at T/N, integration at T/(k N) <= safety x critical.
int steps_per_sample(double sample_dt, double critical_dt, double safety) {
  return std::max(1, static_cast<int>(std::ceil(sample_dt / (safety * critical_dt))));
}

/// 2/omega of a massless boundary's interior with the whole boundary held
/// (u_B = 0: M^_II q'' + K^_II q = 0). Closed contacts constrain u_B, and
/// constraints only raise the condensed interior's frequencies (interlacing),
/// so every contact state's limit is at least this; the free modes' limit
/// (2/omega_psi) holds only while no contact is closed
/// (component_integrator.hpp, caveat). Measured on the gmsh blade,
/// MacNeal-50: 5.46e-6 s free, at 4.675e-6 s it blew up once contacts held.
double held_boundary_critical_dt(const ReducedBasis& basis) {
  std::vector<char> is_boundary(basis.n_reduced(), 0);
  for (int k : basis.boundary_position)
    is_boundary[k] = 1;
  std::vector<int> interior;
  for (int k = 0; k < basis.n_reduced(); ++k)
    if (!is_boundary[k]) interior.push_back(k);
  const int ni = static_cast<int>(interior.size());
  Eigen::MatrixXd k(ni, ni), m(ni, ni);
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < ni; ++j) {
      k(i, j) = basis.stiffness(interior[i], interior[j]);
      m(i, j) = basis.mass(interior[i], interior[j]);
    }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> e(k, m, Eigen::EigenvaluesOnly);
  if (e.info() != Eigen::Success || !(e.eigenvalues().maxCoeff() > 0.0))
    throw ReductionError("the interior of the massless-boundary basis has no positive "
                         "frequency with its boundary held (M^_II or K^_II not definite)");
  return 2.0 / std::sqrt(e.eigenvalues().maxCoeff());
}

RunSummary summary_of(const ComponentRunSummary& c, const std::string& method, int dofs,
                      double max_lambda, double basis_seconds) {
  RunSummary s;
  s.method = method;
  s.n_dofs = dofs;
  s.steps_requested = c.steps_requested;
  s.steps = c.steps;
  s.completed = c.completed;
  s.status = c.status;
  s.dt = c.dt;
  s.omega_max = c.omega_max;
  s.critical_dt = c.critical_dt;
  s.bladed_disk_critical_dt = c.critical_dt;
  s.basis_seconds = basis_seconds;
  s.integration_seconds = c.integration_seconds;
  s.max_penetration = c.max_penetration;
  s.min_lambda = c.min_lambda;
  s.max_lambda = max_lambda;
  s.max_complementarity = c.max_complementarity;
  s.max_cone_violation = c.max_cone_violation;
  s.max_stick_slip_residual = c.max_stick_slip_residual;
  s.stick_slip_transitions = static_cast<int>(std::min<long>(c.stick_slip_transitions, 2147483647L));
  s.stick_contact_steps = c.stick_contact_steps;
  s.slip_contact_steps = c.slip_contact_steps;
  s.initial_energy = c.initial_energy;
  s.energy_balance_error = c.energy_balance_error;
  s.energy_scale = c.energy_scale;
  s.final_contact_work = c.final_contact_work;
  s.final_damping_work = c.final_damping_work;
  return s;
}

RubbingRun run_reduced_rubbing(const RubbingModel& model, const RubbingRunOptions& options,
                               int n_samples, const ComponentRowSink& sink) {
  const RubbingSetup& setup = model.setup;
  const auto t0 = std::chrono::steady_clock::now();
  const ReducedBasis basis = reduce(model.component.stiffness, model.component.mass,
                                    model.component.boundary, options.method, options.modes);
  const auto run_start = std::chrono::steady_clock::now();
  const double basis_seconds = std::chrono::duration<double>(run_start - t0).count();
  CasingGap gap;
  gap.kind = setup.oval_gap ? CasingGapKind::oval : CasingGapKind::constant;
  gap.g0 = setup.gap;
  gap.width = setup.gap_width;
  const RigidCasing casing =
      rigid_casing_of(model.component, model.contact_nodes, gap, setup.rotation_speed,
                      setup.sliding_speed());
  ComponentIntegratorOptions o;
  o.mu = setup.friction_coefficient;
  if (model.component_case.damping.modal_ratio > 0.0)
    o.damping = modal_damping(basis, model.component_case.damping.modal_ratio);
  const double sample_dt = model.period / setup.steps_per_revolution;
  o.dt = sample_dt;
  o.force_step = true; // a probe, only for omega_max
  const double free_critical_dt = ComponentIntegrator(basis, casing, o).critical_dt();
  const double critical_dt =
      basis.massless_boundary ? std::min(free_critical_dt, held_boundary_critical_dt(basis))
                              : free_critical_dt;
  RubbingRun run;
  run.reduced_size = basis.n_reduced();
  run.step_limit = critical_dt;
  if ((options.method == "ccm" || options.method == "macneal") && basis.mode_omega.size() > 0)
    run.first_mode_hz = basis.mode_omega.minCoeff() / (2.0 * M_PI);
  run.steps_per_sample = steps_per_sample(sample_dt, critical_dt, setup.step_safety);
  o.dt = sample_dt / run.steps_per_sample;
  o.force_step = options.force;
  ComponentIntegrator integrator(basis, casing, o);
  ComponentRunOptions ro;
  ro.steps = n_samples * run.steps_per_sample;
  ro.output_every = run.steps_per_sample * setup.output_every;
  ro.energy_every = ro.output_every;
  ro.checkpoint = options.checkpoint;
  ComponentHistory h;
  const ComponentRunSummary c =
      run_component(integrator, basis.transformation.row(model.response_dof), ro, h);
  // The run's wall time, as for the bladed disk's reduced runs: from the
  // basis (basis_seconds) to the last step, the rows' output after it left out.
  const double wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
  const int nc = casing.n_contacts();
  Eigen::VectorXd normal(nc), tangential(2 * nc);
  double max_lambda = 0.0;
  for (int i = 0; i < h.n_rows(); ++i) {
    for (int k = 0; k < nc; ++k) {
      normal(k) = h.lambda[i](3 * k);
      tangential(2 * k) = h.lambda[i](3 * k + 1);
      tangential(2 * k + 1) = h.lambda[i](3 * k + 2);
    }
    max_lambda = std::max(max_lambda, normal.maxCoeff());
    const HistoryRow row{h.time[i],   h.gap[i],          normal,
                         h.energy[i], 0.0,               h.contact_work[i],
                         h.damping_work[i], &tangential};
    sink(row, h.response[i]);
  }
  run.summary = summary_of(c, options.method, basis.n_reduced(), max_lambda, basis_seconds);
  run.summary.wall_seconds = wall_seconds;
  return run;
}

RubbingRun run_full_rubbing(const RubbingModel& model, const RubbingRunOptions& options,
                            int n_samples, const ComponentRowSink& sink) {
  const RubbingSetup& setup = model.setup;
  const ImposedGap gap = setup.oval_gap ? ImposedGap::oval(setup.gap, setup.gap_width)
                                        : ImposedGap::constant(setup.gap);
  const RigidSurfaceContact law(rigid_surface_nodes(model.component, model.contact_nodes), gap,
                                setup.rotation_speed, setup.friction_coefficient,
                                setup.sliding_speed());
  double omega_max = 0.0;
  try {
    omega_max = max_angular_frequency(model.component.stiffness, model.component.mass);
  } catch (const ModalError& e) {
    // A consistent mass may be singular (Rotor 37's C3D15): the reduced
    // methods still run on it, the full-order explicit run cannot.
    throw ModalError("the full-order run of " + model.component.name + ": " + e.what() +
                     "; or run a reduced --method (cb, ccm, macneal)");
  }
  const double sample_dt = model.period / setup.steps_per_revolution;
  RubbingRun run;
  run.step_limit = 2.0 / omega_max;
  run.steps_per_sample = steps_per_sample(sample_dt, run.step_limit, setup.step_safety);
  ComponentReferenceOptions o;
  o.dt = sample_dt / run.steps_per_sample;
  o.steps = n_samples * run.steps_per_sample;
  o.output_every = run.steps_per_sample * setup.output_every;
  o.energy_every = o.output_every;
  o.damping = model.component_case.damping.rayleigh;
  o.omega_max = omega_max;
  o.force = options.force;
  o.checkpoint = options.checkpoint;
  o.progress = options.progress;
  run.summary = run_component_reference(model.component.stiffness, model.component.mass, law,
                                        model.response_dof, o, sink);
  return run;
}

} // namespace

RubbingModel load_rubbing_model(const ComponentCase& c, const ComponentLoadOptions& load) {
  if (!c.rubbing)
    throw CaseError(c.case_path + ": key 'rubbing': missing (a contact run of a component needs "
                                  "its casing, friction, speed and length; data/README.md)");
  RubbingModel model;
  model.component_case = c;
  model.setup = *c.rubbing;
  model.component = load_component(c, load);
  const Component& comp = model.component;
  model.contact_nodes = model.setup.contact_nodes;
  if (model.contact_nodes.empty())
    for (int d : comp.boundary)
      if (model.contact_nodes.empty() || model.contact_nodes.back() != comp.dofs[d].node)
        model.contact_nodes.push_back(comp.dofs[d].node);
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
  for (int node : model.contact_nodes)
    check_point(node, model.setup.contact_nodes.empty() ? "component.boundary"
                                                         : "rubbing.contact_nodes");
  check_point(model.setup.response_node, "rubbing.response");
  const std::string kind = direction_kind(model.setup.response_direction);
  for (int i = 0; i < comp.n_dofs(); ++i)
    if (comp.dofs[i].node == model.setup.response_node && comp.dofs[i].kind == kind)
      model.response_dof = i;
  if (model.response_dof < 0)
    throw CaseError(c.case_path + ": key 'rubbing.response': node " +
                    std::to_string(model.setup.response_node) + " direction " +
                    std::to_string(model.setup.response_direction) +
                    " is not a dof of the model (a free node and direction 1..3)");
  model.response_name = "u_" + std::to_string(model.setup.response_node) + "_" +
                        std::to_string(model.setup.response_direction);
  model.period = 2.0 * M_PI / std::abs(model.setup.rotation_speed);
  return model;
}

RubbingRun run_rubbing(const RubbingModel& model, const RubbingRunOptions& options,
                       const ComponentRowSink& sink) {
  const double revolutions = options.revolutions > 0.0 ? options.revolutions : model.setup.revolutions;
  const int n_samples =
      std::max(1, static_cast<int>(std::lround(revolutions * model.setup.steps_per_revolution)));
  if (options.method == "full") return run_full_rubbing(model, options, n_samples, sink);
  if (options.method == "cb" || options.method == "ccm" || options.method == "guyan" ||
      options.method == "macneal")
    return run_reduced_rubbing(model, options, n_samples, sink);
  throw std::invalid_argument("--method: must be full, cb, ccm, guyan or macneal, got '" +
                              options.method + "'");
}

} // namespace rsi
