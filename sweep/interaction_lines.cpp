#include "interaction_lines.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "modal_analysis.hpp"
#include "nodal_diameter.hpp"

namespace rsi {

double interaction_speed(double blade_hz, double casing_hz, int nodal_diameter) {
  return 2.0 * M_PI * (blade_hz + casing_hz) / nodal_diameter;
}

int aliased_nodal_diameter(int lobes, int n_blades) {
  const int r = lobes % n_blades;
  return std::min(r, n_blades - r);
}

std::vector<InteractionLine> interaction_lines(const std::vector<ClassifiedMode>& disk,
                                               int n_blades,
                                               const std::vector<ClassifiedMode>& casing,
                                               int families, bool aliased) {
  std::map<int, std::vector<double>> disk_hz; // n -> distinct frequencies, ascending
  for (const ClassifiedMode& mode : disk) {
    std::vector<double>& hz = disk_hz[mode.nodal_diameter];
    const double f = mode.frequency_hz;
    // The two modes of a pair agree to round-off (exact cyclic symmetry):
    // a relative 1e-6 separates pairs from distinct families.
    if (hz.empty() || std::abs(f - hz.back()) > 1e-6 * f) hz.push_back(f);
  }
  int top = n_blades / 2;
  if (aliased)
    for (const ClassifiedMode& mode : casing)
      top = std::max(top, mode.nodal_diameter);
  std::vector<InteractionLine> lines;
  for (int j = 1; j <= families; ++j)
    for (int n = 1; n <= top; ++n) {
      const int k = aliased_nodal_diameter(n, n_blades);
      const auto blade = disk_hz.find(k);
      if (blade == disk_hz.end() || static_cast<int>(blade->second.size()) < j) continue;
      const double fb = blade->second[static_cast<size_t>(j - 1)];
      for (size_t m = 0; m < casing.size(); ++m) {
        if (casing[m].nodal_diameter != n) continue;
        const double fc = casing[m].frequency_hz;
        lines.push_back({j, k, fb, static_cast<int>(m) + 1, fc, interaction_speed(fb, fc, n), n});
      }
    }
  return lines;
}

std::vector<InteractionLine> interaction_lines(const Case& c, int families, int casing_modes) {
  const BladedDisk bd = assemble_bladed_disk(c);
  const int n_blades = bd.n_sectors;
  // Each family holds N modes (pairs at 0 < n < N/2): one family more than
  // asked makes sure the last asked one is whole.
  const Modes disk =
      lowest_modes(bd.stiffness, bd.mass, std::min((families + 1) * n_blades, bd.n_dofs()));
  std::vector<ClassifiedMode> disk_modes;
  for (int i = 0; i < disk.n_modes(); ++i)
    disk_modes.push_back(
        {disk.frequency_hz(i), nodal_diameter(disk.shapes.col(i), n_blades, bd.dofs_per_sector)});
  const Casing casing = assemble_casing(c);
  const Modes ring =
      lowest_modes(casing.stiffness, casing.mass, std::min(casing_modes, casing.n_dofs()));
  std::vector<ClassifiedMode> ring_modes;
  for (int m = 0; m < ring.n_modes(); ++m)
    ring_modes.push_back(
        {ring.frequency_hz(m),
         nodal_diameter(on_all_nodes(casing, ring.shapes.col(m)), casing.n_elements, 4)});
  return interaction_lines(disk_modes, n_blades, ring_modes, families);
}

} // namespace rsi
