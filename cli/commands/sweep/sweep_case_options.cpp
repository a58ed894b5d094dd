#include "sweep_case_options.hpp"

#include <algorithm>
#include <cmath>

#include "casing.hpp"
#include "casing_memory.hpp"
#include "command_options.hpp"
#include "component_sweep_points.hpp"
#include "failure_advice.hpp"
#include "paper_sweep_points.hpp"
#include "run_list_checks.hpp"
#include "run_monitor.hpp"
#include "speeds_option.hpp"
#include "usage_error.hpp"

namespace rsi {

std::unique_ptr<SweepPoints> case_sweep(const Case& given, const SweepOptions& options, int jobs) {
  if (options.method == "macneal" || options.method == "cc")
    throw UsageError("--method: must be full, cb, ccm or guyan for the paper's case (macneal, "
                     "cc: component cases), got '" + options.method + "'");
  Case c = given;
  if (!c.sweep.present())
    throw UsageError(c.source + ": key 'sweep': missing; a sweep needs its duration, transient, "
                                "damping and runs (data/README.md)");
  if (!options.speeds.empty())
    c.sweep.speeds = parse_speeds_option(options.speeds, SpeedSign::non_negative);
  if (!options.method.empty()) {
    CampaignRun one;
    one.method = options.method;
    one.modes = options.modes;
    one.selection = options.selection;
    one.casing_modes = options.casing_modes;
    one.step = parse_step_option(options.time_step, options.step_safety);
    c.sweep.runs = {one};
  }
  const int disk_dofs =
      check_runs_against_model(c, c.sweep.runs, c.source + ": key 'sweep.runs'", jobs);
  const Casing casing = assemble_casing(c);
  if (std::any_of(c.sweep.runs.begin(), c.sweep.runs.end(),
                  [](const CampaignRun& r) { return r.method == "full"; })) {
    try {
      check_case_step_bound(c, casing);
    } catch (const StabilityError& e) {
      throw without_force(e, "time.step; a sweep has no --force");
    }
  }
  // The reduced runs' dense casing matrices, one a thread (casing_memory.hpp).
  if (std::any_of(c.sweep.runs.begin(), c.sweep.runs.end(),
                  [](const CampaignRun& r) { return r.method != "full"; }))
    check_dense_casing_fits(c, casing.n_dofs(), jobs);
  // A sweep has no --force: the remedy of a step its run refuses is the
  // key or option that set the step.
  const RefusedStepMessage refused_step = [](const CampaignRun& run, const StabilityError& e) {
    return without_force(
        failure_message(e),
        run.step.kind == StepRule::Kind::given
            ? "a smaller time_step of run " + sweep_run_name(run) +
                  " (sweep.runs or --time-step), dividing the output interval, or \"own\"; a "
                  "sweep has no --force"
            : "time.step; a sweep has no --force");
  };
  return paper_sweep_points(std::move(c), disk_dofs, refused_step);
}

std::unique_ptr<SweepPoints> case_sweep(const ComponentCase& c, const SweepOptions& options,
                                        int jobs) {
  for (const std::string& name : options.paper_run_options)
    throw UsageError(name + ": only for the paper's case (a component's runs step at "
                            "rubbing.step_safety of their own limit, on the whole casing); drop it");
  if (!c.rubbing)
    throw CaseError(c.case_path + ": key 'rubbing': missing (a component's sweep runs its "
                                  "rubbing set-up at each speed; data/README.md)");
  ComponentSweep sweep = c.sweep;
  if (!sweep.present() && (options.speeds.empty() || options.method.empty()))
    throw UsageError(c.case_path + ": key 'sweep': missing; a component's sweep needs its "
                                   "speeds and runs (data/README.md), or --speeds and --method");
  if (!sweep.present()) sweep.revolutions = c.rubbing->revolutions;
  if (!options.speeds.empty()) {
    sweep.speeds = parse_speeds_option(options.speeds, SpeedSign::any);
    for (double w : sweep.speeds) {
      if (w == 0.0)
        throw UsageError("--speeds: a component's speeds must be nonzero (a rubbing run needs a "
                         "rotation), got '" + options.speeds + "'");
      if ((w > 0.0) != (sweep.speeds.front() > 0.0))
        throw UsageError("--speeds: a component's speeds must all have one sign (the rotation's "
                         "direction), got '" + options.speeds + "'");
    }
  }
  if (!options.method.empty()) {
    const std::string& m = options.method;
    if (m != "full" && m != "cb" && m != "ccm" && m != "guyan" && m != "macneal" && m != "cc")
      throw UsageError("--method: a component case takes full, cb, ccm, guyan, macneal or cc, "
                       "got '" + m + "'");
    if (m != "full" && m != "guyan" && m != "cc" && options.modes < 1)
      throw UsageError("--modes: --method " + m + " needs its mode count (>= 1)");
    if (m == "cc" && options.boundary_modes < 1)
      throw UsageError("--boundary-modes: --method cc needs its characteristic constraint "
                       "modes n_c (>= 1; --modes: its fixed-interface modes, >= 0)");
    // A cc run's counted modes are n_c, as in the case's sweep.runs.
    sweep.runs = {m == "cc" ? ComponentSweepRun{m, options.boundary_modes, options.modes}
                            : ComponentSweepRun{m, m == "full" ? 0 : options.modes}};
  }
  if (c.rotation_effects)
    for (const ComponentSweepRun& run : sweep.runs)
      if (run.method == "cc") {
        const std::string why = ": cc with component.rotation_effects: not built in a speed "
                                "subspace (cb, ccm, macneal are); drop component.rotation_effects "
                                "or take another method";
        if (options.method.empty()) throw CaseError(c.case_path + ": key 'sweep.runs'" + why);
        throw UsageError("--method" + why);
      }
  const RubbingSetup& setup = *c.rubbing;
  const double rows_after = std::floor((sweep.revolutions - sweep.transient_revolutions) *
                                       setup.steps_per_revolution / setup.output_every);
  if (rows_after < 16)
    throw CaseError(c.case_path + ": key 'sweep.transient_revolutions': " +
                    std::to_string(static_cast<long>(rows_after)) +
                    " history rows after it, fewer than the 16 the spectrum needs (sweep."
                    "revolutions x rubbing.steps_per_revolution / rubbing.output_every)");
  RubbingModel model = load_rubbing_model(c, options.load);
  const std::string where = options.method.empty() ? c.case_path + ": key 'sweep.runs': run "
                                                   : "--method " + options.method + ": ";
  std::shared_ptr<const RotationFit> rotation;
  if (c.rotation_effects)
    rotation = std::make_shared<const RotationFit>(
        fit_rotation(c, options.load, sweep_rotation_fit_speeds(c, sweep), 2));
  return component_sweep_points(std::move(model), std::move(sweep), where, std::move(rotation),
                                jobs);
}

} // namespace rsi
