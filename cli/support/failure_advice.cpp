#include "failure_advice.hpp"

#include <sstream>

namespace rsi {
namespace {

/// The option or key a command reads the input from.
const char* input_name(FailedInput input) {
  switch (input) {
  case FailedInput::unnamed:
    return "";
  case FailedInput::mode_count:
    return "--modes";
  case FailedInput::boundary_mode_count:
    return "--boundary-modes";
  case FailedInput::method:
    return "--method";
  case FailedInput::casing_mode_count:
    return "casing_modes";
  case FailedInput::time_step_value:
    return "time.step";
  case FailedInput::ccx_cache:
    return "--ccx-cache";
  }
  return "";
}

/// What to change, in the options and keys of the commands that reach it.
const char* remedy_words(Remedy remedy) {
  switch (remedy) {
  case Remedy::fewer_jobs:
    return " or fewer --jobs";
  case Remedy::full_method_no_dense_casing:
    return " (simulate --method full keeps no dense casing matrix)";
  case Remedy::fewer_casing_modes:
    return "; keep fewer casing modes (--casing-modes, casing_modes)";
  case Remedy::fewer_modes_or_another_method:
    return "; keep fewer modes (--modes) or use another --method";
  case Remedy::fewer_modes_campaign_or_another_method:
    return "keep fewer modes (--modes, or the campaign's modes) or use another --method";
  case Remedy::massed_boundary_method:
    return "; use a method with a massed boundary (--method cb or ccm)";
  case Remedy::fewer_modes_or_coarser_model:
    return "; ask for fewer modes (--count, --modes) or make the model coarser (fewer elements)";
  case Remedy::fewer_modes_or_report:
    return "; ask for fewer modes (--count, --modes), or report the model";
  case Remedy::smaller_step_or_force:
    return "; use a smaller step or --force";
  case Remedy::reduced_smaller_step:
    return "; use a smaller step (time.step, or --time-step and the campaign's time_step of a "
           "reduced run)";
  case Remedy::reduced_friction_or_smaller_step:
    return "; change operating_point.friction_coefficient (friction that cancels the contacts' "
           "normal flexibility) or use a smaller step (time.step, --time-step)";
  case Remedy::lumped_mass_or_reduced_method:
    return ": set component.mass to \"lumped\" (HRZ) or run a reduced --method";
  case Remedy::component_lumped_mass_or_reduced_method:
    return ": for a component set component.mass to \"lumped\" (HRZ) or run a reduced --method";
  case Remedy::corrected_or_lumped_mass:
    return ": correct the component's mass (component.source) or set component.mass to "
           "\"lumped\" (HRZ)";
  case Remedy::lumped_mass_or_fewer_modes:
    return "; set component.mass to \"lumped\" (HRZ, positive definite) or keep fewer modes";
  case Remedy::smaller_step_unforced:
    return "; use a smaller step (time.step; a component's rubbing.step_safety), without --force";
  case Remedy::friction_or_smaller_step:
    return "; change the friction coefficient (operating_point.friction_coefficient; a "
           "component's rubbing.friction_coefficient) or use a smaller step (time.step; "
           "rubbing.step_safety)";
  case Remedy::smaller_step_safety_unforced:
    return "; use a smaller rubbing.step_safety, without --force";
  case Remedy::smaller_step_safety_or_friction:
    return "; use a smaller rubbing.step_safety or rubbing.friction_coefficient";
  case Remedy::more_boundary_modes:
    return "; keep more characteristic constraint modes (--boundary-modes; a campaign entry's "
           "modes) or run --method cb";
  case Remedy::thicker_liner_or_larger_clearance:
    return "; the liner model (bars in front of a rigid backing) ends there: give a thicker "
           "liner (rubbing.liner.thickness), a harder one (rubbing.liner.yield_stress), or a "
           "larger clearance (rubbing.gap)";
  }
  return "";
}

} // namespace

std::string with_advice(const std::string& what, const FailureAdvice& advice) {
  std::string out = advice.context;
  if (advice.input != FailedInput::unnamed)
    out += std::string(input_name(advice.input)) +
           (advice.input == FailedInput::time_step_value ? " = " : ": ");
  out += what;
  for (const Remedy r : advice.remedies)
    out += remedy_words(r);
  return out;
}

std::string failure_message(const std::exception& e) {
  return with_advice(e.what(), advice_of(e));
}

std::string run_status(const RunSummary& s) {
  return with_advice(s.status, s.status_advice);
}

std::string without_force(const std::string& what, const std::string& remedy) {
  const std::string force = " or --force";
  const size_t at = what.rfind(force);
  if (at == std::string::npos || at + force.size() != what.size()) return what;
  return what.substr(0, at) + " (" + remedy + ")";
}

StabilityError without_force(const StabilityError& e, const std::string& remedy) {
  return StabilityError(without_force(failure_message(e), remedy));
}

std::string stopped_run_remedy(const RunSummary& s) {
  std::ostringstream remedy;
  remedy.precision(6);
  if (s.dt >= s.critical_dt) {
    remedy << "the step " << s.dt
           << " s is at or above the stability limit 2/omega_max = " << s.critical_dt
           << " s (run with --force): use a smaller step (time.step, --time-step) and drop --force";
  } else {
    // Below the limit the scheme is stable (SPEC §2): the energy came in
    // through the contact, as friction on blades leaning into the rotation.
    remedy << "at a stable step the energy came in through the contact (friction wedges blades "
              "leaning into the rotation: sprag): change "
              "operating_point.friction_coefficient or the sign of bladed_disk.kink_angle_deg";
  }
  return remedy.str();
}

} // namespace rsi
