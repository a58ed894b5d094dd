#pragma once
// Bookkeeping of a contact run, shared by the reference and the reduced
// solvers and by every kind of problem (it is neither integrator nor
// contact code): the stability guard, the summary's maxima over every step,
// the history rows, the energy balance and the blow-up tests; the kind's
// own tests plugged in (KindMonitor).

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <stdexcept>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "case_file.hpp"
#include "casing.hpp"
#include "failure_kinds.hpp"
#include "history.hpp"

namespace rsi {

using Clock = std::chrono::steady_clock;

/// Wall seconds since `start` (the run's own timings, SPEC §6).
inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Delta t at or above the stability limit 2/omega_max, not forced.
class StabilityError : public BadInput {
public:
  using BadInput::BadInput;
};

struct RunOptions {
  bool force = false; ///< integrate even above the stability limit
  /// Stop as a blow-up when the energy exceeds this multiple of E_0 plus the
  /// largest external work done so far (contact can feed energy in, SPEC §3, but a
  /// hundredfold gain is the sprag instability, not a physical response).
  double blowup_factor = 100.0;
  /// Called now and then with the fraction done (for progress display).
  std::function<void(double)> progress;
  /// Called every 1000 steps; may throw to abandon the run (the CLI throws
  /// on SIGINT or SIGTERM, cli/interruption), which then writes nothing.
  std::function<void()> checkpoint;
  /// When set, every history row is handed to it as it is produced and
  /// RunResult::history stays empty (streamed output: the run's memory does
  /// not grow with its length); when empty, the rows are kept in
  /// RunResult::history.
  HistorySink history_sink;
  /// Hand every history row the blade tips' displacements
  /// (HistoryRow::tip_displacement); gathered on output steps only.
  bool tip_displacement = false;
};

/// Writes the blade tips' displacements (u_1, v_1, u_2, v_2, ...) at the
/// current step into its argument (sized by the caller's first call).
using TipDisplacementSource = std::function<void(Eigen::VectorXd&)>;

struct RunResult {
  History history; ///< every row, unless RunOptions::history_sink took them
  RunSummary summary;
  /// Casing radial and tangential displacement of every casing node (zeros
  /// at the clamp) at the first contact (empty without contact), for the
  /// figure of the casing deformation (paper Fig. 9).
  Eigen::VectorXd casing_u_at_first_contact;
  Eigen::VectorXd casing_v_at_first_contact;
  /// A run with an abradable liner: each cell's wear at the end, cell j
  /// n_theta + i (row j, sector i of the casing frame); empty otherwise.
  std::vector<double> wear;
  int wear_n_theta = 0;
  int wear_n_axial = 0;
};

/// What a run exposes after each step.
struct StepState {
  int step = 0;    ///< n + 1
  double time = 0; ///< t_{n+1}
  const Eigen::VectorXd& gap;
  const Eigen::VectorXd& lambda;
  double external_work = 0.0;
  double contact_work = 0.0;
  /// Casing dofs at t_{n+1}; read only when RunMonitor::needs_casing() says
  /// so, and may be empty otherwise.
  Eigen::Ref<const Eigen::VectorXd> casing;
  double damping_work = 0.0; ///< W_damp (0 undamped)
  /// Coulomb law only: lambda_t of the step, d per contact (t1 [, t2]) [N];
  /// nullptr otherwise (then the history rows carry none).
  const Eigen::VectorXd* lambda_tangential = nullptr;
  /// Read on output steps when RunOptions::tip_displacement is set; may be
  /// nullptr otherwise.
  const TipDisplacementSource* tips = nullptr;
  /// With an abradable liner: W_plastic up to the step, subtracted in the
  /// balance and written in the rows; absent (false, 0) otherwise.
  bool liner = false;
  double plastic_work = 0.0;
};

/// Throws StabilityError unless dt < 2 / omega_max or forced; fills the
/// summary's dt, omega_max and critical_dt.
void check_time_step(double dt, double omega_max, bool force, RunSummary& summary);

/// The cheap check before any eigensolver (issue 13, class 9): every
/// Rayleigh quotient x^T K x / x^T M x is at most omega_max^2, so dt >=
/// 2 / sqrt(q) for the largest q found (one dof's, K_ii / M_ii, and the
/// power method's; linalg/largest_eigenvalue_bound.hpp) is already above the
/// stability limit. Throws StabilityError naming `part` then (unless
/// forced); a step below this bound still needs check_time_step.
void check_time_step_bound(double dt, const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, bool force,
                           const std::string& part);

/// What one kind of problem watches beyond the common bookkeeping, plugged
/// into RunMonitor (the paper's: paper_monitor.hpp; a component's on the
/// rigid casing: rubbing_monitor.hpp).
class KindMonitor {
public:
  virtual ~KindMonitor() = default;
  /// How a step ran away from the model, if it did.
  struct Runaway {
    std::string status; ///< empty: no runaway
    /// true: the step is counted in the summary and a row is written at it
    /// before the run stops; false: the step is outside the model, neither.
    bool counted = true;
  };
  /// Every step, before it is counted.
  virtual Runaway runaway(const StepState& state) const = 0;
  /// Every counted step; `first_contact`: the first step with a contact.
  virtual void after_step(const StepReport& report, const StepState& state, bool first_contact,
                          RunResult& result) = 0;
  /// Whether after_step() reads StepState::casing for this report.
  virtual bool needs_casing(const StepReport& report, const RunSummary& summary) const = 0;
};

/// When the common bookkeeping writes rows and checks the energy.
struct MonitorRules {
  int steps_requested = 0;        ///< the run's length
  std::int64_t output_every = 1;  ///< a row every this many steps (>= 1)
  std::int64_t energy_every = 1;  ///< the balance checked every this many steps (>= 1) and at the last
  bool row_at_last_step = true; ///< a row at the last step even off the output steps
  /// Stop when |E - E_0 - W_ext - W_contact + W_damp| > tolerance x scale
  /// (0: never, the balance is only reported).
  double balance_tolerance = 0.0;
};

/// The bookkeeping of a contact run, common to every kind of problem and
/// to both solvers: the summary's maxima over every step, the history rows,
/// the energy balance in its one form
///   E_n - E_0 - W_ext - W_contact + W_damp = 0 (to round-off),
/// with scale = max over the checked steps of |E|, |W_ext|, |W_contact|,
/// W_damp (a kind without forcing has W_ext = 0 exactly), the non-finite
/// energy and the blow-up factor (E > factor x (E_0 + max |W_ext|), checked
/// only when that supply is positive); what one kind adds (its runaway
/// test, the paper's blade-1 intervals and casing at the first contact)
/// comes from a KindMonitor.
class RunMonitor {
public:
  /// The paper's kind (paper_monitor.hpp) with the case's rules: rows every
  /// time.output_every steps and at the last, no balance tolerance.
  /// `casing` and `result` must outlive the monitor (not owned).
  RunMonitor(const Case& c, const Casing& casing, const RunOptions& options, RunResult& result);
  /// Any kind. `options` and `result` must outlive the monitor (not owned).
  RunMonitor(const MonitorRules& rules, std::unique_ptr<KindMonitor> kind,
             const RunOptions& options, RunResult& result);

  /// The row at t = 0.
  void start(const StepState& state, double initial_energy);
  /// Accumulates one step; `energy` is called on rows and balance checks
  /// only (it costs a product with M). Returns false when the run must stop.
  bool after_step(const StepReport& report, const StepState& state,
                  const std::function<double()>& energy);
  /// Stops the run with `status` (a solver's failure the run reports) and
  /// the failure's `advice`.
  void stop_with(const std::string& status, const FailureAdvice& advice) {
    stop(status);
    m_result.summary.status_advice = advice;
  }
  /// Whether after_step() will read StepState::casing for this report (the
  /// first step with a contact, the paper's kind), so a solver need not
  /// gather it otherwise.
  bool needs_casing(const StepReport& report) const {
    return m_kind->needs_casing(report, m_result.summary);
  }
  /// Closes the summary: the two clocks as measured by the run, from which
  /// the time spent in the history sink is taken out (RunSummary::output_seconds).
  void finish(double integration_seconds, double wall_seconds);
  /// History rows produced so far (kept or streamed).
  int n_rows() const { return m_n_rows; }

private:
  void add_row(const StepState& state, double energy);
  bool stop(const std::string& status);

  MonitorRules m_rules;
  std::unique_ptr<KindMonitor> m_kind;
  const RunOptions& m_options;
  RunResult& m_result;
  double m_largest_external_work = 0.0;
  int m_n_rows = 0;
  double m_output_seconds = 0.0; ///< inside the history sink
  double m_last_external_work = 0.0; ///< of the last row
  double m_last_contact_work = 0.0;  ///< of the last row
  double m_last_damping_work = 0.0;  ///< of the last row
  Eigen::VectorXd m_tips;            ///< tip displacements of the row being added
};

} // namespace rsi
