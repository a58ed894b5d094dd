// rsi modes: lowest modes of one component, labelled by nodal diameter
// where the component has a cyclic structure.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "commands.hpp"
#include "component_input.hpp"
#include "modal_analysis.hpp"
#include "output_files.hpp"
#include "staged_output.hpp"
#include "stream_text.hpp"
#include "terminal_progress.hpp"

namespace rsi {
namespace {

ModesTable table_of(const ComponentInput& input, int count) {
  const Component& part = input.component;
  const int n = part.n_dofs();
  if (count < 1 || count > n)
    throw UsageError("--count: must be in [1, " + std::to_string(n) + "] for part " + part.name +
                     " (its number of dofs), got " + std::to_string(count));
  ModesTable table{lowest_modes(part.stiffness, part.mass, count), {}, {}, n};
  const Modes& modes = table.modes;
  std::ostringstream csv;
  csv << "index,frequency_hz,nodal_diameter,uncertainty_hz,digits,rigid_body\n";
  csv.precision(12);
  for (int i = 0; i < modes.n_modes(); ++i) {
    const std::optional<int> nd = input.diameter ? input.diameter(modes.shapes.col(i)) : std::nullopt;
    table.diameters.push_back(nd);
    csv << i + 1 << "," << modes.claimed_frequency_hz(i) << ",";
    if (nd) csv << *nd;
    char uncertainty[32];
    std::snprintf(uncertainty, sizeof uncertainty, "%.3g", modes.uncertainty_hz(i));
    csv << "," << uncertainty << "," << modes.digits(i) << "," << (modes.is_zero(i) ? 1 : 0)
        << "\n";
  }
  table.csv = stream_text(csv);
  return table;
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

} // namespace

ModesTable modes_table(const Case& c, const std::string& part_name, int count) {
  return table_of(paper_part_input(c, part_name), count);
}

int run_modes(const ModesOptions& options, StagedOutput& output) {
  const auto start = std::chrono::steady_clock::now();
  TerminalStage stage("modes: loading " + options.case_path + " and solving for " +
                      std::to_string(options.count) + " modes");
  const ComponentInput input = load_component_input(options.case_path, options.part, options.load);
  const auto loaded = std::chrono::steady_clock::now();
  const ModesTable table = table_of(input, options.count);
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

} // namespace rsi
