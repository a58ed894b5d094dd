#pragma once
// The case file of a component (SPEC §8; schema in data/README.md): which
// model (a CalculiX deck, a Matrix Market folder in `rsi export`'s layout,
// or the project's gmsh blade), its boundary node set, its units and
// rotation axis, and optionally the modal convergence campaign. Relative
// paths are read against the case file's folder.
//
//   {"component": {"name": "rotor37",
//                  "source": {"calculix_deck": "../../../shared/external/rotor37/blade.inp"},
//                  (optionally with "calculix_matrices": "dir/JOB", the prefix of
//                   JOB.sti/.mas/.dof a ccx run of the deck wrote; or instead
//                   {"matrix_market": "folder"}, or {"gmsh_blade": {parameters}}: the
//                   project's blade (gmsh_blade.hpp), meshed by gmsh into the ccx cache,
//                   boundary by default its node set TIP; or {"gmsh_bladed_disk":
//                   {"sectors": N, ..., "blade": {parameters}}}: N such blades on a disk
//                   (gmsh_bladed_disk.hpp), boundary by default every blade's TIP; or
//                   {"gmsh_casing": {parameters}}: the flexible ring (gmsh_casing.hpp),
//                   boundary by default its inner face, node set INNER)
//                  "boundary": {"nodes": [188, 190, ...]},
//                  "units": "N, mm, t, s", "rotation_axis": [0, 0, 1]},
//    "modal_campaign": {"methods": ["cb", "ccm", "macneal"], "modes": [10, 20, 50],
//                       "frequencies": 20},
//    "rubbing": {...}, "damping": {...}}
// "component.mass": "consistent" (absent) or "lumped" (HRZ, mass_lumping.hpp:
// for explicit full-order runs of a model whose consistent mass is singular;
// every command then uses the lumped mass). "rubbing" (optional) is the
// contact run of `rsi simulate` and `rsi campaign` on the component: the
// rigid casing of reference/contact/rigid_surface_contact.hpp over the
// contact nodes (absent: the boundary's nodes), its gap, friction and
// speed, the length of the run in revolutions and the sampling, the
// response dof, and the reduced runs of the campaign (data/README.md).
// "damping" as in the paper's case: Rayleigh for the full model, a modal
// ratio on the kept modes of a reduced one.
//
// A rejected file raises CaseError naming the file and the key (exit 2).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "calculix_deck.hpp"
#include "case_file.hpp"
#include "component.hpp"
#include "gmsh_blade.hpp"
#include "gmsh_bladed_disk.hpp"
#include "casing_surface.hpp"
#include "gmsh_casing.hpp"

namespace rsi {

enum class ComponentSource {
  calculix_deck,
  matrix_market,
  gmsh_blade,
  gmsh_bladed_disk,
  gmsh_casing,
  calculix_sector ///< one sector's deck, assembled into N (sector_assembly.hpp)
};

struct ModalCampaign {
  std::vector<std::string> methods; ///< "cb", "ccm", "macneal"
  std::vector<int> modes;           ///< mode counts, ascending
  int frequencies = 20;             ///< lowest reduced frequencies compared
};

/// One method of the rubbing campaign and its mode counts.
struct RubbingRuns {
  std::string method; ///< "cb", "ccm", "macneal" or "cc"
  /// The mode counts; for "cc" the characteristic constraint modes n_c
  /// (the boundary's), its fixed-interface modes being fixed_interface_modes.
  std::vector<int> modes;
  int fixed_interface_modes = 0; ///< "cc": eta, the Craig-Bampton modes kept
};

/// The "rubbing" object: a contact run on the rigid casing (issue 12).
/// The optional abradable liner of the rigid casing (SPEC §9,
/// reference/contact/abradable_liner.hpp): its bars' material and the cells.
struct LinerSetup {
  double thickness = 0.0;         ///< h > 0 [length]
  double young_modulus = 0.0;     ///< E > 0 [stress]
  double yield_stress = 0.0;      ///< sigma_y > 0 [stress]
  double hardening_modulus = 0.0; ///< H >= 0 [stress]
  int cells_around = 0;           ///< n_theta >= 1
  int rows = 1;                   ///< axial rows >= 1
  /// z_min < z_max along the rotation axis; absent: the contact nodes'
  /// axial extent widened by a margin (problem.cpp).
  bool axial_extent = false;
  double z_min = 0.0;
  double z_max = 0.0;
  /// The tip patch a contact node stands for (rubbing.liner.tip_patch):
  /// its widths around the casing and along the axis, both > 0 [length];
  /// 0: absent, a node presses the one cell under it.
  double patch_circumferential = 0.0;
  double patch_axial = 0.0;
};

struct RubbingSetup {
  std::vector<int> contact_nodes;   ///< empty: the boundary's nodes, in boundary order
  bool oval_gap = true;             ///< oval (g_m, width) or constant (gap)
  double gap = 0.0;                 ///< oval: g_m > 0; constant: g0 [length]
  double gap_width = 0.15;          ///< oval: w in (0, 1)
  double friction_coefficient = 0.0;
  /// Omega [rad/s], signed about rotation_axis: > 0 counter-clockwise,
  /// < 0 clockwise; never 0. The gap phase is theta = Omega t + phi.
  double rotation_speed = 0.0;
  /// How the tip slides over the casing: with the rotation (the casing
  /// moves at -r Omega e_t2 past a tip at rest, the physical case), or
  /// against it (NLstep's PLAUSIBLE set-up: the tip moves at -r Omega e_t2
  /// relative to the casing while its gap phase is Omega t + phi; see
  /// shared/external/rotor37/README.md).
  bool sliding_against_rotation = false;
  /// Omega_s, the casing's sliding speed past the tip (-r Omega_s e_t2):
  /// Omega with the rotation, -Omega against it.
  double sliding_speed() const { return sliding_against_rotation ? -rotation_speed : rotation_speed; }
  double revolutions = 0.0;         ///< length of a run, > 0
  int steps_per_revolution = 0;     ///< N: samples a revolution (MacNeal's step T/N)
  int output_every = 1;             ///< a history row every this many samples
  int response_node = 0;            ///< node id of the response dof
  int response_direction = 0;       ///< 1..3
  double step_safety = 0.9;         ///< mass-carrying runs: dt <= safety 2/omega_max, in (0, 1)
  std::vector<RubbingRuns> campaign; ///< reduced runs of `rsi campaign`
  double full_revolutions = 0.0;    ///< the campaign's full reference window (0: none)
  std::optional<LinerSetup> liner;  ///< absent: the rigid, unworn casing
  /// With component.rotation_effects: the speed [rad/s] at which the gap
  /// above is the clearance (the casing and tips ground hot there): a node's
  /// gap closes by growth(Omega) - growth(clearance_speed). 0: the clearance
  /// at rest (cold), the whole growth closes it.
  double clearance_speed = 0.0;
  /// "casing": the flexible 3D casing the tips meet (issue 27), in place
  /// of the rigid casing's "gap": the ring of gmsh_casing.hpp and the name
  /// of its contact surface (an element surface of its deck). Absent: the
  /// rigid casing.
  std::optional<GmshCasingSpec> casing;
  std::string casing_surface = "SINNER";
  /// "casing.modes": the reduced runs keep the casing in its lowest this
  /// many modes plus a static correction for its load
  /// (reduced/casing_basis.hpp), [1, 100000], fewer than its dofs.
  int casing_modes = 30;
  /// "casing.forcing": the paper's load on the flexible casing
  /// (casing_pressure.hpp): p0 cos(n theta) e_r on its contact surface
  /// while t <= duration. Absent: none.
  struct CasingForcing {
    double pressure = 0.0;    ///< p0 [force/length^2], finite, nonzero
    int nodal_diameters = 2;  ///< n, [0, 1000]
    double duration = 2e-4;   ///< [s], > 0
  };
  std::optional<CasingForcing> casing_forcing;
};

/// One run of a component sweep: "full" (modes 0) or a reduced method and
/// its mode count.
struct ComponentSweepRun {
  std::string method; ///< "full", "cb", "ccm", "guyan", "macneal" or "cc"
  int modes = 0;      ///< cc: n_c, the boundary's characteristic constraint modes
  int fixed_interface_modes = 0; ///< cc only: eta, the Craig-Bampton basis's modes under them
  int entry = -1; ///< its entry's index in sweep.runs (-1: given by rsi sweep's --method)
};

/// The optional "sweep" object of a component case (`rsi sweep`): the
/// rubbing run at each rotation speed, over `revolutions`, its indicators
/// over t >= transient_revolutions x 2 pi / |Omega|.
struct ComponentSweep {
  std::vector<double> speeds; ///< Omega [rad/s]: nonzero, one sign, |Omega| < 1e5
  double revolutions = 0.0;   ///< each run's length, > 0 (absent: rubbing.revolutions)
  double transient_revolutions = 0.0; ///< in [0, revolutions)
  std::vector<ComponentSweepRun> runs; ///< one a (method, mode count), in the file's order
  /// With component.rotation_effects: the 6 speeds K(Omega) is fitted at
  /// (rotation_fit.hpp), ascending, > 0; empty: 0.1, 0.2, 0.4, 0.6, 0.8, 1
  /// times the sweep's largest |Omega|.
  std::vector<double> rotation_fit_speeds;
  bool present() const { return !speeds.empty(); }
};

struct ComponentCase {
  std::string case_path;
  std::string name;
  ComponentSource source = ComponentSource::calculix_deck;
  std::string source_path;                 ///< resolved against the case file's folder
  /// calculix_deck only: JOB prefix of .sti/.mas/.dof already written by
  /// ccx (then ccx is not run); empty: rsi runs ccx into its cache.
  std::string calculix_matrices;
  std::vector<int> boundary_nodes;         ///< explicit ids, or
  std::string boundary_node_set;           ///< an *NSET of the deck (upper case)
  bool boundary_from_dofs = false;         ///< matrix_market: dofs.csv's flags
  GmshBladeSpec gmsh_blade;                ///< gmsh_blade: the blade's parameters
  GmshBladedDiskSpec gmsh_bladed_disk;     ///< gmsh_bladed_disk: the disk's and its blade's
  GmshCasingSpec gmsh_casing;              ///< gmsh_casing: the ring's parameters
  /// calculix_sector: source_path is the sector's deck; its N copies about
  /// rotation_axis; the node sets of its faces at -alpha/2 and +alpha/2.
  int sectors = 0;
  std::string sector_left;
  std::string sector_right;
  std::string units;
  Eigen::Vector3d rotation_axis = Eigen::Vector3d::UnitZ();
  std::optional<ModalCampaign> modal_campaign;
  bool lumped_mass = false;            ///< "component.mass": "lumped" (HRZ)
  /// "component.rotation_effects": a contact run at speed Omega uses the
  /// blade's K(Omega) and its static centrifugal growth in the gap
  /// (rotating_component.hpp); false: the blade at rest at every speed.
  bool rotation_effects = false;
  /// "component.cyclic_bases" (a gmsh_bladed_disk or calculix_sector
  /// source): its CB, CC, Guyan, CCM and MacNeal bases from one sector's
  /// constraint modes, turned to the others (Component::cyclic_bases);
  /// false: each solved.
  bool cyclic_bases = false;
  std::optional<RubbingSetup> rubbing;
  ComponentSweep sweep; ///< empty (no speeds) when the file has no "sweep"
  Damping damping;
};

/// True if the JSON document is a component case (has a "component" key).
bool is_component_case(const nlohmann::json& document);

ComponentCase parse_component_case(const nlohmann::json& document, const std::string& path);

/// Where a component's model comes from at run time: `source_override`
/// replaces the case's source path (the CLI's --source), `ccx_cache` is the
/// folder of ccx's cached runs.
struct ComponentLoadOptions {
  std::string source_override;
  std::string ccx_cache = "out/ccx-cache";
  /// How messages name the two inputs above: the caller's names for them
  /// (the CLI's options); empty, "the source override" and "the ccx cache".
  std::string source_name = {};
  std::string ccx_cache_name = {};
  const std::string& source_named() const;
  const std::string& ccx_cache_named() const;
};

/// The CalculiX deck of a component (its `calculix_deck`, the override, or
/// the gmsh blade meshed into the cache) and its boundary nodes, checked
/// against the deck. Throws CaseError for a Matrix Market component,
/// ImportError as load_component does.
struct ComponentDeck {
  std::string source;        ///< the deck's path
  CalculixDeck deck;
  std::vector<int> boundary; ///< node ids
};
ComponentDeck component_deck(const ComponentCase& c, const ComponentLoadOptions& options);

/// Builds the component: runs ccx (cached) on a deck, or reads a folder.
/// Throws ImportError (bad files, missing ccx) or CaseError.
Component load_component(const ComponentCase& c, const ComponentLoadOptions& options);

/// The flexible casing of rubbing.casing (issue 27): the gmsh ring's
/// component (ccx's K and M, the mass lumped as the rotor's) and its contact
/// surface (casing_surface.hpp). Messages name the keys under
/// rubbing.casing; a source override (--source) is the rotor's, not the
/// casing's. `c` must have rubbing.casing (std::invalid_argument otherwise).
struct FlexibleCasing {
  Component component;
  CasingSurface surface;
};
FlexibleCasing load_flexible_casing(const ComponentCase& c, const ComponentLoadOptions& options);

} // namespace rsi
