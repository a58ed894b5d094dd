#pragma once
// The flexible 3D casing of the paper's system in 3D (issue 27 item 2): a
// ring of quadratic tetrahedra (C3D10) meshed by gmsh, clamped at its
// flanges, the blade tips meeting its inner surface.
//
// Geometry (mm, the bladed disk's frame: z the rotation axis): the annulus
// inner_radius <= r <= inner_radius + thickness, |z| <= width / 2, whole
// (gmsh's OpenCASCADE cylinders, their difference). The flanges are the
// end faces z = -width / 2 (front) and z = +width / 2 (back); the clamped
// ones (NSET FLANGE) are the front one (clamped_flanges = 1: the casing
// bolted to its neighbour at one end, its other end free to ovalise, as the
// 2D ring clamped at one node, SPEC §2) or both (2). The contact surface is
// the inner face r = inner_radius: the element faces whose corners lie on
// it (*SURFACE SINNER, TYPE=ELEMENT: casing_surface.hpp reads it), their
// midside nodes on the chords; NSET INNER holds those faces' nodes off the
// clamped flanges. The mesh: the blade's options (gmsh_mesh_options),
// element_size the largest edge.
//
// Measured (rsi modes, ccx's matrices), a steel ring of inner radius 272
// mm, element_size 15 mm, lowest frequency:
//   width x thickness [mm]   both flanges clamped   the front one
//   60 x 10                  14,326 Hz              3,572 Hz (22,437 dofs)
//   60 x 5                                          2,482 Hz (21,777 dofs)
//   100 x 5                                         1,467 Hz (33,972 dofs)
//   300 x 5                  1,107 Hz (96,399 dofs)
//   500 x 5 (element 20)     685 Hz (91,242 dofs)
// A casing clamped at both ends is a short shell between two clamps; with
// one end free its lowest modes are the free end's ovalisation (pairs).
//
// Files written into DIR: casing.geo (the gmsh script), casing_gmsh.inp
// (gmsh's mesh), gmsh.log and casing.inp (the deck: *NODE, *ELEMENT
// TYPE=C3D10 ELSET=EALL, *NSET FLANGE and INNER, *SURFACE SINNER,
// *MATERIAL, *SOLID SECTION, *BOUNDARY FLANGE 1-3; model only, no *STEP). Node and element numbers are
// gmsh's.

#include <string>

#include "gmsh_blade.hpp"

namespace rsi {

struct GmshCasingSpec {            // units: mm, t, s, N
  double inner_radius = 272.0;     ///< (0, inf) [mm]; the default blade's tip is at 270-270.8
  double thickness = 5.0;          ///< radial, (0, inf) [mm]
  double width = 60.0;             ///< axial, centred on z = 0, (0, inf) [mm]
  double element_size = 10.0;      ///< (0, pi inner_radius / 6] [mm], at least 12 around
  int clamped_flanges = 1;         ///< 1 (front, z = -width/2) or 2 (both)
  double young_modulus = 210000.0; ///< E, (0, inf) [N/mm^2]
  double poisson_ratio = 0.3;      ///< nu, (-1, 0.5) [-]
  double density = 7.85e-9;        ///< rho, (0, inf) [t/mm^3]
};

/// The mesh's size before gmsh: quadratic tetrahedra of edge h, h x h x
/// min(h, thickness) each (one element at least across the thickness, as
/// gmsh_blade_mesh_estimate), about 2 nodes an element, 3 dofs a node.
double gmsh_casing_estimated_dofs(const GmshCasingSpec& spec);

/// The largest estimated dof count accepted (the blade's bound,
/// gmsh_blade_max_estimated_dofs: ccx's matrices of such a mesh take about
/// 200 MB a file).
constexpr double gmsh_casing_max_estimated_dofs = gmsh_blade_max_estimated_dofs;

/// Throws std::invalid_argument("GmshCasingSpec.FIELD: ... allowed ...")
/// for the first field out of range or not finite, and
/// ("GmshCasingSpec.element_size: ...") when the estimated mesh exceeds
/// gmsh_casing_max_estimated_dofs.
void check_gmsh_casing_spec(const GmshCasingSpec& spec);

/// The gmsh script. Checks the spec.
std::string gmsh_casing_geo(const GmshCasingSpec& spec);

/// Everything casing.inp is made of, as text for a cache key (the script and
/// the material lines). Checks the spec.
std::string gmsh_casing_cache_key(const GmshCasingSpec& spec);

/// Meshes the ring with gmsh and writes DIR/casing.inp (DIR created if
/// needed); returns its path. Throws std::invalid_argument for a bad spec,
/// GmshError when gmsh fails or its mesh has fewer than 3 nodes on either
/// flange or none on the inner face off them, std::runtime_error when a file cannot
/// be written.
std::string write_gmsh_casing_deck(const GmshCasingSpec& spec, const std::string& dir);

} // namespace rsi
