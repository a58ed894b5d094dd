#pragma once
// A component case's contact run on the rigid casing (its "rubbing" object):
// the full-order reference (the one full-order loop on the case's problem,
// reference/solver/full_order_run) or a reduced model
// (reduced/component_integrator), each at its own stable step, sampled at
// the same times.
//
// Time steps. T = 2 pi / Omega, N = steps_per_revolution. Every run
// integrates at dt = T / (k N), k >= 1 the smallest integer with
// dt <= step_safety x 2/omega_max of the model integrated (the full model:
// Lanczos on (K, M); CB, CCM, Guyan: of (K^, M^); MacNeal: of its interior
// with the whole boundary held, the stiffest contact state, rubbing_run.cpp),
// and samples every k steps (times output_every): every method's
// rows fall at the same instants t = j T / N, so histories compare row by
// row with no interpolation.
//
// Multipliers in a row: the full run and the mass-carrying reduced runs
// (CB, CCM, Guyan) give lambda of the step that produced u_n (lambda_{n-1},
// forward increment); MacNeal's massless boundary gives lambda_n, in static
// balance with u_B^n (component_integrator.hpp). Both are the contact force
// at t_n to first order in dt.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "casing_basis.hpp"
#include "component_case.hpp"
#include "history.hpp"
#include "problem.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// A component case with its rubbing set-up, as the one loader describes it
/// (problem.hpp: component_problem), and the views the runs read.
struct RubbingModel {
  Problem problem; ///< the component kind, with contact (rigid_surface)
  const ComponentCase& component_case() const { return *problem.component_case; }
  const RubbingSetup& setup() const { return *problem.component_case->rubbing; }
  const Component& component() const { return problem.structures.front(); }
  /// Node ids, the casing's contact order.
  const std::vector<int>& contact_nodes() const { return problem.contact.contact_nodes; }
  int response_dof() const { return problem.outputs.response_dof; }
  /// "u_NODE_DIR", the history column.
  const std::string& response_name() const { return problem.outputs.response_name; }
};

/// The component and its rubbing set-up. Throws CaseError (no "rubbing"
/// object, a response or contact node that is not in the model) or
/// ImportError.
RubbingModel load_rubbing_model(const ComponentCase& c, const ComponentLoadOptions& load);

/// One history row with the response dof's displacement beside it.
using ComponentRowSink = std::function<void(const HistoryRow& row, double response)>;

struct RubbingRunOptions {
  std::string method = "full"; ///< full, cb, ccm, guyan, macneal, cc
  int modes = 0;
  /// cc: n_c, the characteristic constraint modes kept of the boundary
  /// (characteristic_constraint.hpp); 0 for the other methods.
  int boundary_modes = 0;
  double revolutions = 0.0;    ///< 0: the case's
  /// The case key `revolutions` comes from, named when the run's step count
  /// is refused (the campaign's full run: rubbing.campaign.full_revolutions).
  std::string revolutions_key = "rubbing.revolutions";
  bool force = false;          ///< integrate at or above the stable step
  /// Omega [rad/s] in place of rubbing.rotation_speed (0: the case's): the
  /// gap's phase, the sliding and the period T (rsi sweep's speeds).
  double rotation_speed = 0.0;
  /// Against the flexible casing: its modes kept in place of
  /// rubbing.casing.modes (0: the case's).
  int casing_modes = 0;
  /// A reduced method's basis built once for several runs (rsi sweep's
  /// speeds share it: the rotation enters only through the contact); it
  /// must be reduce()'s of this model, method and modes. nullptr: built here.
  const ReducedBasis* basis = nullptr;
  /// Against the flexible casing, a reduced run's casing basis built once
  /// for several runs (rsi sweep's speeds): rubbing_casing_basis() of this
  /// model and casing_modes. nullptr: built here.
  const CasingBasis* casing_basis = nullptr;
  std::function<void()> checkpoint;
  std::function<void(double)> progress;
};

struct RubbingRun {
  RunSummary summary;
  int steps_per_sample = 1; ///< k of the header
  int reduced_size = 0;     ///< r of a reduced model (0: full)
  double step_limit = 0.0;  ///< the limit the step was chosen under [s] (MacNeal: boundary held)
  double first_mode_hz = 0.0; ///< CCM, MacNeal: the lowest kept free-interface mode (0: none)
  /// A full run with an abradable liner: RunResult's wear, n_theta, n_axial.
  std::vector<double> wear;
  int wear_n_theta = 0;
  int wear_n_axial = 0;
};

/// A reduced run's flexible casing: its `modes` lowest modes (0: the case's
/// rubbing.casing.modes) plus the static correction for its load. Throws
/// CaseError naming the count's key (or --casing-modes) when it is not
/// below the casing's dofs.
CasingBasis rubbing_casing_basis(const RubbingModel& model, int modes);

/// The most steps a run counts (RunSummary's int), and the largest
/// history.csv a run may write [bytes] (as the paper's case, about 24
/// bytes a number).
constexpr std::int64_t max_rubbing_steps = 2147483647;
constexpr double max_rubbing_history_bytes = 100e9;

/// Runs and streams every row (t, the response dof, gaps, multipliers,
/// energy, works) to `sink`, reduced runs as full ones: no row is kept.
/// Before the first step, in 64-bit arithmetic: the samples (revolutions x
/// steps_per_revolution) times the steps a sample (k of the header) must be
/// at most max_rubbing_steps, and the history at most
/// max_rubbing_history_bytes, else CaseError naming the keys (exit 2).
/// Throws ReductionError (bad mode count) and std::invalid_argument (a bad
/// method).
RubbingRun run_rubbing(const RubbingModel& model, const RubbingRunOptions& options,
                       const ComponentRowSink& sink);

} // namespace rsi
