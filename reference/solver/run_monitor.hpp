#pragma once
// Bookkeeping of a contact run, shared by the reference and the reduced
// solvers (it is neither integrator nor contact code): the stability guard,
// the summary's maxima over every step, the blade-1 contact intervals, the
// history rows, the energy balance and the blow-up tests.

#include <chrono>
#include <functional>
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

class RunMonitor {
public:
  /// `casing` and `result` must outlive the monitor (not owned).
  RunMonitor(const Case& c, const Casing& casing, const RunOptions& options, RunResult& result);

  /// The row at t = 0.
  void start(const StepState& state, double initial_energy);
  /// Accumulates one step; `energy` is called on output steps only (it
  /// costs a product with M). Returns false when the run must stop.
  bool after_step(const StepReport& report, const StepState& state,
                  const std::function<double()>& energy);
  /// Whether after_step() will read StepState::casing for this report (the
  /// first step with a contact), so a solver need not gather it otherwise.
  bool needs_casing(const StepReport& report) const {
    return m_result.summary.first_contact_step < 0 && report.n_active > 0;
  }
  /// Closes the summary: the two clocks as measured by the run, from which
  /// the time spent in the history sink is taken out (RunSummary::output_seconds).
  void finish(double integration_seconds, double wall_seconds);
  /// History rows produced so far (kept or streamed).
  int n_rows() const { return m_n_rows; }

private:
  void add_row(const StepState& state, double energy);
  bool stop(const std::string& status);

  const Casing& m_casing;
  const RunOptions& m_options;
  RunResult& m_result;
  int m_output_every;
  double m_runaway_gap;
  double m_largest_external_work = 0.0;
  bool m_in_contact = false;
  int m_n_rows = 0;
  double m_output_seconds = 0.0; ///< inside the history sink
  double m_last_external_work = 0.0; ///< of the last row
  double m_last_contact_work = 0.0;  ///< of the last row
  double m_last_damping_work = 0.0;  ///< of the last row
  Eigen::VectorXd m_tips;            ///< tip displacements of the row being added
};

} // namespace rsi
