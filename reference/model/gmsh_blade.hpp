#pragma once
// A parametric 3D blade of the project's own (imitating the external NASA
// Rotor 37 blade of shared/external/rotor37), meshed by gmsh and written as
// a CalculiX deck from which `ccx` produces K and M
// (*FREQUENCY, SOLVER=MATRIXSTORAGE).
//
// Frame and units (those of Rotor 37): mm, t, s, N; z is the rotation axis,
// the blade spans radially along +x.
//   - Root block: a box root_height (along x) x root_length (along the root
//     chord) x root_width (across it), from x = root_radius to
//     x_top = root_radius + root_height, turned about the x axis like the
//     root section so that the root section always lies inside its top
//     face. Its bottom face x = root_radius is clamped (NSET ROOT).
//   - Blade: sections in the planes x = x_top + s, 0 <= s <= span, all the
//     same section turned about the x axis by
//         theta(s) = stagger + twist s / span,
//     a section point (u, v) (u along the chord, v across it) sitting at
//         (x_top + s, u sin(theta) + v cos(theta), u cos(theta) - v sin(theta)),
//     i.e. theta is the angle of the chord from the rotation axis z towards y.
//   - Section: a cambered plate of constant thickness. Its camber line is a
//     circular arc through (u, v) = (-chord/2, 0), (chord/2, 0) with
//     sagitta f = camber chord at u = 0 (radius R = (chord^2/4 + f^2) / (2 f),
//     a straight line for camber 0); the section is bounded by the two arcs
//     concentric with it at radii R -+ thickness/2 and by two straight ends
//     normal to the camber line at its end points. Square ends rather than
//     a NACA-like round or sharp edge: the edges have no small radius and no
//     sliver, so gmsh's straight-sided tetrahedra are valid at any element
//     size (tried: round ends of radius thickness/2 gave a tetrahedron with
//     a negative Jacobian at element_size 5 with curved second-order
//     elements).
//   - Geometry by gmsh's OpenCASCADE kernel: ThruSections through
//     n = max(2, 1 + ceil(|twist| / 5 deg)) section wires (the linear twist
//     interpolated smoothly), BooleanUnion with the root block.
//   - Mesh: second-order tetrahedra with straight edges
//     (Mesh.SecondOrderLinear = 1: midside nodes at edge midpoints, so every
//     element has a constant positive Jacobian; the arcs of radius ~R are
//     faceted, a sagitta of element_size^2 / (8 R), 0.12 mm at the default).
//     gmsh writes them as Abaqus C3D10 (node order checked here: nodes 5-10
//     are the midpoints of edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4), which ccx reads.
//   - Contact nodes, NSET TIP: the mesh nodes at n_tip_stations = 16 stations
//     equally spaced along the tip's camber line (equal arc length), both
//     end points included (they are the midpoints of the tip face's
//     leading- and trailing-edge segments), in order of increasing u. The 14
//     interior stations are points embedded in the tip face (mesh size
//     min(element_size, station spacing) there), so they are nodes of every
//     mesh: the same 16 physical points at any refinement, like Rotor 37's
//     16 contact nodes.
//
// Node and element numbers are gmsh's (nodes that no element uses are
// dropped, none in practice). Files written into DIR: blade.geo (the gmsh
// script), blade_gmsh.inp (gmsh's mesh), gmsh.log (its output) and
// blade.inp (the deck).
//
// Defaults (the members' initial values) give the coarse model used by CI:
// span 100, chord 40, thickness 3, camber 0.05, twist 30 deg, stagger
// 30 deg, root block 50 x 12 x 20 at root_radius 150 (tip at radius 270),
// element_size 10 [mm]; steel E = 210000 N/mm^2, nu = 0.3,
// rho = 7.85e-9 t/mm^3.
//
// Sizes measured with gmsh 4.8.4 and ccx 2.20 (Debian), default geometry,
// element_size varied (verification/imports/test_gmsh_blade, DISABLED_ScalingStudy).
// dofs = 3 (nodes - ROOT nodes) = the rows of ccx's .dof; gmsh = wall time
// of write_gmsh_blade_deck; ccx = wall time of `ccx` on the deck with one
// `*FREQUENCY, SOLVER=MATRIXSTORAGE` step; .sti = size of the stiffness
// file (.mas the same). 2-core machine shared with other jobs: times vary
// by up to 2x between runs.
//
//   element_size  nodes   C3D10  ROOT    dofs  gmsh [s]  ccx [s]  .sti [MB]
//   10 (default)   1426     658    59    4101    0.19      0.19       4.1
//    6.667         2811    1359    97    8142    0.22      0.37       8.5
//    5             4513    2199   163   13050    0.26      0.57      13.9
//    3.333         9778    5010   303   28425    0.47      1.28      32.1
//    2.5          18795    9967   547   54744    0.61      2.55      63.7
//    2            29881   16339   787   87282    0.91      4.32     103.8
//    1.8          37708   20811   983  110175    1.27      5.49     132.6
//    1.667        51056   29834  1101  149865    1.51      7.79     189.2
//
// Down to element_size = thickness the plate is crossed by about one
// element and the node count grows like element_size^-2 (a surface
// refinement); below it like element_size^-3.
//
// First frequencies (ccx Lanczos, Hz) at element_size 10 / 5 / 2.5:
// 290.35 / 287.51 / 286.13 (mode 1, near the beam estimates below),
// 1370.5 / 1352.7 / 1346.0, 1641.7 / 1622.8 / 1614.8, 3152.8 / 3134.2 /
// 3123.0, 4289.6 / 4211.3 / 4186.7; observed orders 1.04, 1.41, 1.26, 0.74,
// 1.67 (pre-asymptotic; the re-entrant edge where the blade meets the block
// limits the asymptotic order to about 1.09, see the test). Euler-Bernoulli
// cantilever of span 100: 250.65 Hz for the flat plate 40 x 3, 303.0 Hz for
// the cambered section (I = 132.4 instead of 90 mm^4). The FE model at
// element_size 5 gives 251.5 Hz flat and untwisted, 297.0 cambered and
// untwisted (camber +18 %), 251.0 flat and twisted (twist -0.2 %) and 287.5
// cambered and twisted (twist -3.2 % on the cambered blade).
//
// Valid ranges (check_gmsh_blade_spec): see each member.

#include <array>
#include <iosfwd>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rsi {

/// gmsh is missing, fails, or writes a mesh that is not what the deck needs.
class GmshError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct GmshBladeSpec {       // units: mm, t, s, N (like Rotor 37)
  double span = 100.0;       ///< blade height from the root block's top to the tip, (0, inf) [mm]
  double chord = 40.0;       ///< chord of the camber line, (0, inf) [mm]
  double thickness = 3.0;    ///< constant thickness of the section, (0, chord/2] [mm]
  double camber = 0.05;      ///< sagitta of the camber line / chord, [0, 0.25] [-]
  double twist = 30.0;       ///< twist from root to tip, [-90, 90] [deg]
  double stagger = 30.0;     ///< angle of the root chord from z towards y, [-90, 90] [deg]
  double root_length = 50.0; ///< along the root chord, > chord + thickness [mm]
  double root_width = 12.0;  ///< across the root chord, > camber chord + thickness [mm]
  double root_height = 20.0; ///< along x (radial), (0, inf) [mm]
  double element_size =
      10.0; ///< target size of the quadratic tetrahedra, [chord/100, max(span, chord)] [mm]
  double young_modulus = 210000.0; ///< E, (0, inf) [N/mm^2]
  double poisson_ratio = 0.3;      ///< nu, (-1, 0.5) [-]
  double density = 7.85e-9;        ///< rho, (0, inf) [t/mm^3]
  /// Radius of the root block's bottom (clamped) face, [0, inf) [mm]; the
  /// tip lies at root_radius + root_height + span.
  double root_radius = 150.0;
};

/// Number of contact nodes (NSET TIP) at any element size.
constexpr int n_tip_stations = 16;

/// The mesh size gmsh will make of a spec, estimated from the volume
/// before gmsh runs: the root block in regular tetrahedra of edge
/// element_size h (volume h^3 / (6 sqrt 2) each), the blade's plate in
/// h x h x min(h, thickness) ones (about one element across a plate thinner
/// than h), 2 nodes an element (second order), 3 dofs a node. Against the
/// measured table above (default geometry): 0.65 x the dofs at h = 10, 1.0
/// at h = 5, 1.91 at h = 1.8, 1.77 at h = 5/3: within a factor 2 over the table
/// (test_gmsh_blade_cache). Does not check the spec.
struct GmshBladeMeshEstimate {
  double elements = 0.0;
  double nodes = 0.0;
  double dofs = 0.0;
};
GmshBladeMeshEstimate gmsh_blade_mesh_estimate(const GmshBladeSpec& spec);

/// The largest estimated dof count check_gmsh_blade_spec accepts: just
/// above the estimate of the finest mesh measured (element_size 5/3:
/// 149,865 dofs, estimated 264,804; gmsh 1.5 s, ccx 7.8 s, 189 MB a matrix
/// file), so every mesh of the table passes and none far past it. The smallest
/// element_size of the range, chord / 100, would make about 19 million
/// dofs: minutes of gmsh before ccx runs out of memory.
constexpr double gmsh_blade_max_estimated_dofs = 300000.0;

/// Throws std::invalid_argument("GmshBladeSpec.FIELD: ... allowed range
/// ...") for the first field out of range or not finite, and
/// ("GmshBladeSpec.element_size: ...") when the estimated mesh
/// (gmsh_blade_mesh_estimate) exceeds gmsh_blade_max_estimated_dofs.
void check_gmsh_blade_spec(const GmshBladeSpec& spec);

/// The n_tip_stations contact points on the tip's camber line, in order of
/// increasing u [mm]. Checks the spec.
std::vector<Eigen::Vector3d> gmsh_blade_tip_stations(const GmshBladeSpec& spec);

/// Area [mm^2] of the section (annular sector 2 phi0 R thickness, phi0 the
/// half-angle of the camber arc; chord thickness when straight) and volume
/// [mm^3] of the model: root block + section area x span (every section is
/// the same, only turned). Checks the spec.
double gmsh_blade_section_area(const GmshBladeSpec& spec);
double gmsh_blade_volume(const GmshBladeSpec& spec);

/// The gmsh script (OpenCASCADE kernel) of the model, meshing options
/// included. Checks the spec.
std::string gmsh_blade_geo(const GmshBladeSpec& spec);

/// Lines another model adds to the blade's script (gmsh_bladed_disk.hpp):
/// `volumes`, after the root block (volume 2), makes more volumes, named by
/// the gmsh list `fused` (e.g. "ring()"), which the union fuses with blade
/// and block; `after_union` follows the union's check. Empty: the blade's
/// own script, byte for byte.
struct GmshGeoAddition {
  std::string volumes;
  std::string fused;
  std::string after_union;
};
std::string gmsh_blade_geo(const GmshBladeSpec& spec, const GmshGeoAddition& addition);

/// The mesh options every rsi gmsh script ends with: quadratic tetrahedra
/// with straight edges of at most `element_size` [mm], and gmsh 4.8's
/// defaults of the other options written out (a user's ~/.gmsh-options
/// cannot change the mesh).
std::string gmsh_mesh_options(double element_size);

/// Mesh as gmsh wrote it (Abaqus format): nodes by number, C3D10 elements.
struct GmshMesh {
  std::map<long, Eigen::Vector3d> nodes;
  std::vector<std::array<long, 11>> elements; ///< number, then 10 nodes
};

/// A checked mesh of a gmsh script, and how it was made (for messages).
struct GmshMeshOutcome {
  GmshMesh mesh;
  std::set<long> used; ///< the nodes the elements use
  std::vector<std::string> command;
  std::string where;
  /// GmshError("... the mesh of 'COMMAND' (in DIR, ...) WHAT").
  GmshError failure(const std::string& what) const;
};

/// Writes `geo_text` to DIR/STEM.geo, runs gmsh (DIR/STEM_gmsh.inp) and
/// reads and checks its C3D10 mesh: nodes present, corners positively
/// oriented, midside nodes the Abaqus edge midpoints to `tol` [mm]. Throws
/// GmshError (gmsh missing or failing, no element, a bad element) or
/// std::runtime_error (a file not written).
GmshMeshOutcome mesh_gmsh_script(const std::string& geo_text, const std::string& dir, double tol,
                                 const std::string& stem = "blade");

/// The mesh node at each of the n_tip_stations tip stations, in their
/// order; throws meshed.failure(...) naming a station with no node within
/// 1e-6 thickness of it.
std::vector<long> gmsh_blade_tip_nodes(const GmshBladeSpec& spec, const GmshMeshOutcome& meshed);

/// A number as the blade's deck writes it (%.15g).
std::string deck_number(double x);
/// Writes `text` to PATH through PATH.partial, renamed when complete (no
/// half-written deck under PATH); std::runtime_error("WHO: cannot ...").
void write_deck_file(const std::string& path, const std::string& text, const std::string& who);
/// *NODE, NSET=NALL with the coordinates in %.12e (19 characters at most,
/// of the 20 ccx reads of a field: a turned copy's rounding, e.g. -2.3e-13
/// for a 0, would take 21 in %.15g).
void write_deck_nodes(std::ostream& out, const std::map<long, Eigen::Vector3d>& nodes);
/// *ELEMENT, TYPE=C3D10, ELSET=EALL and the elements (number, 10 nodes).
void write_deck_c3d10(std::ostream& out, const std::vector<std::array<long, 11>>& elements);
/// An isotropic elastic material, its solid section on ELSET EALL and the
/// node set `clamped` held in ux, uy, uz: the lines every rsi gmsh deck
/// ends with.
std::string deck_material_lines(const std::string& material, double young_modulus,
                                double poisson_ratio, double density, const std::string& clamped);
/// *NSET, NSET=NAME and the numbers, 8 a line.
void write_deck_node_set(std::ostream& out, const std::string& name,
                         const std::vector<long>& nodes);

/// Everything blade.inp is made of, as text for a cache key: the gmsh
/// script (geometry, mesh options) and the deck's material, section and
/// clamping lines. Two specs with the same key give the same deck. Checks
/// the spec.
std::string gmsh_blade_cache_key(const GmshBladeSpec& spec);

/// Writes DIR/blade.geo, runs gmsh (second-order tetrahedra, C3D10) and
/// writes DIR/blade.inp: a self-contained CalculiX deck of the model only
/// (*NODE, *ELEMENT TYPE=C3D10 ELSET=EALL, *NSET ROOT and TIP, *MATERIAL,
/// *SOLID SECTION, *BOUNDARY ROOT 1-3), no *STEP. Creates DIR if needed.
/// Returns the deck path. Throws std::invalid_argument for a bad spec,
/// GmshError if gmsh is missing or fails (naming the command and its
/// output) or its mesh lacks a required part (elements, ROOT nodes, a tip
/// station), std::runtime_error if a file cannot be written.
std::string write_gmsh_blade_deck(const GmshBladeSpec& spec, const std::string& dir);

} // namespace rsi
