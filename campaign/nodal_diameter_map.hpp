#pragma once
// The 3D system's nodal-diameter map and interaction lines (issue 27 item
// 6, the paper's Fig. 3): the bladed disk's lowest modes with their nodal
// diameters (cyclic_images.hpp), the flexible casing's with their lobes, and
// the speeds Omega_int = 2 pi (f_b + f_c) / n at which a disk family's
// backward wave and a casing mode's forward wave of n lobes travel together
// (sweep/interaction_lines.hpp, Legrand et al. 2009).

#include <optional>
#include <string>
#include <vector>

#include "component.hpp"
#include "interaction_lines.hpp"
#include "rubbing_run.hpp"

namespace rsi {

struct NodalDiameterMap {
  int sectors = 0;
  std::vector<ClassifiedMode> disk;   ///< ascending
  std::vector<ClassifiedMode> casing; ///< ascending
  std::vector<InteractionLine> lines;
};

/// `families` whole families of the disk (families + 1 times N modes, the
/// last family's pairs whole) and the casing's `casing_modes` lowest; the
/// lines of every casing mode with lobes, those above N/2 through their
/// alias (interaction_lines.hpp).
NodalDiameterMap nodal_diameter_map(const Component& disk, int sectors, const Component& casing,
                                    int families, int casing_modes);

/// The bladed disk's sectors (a gmsh_bladed_disk or calculix_sector rotor),
/// 0 for another rotor.
int rotor_sectors(const ComponentCase& c);

/// The map of a bladed-disk rotor against its flexible casing, as `rsi
/// campaign` and `rsi sweep` write it: two families of the disk (3N modes),
/// the casing's 30 lowest (lobes 0 to 15 on the gmsh rings); nullopt for
/// another rotor or a rigid casing.
std::optional<NodalDiameterMap> system_nodal_diameter_map(const RubbingModel& model);

/// part,index,frequency_hz,nodal_diameter (part: bladed-disk or casing).
std::string nodal_diameters_csv(const NodalDiameterMap& map);

/// family,nodal_diameter,blade_hz,casing_mode,casing_hz,speed_rad_s (17
/// significant digits): the paper's sweep's interaction_lines.csv (2D).
std::string interaction_lines_csv(const std::vector<InteractionLine>& lines);

/// family,nodal_diameter,casing_lobes,blade_hz,casing_mode,casing_hz,speed_rad_s:
/// the 3D system's interaction_lines.csv (rsi campaign, rsi sweep), its
/// lines above N/2 lobes aliased (nodal_diameter k, casing_lobes n).
std::string system_interaction_lines_csv(const std::vector<InteractionLine>& lines);

} // namespace rsi
