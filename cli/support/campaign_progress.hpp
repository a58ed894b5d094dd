#pragma once
// Progress of `rsi campaign` on stderr (issue 13, class 9: anything that
// runs more than a few seconds shows it). Each finished run prints its line
// (name, "done in S s" or why it failed) followed by the runs done out of
// the total, the time elapsed since the campaign started and the estimated
// time left; these lines go to stderr whether or not it is a terminal (a
// log keeps them, as it kept the runs' lines before). On a terminal a line
// is also redrawn while runs are in progress (at most 4 times a second,
// from the second second on), from the fraction each run reports every
// 1000 steps: a long reference run shows its progress before any run ends.
//
// The estimate counts every run as an equal share of the work: with f the
// mean of the runs' fractions done (a finished run 1), time left = elapsed
// (1 - f) / f. The reference run costs more than a reduced one, so the
// estimate is low while the reduced runs finish and the reference has not.
//
// Thread-safe: the workers of the campaign call update and finished.

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

namespace rsi {

class CampaignProgress {
public:
  /// `n_runs` runs (> 0); the clock starts now. `terminal`: draw the live
  /// line (stderr is a terminal).
  CampaignProgress(int n_runs, bool terminal);

  /// Run `run` (index in [0, n_runs)) is `fraction` in [0, 1] done.
  void update(int run, double fraction);
  /// Run `run` ended: prints `name`, `outcome` and the campaign's counts.
  void finished(int run, const std::string& name, const std::string& outcome);
  /// "[k/N runs, E s elapsed, about L s left]" (no estimate once all are done).
  std::string counts() const;

private:
  using Clock = std::chrono::steady_clock;
  std::string counts_locked() const; ///< counts(), m_mutex held
  double elapsed() const;
  double fraction_done() const; ///< mean of m_fraction

  mutable std::mutex m_mutex;
  std::vector<double> m_fraction; ///< of each run; 1 once finished
  int m_done = 0;                 ///< runs finished
  Clock::time_point m_start;
  bool m_terminal;
  bool m_drawn = false;      ///< a live line is on the terminal, not yet ended
  double m_last_drawn = 0.0; ///< elapsed seconds when it was drawn
};

} // namespace rsi
