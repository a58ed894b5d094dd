#pragma once
// A 3D bladed disk of N identical sectors (issue 27 item 1): each sector the
// project's gmsh blade (gmsh_blade.hpp) fused with a sector of an annular
// disk, meshed by gmsh once, and the N copies turned about z by k alpha,
// alpha = 2 pi / N, with each sector face's nodes shared by the two sectors
// that meet there. The hub (the bore) is clamped.
//
// Geometry (mm, the blade's frame: z the rotation axis, blade 0 along +x):
// the disk sector is the annulus bore_radius <= r <= rim_radius, |z| <=
// disk_width / 2, between the polar angles -alpha/2 (face LEFT) and
// +alpha/2 (face RIGHT). The root block's bottom (x = root_radius) lies
// inside the disk (rim_radius in (root_radius, root_radius + root_height]),
// so blade, block and disk fuse into one volume. gmsh's `Periodic Surface
// RIGHT = LEFT Rotate alpha` makes the two faces one node pattern: the face
// RIGHT of copy k is the face LEFT of copy k + 1 node for node, not within a
// tolerance (tried: 1.2e-13 mm worst, docs/bladed-disk-sector.md).
//
// Numbering of the assembly: sector k's node j is k * stride + j (stride =
// 1 + the largest node number of the sector), except the nodes of its face
// LEFT, which are sector k - 1's (mod N) paired RIGHT nodes; element e of
// sector k is k * element_stride + e. Node sets: BORE (clamped), TIPk (k = 1
// .. N, the blade's 16 contact nodes of gmsh_blade.hpp in their order), TIP
// (all of them, TIP1's first).
//
// Files written into DIR: blade.geo, blade_gmsh.inp, gmsh.log (the
// sector's), sector.inp (the sector alone with ccx's cyclic symmetry tie:
// NSET NLEFT = LEFT without the bore's nodes, the dependent side; NRIGHT;
// *CYCLIC SYMMETRY MODEL N about z; no step) and disk.inp (the assembly,
// model only, no step).

#include <string>
#include <vector>

#include "gmsh_blade.hpp"

namespace rsi {

struct GmshBladedDiskSpec {
  GmshBladeSpec blade;       ///< one sector's blade (its element_size meshes the disk too)
  int sectors = 22;          ///< N, [3, 200]; the blade must fit its sector (checked)
  double bore_radius = 90.0; ///< clamped inner radius, (0, rim_radius) [mm]
  double rim_radius = 160.0; ///< (blade.root_radius, blade.root_radius + root_height] [mm]
  double disk_width = 50.0;  ///< axial, centred on z = 0, (0, inf) [mm]
};

/// Throws std::invalid_argument naming the first field out of range
/// (GmshBladedDiskSpec.FIELD or the blade's GmshBladeSpec.FIELD), and
/// GmshBladedDiskSpec.sectors when the blade (its root block or its tip's
/// chord, the larger polar angle) does not fit inside its sector.
void check_gmsh_bladed_disk_spec(const GmshBladedDiskSpec& spec);

/// The sector's gmsh script: the blade's (gmsh_blade_geo) with the disk
/// sector fused in and the periodic faces. Checks the spec.
std::string gmsh_bladed_disk_sector_geo(const GmshBladedDiskSpec& spec);

/// Everything the decks are made of, as text for a cache key (the sector's
/// script and the material lines). Checks the spec.
std::string gmsh_bladed_disk_cache_key(const GmshBladedDiskSpec& spec);

struct GmshBladedDiskDecks {
  std::string disk;   ///< DIR/disk.inp, the assembly
  std::string sector; ///< DIR/sector.inp, one sector with the cyclic tie
};

/// Meshes one sector with gmsh and writes both decks into DIR (created if
/// needed). Throws std::invalid_argument for a bad spec, GmshError when gmsh
/// fails or its mesh lacks a part the decks need (LEFT and RIGHT faces
/// whose nodes do not pair within 1e-9 of the model's size, no bore nodes,
/// a tip station), std::runtime_error when a file cannot be written.
GmshBladedDiskDecks write_gmsh_bladed_disk_decks(const GmshBladedDiskSpec& spec,
                                                 const std::string& dir);

} // namespace rsi
