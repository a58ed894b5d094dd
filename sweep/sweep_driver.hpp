#pragma once
// The driver of a sweep: which tasks this rank runs (sweep_schedule.hpp on
// the runs' expected costs), its worker threads (run_on_threads,
// worker_threads.hpp), and on rank 0 the rows written in task order as soon
// as every row before them is in. A row depends only on its (speed, run),
// so one process, threads or ranks give the same sweep.csv byte for byte.
//
// Only the calling thread talks to the other ranks (MPI_THREAD_FUNNELED):
// the workers run under one host thread while the caller collects their
// rows, forwards them (ranks > 0) or receives the others' (rank 0).

#include <functional>
#include <string>
#include <vector>

#include "sweep_points.hpp"

namespace rsi {

/// What another rank sent: a finished task, its end, or its fatal error.
struct SweepMessage {
  enum class Kind { task, done, fatal };
  Kind kind = Kind::task;
  int rank = 0;
  int task = -1;       ///< Kind::task: the task's index
  double seconds = 0.; ///< Kind::task: the run's wall time
  std::string text;    ///< Kind::task: the row, then the error; Kind::fatal: the error
};

/// The ranks of the sweep as the driver sees them (MPI, or one process).
class SweepRanks {
public:
  virtual ~SweepRanks() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// To rank 0, from another rank.
  virtual void send_task(int task, double seconds, const std::string& text) const = 0;
  virtual void send_done() const = 0;
  /// From a rank other than 0 that cannot go on: tells rank 0, and may end
  /// the process (MPI: status 0, so that mpirun lets rank 0 publish).
  virtual void send_fatal(const std::string& what) const = 0;
  /// Rank 0: the next message that has arrived, without waiting.
  virtual bool poll(SweepMessage& message) const = 0;
};

struct SweepDriverOptions {
  int jobs = 1;             ///< worker threads of this rank, >= 1
  bool quiet = false;       ///< no progress lines on stderr
  int inject_speed = -1;    ///< the speed index whose runs fail on purpose (tests)
  /// True once a signal asked to stop: no new task is started.
  std::function<bool()> stop_requested;
  /// Throws the interruption when a signal came (called before returning).
  std::function<void()> throw_if_stopped;
};

struct SweepOutcome {
  std::vector<double> seconds;       ///< each task's wall time (rank 0)
  std::vector<std::string> failures; ///< one line per failed task (rank 0)
};

/// Runs this rank's share of `points` (prepared) and, on rank 0, hands each
/// row to `write_row` in task order. Throws std::runtime_error ("sweep:
/// ...") when a worker's error ends the sweep (after telling rank 0), and
/// whatever throw_if_stopped throws.
SweepOutcome drive_sweep(const SweepPoints& points, const SweepRanks& ranks,
                         const SweepDriverOptions& options,
                         const std::function<void(const std::string&)>& write_row);

/// "310" for 310 rad/s: the speed as sweep.csv writes it.
std::string sweep_speed_text(double speed);

} // namespace rsi
