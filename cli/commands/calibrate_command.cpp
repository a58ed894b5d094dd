// rsi calibrate: the blade thickness that centres the first family on a target.

#include <cstdio>

#include "calibration.hpp"
#include "commands.hpp"

namespace rsi {

int run_calibrate(const CalibrateOptions& options) {
  const Case c = load_case(options.case_path);
  if (!(options.target_hz > 0.0))
    throw UsageError("--target-hz: must be > 0 Hz, got " + std::to_string(options.target_hz));
  const double before = first_family_mean_hz(c);
  // The bracket spans blade thicknesses from 1/20 to 20 times the case's value.
  const double thickness =
      calibrate_blade_thickness(c, options.target_hz, c.bladed_disk.blade.thickness / 20.0,
                                c.bladed_disk.blade.thickness * 20.0);
  Case calibrated = c;
  calibrated.bladed_disk.blade.thickness = thickness;
  std::printf("first family mean with the case's blade thickness %.9g m: %.6f Hz\n",
              c.bladed_disk.blade.thickness, before);
  std::printf("calibrated blade thickness: %.9g m -> first family mean %.6f Hz (target %.3f Hz)\n",
              thickness, first_family_mean_hz(calibrated), options.target_hz);
  return 0;
}

} // namespace rsi
