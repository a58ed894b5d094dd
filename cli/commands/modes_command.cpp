// rsi modes: lowest modes of one component, labelled by nodal diameter
// where the component has a cyclic structure.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>

#include "command.hpp"
#include "command_options.hpp"
#include "component_input.hpp"
#include "modal_analysis.hpp"
#include "modes_table.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "campbell_crossings.hpp"
#include "speeds_option.hpp"
#include "usage_error.hpp"
#include "rotating_component.hpp"
#include "rotation_fit.hpp"
#include "staged_output.hpp"
#include "terminal_progress.hpp"

namespace rsi {
namespace {

struct ModesOptions {
  std::string case_path;
  std::string part;  ///< empty: the bladed disk, or the component of a component case
  int count = 50;
  double speed = 0.0; ///< Omega [rad/s]: K(Omega) of a component case
  std::string speeds; ///< a Campbell diagram over these speeds (speeds_option.hpp)
  /// With speeds: K(Omega) from the rotation fit at these 6 speeds (rotation_fit.hpp)
  /// instead of a ccx run at each speed.
  std::string rotation_fit;
  std::string out = "out/modes";
  ComponentLoadOptions load;
};

class ModesCommand : public Command {
public:
  explicit ModesCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  int run_campbell(StagedOutput& output);

  ModesOptions m_options;
};

ModesCommand::ModesCommand(CLI::App& app)
    : Command(*app.add_subcommand("modes", "Lowest modes of one component -> DIR/modes.csv")) {
  ModesOptions& modes = m_options;
  m_command.add_option("case", modes.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  m_command.add_option("--part", modes.part,
                       "bladed-disk (default) or casing for the paper's case; a component "
                       "case has one part, its name");
  m_command.add_option("--count", modes.count, "number of modes, 1..number of dofs")
      ->capture_default_str()
      ->check(integer_in(1, 1000000000, "an integer in [1, the part's number of dofs]"));
  m_command.add_option("--speed", modes.speed,
                       "rotation speed Omega [rad/s] of a component case: the modes of its "
                       "prestressed K(Omega) (ccx: centrifugal static step, then perturbation), "
                       "|Omega| < 1e5")
      ->check(number_between(-1e5, 1e5, "a speed in rad/s, |Omega| < 1e5"));
  m_command
      .add_option("--speeds", modes.speeds,
                  "a Campbell diagram of a component case instead: the --count lowest "
                  "frequencies of K(Omega) at each speed, FROM:TO:COUNT or W1,W2,... [rad/s], "
                  "ascending, at least two, in [0, 100000) -> DIR/campbell.csv and the engine "
                  "orders 1-10's crossings DIR/crossings.csv")
      ->excludes("--speed");
  m_command
      .add_option("--rotation-fit", modes.rotation_fit,
                  "with --speeds: K(Omega) at each speed from the parametric model fitted at "
                  "these 6 speeds W1,...,W6 [rad/s], ascending, > 0, the last at least the "
                  "highest of --speeds (6 ccx runs in all, cached) instead of a ccx run a speed")
      ->needs("--speeds");
  m_command.add_option("--out", modes.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  add_component_options(m_command, modes.load);
}

/// What the check of the modes found and how many digits the frequencies
/// are claimed to (solver/modal_check.hpp).
void print_accuracy(const Modes& modes) {
  const ModalAccuracy& a = modes.accuracy;
  if (!a.checked || modes.n_modes() == 0) return;
  std::printf("solver: %s\n", a.solver.c_str());
  if (!a.replaced.empty())
    std::printf("  in place of %s, whose answer failed its check\n", a.replaced.c_str());
  std::printf("checked: residuals |K phi - lambda M phi| / (|K phi| + |lambda| |M phi|) <= %.2e "
              "(each within its bound), max |Phi^T M Phi - I| = %.2e (bound %.2e), Sturm count: %d "
              "eigenvalues below %.6e rad^2/s^2",
              a.residual.maxCoeff(), a.orthonormality, a.orthonormality_bound, a.sturm_count,
              a.sturm_shift);
  if (a.sturm_count_below >= 0)
    std::printf(" (%d below %.6e, as returned)", a.sturm_count_below, a.sturm_shift_below);
  std::printf("\n");
  int fewest = 17;
  int most = 0;
  for (int i = 0; i < modes.n_modes(); ++i)
    if (!modes.is_zero(i)) {
      fewest = std::min(fewest, modes.digits(i));
      most = std::max(most, modes.digits(i));
    }
  std::printf("precision: K and M carry %d significant digits (entries rounded to %.1e relative); ",
              a.input_digits, a.input_rounding);
  if (most > 0) {
    double input = 0.0;  // the largest relative uncertainty of an eigenvalue from each source
    double solver = 0.0;
    for (int i = 0; i < modes.n_modes(); ++i)
      if (!modes.is_zero(i)) {
        input = std::max(input, a.rounding(i) / std::abs(modes.omega_squared(i)));
        solver = std::max(solver, a.solver_error(i) / std::abs(modes.omega_squared(i)));
      }
    std::printf("the frequencies are claimed to %d to %d significant digits (+-_hz, digits; "
                "eigenvalues to %.1e relative from the input's rounding, %.1e from the solver)\n",
                fewest, most, input, solver);
  }
  else
    std::printf("no nonzero frequency\n");
  if (a.n_zero > 0)
    std::printf("rigid-body modes: %d, zero frequency to within their uncertainty (the part is "
                "free, or too stiff for double precision to tell)\n",
                a.n_zero);
}

/// The speed of a rotating component's K(Omega) and its operating point:
/// the largest static deflection and the boundary nodes' radial growth.
void print_rotation(const ComponentInput& input) {
  const Component& c = input.component;
  int largest = 0;
  for (int i = 0; i < c.n_dofs(); ++i)
    if (std::abs(input.deflection(i)) > std::abs(input.deflection(largest))) largest = i;
  std::printf("\nrotation speed %.6g rad/s (%.6g rpm): K(Omega) from ccx's perturbation step after "
              "its nonlinear static step under the centrifugal load; largest static deflection "
              "%.6e (node %d, %s)",
              input.speed, input.speed * 30.0 / M_PI, input.deflection(largest),
              c.dofs[largest].node, c.dofs[largest].kind.c_str());
  std::vector<int> nodes;
  for (int i : c.boundary)
    if (nodes.empty() || nodes.back() != c.dofs[i].node) nodes.push_back(c.dofs[i].node);
  if (nodes.empty()) return;
  double low = INFINITY, high = -INFINITY;
  for (int node : nodes) {
    const double g = radial_growth(c, input.deflection, node);
    low = std::min(low, g);
    high = std::max(high, g);
  }
  std::printf("; radial growth of the %zu boundary nodes %.6e to %.6e", nodes.size(), low, high);
}

} // namespace

int ModesCommand::run_campbell(StagedOutput& output) {
  const ModesOptions& options = m_options;
  const std::vector<double> speeds = parse_speeds_option(options.speeds, SpeedSign::non_negative);
  if (speeds.size() < 2)
    throw UsageError("--speeds: a Campbell diagram needs at least two speeds, got '" +
                     options.speeds + "'");
  for (size_t s = 1; s < speeds.size(); ++s)
    if (!(speeds[s] > speeds[s - 1]))
      throw UsageError("--speeds: the speeds must ascend, got '" + options.speeds + "'");
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd hz(speeds.size(), options.count);
  std::string name;
  // With --rotation-fit: the component at rest once, the fit, then every
  // speed's K(Omega) from it.
  std::optional<ComponentInput> rest;
  std::optional<RotationFit> fit;
  if (!options.rotation_fit.empty()) {
    std::vector<double> fit_speeds;
    try {
      fit_speeds = parse_speeds_option(options.rotation_fit, SpeedSign::non_negative);
    } catch (const UsageError& e) {
      throw UsageError(std::string("--rotation-fit: ") + e.what());
    }
    if (fit_speeds.size() != 6 || fit_speeds.front() <= 0.0)
      throw UsageError("--rotation-fit: 6 ascending speeds above 0 rad/s (2 deflection shapes), "
                       "got '" + options.rotation_fit + "'");
    if (speeds.back() > fit_speeds.back())
      throw UsageError("--rotation-fit: the highest fit speed must be at least the highest of "
                       "--speeds (" + std::to_string(speeds.back()) + " rad/s), got '" +
                       options.rotation_fit + "'");
    rest = load_component_input(options.case_path, options.part, options.load, 0.0, "--speeds");
    if (!rest->component_case)
      throw UsageError("--speeds: a Campbell diagram is for a component case (a CalculiX deck or "
                       "the gmsh blade); " + options.case_path + " is the paper's 2D case");
    TerminalStage stage("modes: the rotation fit (ccx at " + options.rotation_fit + " rad/s)");
    fit = fit_rotation(*rest->component_case, options.load, fit_speeds, 2);
    stage.done();
  }
  for (size_t s = 0; s < speeds.size(); ++s) {
    TerminalStage stage("modes: " + std::to_string(options.count) + " modes at " +
                        std::to_string(speeds[s]) + " rad/s (" + std::to_string(s + 1) + " of " +
                        std::to_string(speeds.size()) + ")");
    ComponentInput input;
    if (fit) {
      input = *rest;
      RotatingComponent at = rotating_component_at(*fit, speeds[s]);
      input.component = std::move(at.component);
      input.speed = speeds[s];
      input.deflection = std::move(at.deflection);
    } else {
      input = load_component_input(options.case_path, options.part, options.load, speeds[s], "--speeds");
    }
    if (!input.component_case)
      throw UsageError("--speeds: a Campbell diagram is for a component case (a CalculiX deck or "
                       "the gmsh blade); " + options.case_path + " is the paper's 2D case");
    const ModesTable table = modes_table(input, options.count);
    for (int i = 0; i < options.count; ++i) hz(s, i) = table.modes.frequency_hz(i);
    name = input.component.name;
    stage.done();
  }
  const int max_order = 10;
  const std::vector<CampbellCrossing> crossings = campbell_crossings(speeds, hz, max_order);
  std::ostringstream campbell;
  campbell.precision(17);
  campbell << "speed_rad_s,mode,frequency_hz\n";
  for (size_t s = 0; s < speeds.size(); ++s)
    for (int i = 0; i < options.count; ++i)
      campbell << speeds[s] << "," << i + 1 << "," << hz(s, i) << "\n";
  std::ostringstream table;
  table.precision(17);
  table << "mode,engine_order,speed_rad_s,frequency_hz\n";
  for (const CampbellCrossing& c : crossings)
    table << c.mode << "," << c.engine_order << "," << c.speed_rad_s << "," << c.frequency_hz
          << "\n";
  const std::string dir = output.open(options.out, "--out", campbell_output_set());
  write_text_file(dir + "/campbell.csv", campbell.str());
  write_text_file(dir + "/crossings.csv", table.str());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %s, %d modes at %zu speeds from %g to %g rad/s in %.1f s (K(Omega) %s)\n",
              options.case_path.c_str(), name.c_str(), options.count, speeds.size(),
              speeds.front(), speeds.back(), seconds,
              fit ? ("from the rotation fit at " + options.rotation_fit + " rad/s, feature rank " +
                     std::to_string(fit->feature_rank)).c_str()
                  : "from ccx at each speed, cached");
  std::printf("%6s %8s %10s %10s  engine-order crossings (mode i = the i-th lowest frequency at "
              "each speed; located by linear interpolation between grid speeds)\n",
              "mode", "order", "rad/s", "Hz");
  for (const CampbellCrossing& c : crossings)
    if (c.mode <= 3)
      std::printf("%6d %8d %10.1f %10.2f\n", c.mode, c.engine_order, c.speed_rad_s,
                  c.frequency_hz);
  output.announce("wrote " + options.out + "/campbell.csv and " + options.out +
                  "/crossings.csv (" + std::to_string(crossings.size()) + " crossings)\n");
  return 0;
}

int ModesCommand::run(StagedOutput& output) {
  const ModesOptions& options = m_options;
  if (!options.speeds.empty()) return run_campbell(output);
  const auto start = std::chrono::steady_clock::now();
  TerminalStage stage("modes: loading " + options.case_path + " and solving for " +
                      std::to_string(options.count) + " modes");
  const ComponentInput input = load_component_input(options.case_path, options.part, options.load, options.speed);
  const auto loaded = std::chrono::steady_clock::now();
  const ModesTable table = modes_table(input, options.count);
  const auto solved = std::chrono::steady_clock::now();
  stage.done();
  const Modes& modes = table.modes;
  const int n = table.n_dofs;
  const std::string dir = output.open(options.out, "--out", modes_output_set());
  write_text_file(dir + "/modes.csv", table.csv);
  const std::string path = options.out + "/modes.csv";

  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("%s: %s, %d dofs (%s)\n", input.case_source.c_str(), input.component.name.c_str(),
              n, input.component.units.c_str());
  if (std::isfinite(modes.omega_max))
    std::printf("omega_max = %.6e rad/s (%.1f Hz), critical central-difference step 2/omega_max = "
                "%.6e s",
                modes.omega_max, modes.omega_max / (2.0 * M_PI), modes.critical_time_step());
  else
    std::printf("omega_max = inf: M is singular (massless directions, infinite eigenvalues); "
                "central differences cannot integrate the full model");
  if (input.case_time_step > 0.0) std::printf(" (case step %.3e s)", input.case_time_step);
  if (input.speed != 0.0) print_rotation(input);
  std::printf("\nload %.2f s, %d modes %.2f s, peak memory %.0f MB\n", seconds(start, loaded),
              modes.n_modes(), seconds(loaded, solved), peak_memory_bytes() / 1048576.0);
  print_accuracy(modes);
  std::printf("%6s %16s %10s %6s %6s\n", "index", "frequency_hz", "+-_hz", "digits", "ND");
  const int shown = std::min(modes.n_modes(), 30);
  for (int i = 0; i < shown; ++i) {
    std::printf("%6d %16.6f %10.2g %6d", i + 1, modes.claimed_frequency_hz(i),
                modes.uncertainty_hz(i), modes.digits(i));
    if (table.diameters[i]) std::printf(" %6d", *table.diameters[i]);
    if (modes.is_zero(i)) std::printf("  rigid-body (zero to its uncertainty)");
    std::printf("\n");
  }
  if (shown < modes.n_modes()) std::printf("   ... %d more\n", modes.n_modes() - shown);
  output.announce("wrote " + path + "\n");
  return 0;
}

std::unique_ptr<Command> add_modes_command(CLI::App& app) {
  return std::make_unique<ModesCommand>(app);
}

} // namespace rsi
