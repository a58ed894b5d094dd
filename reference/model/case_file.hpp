#pragma once
// The case file: every parameter of the model and the run (SPEC §2), read
// from JSON and validated. The schema is documented in data/README.md.
//
// Units are SI throughout; angles in the file are in degrees and are
// converted to radians here. A rejected file raises CaseError whose message
// names the file, the key (dotted path) and the allowed range.

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "failure_kinds.hpp"

namespace rsi {

/// Bad input in a case file: unknown, missing, mistyped or out-of-range key.
class CaseError : public BadInput {
public:
  using BadInput::BadInput;
};

/// Rectangular beam section: `width` out of plane, `thickness` in plane [m].
struct Section {
  double width = 0.0;
  double thickness = 0.0;
};

/// Linear elastic isotropic material.
struct Material {
  double young_modulus = 0.0; ///< E [Pa]
  double density = 0.0;       ///< rho [kg/m^3]
};

/// Bladed disk of SPEC §2: n_blades identical sectors, one disk element from
/// hub to rim, n_blade_elements kinked blade elements from rim to tip.
struct BladedDiskSpec {
  int n_blades = 0;
  double hub_radius = 0.0; ///< r_h [m]
  double rim_radius = 0.0; ///< r_r [m]
  double tip_radius = 0.0; ///< R_t [m], radius of every undeformed tip node
  int n_blade_elements = 0;
  double kink_angle = 0.0; ///< a [rad]; > 0 turns the blade clockwise (tip trails)
  Section blade;
  Section disk;
  Section rim_ring;
};

/// Casing ring of curved beam elements, clamped at one node.
struct CasingSpec {
  double radius = 0.0; ///< R_c [m]
  int n_elements = 0;
  Section section;
  double clamp_angle = 0.0; ///< polar angle of the clamped node [rad]
};

/// How friction acts at a closed contact (SPEC §3, §8).
enum class FrictionLaw {
  /// The first version's law: always sliding, mu lambda along the sign of
  /// the predicted sliding velocity (chatters near zero sliding speed).
  sliding_sign,
  /// Coulomb with stick and slip on the forward increment of the step.
  coulomb
};

struct OperatingPoint {
  double rotation_speed = 0.0;       ///< Omega [rad/s], counter-clockwise
  double friction_coefficient = 0.0; ///< mu [-]
  /// "friction_law": "coulomb" (also when absent: stick and slip) or
  /// "sliding_sign" (the first version's law, kept by name for the paper's
  /// comparison; it chatters where the sliding speed vanishes).
  FrictionLaw friction_law = FrictionLaw::coulomb;
};

/// Radial nodal forces amplitude * cos(nodal_diameter * theta_j) on every
/// casing node j for 0 <= t <= duration.
struct Forcing {
  double amplitude = 0.0; ///< F0 [N]
  int nodal_diameter = 0;
  double duration = 0.0; ///< [s]
};

struct TimeStepping {
  double step = 0.0;     ///< Delta t [s]
  double duration = 0.0; ///< simulated time [s]
  int output_every = 0;  ///< one history row every this many steps
};

/// Rayleigh damping C = alpha M + beta K: the full models, and the casing
/// of reduced runs (SPEC §8). Modal ratio of mode i: alpha/(2 omega_i) +
/// beta omega_i / 2.
struct RayleighDamping {
  double alpha = 0.0; ///< [1/s], >= 0
  double beta = 0.0;  ///< [s], >= 0
  bool any() const { return alpha != 0.0 || beta != 0.0; }
};

/// The optional "damping" object of the case file; absent = all zero
/// (undamped, the first round's behaviour bit for bit).
struct Damping {
  RayleighDamping rayleigh;
  /// zeta of every kept mode of a reduced bladed disk (fixed-interface for
  /// CB, free-interface for CCM), none on its boundary coordinates; in [0, 1).
  double modal_ratio = 0.0;
  /// Reduced runs of the paper's case: the bladed disk gets
  /// C^ = T^T (alpha M + beta K) T = alpha M^ + beta K^, the Galerkin
  /// projection of the full model's Rayleigh damping, in place of modal
  /// ratios: full and reduced runs then carry the same damping, and their
  /// difference is the reduction's alone. Exclusive with modal_ratio.
  bool projected_rayleigh = false;
};

/// The time step of a run (issue 14). Every rule gives dt = I / k, I =
/// time.step * time.output_every the case's output interval and k >= 1 an
/// integer, so a run's history rows fall on the reference's output times
/// (no interpolation) and e2, e_inf compare row by row.
struct StepRule {
  enum class Kind {
    case_step, ///< time.step (k = output_every): the first round's runs
    own,       ///< the run's own stable step: k smallest with I / k <= safety * 2 / omega_max
    given      ///< an explicit dt that divides I (k = I / dt an integer)
  };
  Kind kind = Kind::case_step;
  double safety = 0.9; ///< own: in (0, 1)
  double step = 0.0;   ///< given: dt [s]
  /// "case", "own" or the step in seconds, for run names and summaries.
  std::string name() const;
};

/// One reduced run of the campaign (SPEC §4 V6): a method and a mode count,
/// with the axes of issue 14 (mode selection, casing basis, time step).
struct CampaignRun {
  std::string method; ///< "cb", "ccm" or "guyan" ("full" in a sweep's runs)
  int modes = 0;
  std::string selection = "lowest"; ///< mode_selection.hpp; "lowest" is the first round's
  int casing_modes = 0;             ///< 0: the full casing; N_c: casing_basis.hpp
  StepRule step;
  /// "cb-64" for the first round's runs; the issue-14 axes append
  /// "-<selection>" (not lowest), "-c<N_c>" (modal casing) and "-dt-own" or
  /// "-dt-<step>" (not the case's step): "cb-64-families-c20-dt-own". The
  /// campaign's runs/ directory and the thresholds' key ("full-0" for the
  /// campaign's reference).
  std::string name() const;
};

/// The optional "sweep" object (issue 15): the runs of `rsi sweep` over
/// rotation speeds. Each run is the case at one Omega, over `duration`, with
/// `damping` in place of the case's; its indicators are taken over the
/// history rows at t >= transient.
struct SweepSpec {
  std::vector<double> speeds; ///< Omega [rad/s], in the order given (a range: ascending)
  double duration = 0.0;      ///< each run's simulated time [s]
  double transient = 0.0;     ///< the indicators read t >= transient [s]
  Damping damping;            ///< replaces the case's damping in the sweep's runs
  /// "full" (method "full") and reduced runs, as campaign entries.
  std::vector<CampaignRun> runs;
  bool present() const { return !speeds.empty(); }
};

struct Case {
  std::string source; ///< where the case was read from, for messages
  Material material;
  BladedDiskSpec bladed_disk;
  CasingSpec casing;
  OperatingPoint operating_point;
  Forcing forcing;
  TimeStepping time;
  Damping damping;
  std::vector<CampaignRun> campaign; ///< empty when the file has no campaign
  SweepSpec sweep;                   ///< empty (no speeds) when the file has no sweep
};

/// Validates `document` against the schema of data/README.md.
/// Throws CaseError naming `source`, the key and the allowed range.
Case parse_case(const nlohmann::json& document, const std::string& source);

/// Parses `text` as JSON and validates it (parse_case). Throws CaseError
/// naming `source` for malformed JSON and every schema violation; no other
/// exception escapes for any text (checked by fuzz/fuzz_case_loader.cpp).
Case parse_case_text(const std::string& text, const std::string& source);

/// The JSON document of a case file of either kind (the paper's case or a
/// component case), parsed by case_json::parse_document. Throws CaseError
/// for a missing or unreadable file, malformed JSON, a repeated key or
/// too deep a nesting.
nlohmann::json read_case_document(const std::string& path);

/// Reads and validates a case file (parse_case_text on its contents). Throws
/// CaseError for a missing or unreadable file, malformed JSON and every
/// schema violation.
Case load_case(const std::string& path);

} // namespace rsi
