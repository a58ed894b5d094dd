#pragma once
// The one time loop of the full-order solver, for every kind of problem
// (problem.hpp): the structures' K and M side by side, one contact law
// behind StructureContact, central differences (central_difference.hpp)
//   M (u_{n+1} - 2 u_n + u_{n-1}) / dt^2 + C (u_{n+1} - u_{n-1}) / (2 dt) + K u_n = F_n + R_n,
// C = alpha M + beta K, from rest (u_0 = 0, u_{-1} = dt^2/2 A^-1 F_0), F_n
// the problem's force while t_n <= until (held, so a piecewise constant
// force costs nothing a step), R_n the contact force of the step.
//
// The loop owns no physics and no bookkeeping: each step's state (gaps,
// multipliers, the works, E on demand, the casing and tips when asked) goes
// to a RunMonitor, whose common part keeps the summary, the rows and the
// energy balance in its one form for every kind,
//   E_{n-1/2} - E_0 - W_ext - W_contact + W_damp = 0 (to round-off),
// (W_ext = 0 exactly for a kind without forcing: the same numbers as a
// balance without it), and whose KindMonitor adds the kind's tests (the
// paper's: paper_monitor.hpp; a component's on the rigid casing:
// rubbing_monitor.hpp).
//
// A failed contact solve (IntegrationError) propagates, or when the loop is
// told so it stops the run with the solver's message as the status (the
// rows before it already written).

#include <functional>

#include <Eigen/SparseCore>

#include "problem.hpp"
#include "liner_surface.hpp"
#include "run_monitor.hpp"
#include "structure_contact.hpp"

namespace rsi {

/// What the loop integrates (not owned: each must outlive the run).
struct FullOrderSystem {
  const Eigen::SparseMatrix<double>* stiffness = nullptr; ///< K of the whole system
  const Eigen::SparseMatrix<double>* mass = nullptr;      ///< M of the whole system
  double dt = 0.0;                                        ///< [s], > 0
  RayleighDamping damping;                                ///< alpha, beta >= 0
  const StructureContact* contact = nullptr;
  const ProblemForcing* forcing = nullptr; ///< nullptr or empty: unforced
  /// The flexible casing's dofs [first, first + count) for the monitor's
  /// first contact (count 0: none).
  int casing_first = 0;
  int casing_count = 0;
  /// The rows' tip displacements (RunOptions::tip_displacement): these
  /// system dofs, in the row's order (empty: none).
  std::vector<int> tip_dofs;
  /// A failed contact solve stops the run as its status (else it throws).
  bool failure_is_status = false;
  /// The abradable liner on the rigid law of `contact` (nullptr: none):
  /// the integrator's normal law (CentralDifference::attach_liner), E with
  /// the bars' elastic energy, W_contact the blade-and-liner work, and
  /// W_plastic in the balance and the rows. `source` names the case in the
  /// refusal of a mass the liner's solve cannot take (CaseError).
  LinerSurface* liner = nullptr;
  std::string source;
};

/// Runs `system` for the monitor's steps_requested steps from rest and
/// closes the monitor (RunMonitor::finish: the time loop's clock and the
/// wall clock since `start`). Fills `summary`'s flops_per_step and the
/// integrator's final works. Throws IntegrationError (unless
/// failure_is_status) and what the monitor or the options' checkpoint throws.
void drive_full_order(const FullOrderSystem& system, RunMonitor& monitor, RunSummary& summary,
                      Clock::time_point start);

/// Where a run departs from its problem's case (zero: the case's value).
struct RunPoint {
  /// Omega [rad/s] in place of the case's: the gap's phase, the casing's
  /// sliding and the period T (rsi sweep's speeds). Rigid casing only.
  double rotation_speed = 0.0;
  double revolutions = 0.0; ///< per_revolution: the run's length
  /// omega_max of the rotor's (K, M) when the caller has it [rad/s] (0:
  /// computed here, by Lanczos).
  double omega_max = 0.0;
};

/// The relative tolerance of a rubbing run's energy balance (rigid casing,
/// per_revolution), of its scale (docs/decisions.md, "Monitors"): the value
/// the component runs have been held to since they were written.
constexpr double rubbing_balance_tolerance = 1e-8;

/// The full-order run of any problem, by its step rule:
/// - fixed (the paper's kind): the stability checks of each structure
///   (check_time_step_bound, then check_time_step on the largest omega_max),
///   the paper's monitor, rows kept or streamed as RunOptions says;
/// - per_revolution (a component on the rigid casing): dt = T/(k N)
///   (ProblemSteps::steps_per_sample under 2/omega_max of the rotor), the
///   rubbing monitor, a row at t = 0 and every k x output_every steps with
///   the response dof as the row's one tip displacement; a failed contact
///   solve stops the run as its status; the clocks include the rows' output.
/// Throws StabilityError, IntegrationError or ModalError;
/// std::invalid_argument for a problem without contact, a RunPoint the
/// rule does not take, or more steps than a run counts.
RunResult run_full_order(const Problem& problem, const RunOptions& options,
                         const RunPoint& point = {});

} // namespace rsi
