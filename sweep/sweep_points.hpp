#pragma once
// The runs of one sweep, whatever the case: a list of speeds, a list of
// runs, and for one (speed, run) its CSV row. `rsi sweep` chooses the kind
// once, where it reads the case (the paper's bladed disk in its flexible
// casing, or a component rubbing on its rigid casing), and the driver
// (sweep_driver.hpp) schedules, runs and writes through this interface
// alone. A task is one (speed index s, run j), numbered t = s n_runs + j:
// the row order of sweep.csv.
//
// Thread safety: after prepare(), run() and failed_row() are called from
// several threads at once and must only read the object.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace rsi {

/// What one task left: its CSV row and, when it failed, why.
struct SweepTaskResult {
  int task = -1;
  double seconds = 0.0; ///< the run's wall time
  std::string row;      ///< one line of sweep.csv, '\n' included
  std::string error;    ///< empty unless the run failed
};

class SweepPoints {
public:
  virtual ~SweepPoints() = default;

  /// The speeds [rad/s], in sweep.csv's order.
  virtual const std::vector<double>& speeds() const = 0;
  virtual int n_runs() const = 0;
  /// The run's name in sweep.csv and in messages ("full", "macneal-50").
  virtual std::string run_name(int run) const = 0;
  /// Builds what every speed shares (bases, the model). Called once, after
  /// every input check and after --out was opened.
  virtual void prepare() = 0;
  /// Expected cost of the run at `speed` (steps x coordinates): the
  /// schedule's weight, not a measurement. After prepare().
  virtual double cost(double speed, int run) const = 0;
  /// sweep.csv's first line, '\n' included.
  virtual std::string csv_header() const = 0;
  /// Runs (speed, run). A numerical failure or a bad setting is a result
  /// with `error` set (the sweep goes on); an interruption or an exhausted
  /// memory is thrown (the sweep ends). `inject_failure`: fail on purpose
  /// (the tests' RSI_SWEEP_FAIL_SPEED).
  virtual SweepTaskResult run(double speed, int run, bool inject_failure) const = 0;
  /// The row of a run that never came back (its rank stopped).
  virtual std::string failed_row(double speed, int run) const = 0;
  /// Files written beside sweep.csv before the runs: (name, text).
  virtual std::vector<std::pair<std::string, std::string>> side_files() const = 0;
  /// sweep_summary.json's keys of this kind of case (the driver adds
  /// speeds, ranks, jobs, wall_s, failures and runs).
  virtual nlohmann::json summary() const = 0;
  /// A run's entry of sweep_summary.json "runs" (the driver adds name, wall
  /// times and expected cost).
  virtual nlohmann::json run_summary(int run) const = 0;
  /// The report generator of reports/ that reads the outputs.
  virtual std::string report_script() const = 0;
};

} // namespace rsi
