#include "rubbing_run.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "component_integrator.hpp"
#include "component_run.hpp"
#include "full_order_run.hpp"
#include "liner_wear.hpp"
#include "failure_advice.hpp"
#include "modal_analysis.hpp"
#include "modal_damping.hpp"
#include "reduction.hpp"
#include "rigid_casing.hpp"
#include "rubbing_points.hpp"
#include "solid_casing_part.hpp"

namespace rsi {
namespace {

/// A run's counts, in 64-bit: samples, steps a sample (k of the header),
/// steps.
struct RunCounts {
  std::int64_t samples = 0;
  std::int64_t steps_per_sample = 1;
  std::int64_t steps = 0;
};

std::string count_text(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.0f", x);
  return buffer;
}

/// k of the header (samples at T/N, integration at T/(k N) <= safety x
/// critical) and the run's step count, checked against max_rubbing_steps
/// in floating point before any integer holds them: CaseError naming the
/// keys. `method` and `critical_dt` say which model's stability limit set k.
RunCounts checked_counts(const RubbingModel& model, const RubbingRunOptions& options,
                         std::int64_t samples, double sample_dt, double critical_dt,
                         const std::string& method) {
  const RubbingSetup& setup = model.setup();
  const double k = model.problem.steps.steps_per_sample(sample_dt, critical_dt);
  const double steps = static_cast<double>(samples) * k;
  if (!(steps <= static_cast<double>(max_rubbing_steps))) {
    std::ostringstream m;
    m.precision(6);
    m << model.component_case().case_path << ": keys '" << options.revolutions_key
      << "' and 'rubbing.steps_per_revolution': " << samples << " samples x " << count_text(k)
      << " steps a sample (the " << method << " run steps at T/(k N) <= rubbing.step_safety "
      << setup.step_safety << " x its stability limit " << critical_dt << " s, T/N = " << sample_dt
      << " s) = " << count_text(steps) << " steps, more than the " << max_rubbing_steps
      << " a run can count: fewer revolutions or samples a revolution, or a faster "
         "rubbing.rotation_speed";
    throw CaseError(m.str());
  }
  RunCounts c;
  c.samples = samples;
  c.steps_per_sample = static_cast<std::int64_t>(k);
  c.steps = samples * c.steps_per_sample;
  return c;
}

/// The samples of a run and its history's size, checked before the run:
/// CaseError naming the keys.
std::int64_t checked_samples(const RubbingModel& model, const RubbingRunOptions& options,
                             double revolutions) {
  const RubbingSetup& setup = model.setup();
  // revolutions <= 1e5, steps_per_revolution <= 1e8 (the case's ranges):
  // at most 1e13 samples, exact in a double and an int64.
  const double samples = model.problem.steps.samples(revolutions);
  if (!(samples <= static_cast<double>(max_rubbing_steps)))
    throw CaseError(model.component_case().case_path + ": keys '" + options.revolutions_key +
                    "' and 'rubbing.steps_per_revolution': " + count_text(samples) +
                    " samples, more than the " + std::to_string(max_rubbing_steps) +
                    " steps a run can count");
  // t, the response, per contact gap, lambda_n, lambda_t1, lambda_t2, and
  // E, W_ext, W_contact, W_damp: about 24 bytes each (%.17g and a comma).
  const double columns = 6.0 + 4.0 * static_cast<double>(model.contact_nodes().size());
  const double bytes = (std::floor(samples / setup.output_every) + 1.0) * columns * 24.0;
  if (bytes > max_rubbing_history_bytes) {
    std::ostringstream m;
    m.precision(4);
    m << model.component_case().case_path << ": key 'rubbing.output_every': " << count_text(samples)
      << " samples (" << options.revolutions_key
      << " x rubbing.steps_per_revolution) written every " << setup.output_every
      << " would make history.csv about " << bytes / 1e9 << " GB (limit "
      << max_rubbing_history_bytes / 1e9 << " GB): raise rubbing.output_every";
    throw CaseError(m.str());
  }
  return static_cast<std::int64_t>(samples);
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
  s.steps_requested = static_cast<int>(c.steps_requested); // at most max_rubbing_steps
  s.steps = static_cast<int>(c.steps);
  s.completed = c.completed;
  s.status = c.status;
  s.status_advice = c.status_advice;
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

/// The run's Omega: the option's, else the case's.
double run_speed(const RubbingModel& model, const RubbingRunOptions& options) {
  return options.rotation_speed != 0.0 ? options.rotation_speed : model.setup().rotation_speed;
}

/// The case's liner as the reduced solver takes it (none: absent).
std::optional<ComponentLiner> component_liner(const Problem& problem) {
  if (!problem.casing.liner) return std::nullopt;
  const ProblemLiner& l = *problem.casing.liner;
  ComponentLiner liner;
  liner.geometry.radius = l.radius;
  liner.geometry.thickness = l.thickness;
  liner.geometry.n_theta = l.n_theta;
  liner.geometry.n_axial = l.n_axial;
  liner.geometry.z_min = l.z_min;
  liner.geometry.z_max = l.z_max;
  liner.material.young = l.young;
  liner.material.yield = l.yield;
  liner.material.hardening = l.hardening;
  liner.patch.circumferential = l.patch_circumferential;
  liner.patch.axial = l.patch_axial;
  return liner;
}

/// The flexible casing's modes plus the static correction for its load;
/// `key` names where the count came from.
CasingBasis solid_casing_basis(const RubbingModel& model, int modes, const std::string& key) {
  const Problem& p = model.problem;
  const Component& casing = p.structures.at(static_cast<size_t>(p.casing.structure));
  Eigen::VectorXd load;
  if (p.forcing.any()) load = p.forcing.force.tail(casing.n_dofs());
  if (modes >= casing.n_dofs())
    throw CaseError(p.source + ": " + key + ": " + std::to_string(modes) +
                    ", allowed fewer than the casing's " + std::to_string(casing.n_dofs()) +
                    " dofs");
  return reduce_solid_casing(casing, modes, load);
}

/// The flexible casing's part of a reduced run at step dt: the tips of
/// `tips`, the casing's surface, dofs, basis and load.
std::unique_ptr<ComponentCasingPart> solid_casing_part(const RubbingModel& model,
                                                       const RigidCasing& tips,
                                                       const CasingBasis& basis, double dt) {
  const Problem& p = model.problem;
  const Component& casing = p.structures.at(static_cast<size_t>(p.casing.structure));
  SolidCasingLoad load;
  if (p.forcing.any()) {
    load.force = p.forcing.force.tail(casing.n_dofs());
    load.duration = p.forcing.until;
  }
  return std::make_unique<SolidCasingPart>(tips, static_cast<int>(model.component().boundary.size()),
                                           dt, *p.casing.surface, node_translations(casing.dofs),
                                           basis, std::move(load));
}

} // namespace

CasingBasis rubbing_casing_basis(const RubbingModel& model, int modes) {
  if (!model.setup().casing)
    throw std::invalid_argument("rubbing_casing_basis: the case has no flexible casing");
  return modes > 0 ? solid_casing_basis(model, modes, "--casing-modes")
                   : solid_casing_basis(model, model.setup().casing_modes,
                                        "key 'rubbing.casing.modes'");
}

namespace {

RubbingRun run_reduced_rubbing(const RubbingModel& model, const RubbingRunOptions& options,
                               std::int64_t n_samples, const ComponentRowSink& sink) {
  const RubbingSetup& setup = model.setup();
  const double omega = run_speed(model, options);
  // The flexible casing's basis first (its count checked before the
  // rotor's basis is built); its build time is added to basis_seconds.
  std::optional<CasingBasis> own_casing;
  if (setup.casing && options.casing_basis == nullptr)
    own_casing = rubbing_casing_basis(model, options.casing_modes);
  const CasingBasis* casing_basis =
      options.casing_basis != nullptr ? options.casing_basis : own_casing ? &*own_casing : nullptr;
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<ReducedBasis> own;
  const Component& component = model.component();
  if (options.basis == nullptr)
    own = reduce(component, options.method, options.modes, options.boundary_modes);
  const ReducedBasis& basis = options.basis != nullptr ? *options.basis : *own;
  const auto run_start = std::chrono::steady_clock::now();
  const double basis_seconds = std::chrono::duration<double>(run_start - t0).count();
  CasingGap gap;
  gap.kind = setup.oval_gap ? CasingGapKind::oval : CasingGapKind::constant;
  gap.g0 = setup.gap;
  gap.width = setup.gap_width;
  const std::vector<double>& growth = model.problem.casing.tip_growth;
  if (!growth.empty() && omega != model.problem.contact.rotation_speed)
    throw std::invalid_argument(model.problem.source +
                                ": with rotation effects the model holds K(Omega) at the case's "
                                "speed only");
  const RigidCasing casing =
      setup.casing
          ? rigid_casing_of(model.component(), model.contact_nodes(), CasingGap{}, omega, omega)
          : rigid_casing_of(model.component(), model.contact_nodes(), gap, omega,
                            model.problem.contact.sliding_speed_at(omega), growth);
  // The integrator against the rigid casing, or against the flexible
  // casing's part made at the integrator's step.
  const auto integrator_of = [&](const ComponentIntegratorOptions& io) {
    if (!casing_basis) return ComponentIntegrator(basis, casing, io);
    return ComponentIntegrator(basis, solid_casing_part(model, casing, *casing_basis, io.dt), io);
  };
  ComponentIntegratorOptions o;
  o.mu = setup.friction_coefficient;
  o.liner = component_liner(model.problem); // checked by the loader (problem.cpp)
  if (model.component_case().damping.modal_ratio > 0.0)
    o.damping = modal_damping(basis, model.component_case().damping.modal_ratio);
  const double sample_dt = model.problem.steps.sample_step(omega);
  o.dt = sample_dt;
  o.force_step = true; // a probe, only for omega_max
  const double free_critical_dt = integrator_of(o).critical_dt();
  const double critical_dt =
      basis.massless_boundary ? std::min(free_critical_dt, held_boundary_critical_dt(basis))
                              : free_critical_dt;
  const RunCounts counts =
      checked_counts(model, options, n_samples, sample_dt, critical_dt, options.method);
  RubbingRun run;
  run.reduced_size = basis.n_reduced();
  run.step_limit = critical_dt;
  if ((options.method == "ccm" || options.method == "macneal") && basis.mode_omega.size() > 0)
    run.first_mode_hz = basis.mode_omega.minCoeff() / (2.0 * M_PI);
  run.steps_per_sample = static_cast<int>(counts.steps_per_sample);
  o.dt = sample_dt / run.steps_per_sample;
  o.force_step = options.force;
  ComponentIntegrator integrator = integrator_of(o);
  ComponentRunOptions ro;
  ro.steps = counts.steps;
  ro.output_every = counts.steps_per_sample * setup.output_every;
  ro.energy_every = ro.output_every;
  ro.checkpoint = options.checkpoint;
  // Each row goes to the sink as the step loop makes it, as in the full run:
  // nothing is kept (a run of 1000 revolutions once held hundreds of MB).
  const int nc = casing.n_contacts();
  Eigen::VectorXd normal(nc), tangential(2 * nc);
  double max_lambda = 0.0;
  const ComponentSampleSink rows = [&](const ComponentSample& sample) {
    for (int k = 0; k < nc; ++k) {
      normal(k) = sample.lambda(3 * k);
      tangential(2 * k) = sample.lambda(3 * k + 1);
      tangential(2 * k + 1) = sample.lambda(3 * k + 2);
    }
    max_lambda = std::max(max_lambda, normal.maxCoeff());
    const HistoryRow row{sample.time,         sample.gap,          normal,     sample.energy, sample.external_work,
                         sample.contact_work, sample.damping_work, &tangential, nullptr,
                         sample.plastic_work};
    sink(row, sample.response);
  };
  const ComponentRunSummary c =
      run_component(integrator, basis.transformation.row(model.response_dof()), ro, rows);
  // The run's wall time, as for the bladed disk's reduced runs: from the
  // basis (basis_seconds) to the last step, the rows' output (streamed during
  // the steps, as the full run's) included.
  const double wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
  run.summary = summary_of(c, options.method, basis.n_reduced(), max_lambda, basis_seconds);
  if (casing_basis) {
    // The system's size and its casing's basis, as the paper case's summaries.
    run.summary.n_dofs += casing_basis->size();
    run.summary.casing_basis = casing_basis->name();
    run.summary.basis_seconds += casing_basis->build_seconds;
    run.summary.final_external_work = c.final_external_work;
  }
  run.summary.wall_seconds = wall_seconds;
  if (const LinerContactSolve* liner = integrator.liner()) {
    const AbradableCells& cells = liner->cells();
    run.wear = cells.wear();
    run.wear_n_theta = cells.n_theta();
    run.wear_n_axial = cells.n_axial();
    RunSummary& s = run.summary;
    s.liner = true;
    s.final_plastic_work = c.final_plastic_work;
    s.liner_unmatched_work = c.liner_unmatched_work;
    s.liner_cell_area = cells.area();
    s.liner_bar_stiffness = cells.stiffness();
    s.max_wear_depth = *std::max_element(run.wear.begin(), run.wear.end());
    s.wear_lobes = wear_lobes(run.wear, cells.n_theta(), cells.n_axial());
  }
  return run;
}

RubbingRun run_full_rubbing(const RubbingModel& model, const RubbingRunOptions& options,
                            std::int64_t n_samples, double revolutions,
                            const ComponentRowSink& sink) {
  const Component& component = model.component();
  RunPoint point;
  point.rotation_speed = run_speed(model, options);
  point.revolutions = revolutions;
  try {
    // The system's: the rotor's, and the flexible casing's beside it.
    for (const Component& part : model.problem.structures)
      point.omega_max = std::max(point.omega_max, max_angular_frequency(part.stiffness, part.mass));
  } catch (const ModalError& e) {
    // A consistent mass may be singular (Rotor 37's C3D15): the reduced
    // methods still run on it, the full-order explicit run cannot.
    throw ModalError("the full-order run of " + component.name + ": " + failure_message(e) +
                     "; or run a reduced --method (cb, ccm, macneal)");
  }
  RubbingRun run;
  run.step_limit = 2.0 / point.omega_max;
  const RunCounts counts = checked_counts(model, options, n_samples,
                                          model.problem.steps.sample_step(point.rotation_speed),
                                          run.step_limit, "full");
  run.steps_per_sample = static_cast<int>(counts.steps_per_sample);
  RunOptions o;
  o.force = options.force;
  o.checkpoint = options.checkpoint;
  o.progress = options.progress;
  // The response rides in each row as its one tip displacement.
  o.history_sink = [&sink](const HistoryRow& row) {
    const double response = (*row.tip_displacement)(0);
    const HistoryRow out{row.time,          row.gap,           row.lambda,
                         row.energy,        row.external_work, row.contact_work,
                         row.damping_work,  row.lambda_tangential,
                         nullptr,           row.plastic_work};
    sink(out, response);
  };
  RunResult result = run_full_order(model.problem, o, point);
  run.summary = result.summary;
  run.wear = std::move(result.wear);
  run.wear_n_theta = result.wear_n_theta;
  run.wear_n_axial = result.wear_n_axial;
  return run;
}

} // namespace

RubbingModel load_rubbing_model(const ComponentCase& c, const ComponentLoadOptions& load) {
  require_rubbing(c);
  return RubbingModel{component_problem(c, load)};
}

RubbingRun run_rubbing(const RubbingModel& model, const RubbingRunOptions& options,
                       const ComponentRowSink& sink) {
  if (options.method != "full" && options.method != "cb" && options.method != "ccm" &&
      options.method != "guyan" && options.method != "macneal" && options.method != "cc")
    throw std::invalid_argument("--method: must be full, cb, ccm, guyan, macneal or cc, got '" +
                                options.method + "'");
  const double revolutions = options.revolutions > 0.0 ? options.revolutions : model.setup().revolutions;
  const std::int64_t n_samples = checked_samples(model, options, revolutions);
  if (options.method == "full")
    return run_full_rubbing(model, options, n_samples, revolutions, sink);
  return run_reduced_rubbing(model, options, n_samples, sink);
}

} // namespace rsi
