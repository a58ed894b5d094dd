// rsi modes: lowest modes of one part, labelled by nodal diameter.

#include <cstdio>
#include <functional>
#include <sstream>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "commands.hpp"
#include "modal_analysis.hpp"
#include "nodal_diameter.hpp"
#include "output_files.hpp"

namespace rsi {
namespace {

struct Part {
  Eigen::SparseMatrix<double> stiffness;
  Eigen::SparseMatrix<double> mass;
  /// Nodal diameter of a mode shape of this part.
  std::function<int(const Eigen::VectorXd&)> label;
};

Part load_part(const Case& c, const std::string& name) {
  if (name == "bladed-disk") {
    BladedDisk bd = assemble_bladed_disk(c);
    const int n = bd.n_sectors;
    const int block = bd.dofs_per_sector;
    return {bd.stiffness, bd.mass,
            [n, block](const Eigen::VectorXd& x) { return nodal_diameter(x, n, block); }};
  }
  if (name == "casing") {
    Casing casing = assemble_casing(c);
    return {casing.stiffness, casing.mass, [casing](const Eigen::VectorXd& x) {
              return nodal_diameter(on_all_nodes(casing, x), casing.n_elements, 4);
            }};
  }
  throw UsageError("--part: must be bladed-disk or casing, got '" + name + "'");
}

} // namespace

ModesTable modes_table(const Case& c, const std::string& part_name, int count) {
  const Part part = load_part(c, part_name);
  const int n = static_cast<int>(part.stiffness.rows());
  if (count < 1 || count > n)
    throw UsageError("--count: must be in [1, " + std::to_string(n) + "] for part " + part_name +
                     " (its number of dofs), got " + std::to_string(count));
  ModesTable table{lowest_modes(part.stiffness, part.mass, count), {}, {}, n};
  std::ostringstream csv;
  csv << "index,frequency_hz,nodal_diameter\n";
  csv.precision(12);
  for (int i = 0; i < table.modes.n_modes(); ++i) {
    table.diameters.push_back(part.label(table.modes.shapes.col(i)));
    csv << i + 1 << "," << table.modes.frequency_hz(i) << "," << table.diameters.back() << "\n";
  }
  table.csv = csv.str();
  return table;
}

int run_modes(const ModesOptions& options, OutputDirectories& directories) {
  const Case c = load_case(options.case_path);
  const ModesTable table = modes_table(c, options.part, options.count);
  const Modes& modes = table.modes;
  const std::vector<int>& diameters = table.diameters;
  const int n = table.n_dofs;
  directories.make(options.out, "--out");
  const std::string path = options.out + "/modes.csv";
  write_text_file(path, table.csv);

  std::printf("%s: %s, %d dofs\n", c.source.c_str(), options.part.c_str(), n);
  std::printf(
      "omega_max = %.6e rad/s (%.1f Hz), critical central-difference step 2/omega_max = %.6e s"
      " (case step %.3e s)\n",
      modes.omega_max, modes.omega_max / (2.0 * M_PI), modes.critical_time_step(), c.time.step);
  std::printf("%6s %16s %6s\n", "index", "frequency_hz", "ND");
  const int shown = std::min(modes.n_modes(), 30);
  for (int i = 0; i < shown; ++i)
    std::printf("%6d %16.6f %6d\n", i + 1, modes.frequency_hz(i), diameters[i]);
  if (shown < modes.n_modes()) std::printf("   ... %d more\n", modes.n_modes() - shown);
  std::printf("wrote %s\n", path.c_str());
  return 0;
}

} // namespace rsi
