#pragma once
// A problem, whatever the kind of its case file (SPEC §9): the structures,
// how they meet, the casing, the forcing, the damping, the friction law, the
// step rule and the outputs. One loader (load_problem) reads either kind of
// case through the existing readers (load_case; parse_component_case and
// load_component) and hands every solver the same description.
//
// The system a solver integrates is the structures side by side: the dofs
// of structure s are offset(s) .. offset(s) + n_s - 1, and
//   K = diag(K_0, K_1, ...),  M = diag(M_0, M_1, ...)
// (the structures share no dof: they interact only through contact).
//
// The kinds today:
// - paper (SPEC §2): structure 0 the bladed disk (boundary: the tips'
//   u, v), structure 1 the flexible casing ring; they meet through the 2D
//   tip/ring law (contact: tip_ring) with the case's friction law
//   (sliding_sign or Coulomb); radial forcing F0 cos(ND theta_j) on the
//   casing nodes while t <= forcing.duration; Rayleigh damping of both; a
//   fixed step time.step, a history row every output_every steps.
// - component (SPEC §8): one structure (a CalculiX deck, a Matrix Market
//   folder or the gmsh blade) on a rigid casing with an imposed gap g0(theta),
//   theta = Omega t + phi (constant or oval); they meet through the 3D
//   node-to-rigid-surface law (contact: rigid_surface, Coulomb) at the
//   contact nodes; no forcing; the step T/(k N), T = 2 pi/|Omega|, N samples
//   a revolution and k the smallest integer under step_safety x 2/omega_max;
//   a row every output_every samples with the response dof beside it. A
//   component case without "rubbing" has its structure and no contact.
//   With component.rotation_effects the structure is K(Omega) at the
//   case's speed and the gaps close by the contact nodes' static growth
//   (ProblemCasing::tip_growth).
//   With rubbing.casing the casing is flexible instead: structure 1 the
//   gmsh ring (gmsh_casing.hpp), its contact surface read from its deck;
//   they meet through the 3D tip/solid-casing law (contact: solid_casing,
//   Coulomb); the step from the larger omega_max of the two.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "casing.hpp"
#include "casing_surface.hpp"
#include "component.hpp"
#include "component_case.hpp"

namespace rsi {

enum class ProblemKind { paper, component };

/// Which law makes the structures meet (reference/contact builds it).
enum class ContactKind {
  none,         ///< no contact (a component case without "rubbing")
  tip_ring,     ///< 2D blade tips against the flexible ring (tip_casing_contact, tip_ring_frictional_contact)
  rigid_surface, ///< 3D nodes against the rigid casing (rigid_surface_contact)
  solid_casing   ///< 3D nodes against the flexible solid casing (solid_casing_contact)
};

/// How the structures meet.
struct ProblemContact {
  ContactKind kind = ContactKind::none;
  FrictionLaw friction_law = FrictionLaw::coulomb; ///< rigid_surface: always Coulomb
  double friction_coefficient = 0.0;               ///< mu >= 0
  /// Omega [rad/s]: the gap's phase theta = Omega t + phi (signed; paper: > 0
  /// counter-clockwise).
  double rotation_speed = 0.0;
  /// Omega_s [rad/s]: how fast the casing slides past a tip (Omega with the
  /// rotation, -Omega against it: RubbingSetup::sliding_speed).
  double sliding_speed = 0.0;
  /// The casing slides against the rotation (Omega_s = -Omega).
  bool sliding_against_rotation = false;
  /// The system dofs the law reads on the rotor side (paper: the tips' u, v;
  /// component: the contact nodes' ux, uy, uz), in contact order.
  std::vector<int> rotor_dofs;
  /// component: the contact nodes' ids, in contact order (empty for the paper).
  std::vector<int> contact_nodes;
  int n_contacts() const;
  /// Omega_s at rotation speed `omega` (a run at another speed than the
  /// case's: rsi sweep), with or against the rotation as the case says.
  double sliding_speed_at(double omega) const { return sliding_against_rotation ? -omega : omega; }
};

/// The casing: rigid with an imposed gap, or a flexible structure.
/// The abradable liner on the rigid casing (rubbing.liner; the law is
/// reference/contact/abradable_liner.hpp). The unworn surface's radius is
/// the largest radius of the contact nodes about the rotation axis (their
/// gap is measured to that surface; it sets the cells' area r dtheta dz);
/// the axial extent is the case's, or the contact nodes' axial coordinates
/// (a . X) widened by 5 % of their span on each side (by the thickness when
/// they all lie at one axial coordinate).
struct ProblemLiner {
  double radius = 0.0;    ///< r > h [length]
  double thickness = 0.0; ///< h [length]
  double young = 0.0;     ///< E [stress]
  double yield = 0.0;     ///< sigma_y [stress]
  double hardening = 0.0; ///< H [stress]
  int n_theta = 1;
  int n_axial = 1;
  double z_min = 0.0;
  double z_max = 0.0;
  /// The tip patch of every contact node (liner_patch.hpp): its widths
  /// around the casing and along the axis [length]; both 0: no patch, a
  /// node presses the one cell under it.
  double patch_circumferential = 0.0;
  double patch_axial = 0.0;
};

struct ProblemCasing {
  bool rigid = false;
  int structure = -1;      ///< flexible: its index in Problem::structures
  bool oval_gap = false;   ///< rigid: oval g0 = g_m (1 - ...) or constant g0
  double gap = 0.0;        ///< rigid: g_m (oval) or g0 (constant) [length]
  double gap_width = 0.0;  ///< rigid oval: w in (0, 1)
  double clearance = 0.0;  ///< flexible: R_c - R_t at rest [m]
  /// rigid, with rotation effects: each contact node's static radial growth
  /// at the problem's speed (rotating_component.hpp), subtracted from its
  /// imposed gap (the dynamic displacement is measured from the deflected
  /// state); empty: none.
  std::vector<double> tip_growth;
  /// rigid: the abradable liner on it (absent: the rigid, unworn surface).
  std::optional<ProblemLiner> liner;
  /// flexible 3D (solid_casing): its contact surface (casing_surface.hpp).
  std::optional<CasingSurface> surface;
};

/// The external force on the system dofs: F while t <= until (plus 1e-6 dt,
/// forcing_active in casing_forcing.hpp), zero after. Empty `force`: none.
struct ProblemForcing {
  Eigen::VectorXd force;
  double until = 0.0; ///< [s]
  bool any() const { return force.size() > 0; }
};

/// The step rule of the full-order run.
struct ProblemSteps {
  enum class Rule {
    fixed,         ///< paper: dt = time.step, steps = round(duration / dt)
    per_revolution ///< component: dt = T / (k N), k from step_safety x 2/omega_max
  };
  Rule rule = Rule::fixed;
  double step = 0.0;            ///< fixed: dt [s]
  double duration = 0.0;        ///< fixed: simulated time [s]
  double revolutions = 0.0;     ///< per_revolution: the run's length
  int steps_per_revolution = 0; ///< per_revolution: N, the samples a revolution
  double step_safety = 0.0;     ///< per_revolution: in (0, 1)
  /// Steps of the fixed rule (round(duration / step)); 0 for per_revolution,
  /// whose count needs omega_max.
  long fixed_steps() const;
  // per_revolution, in double (a caller checks the counts before an integer
  // holds them; every method's runs sample at the same instants j T / N):
  /// The samples of `revolutions`: max(1, round(revolutions N)).
  double samples(double revolutions) const;
  /// T / N at rotation speed `omega` [s], T = 2 pi / |omega|.
  double sample_step(double omega) const;
  /// k, the steps a sample: the smallest integer >= 1 with
  /// sample_dt / k <= step_safety x critical_dt (the model's 2/omega_max).
  double steps_per_sample(double sample_dt, double critical_dt) const;
};

/// What a run writes beside the solver's state.
struct ProblemOutputs {
  int output_every = 1;      ///< a history row every this many steps (paper) or samples (component)
  int response_dof = -1;     ///< component: the system dof of rubbing.response (-1: none)
  std::string response_name; ///< its history column, "u_NODE_DIR"
};

/// The 2D parts as the tip/ring laws read them (their geometry and the case).
struct PaperParts {
  Case case_file;
  BladedDisk bladed_disk;
  Casing casing;
};

struct Problem {
  ProblemKind kind = ProblemKind::paper;
  std::string source; ///< the case file, for messages
  /// Rotor first (the bladed disk, or the component), then a flexible casing.
  std::vector<Component> structures;
  ProblemContact contact;
  ProblemCasing casing;
  ProblemForcing forcing;
  Damping damping;
  ProblemSteps steps;
  ProblemOutputs outputs;
  std::optional<PaperParts> paper;              ///< the paper's kind only
  std::optional<ComponentCase> component_case;  ///< the component kind only

  int n_dofs() const;
  int offset(int structure) const; ///< first system dof of a structure
  /// K and M of the whole system (block diagonal over the structures).
  Eigen::SparseMatrix<double> stiffness() const;
  Eigen::SparseMatrix<double> mass() const;
};

/// The problem of the paper's case `c` (the parts assembled).
Problem paper_problem(const Case& c);

/// The problem of a component case: the component loaded (ccx run or cached,
/// folder read, gmsh meshed), its rubbing set-up resolved (rubbing_points.hpp).
/// Throws CaseError or ImportError as load_component and resolve_rubbing_points.
Problem component_problem(const ComponentCase& c, const ComponentLoadOptions& load);

/// Any case file: read_case_document, then the paper's or the component's
/// reader by its keys. Throws CaseError (file, key, range) or ImportError.
Problem load_problem(const std::string& path, const ComponentLoadOptions& load = {});

} // namespace rsi
