#include "nodal_diameter_map.hpp"

#include <algorithm>

#include "cyclic_images.hpp"
#include "modal_analysis.hpp"
#include "run_outputs.hpp"

namespace rsi {

NodalDiameterMap nodal_diameter_map(const Component& disk, int sectors, const Component& casing,
                                    int families, int casing_modes) {
  NodalDiameterMap map;
  map.sectors = sectors;
  const CyclicImages images = cyclic_images(disk, sectors);
  const Modes d =
      lowest_modes(disk.stiffness, disk.mass, std::min((families + 1) * sectors, disk.n_dofs()));
  for (int i = 0; i < d.n_modes(); ++i)
    map.disk.push_back({d.frequency_hz(i), cyclic_nodal_diameter(images, d.shapes.col(i))});
  const Modes c =
      lowest_modes(casing.stiffness, casing.mass, std::min(casing_modes, casing.n_dofs()));
  // Lobes up to 64: past twice the ring's lowest modes' (4 to 12 on the
  // gmsh rings), below its nodes' spacing.
  for (int i = 0; i < c.n_modes(); ++i)
    map.casing.push_back(
        {c.frequency_hz(i), circumferential_harmonic(casing, c.shapes.col(i), 64)});
  map.lines = interaction_lines(map.disk, sectors, map.casing, families, true);
  return map;
}

int rotor_sectors(const ComponentCase& c) {
  if (c.source == ComponentSource::gmsh_bladed_disk) return c.gmsh_bladed_disk.sectors;
  if (c.source == ComponentSource::calculix_sector) return c.sectors;
  return 0;
}

std::optional<NodalDiameterMap> system_nodal_diameter_map(const RubbingModel& model) {
  const int sectors = rotor_sectors(model.component_case());
  if (sectors == 0 || !model.setup().casing) return std::nullopt;
  const Component& casing =
      model.problem.structures.at(static_cast<size_t>(model.problem.casing.structure));
  return nodal_diameter_map(model.component(), sectors, casing, 2, 30);
}

std::string nodal_diameters_csv(const NodalDiameterMap& map) {
  std::string csv = "part,index,frequency_hz,nodal_diameter\n";
  const auto rows = [&csv](const char* part, const std::vector<ClassifiedMode>& modes) {
    for (size_t i = 0; i < modes.size(); ++i) {
      csv += std::string(part) + "," + std::to_string(i + 1) + ",";
      append_csv_number(csv, modes[i].frequency_hz);
      csv += "," + std::to_string(modes[i].nodal_diameter) + "\n";
    }
  };
  rows("bladed-disk", map.disk);
  rows("casing", map.casing);
  return csv;
}

namespace {

std::string lines_csv(const std::vector<InteractionLine>& lines, bool lobes) {
  std::string csv = std::string("family,nodal_diameter,") + (lobes ? "casing_lobes," : "") +
                    "blade_hz,casing_mode,casing_hz,speed_rad_s\n";
  for (const InteractionLine& l : lines) {
    csv += std::to_string(l.family) + "," + std::to_string(l.nodal_diameter) + ",";
    if (lobes) csv += std::to_string(l.casing_lobes) + ",";
    append_csv_number(csv, l.blade_hz);
    csv += "," + std::to_string(l.casing_mode) + ",";
    append_csv_number(csv, l.casing_hz);
    csv += ",";
    append_csv_number(csv, l.speed_rad_s);
    csv += "\n";
  }
  return csv;
}

} // namespace

std::string interaction_lines_csv(const std::vector<InteractionLine>& lines) {
  return lines_csv(lines, false);
}

std::string system_interaction_lines_csv(const std::vector<InteractionLine>& lines) {
  return lines_csv(lines, true);
}

} // namespace rsi
