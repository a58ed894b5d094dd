#include "full_order_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "case_file.hpp"
#include "casing_forcing.hpp"
#include "liner_wear.hpp"
#include "central_difference.hpp"
#include "modal_analysis.hpp"
#include "paper_monitor.hpp"
#include "rubbing_monitor.hpp"

namespace rsi {
namespace {

/// The integrator over whichever law the handle holds (in place: it keeps
/// references into its own members).
void emplace_integrator(std::optional<CentralDifference>& cd, const FullOrderSystem& system) {
  const StructureContact& contact = *system.contact;
  if (contact.law())
    cd.emplace(*system.stiffness, *system.mass, system.dt, *contact.law(), system.damping);
  else
    cd.emplace(*system.stiffness, *system.mass, system.dt, *contact.frictional_law(),
               system.damping);
}

/// A structure's name in messages ("bladed-disk" -> "bladed disk").
std::string part_name(const Component& component) {
  std::string name = component.name;
  std::replace(name.begin(), name.end(), '-', ' ');
  return name;
}

} // namespace

void drive_full_order(const FullOrderSystem& system, RunMonitor& monitor, RunSummary& s,
                      Clock::time_point start) {
  std::optional<CentralDifference> integrator;
  emplace_integrator(integrator, system);
  CentralDifference& cd = *integrator;
  LinerSurface* const liner = system.liner;
  if (liner) {
    try {
      cd.attach_liner(*liner);
    } catch (const std::invalid_argument& e) {
      throw CaseError(system.source + ": the abradable liner: " + e.what() +
                      "; use a lumped mass and no stiffness-proportional Rayleigh damping");
    }
  }
  s.flops_per_step = cd.flops_per_step();
  const Eigen::Index n_dofs = system.stiffness->rows();
  const bool has_force = system.forcing != nullptr && system.forcing->any();
  const Eigen::VectorXd no_force = Eigen::VectorXd::Zero(n_dofs);
  Forcing window; // forcing_active's rule: t <= until + 1e-6 dt
  window.duration = has_force ? system.forcing->until : 0.0;
  const auto active = [&](double t) { return has_force && forcing_active(window, t, system.dt); };

  // The casing displacement is gathered from the integrator's permuted state
  // only when the monitor reads it (the paper's first contact).
  const Eigen::VectorXd not_needed;
  const TipDisplacementSource tips = [&](Eigen::VectorXd& out) {
    const Eigen::VectorXd& u = cd.displacement();
    out.resize(static_cast<Eigen::Index>(system.tip_dofs.size()));
    for (size_t i = 0; i < system.tip_dofs.size(); ++i)
      out(static_cast<Eigen::Index>(i)) = u(system.tip_dofs[i]);
  };
  const bool coulomb = system.contact->coulomb();
  auto state = [&](bool with_casing) {
    return StepState{
        cd.step_index(),
        cd.time(),
        cd.gap(),
        cd.lambda(),
        cd.external_work(),
        liner ? cd.liner_contact_work() : cd.contact_work(),
        with_casing && system.casing_count > 0
            ? Eigen::Ref<const Eigen::VectorXd>(
                  cd.displacement().segment(system.casing_first, system.casing_count))
            : Eigen::Ref<const Eigen::VectorXd>(not_needed),
        cd.damping_work(),
        coulomb ? &cd.lambda_tangential() : nullptr,
        system.tip_dofs.empty() ? nullptr : &tips,
        liner != nullptr,
        liner ? liner->plastic_work() : 0.0};
  };
  // With a liner E holds the bars' elastic energy beside the blade's
  // (decisions.md: the liner's balance).
  const auto energy = [&]() { return liner ? cd.energy() + liner->elastic_energy() : cd.energy(); };

  const Clock::time_point integration_start = Clock::now();
  bool forced = active(0.0);
  cd.start(forced ? system.forcing->force : no_force);
  monitor.start(state(false), cd.initial_energy());
  for (int n = 0; n < s.steps_requested; ++n) {
    if (active(n * system.dt) != forced) {
      forced = !forced;
      cd.set_force(forced ? system.forcing->force : no_force);
    }
    StepReport r;
    try {
      r = cd.step();
    } catch (const IntegrationError& e) {
      if (!system.failure_is_status) throw;
      monitor.stop_with(e.what(), e.advice());
      break;
    }
    if (!monitor.after_step(r, state(monitor.needs_casing(r)), energy)) break;
  }
  monitor.finish(seconds_since(integration_start), seconds_since(start));
  // The works where the run stopped (the last row's unless the last step was
  // outside the model and wrote none).
  s.final_external_work = cd.external_work();
  s.final_contact_work = liner ? cd.liner_contact_work() : cd.contact_work();
  if (liner) s.liner_unmatched_work = cd.liner_unmatched_work();
  s.final_damping_work = cd.damping_work();
}

namespace {

/// The fixed step rule (the paper's kind).
RunResult run_fixed_step(const Problem& problem, const RunOptions& options) {
  const Clock::time_point start = Clock::now();
  const double dt = problem.steps.step;
  const Eigen::SparseMatrix<double> k = problem.stiffness();
  const Eigen::SparseMatrix<double> m = problem.mass();

  RunResult result;
  RunSummary& s = result.summary;
  s.method = "full";
  s.n_dofs = static_cast<int>(k.rows());
  for (const Component& part : problem.structures)
    check_time_step_bound(dt, part.stiffness, part.mass, options.force, part_name(part));
  // The rotor's own limit is reported (a reduced run's is compared with it);
  // the system's is the largest omega_max of its structures.
  const double omega_rotor =
      max_angular_frequency(problem.structures.front().stiffness, problem.structures.front().mass);
  s.bladed_disk_critical_dt = 2.0 / omega_rotor;
  double omega_max = omega_rotor;
  for (size_t i = 1; i < problem.structures.size(); ++i)
    omega_max = std::max(omega_max, max_angular_frequency(problem.structures[i].stiffness,
                                                           problem.structures[i].mass));
  check_time_step(dt, omega_max, options.force, s);

  // The friction law of the case: sliding_sign (the first round's, the
  // golden history's) or Coulomb with stick and slip. Rayleigh damping of
  // both parts; with central damping (central_difference.hpp) the stable
  // step is 2/omega_max for any alpha, beta >= 0: the check above stands.
  const StructureContact contact(problem);
  if (!problem.paper) throw std::invalid_argument(problem.source + ": no flexible casing");
  RunMonitor monitor(problem.paper->case_file, problem.paper->casing, options, result);
  FullOrderSystem system;
  system.stiffness = &k;
  system.mass = &m;
  system.dt = dt;
  system.damping = problem.damping.rayleigh;
  system.contact = &contact;
  system.forcing = &problem.forcing;
  system.casing_first = problem.offset(problem.casing.structure);
  system.casing_count = problem.structures[static_cast<size_t>(problem.casing.structure)].n_dofs();
  system.tip_dofs = problem.contact.rotor_dofs;
  drive_full_order(system, monitor, s, start);
  return result;
}

/// The per-revolution rule (a component on the rigid casing, or with the
/// flexible solid casing beside it).
RunResult run_per_revolution(const Problem& problem, const RunOptions& options,
                             const RunPoint& point) {
  const bool flexible = problem.contact.kind == ContactKind::solid_casing;
  if (problem.contact.kind != ContactKind::rigid_surface && !flexible)
    throw std::invalid_argument(problem.source + ": no rubbing set-up to run");
  const Component& rotor = problem.structures.front();
  // The system: the rotor alone, or rotor and casing side by side.
  Eigen::SparseMatrix<double> system_k, system_m;
  if (flexible) {
    system_k = problem.stiffness();
    system_m = problem.mass();
  }
  const Eigen::SparseMatrix<double>& k_all = flexible ? system_k : rotor.stiffness;
  const Eigen::SparseMatrix<double>& m_all = flexible ? system_m : rotor.mass;
  const ProblemSteps& rule = problem.steps;
  const double omega = point.rotation_speed != 0.0 ? point.rotation_speed
                                                   : problem.contact.rotation_speed;
  const double revolutions = point.revolutions > 0.0 ? point.revolutions : rule.revolutions;
  const Clock::time_point start = Clock::now();
  RunResult result;
  RunSummary& s = result.summary;
  s.method = "full";
  s.n_dofs = static_cast<int>(k_all.rows());
  // The rotor's own omega_max, and the system's (the largest of its structures').
  const double omega_rotor =
      flexible || !(point.omega_max > 0.0) ? max_angular_frequency(rotor.stiffness, rotor.mass)
                                           : point.omega_max;
  double omega_max = point.omega_max > 0.0 ? point.omega_max : omega_rotor;
  if (flexible && !(point.omega_max > 0.0))
    for (size_t i = 1; i < problem.structures.size(); ++i)
      omega_max = std::max(omega_max, max_angular_frequency(problem.structures[i].stiffness,
                                                            problem.structures[i].mass));
  const double sample_dt = rule.sample_step(omega);
  const double k = rule.steps_per_sample(sample_dt, 2.0 / omega_max);
  const double steps = rule.samples(revolutions) * k;
  if (!(steps <= std::numeric_limits<int>::max()))
    throw std::invalid_argument(problem.source + ": " + std::to_string(std::llround(steps)) +
                                " steps, more than a run counts");
  const double dt = sample_dt / k;
  check_time_step(dt, omega_max, options.force, s);
  // The rotor's own limit (a reduced run's is compared with it).
  s.bladed_disk_critical_dt = flexible ? 2.0 / omega_rotor : s.critical_dt;

  // The response dof rides in the rows as the one "tip", gathered on output
  // steps.
  RunOptions run = options;
  run.tip_displacement = problem.outputs.response_dof >= 0;
  MonitorRules rules;
  rules.steps_requested = static_cast<int>(steps);
  rules.output_every = static_cast<std::int64_t>(k) * problem.outputs.output_every;
  rules.energy_every = rules.output_every;
  rules.row_at_last_step = false;
  rules.balance_tolerance = rubbing_balance_tolerance;
  const StructureContact contact(problem, omega);
  std::optional<LinerSurface> liner;
  if (problem.casing.liner) {
    const ProblemLiner& l = *problem.casing.liner;
    LinerGeometry geometry;
    geometry.radius = l.radius;
    geometry.thickness = l.thickness;
    geometry.n_theta = l.n_theta;
    geometry.n_axial = l.n_axial;
    geometry.z_min = l.z_min;
    geometry.z_max = l.z_max;
    LinerMaterial material;
    material.young = l.young;
    material.yield = l.yield;
    material.hardening = l.hardening;
    try {
      liner.emplace(*contact.rigid_surface(), geometry, material,
                    LinerPatch{l.patch_circumferential, l.patch_axial});
    } catch (const std::invalid_argument& e) {
      throw CaseError(problem.source + ": the abradable liner: " + e.what());
    }
  }
  RunMonitor monitor(rules,
                     flexible ? std::make_unique<RubbingMonitor>(*contact.solid_casing())
                              : std::make_unique<RubbingMonitor>(*contact.rigid_surface()),
                     run, result);
  FullOrderSystem system;
  system.stiffness = &k_all;
  system.mass = &m_all;
  system.dt = dt;
  system.damping = problem.damping.rayleigh;
  system.contact = &contact;
  system.forcing = &problem.forcing; // the flexible casing's load (none on the rigid one)
  if (run.tip_displacement) system.tip_dofs = {problem.outputs.response_dof};
  system.failure_is_status = true;
  system.liner = liner ? &*liner : nullptr;
  system.source = problem.source;
  drive_full_order(system, monitor, s, start);
  if (liner) {
    const AbradableLiner& a = liner->liner();
    result.wear_n_theta = a.n_theta();
    result.wear_n_axial = a.n_axial();
    result.wear.resize(static_cast<size_t>(a.n_cells()));
    for (int cell = 0; cell < a.n_cells(); ++cell) result.wear[static_cast<size_t>(cell)] = a.wear(cell);
    s.liner = true;
    s.final_plastic_work = liner->plastic_work();
    s.liner_cell_area = a.cell_area();
    s.liner_bar_stiffness = a.stiffness();
    s.max_wear_depth = *std::max_element(result.wear.begin(), result.wear.end());
    s.wear_lobes = wear_lobes(result.wear, a.n_theta(), a.n_axial());
  }
  // A component run's clocks include its rows' output (as its reduced runs'
  // do: campaign/rubbing_run.hpp compares them).
  s.integration_seconds += s.output_seconds;
  s.wall_seconds += s.output_seconds;
  s.output_seconds = 0.0;
  return result;
}

} // namespace

RunResult run_full_order(const Problem& problem, const RunOptions& options,
                         const RunPoint& point) {
  if (problem.steps.rule == ProblemSteps::Rule::per_revolution)
    return run_per_revolution(problem, options, point);
  if (point.rotation_speed != 0.0 || point.revolutions != 0.0)
    throw std::invalid_argument(problem.source + ": a run at another speed or length than the "
                                                 "case's takes the per-revolution step rule");
  return run_fixed_step(problem, options);
}

} // namespace rsi
