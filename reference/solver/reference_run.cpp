#include "reference_run.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

#include "assembler.hpp"
#include "bladed_disk.hpp"
#include "casing.hpp"
#include "casing_forcing.hpp"
#include "central_difference.hpp"
#include "modal_analysis.hpp"
#include "tip_casing_contact.hpp"
#include "tip_ring_frictional_contact.hpp"

namespace rsi {
namespace {} // namespace

RunResult run_reference(const Case& c, const RunOptions& options) {
  const Clock::time_point start = Clock::now();
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  const Eigen::SparseMatrix<double> k = block_diagonal(bd.stiffness, casing.stiffness);
  const Eigen::SparseMatrix<double> m = block_diagonal(bd.mass, casing.mass);

  RunResult result;
  RunSummary& s = result.summary;
  s.method = "full";
  s.n_dofs = static_cast<int>(k.rows());
  check_time_step_bound(c.time.step, bd.stiffness, bd.mass, options.force, "bladed disk");
  check_time_step_bound(c.time.step, casing.stiffness, casing.mass, options.force, "casing");
  const double omega_bladed_disk = max_angular_frequency(bd.stiffness, bd.mass);
  s.bladed_disk_critical_dt = 2.0 / omega_bladed_disk;
  check_time_step(c.time.step,
                  std::max(omega_bladed_disk, max_angular_frequency(casing.stiffness, casing.mass)),
                  options.force, s);

  // The friction law of the case: sliding_sign (the first round's, the
  // golden history's) or Coulomb with stick and slip. Rayleigh damping of
  // both parts; with central damping (central_difference.hpp) the stable
  // step is 2/omega_max for any alpha, beta >= 0: the check above stands.
  const bool coulomb = c.operating_point.friction_law == FrictionLaw::coulomb;
  std::optional<TipCasingContact> sliding_sign_law;
  std::optional<TipRingFrictionalContact> coulomb_law;
  std::optional<CentralDifference> integrator;
  if (coulomb) {
    coulomb_law.emplace(bd, casing, c);
    integrator.emplace(k, m, c.time.step, *coulomb_law, c.damping.rayleigh);
  } else {
    sliding_sign_law.emplace(bd, casing, c);
    integrator.emplace(k, m, c.time.step, *sliding_sign_law, c.damping.rayleigh);
  }
  CentralDifference& cd = *integrator;
  s.flops_per_step = cd.flops_per_step();
  Eigen::VectorXd forcing = Eigen::VectorXd::Zero(k.rows());
  forcing.tail(casing.n_dofs()) = casing_forcing(casing, c.forcing);
  const Eigen::VectorXd no_force = Eigen::VectorXd::Zero(k.rows());

  RunMonitor monitor(c, casing, options, result);
  // The casing displacement is gathered from the integrator's permuted state
  // only when the monitor reads it (the first contact).
  const Eigen::VectorXd not_needed;
  // The bladed-disk dofs come first in u, the tips' (u, v) at bd.boundary.
  const TipDisplacementSource tips = [&](Eigen::VectorXd& out) {
    const Eigen::VectorXd& u = cd.displacement();
    out.resize(static_cast<Eigen::Index>(bd.boundary.size()));
    for (size_t i = 0; i < bd.boundary.size(); ++i)
      out(static_cast<Eigen::Index>(i)) = u(bd.boundary[i]);
  };
  auto state = [&](bool with_casing) {
    return StepState{
        cd.step_index(),
        cd.time(),
        cd.gap(),
        cd.lambda(),
        cd.external_work(),
        cd.contact_work(),
        with_casing ? Eigen::Ref<const Eigen::VectorXd>(cd.displacement().tail(casing.n_dofs()))
                    : Eigen::Ref<const Eigen::VectorXd>(not_needed),
        cd.damping_work(),
        coulomb ? &cd.lambda_tangential() : nullptr,
        &tips};
  };
  const Clock::time_point integration_start = Clock::now();
  bool forced = forcing_active(c.forcing, 0.0, s.dt);
  cd.start(forced ? forcing : no_force);
  monitor.start(state(false), cd.initial_energy());
  for (int n = 0; n < s.steps_requested; ++n) {
    if (forcing_active(c.forcing, n * s.dt, s.dt) != forced) {
      forced = !forced;
      cd.set_force(forced ? forcing : no_force);
    }
    const StepReport r = cd.step();
    if (!monitor.after_step(r, state(monitor.needs_casing(r)), [&]() { return cd.energy(); }))
      break;
  }
  monitor.finish(seconds_since(integration_start), seconds_since(start));
  return result;
}

} // namespace rsi
