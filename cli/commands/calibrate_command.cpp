// rsi calibrate: the blade thickness that centres the first family on a target.

#include <cstdio>

#include <CLI/CLI.hpp>

#include "command.hpp"
#include "command_options.hpp"
#include "usage_error.hpp"
#include "calibration.hpp"

namespace rsi {
namespace {

struct CalibrateOptions {
  std::string case_path;
  double target_hz = 44.0;
};

class CalibrateCommand : public Command {
public:
  explicit CalibrateCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  CalibrateOptions m_options;
};

CalibrateCommand::CalibrateCommand(CLI::App& app)
    : Command(*app.add_subcommand(
          "calibrate", "Blade thickness that centres the first family of frequencies on a target")) {
  CalibrateOptions& calibrate = m_options;
  m_command.add_option("case", calibrate.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  m_command.add_option("--target-hz", calibrate.target_hz, "target mean frequency [Hz], > 0")
      ->capture_default_str()
      ->check(number_above(0.0, "a finite number of Hz above 0"));
}

} // namespace

int CalibrateCommand::run(StagedOutput&) {
  const CalibrateOptions& options = m_options;
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

std::unique_ptr<Command> add_calibrate_command(CLI::App& app) {
  return std::make_unique<CalibrateCommand>(app);
}

} // namespace rsi
