#include "failure_remedies.hpp"

#include <sstream>

namespace rsi {

std::string without_force(const std::string& what, const std::string& remedy) {
  const std::string force = " or --force";
  const size_t at = what.rfind(force);
  if (at == std::string::npos || at + force.size() != what.size()) return what;
  return what.substr(0, at) + " (" + remedy + ")";
}

StabilityError without_force(const StabilityError& e, const std::string& remedy) {
  return StabilityError(without_force(std::string(e.what()), remedy));
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
