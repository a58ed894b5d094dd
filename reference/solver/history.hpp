#pragma once
// What a contact run produces (SPEC §5): the sampled history of the blade
// tip gaps and multipliers with the energy terms, and the run's summary.
// Both solvers (reference/ and reduced/) fill these same records, either
// kept whole in memory (History) or handed out row by row as they are
// produced (HistorySink), so that a long run's memory does not grow with
// its length.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "failure_kinds.hpp"

namespace rsi {

/// Contact monitors of one step, at the corrected u_{n+1} (SPEC §3, V5).
struct StepReport {
  int n_active = 0;
  double max_penetration = 0.0;       ///< max(0, -g_k) [m]
  double min_lambda = 0.0;            ///< min lambda_k over all constraints [N]
  double max_complementarity = 0.0;   ///< max |lambda_k g_k| [N m]
  double max_friction_residual = 0.0; ///< max | f_t + mu lambda sign(v_slide) | [N]
  int sliding_reversals = 0;          ///< active constraints whose sliding changed sign
  // Coulomb stick/slip (friction_law "coulomb"): the certificate of the
  // step's frictional contact problem (reference/contact/frictional_contact_problem,
  // reduced/reduced_coulomb_certificate).
  double max_cone_violation = 0.0;      ///< max(|lambda_t| - mu lambda_n, 0) [N]
  double max_stick_slip_residual = 0.0; ///< stick: slip increment; slip: lambda_t against -mu lambda_n s^ (scaled, -)
  int stick_slip_transitions = 0;       ///< contacts whose state (open, stick, slip) changed since the last step
  int n_stick = 0;                      ///< contacts sticking after the step
  int n_slip = 0;                       ///< contacts slipping after the step
};

/// One history row as the run produces it. The vectors are views of the
/// solver's state (not owned): valid only during the call that receives the
/// row; copy what must outlive it.
struct HistoryRow {
  double time = 0.0;             ///< t_n [s]
  const Eigen::VectorXd& gap;    ///< g_k at u_n, blades 1..N [m]
  const Eigen::VectorXd& lambda; ///< lambda_k of the step that produced u_n [N]
  double energy = 0.0;           ///< discrete energy E_{n-1/2} [J]
  double external_work = 0.0;    ///< W_ext up to step n-1 [J]
  double contact_work = 0.0;     ///< W_contact up to step n-1 [J]
  double damping_work = 0.0;     ///< W_damp up to step n-1, >= 0 [J] (0 undamped)
  /// Coulomb law only (friction_law "coulomb"): the tangential multipliers
  /// lambda_t of the step that produced u_n, d per contact in contact order
  /// (t1 [, t2]; d = 1 in 2D, 2 in 3D) [N]; nullptr for the sliding_sign law
  /// (history.csv then has no lambda_t columns).
  const Eigen::VectorXd* lambda_tangential = nullptr;
  /// When the run was asked for them (RunOptions::tip_displacement): the
  /// blade tips' displacements at u_n in the tip polar frame, (u_1, v_1,
  /// u_2, v_2, ...) radial outward and tangential counter-clockwise [m];
  /// nullptr otherwise. Not written to history.csv (rsi sweep reads them).
  const Eigen::VectorXd* tip_displacement = nullptr;
  /// A run with an abradable liner: W_plastic, the liner's plastic work up
  /// to the row (a history.csv column W_plastic); nullptr otherwise.
  const double* plastic_work = nullptr;
};

/// Receives each history row as it is produced, in order (streamed output).
using HistorySink = std::function<void(const HistoryRow&)>;

/// One row every output_every steps, the first at t = 0.
struct History {
  std::vector<double> time;            ///< t_n [s]
  std::vector<Eigen::VectorXd> gap;    ///< g_k at u_n, blades 1..N [m]
  std::vector<Eigen::VectorXd> lambda; ///< lambda_k of the step that produced u_n [N]
  std::vector<double> energy;          ///< discrete energy E_{n-1/2} [J]
  std::vector<double> external_work;   ///< W_ext up to step n-1 [J]
  std::vector<double> contact_work;    ///< W_contact up to step n-1 [J]
  std::vector<double> damping_work;    ///< W_damp up to step n-1 [J]
  /// lambda_t of each row (HistoryRow::lambda_tangential); empty unless the
  /// rows carry it (Coulomb law).
  std::vector<Eigen::VectorXd> lambda_tangential;

  int n_rows() const { return static_cast<int>(time.size()); }

  /// Keeps a copy of `row`.
  void append(const HistoryRow& row) {
    time.push_back(row.time);
    gap.push_back(row.gap);
    lambda.push_back(row.lambda);
    energy.push_back(row.energy);
    external_work.push_back(row.external_work);
    contact_work.push_back(row.contact_work);
    damping_work.push_back(row.damping_work);
    if (row.lambda_tangential) lambda_tangential.push_back(*row.lambda_tangential);
  }
};

struct RunSummary {
  std::string method;
  int n_dofs = 0; ///< dofs integrated (bladed disk + casing)
  int steps_requested = 0;
  int steps = 0; ///< steps actually taken
  bool completed = false;
  std::string status; ///< "completed" or what stopped the run, with the step
  /// What to change, when a solver's failure stopped the run (the CLI words
  /// it after the status: cli/support/failure_advice.hpp, run_status).
  FailureAdvice status_advice;
  double dt = 0.0;
  double omega_max = 0.0;               ///< of the integrated model [rad/s]
  double critical_dt = 0.0;             ///< 2 / omega_max [s]
  double bladed_disk_critical_dt = 0.0; ///< 2 / omega_max of the (reduced) bladed disk alone [s]
  double flops_per_step = 0.0;          ///< counted for a contact-free step
  double casing_flops_per_step = 0.0;   ///< the full casing's part of it (reduced runs)
  double basis_seconds = 0.0;           ///< time to build the reduced basis (reduced runs)
  std::string casing_basis = "full";    ///< "full" or casing_basis.hpp's name ("modal-20+s")
  std::string time_step_rule = "case";  ///< StepRule::name(): "case", "own" or the given step
  double step_safety = 0.0;             ///< of the "own" rule (0 otherwise)
  std::string selection;                ///< mode selection of a reduced run ("" for full)
  int modes_kept = 0;                   ///< the reduced basis's kept modes (0 for full)
  /// Whole run (assembly, omega_max, integration, monitoring) without
  /// output_seconds: the solver's time, which speedups compare.
  double wall_seconds = 0.0;
  double integration_seconds = 0.0; ///< the time loop, without output_seconds
  /// Spent in RunOptions::history_sink (formatting and writing history rows,
  /// the same rows for every run of a campaign); 0 when rows stay in memory.
  double output_seconds = 0.0;
  double max_penetration = 0.0;       ///< [m]
  double min_lambda = 0.0;            ///< [N]
  double max_lambda = 0.0;            ///< [N]
  double max_complementarity = 0.0;   ///< max |lambda g| [N m]
  double max_friction_residual = 0.0; ///< [N]
  int sliding_reversals = 0;          ///< (step, contact) pairs where sliding changed sign
  double max_cone_violation = 0.0;      ///< [N] (Coulomb law)
  double max_stick_slip_residual = 0.0; ///< scaled, - (Coulomb law)
  int stick_slip_transitions = 0;       ///< (step, contact) pairs whose state changed (Coulomb law)
  long stick_contact_steps = 0;         ///< (step, contact) pairs in stick (Coulomb law)
  long slip_contact_steps = 0;          ///< (step, contact) pairs in slip (Coulomb law)
  double initial_energy = 0.0;        ///< [J]
  double max_energy = 0.0;            ///< [J]
  double energy_balance_error = 0.0;  ///< max_n |E_n - E_0 - W_ext - W_contact + W_damp| [J]
  double energy_scale = 0.0;          ///< max_n max(E_n, |W_ext|, |W_contact|, W_damp) [J]
  double final_external_work = 0.0;
  double final_contact_work = 0.0;
  double final_damping_work = 0.0; ///< W_damp at the last row (0 undamped) [J]
  int max_active = 0;              ///< most contacts active at once
  int first_contact_step = -1;     ///< first step with any lambda > 0 (-1: none)
  /// [first, last] step times with lambda_1 > 0: one entry per contact
  /// interval of blade 1 (not per step), so it grows with the number of
  /// separate contacts, never with the run's length alone.
  std::vector<std::pair<double, double>> contact_intervals_blade_1;
  /// A run with an abradable liner (summary.json's "liner" object only then).
  bool liner = false;
  double final_plastic_work = 0.0; ///< W_plastic at the end [force * length]
  /// The bars' work not done by the contact force at the end
  /// (CentralDifference::liner_unmatched_work) [force * length].
  double liner_unmatched_work = 0.0;
  double liner_cell_area = 0.0;     ///< A = r dtheta dz of a cell [length^2]
  double liner_bar_stiffness = 0.0; ///< k = E A / h [force / length]
  double max_wear_depth = 0.0;     ///< the deepest cell's wear at the end [length]
  /// Peaks of the wear around the circumference standing out at least a
  /// tenth of the deepest cell (liner_wear.hpp), the most over the axial rows.
  int wear_lobes = 0;
};

} // namespace rsi
