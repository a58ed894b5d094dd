#include "reduced_run.hpp"

#include <chrono>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "casing_forcing.hpp"
#include "casing_memory.hpp"
#include "modal_analysis.hpp"
#include "modal_damping.hpp"
#include "reduced_contact.hpp"
#include "reduced_integrator.hpp"
#include "reduction.hpp"

namespace rsi {
namespace {} // namespace

ReducedRunResult run_reduced(const Case& c, const std::string& method, int modes,
                             const ReducedRunOptions& options) {
  // The full casing's step limit, bounded cheaply before the basis is built.
  const Casing casing = assemble_casing(c);
  check_time_step_bound(c.time.step, casing.stiffness, casing.mass, options.run.force, "casing");
  check_dense_casing_fits(c, casing.n_dofs(), options.runs_at_once);
  return run_reduced(c, reduce_bladed_disk(assemble_bladed_disk(c), method, modes), options);
}

ReducedRunResult run_reduced(const Case& c, const ReducedBasis& basis,
                             const ReducedRunOptions& options) {
  if (basis.massless_boundary)
    throw ReductionError(
        "--method: " + basis.method +
        " has a massless boundary, which needs a static boundary balance at "
        "every step (SPEC §8); the reduced integrator inverts M^ and cannot run it");
  const Clock::time_point start = Clock::now();
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  ReducedRunResult out;
  out.basis = basis;
  RunResult& result = out.run;
  RunSummary& s = result.summary;
  s.method = basis.method;
  s.n_dofs = out.basis.n_reduced() + casing.n_dofs();
  s.basis_seconds = basis.build_seconds;
  const double omega_bladed_disk = reduced_omega_max(out.basis);
  s.bladed_disk_critical_dt = 2.0 / omega_bladed_disk;
  check_time_step(c.time.step,
                  std::max(omega_bladed_disk, max_angular_frequency(casing.stiffness, casing.mass)),
                  options.run.force, s);

  const ReducedTipContact contact(bd, out.basis, casing, c);
  // Modal ratio on the kept modes, Rayleigh on the full casing; with central
  // damping the stable step is 2/omega_max for any C >= 0 (reduced_integrator.hpp):
  // the check above stands.
  ReducedDamping damping;
  damping.bladed_disk = modal_damping(out.basis, c.damping.modal_ratio);
  damping.casing = c.damping.rayleigh;
  ReducedIntegrator integrator(out.basis, casing, c.time.step, contact, damping);
  s.flops_per_step = integrator.flops_per_step();
  s.casing_flops_per_step = integrator.casing_flops_per_step();
  const Eigen::VectorXd forcing = casing_forcing(casing, c.forcing);
  const Eigen::VectorXd no_force = Eigen::VectorXd::Zero(casing.n_dofs());

  RunMonitor monitor(c, casing, options.run, result);
  std::vector<Eigen::VectorXd> field;
  const bool coulomb = c.operating_point.friction_law == FrictionLaw::coulomb;
  auto state = [&]() {
    // The tangential multipliers (one a tip) go to history.csv with the
    // Coulomb law only, as in the reference run: sliding_sign histories keep
    // their columns.
    return StepState{integrator.step_index(),
                     integrator.time(),
                     integrator.gap(),
                     integrator.lambda(),
                     integrator.external_work(),
                     integrator.contact_work(),
                     integrator.casing(),
                     integrator.damping_work(),
                     coulomb ? &integrator.tangential_lambda() : nullptr};
  };
  Eigen::VectorXd u(bd.n_dofs());
  auto record_field = [&]() {
    if (!options.full_field) return;
    u.noalias() = out.basis.transformation * integrator.q();
    if (options.field_sink)
      options.field_sink(integrator.time(), u);
    else
      field.push_back(u);
  };
  const Clock::time_point integration_start = Clock::now();
  bool force_on = forcing_active(c.forcing, 0.0, s.dt);
  integrator.start(force_on ? forcing : no_force);
  monitor.start(state(), integrator.initial_energy());
  record_field();
  for (int n = 0; n < s.steps_requested; ++n) {
    if (forcing_active(c.forcing, n * s.dt, s.dt) != force_on) { // held until it changes
      force_on = !force_on;
      integrator.set_force(force_on ? forcing : no_force);
    }
    const StepReport r = integrator.step();
    const int rows = monitor.n_rows();
    const bool go_on = monitor.after_step(r, state(), [&]() { return integrator.energy(); });
    if (monitor.n_rows() > rows) record_field();
    if (!go_on) break;
  }
  monitor.finish(seconds_since(integration_start), seconds_since(start));
  if (options.full_field && !options.field_sink) {
    out.field.resize(static_cast<Eigen::Index>(field.size()), bd.n_dofs());
    for (size_t i = 0; i < field.size(); ++i)
      out.field.row(static_cast<Eigen::Index>(i)) = field[i].transpose();
  }
  return out;
}

} // namespace rsi
