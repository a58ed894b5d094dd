#include "reduced_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "basis_memory.hpp"
#include "bladed_disk.hpp"
#include "casing.hpp"
#include "casing_forcing.hpp"
#include "casing_memory.hpp"
#include "modal_analysis.hpp"
#include "modal_damping.hpp"
#include "reduced_contact.hpp"
#include "reduced_drive.hpp"
#include "reduced_integrator.hpp"
#include "reduction.hpp"
#include "run_step.hpp"

namespace rsi {
namespace {

ReducedBasis reduce_selected(const Case& c, const BladedDisk& bd, const std::string& method,
                             int modes, const std::string& selection) {
  if (selection == "lowest") return reduce_bladed_disk(bd, method, modes);
  return reduce_bladed_disk(bd, method, modes, parse_mode_selection(selection),
                            selection_context(bd, c.forcing.nodal_diameter));
}

/// The paper case's monitor: the casing force held between the changes of
/// its schedule, the history rows and the blow-up tests of RunMonitor (the
/// reference run's bookkeeping), and the recovered field u = T q on the rows.
class BladedDiskMonitor final : public DriveMonitor {
public:
  /// Every argument must outlive the monitor (not owned).
  BladedDiskMonitor(ReducedIntegrator& integrator, RunMonitor& monitor,
                    const ForcingSchedule& schedule, const Eigen::VectorXd& forcing, bool coulomb,
                    const Eigen::MatrixXd& transformation, const ReducedRunOptions& options,
                    std::vector<Eigen::VectorXd>& field)
      : m_integrator(integrator)
      , m_monitor(monitor)
      , m_schedule(schedule)
      , m_forcing(forcing)
      , m_coulomb(coulomb)
      , m_transformation(transformation)
      , m_options(options)
      , m_field(field)
      , m_share(schedule.share(0))
      , m_tips([this](Eigen::VectorXd& out) { m_integrator.tip_displacement(out); })
      , m_u(transformation.rows()) {}

  /// The casing force at `share` of the forcing.
  Eigen::VectorXd force_of(double share) const {
    return share == 1.0 ? m_forcing : Eigen::VectorXd(share * m_forcing);
  }

  void started() override {
    m_monitor.start(state(), m_integrator.initial_energy());
    record_field();
  }

  void before_step(std::int64_t n) override {
    if (m_schedule.share(n) != m_share) { // held until it changes
      m_share = m_schedule.share(n);
      m_integrator.set_force(force_of(m_share));
    }
  }

  bool after_step(std::int64_t /*n_next*/, const StepReport& r) override {
    const int rows = m_monitor.n_rows();
    const bool go_on = m_monitor.after_step(r, state(), [this]() { return m_integrator.energy(); });
    if (m_monitor.n_rows() > rows) record_field();
    return go_on;
  }

private:
  StepState state() const {
    // The tangential multipliers (one a tip) go to history.csv with the
    // Coulomb law only, as in the reference run: sliding_sign histories keep
    // their columns.
    return StepState{m_integrator.step_index(),
                     m_integrator.time(),
                     m_integrator.gap(),
                     m_integrator.lambda(),
                     m_integrator.external_work(),
                     m_integrator.contact_work(),
                     m_integrator.casing(),
                     m_integrator.damping_work(),
                     m_coulomb ? &m_integrator.tangential_lambda() : nullptr,
                     &m_tips};
  }

  void record_field() {
    if (!m_options.full_field) return;
    m_u.noalias() = m_transformation * m_integrator.q();
    if (m_options.field_sink)
      m_options.field_sink(m_integrator.time(), m_u);
    else
      m_field.push_back(m_u);
  }

  ReducedIntegrator& m_integrator;
  RunMonitor& m_monitor;
  const ForcingSchedule& m_schedule;
  const Eigen::VectorXd& m_forcing;
  bool m_coulomb;
  const Eigen::MatrixXd& m_transformation;
  const ReducedRunOptions& m_options;
  std::vector<Eigen::VectorXd>& m_field;
  double m_share;
  TipDisplacementSource m_tips;
  Eigen::VectorXd m_u;
};

} // namespace

ReducedRunResult run_reduced(const Case& c, const std::string& method, int modes,
                             const ReducedRunOptions& options) {
  // The full casing's step limit, bounded cheaply before the basis is built.
  const Casing casing = assemble_casing(c);
  if (options.casing_modes == 0 && options.step.kind != StepRule::Kind::own) {
    const double dt = options.step.kind == StepRule::Kind::given ? options.step.step : c.time.step;
    check_time_step_bound(dt, casing.stiffness, casing.mass, options.run.force, "casing");
  }
  check_dense_casing_fits(c, casing.n_dofs(), options.runs_at_once);
  const BladedDisk bd = assemble_bladed_disk(c);
  check_dense_basis_fits(
      options.modes_key.empty() ? failed_input(FailedInput::mode_count, c.source + ": ")
                                : shown_after(c.source + ": " + options.modes_key + ": "),
      bd.n_dofs(), static_cast<int>(bd.boundary.size()), modes, options.runs_at_once);
  return run_reduced(c, reduce_selected(c, bd, method, modes, options.selection), options);
}

ReducedBasis build_reduced_basis(const Case& c, const std::string& method, int modes,
                                 const std::string& selection) {
  return reduce_selected(c, assemble_bladed_disk(c), method, modes, selection);
}

ReducedRunResult run_reduced(const Case& case_in, const ReducedBasis& basis,
                             const ReducedRunOptions& options) {
  if (basis.massless_boundary)
    throw ReductionError(basis.method +
                             " has a massless boundary, which needs a static boundary balance at "
                             "every step (SPEC §8); the reduced integrator inverts M^ and cannot "
                             "run it",
                         failed_input(FailedInput::method));
  ReducedRunResult out;
  {
    // The casing basis is a basis like the bladed disk's: built before the
    // run's clock starts, its time counted in basis_seconds.
    const Casing casing = assemble_casing(case_in);
    if (options.casing_modes < 0 || options.casing_modes > casing.n_dofs())
      throw ReductionError("must be in [0, " + std::to_string(casing.n_dofs()) +
                               "] (0: the full casing; at most its dofs), got " +
                               std::to_string(options.casing_modes),
                           failed_input(FailedInput::casing_mode_count));
    if (options.casing_modes != 0)
      out.casing_basis = reduce_casing(casing, options.casing_modes,
                                       casing_forcing(casing, case_in.forcing));
  }
  // The reduced bladed disk's modes, for the integrator's modal coordinates
  // (undamped runs; reduced_integrator.hpp): built once with the basis, a
  // property of the reduced model that serves every run made with it.
  const bool modal_disk = case_in.damping.modal_ratio == 0.0 && !case_in.damping.projected_rayleigh;
  ReducedModes disk_modes;
  double disk_modes_seconds = 0.0;
  if (modal_disk) {
    const Clock::time_point modes_start = Clock::now();
    disk_modes = reduced_modes(basis);
    disk_modes_seconds = seconds_since(modes_start);
  }
  // The bladed disk's own matrices are the basis's business (its build time
  // is basis_seconds): the run reads its reduced matrices and the tips'
  // angles, so the 72-element model's assembly (6-8 ms, half of a CB-88 run)
  // is not repeated here.
  const Clock::time_point start = Clock::now();
  const Casing casing = assemble_casing(case_in);
  const Eigen::VectorXd forcing = casing_forcing(casing, case_in.forcing);
  const bool modal_casing = out.casing_basis.size() > 0;
  RunResult& result = out.run;
  RunSummary& s = result.summary;
  s.method = basis.method;
  s.n_dofs = basis.n_reduced() + (modal_casing ? out.casing_basis.size() : casing.n_dofs());
  s.basis_seconds = basis.build_seconds + out.casing_basis.build_seconds + disk_modes_seconds;
  s.casing_basis = modal_casing ? out.casing_basis.name() : "full";
  s.selection = basis.selection;
  s.modes_kept = basis.n_modes;
  s.time_step_rule = options.step.name();
  if (options.step.kind == StepRule::Kind::own) s.step_safety = options.step.safety;
  const double omega_bladed_disk =
      modal_disk ? disk_modes.omega_max() : reduced_omega_max(basis);
  s.bladed_disk_critical_dt = 2.0 / omega_bladed_disk;
  const double omega_casing = modal_casing
                                  ? std::sqrt(out.casing_basis.omega_squared.maxCoeff())
                                  : max_angular_frequency(casing.stiffness, casing.mass);
  const double omega_max = std::max(omega_bladed_disk, omega_casing);
  const RunStep step = run_step(options.step, case_in.time, omega_max, options.step_key);
  const Case c = with_run_step(case_in, step);
  check_time_step(c.time.step, omega_max, options.run.force, s);

  const ReducedTipContact contact(basis, casing, c);
  // Modal ratio on the kept modes, Rayleigh on the full casing; with central
  // damping the stable step is 2/omega_max for any C >= 0 (reduced_integrator.hpp):
  // the check above stands.
  ReducedDamping damping;
  if (c.damping.projected_rayleigh) // T^T (alpha M + beta K) T, T constant
    damping.bladed_disk_matrix =
        c.damping.rayleigh.alpha * basis.mass + c.damping.rayleigh.beta * basis.stiffness;
  else
    damping.bladed_disk = modal_damping(basis, c.damping.modal_ratio);
  damping.casing = c.damping.rayleigh;
  ReducedIntegrator integrator(basis, casing, c.time.step, contact, damping,
                               modal_casing ? &out.casing_basis : nullptr,
                               modal_disk ? &disk_modes : nullptr);
  s.flops_per_step = integrator.flops_per_step();
  s.casing_flops_per_step = integrator.casing_flops_per_step();
  const ForcingSchedule schedule(c.forcing, case_in.time, step.k);
  RunMonitor monitor(c, casing, options.run, result);
  std::vector<Eigen::VectorXd> field;
  const Eigen::Index n_physical = basis.transformation.rows();
  BladedDiskMonitor bladed_disk_monitor(integrator, monitor, schedule, forcing,
                                        c.operating_point.friction_law == FrictionLaw::coulomb,
                                        basis.transformation, options, field);
  const Clock::time_point integration_start = Clock::now();
  integrator.set_force(bladed_disk_monitor.force_of(schedule.share(0)));
  drive_reduced(integrator, s.steps_requested, bladed_disk_monitor);
  monitor.finish(seconds_since(integration_start), seconds_since(start));
  // The caller's copy of the basis, made after the clock stops: bookkeeping,
  // not the run (5 MB for the 72-element CB-88 basis).
  out.basis = basis;
  if (options.full_field && !options.field_sink) {
    out.field.resize(static_cast<Eigen::Index>(field.size()), n_physical);
    for (size_t i = 0; i < field.size(); ++i)
      out.field.row(static_cast<Eigen::Index>(i)) = field[i].transpose();
  }
  return out;
}

} // namespace rsi
