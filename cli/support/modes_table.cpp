#include "modes_table.hpp"

#include <cstdio>
#include <sstream>

#include "stream_text.hpp"
#include "usage_error.hpp"

namespace rsi {

ModesTable modes_table(const ComponentInput& input, int count) {
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
    const std::optional<int> nd =
        input.diameter ? input.diameter(modes.shapes.col(i)) : std::nullopt;
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

ModesTable modes_table(const Case& c, const std::string& part, int count) {
  return modes_table(paper_part_input(c, part), count);
}

} // namespace rsi
