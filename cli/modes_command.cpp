// rsi modes: lowest modes of one component, labelled by nodal diameter
// where the component has a cyclic structure.

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
  std::ostringstream csv;
  csv << "index,frequency_hz,nodal_diameter\n";
  csv.precision(12);
  for (int i = 0; i < table.modes.n_modes(); ++i) {
    const std::optional<int> nd =
        input.diameter ? input.diameter(table.modes.shapes.col(i)) : std::nullopt;
    table.diameters.push_back(nd);
    csv << i + 1 << "," << table.modes.frequency_hz(i) << ",";
    if (nd) csv << *nd;
    csv << "\n";
  }
  table.csv = stream_text(csv);
  return table;
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
  std::printf("%6s %16s %6s\n", "index", "frequency_hz", "ND");
  const int shown = std::min(modes.n_modes(), 30);
  for (int i = 0; i < shown; ++i) {
    std::printf("%6d %16.6f", i + 1, modes.frequency_hz(i));
    if (table.diameters[i]) std::printf(" %6d", *table.diameters[i]);
    std::printf("\n");
  }
  if (shown < modes.n_modes()) std::printf("   ... %d more\n", modes.n_modes() - shown);
  std::printf("wrote %s\n", path.c_str());
  return 0;
}

} // namespace rsi
