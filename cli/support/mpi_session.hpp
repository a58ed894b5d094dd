#pragma once
// The MPI side of `rsi sweep` (issue 15): Debian's OpenMPI, used only when
// the process was started by a launcher (mpirun, srun: its environment
// names the rank), so the same binary runs alone without MPI_Init. Rank 0
// owns the output; the other ranks send it one message per finished task
// and one when they are done, and stay silent (rank 0 speaks for all).

#include <string>

namespace rsi {

/// What another rank sent: a finished task, its end, or its fatal error.
struct RankMessage {
  enum class Kind { task, done, fatal };
  Kind kind = Kind::task;
  int rank = 0;
  int task = -1;       ///< Kind::task: the task's index
  double seconds = 0.; ///< Kind::task: the run's wall time
  std::string text;    ///< Kind::task: the CSV row; Kind::fatal: the error
};

class MpiSession {
public:
  /// MPI_Init when started by a launcher (MPI_THREAD_FUNNELED: only the
  /// calling thread talks to MPI), else a session of one rank. Ranks other
  /// than 0 send their stdout and stderr to /dev/null.
  MpiSession();
  /// MPI_Finalize if it was initialised, except on rank 0 during the
  /// unwinding of an exception: rank 0 then exits without it (it would wait
  /// for the other ranks), and mpirun ends the job.
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return m_rank; }
  int size() const { return m_size; }
  bool distributed() const { return m_initialised; }

  /// To rank 0 (from another rank; blocking, small messages).
  void send_task(int task, double seconds, const std::string& row) const;
  void send_done() const;
  void send_fatal(const std::string& what) const;
  /// A rank other than 0 that cannot go on (a signal, out of memory):
  /// sends `what` to rank 0 (send_fatal), finalizes MPI and ends the
  /// process with status 0. Rank 0 speaks for the job: it writes a failed
  /// row for each of this rank's runs that never came, names the rank and
  /// `what` in the summary, publishes and exits 3. A non-zero status here
  /// would make mpirun abort the job and kill rank 0 before it publishes
  /// (measured: --out left with the lock and the staging folder).
  [[noreturn]] void end_reported(const std::string& what);
  /// Rank 0: the next message that has arrived, without waiting; false when none.
  bool poll(RankMessage& message) const;

private:
  bool m_initialised = false;
  int m_rank = 0;
  int m_size = 1;
};

} // namespace rsi
