#pragma once
// The paper's campaign (SPEC §4 V6): the full-order reference and every
// reduced run of the case's "campaign", taken in turn by a pool of worker
// threads (worker_threads.hpp), each history row handed to the caller as
// the run produces it; and the error norms of the blade-1 gap against the
// reference's, over series read back in chunks (error_norms.hpp).
//
// The runs are those of reference/solver/reference_run and
// reduced/reduced_run; this file schedules them and sorts out what ends one
// run (its own failure, recorded) from what ends the campaign (thrown).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "error_norms.hpp"
#include "history.hpp"
#include "reference_run.hpp"

namespace rsi {

/// One run of the campaign and what it left.
struct PaperCampaignJob {
  CampaignRun run;   ///< job 0: the reference (method "full")
  RunResult result;  ///< its summary; its history went to the row hook, not kept
  std::string error; ///< why the run could not be made or was stopped (empty: completed)
  /// `error` is the message of a StabilityError: the run's step at or above
  /// its stability limit (the caller adds the key that set the step).
  bool step_refused = false;
  int modes_kept = 0; ///< the basis's modes (a selection keeps whole units, rounding down)
};

/// Job 0 the reference, then the case's campaign runs in their order.
std::vector<PaperCampaignJob> paper_campaign_jobs(const Case& c);

/// What the caller does while the jobs run; every hook must be set. Each may be called from
/// any worker thread (the caller serializes what it shares).
struct PaperCampaignHooks {
  /// Each history row of job `job`, as the run produces it. An exception
  /// it throws ends the campaign (a failed write), not the run.
  std::function<void(std::size_t job, const HistoryRow&)> row;
  /// Job `job` is `fraction` in [0, 1] done.
  std::function<void(std::size_t job, double fraction)> progress;
  /// Job `job` ended, completed or with its `error` (which the hook may
  /// reword); not called for the reference whose step is refused (thrown).
  std::function<void(std::size_t job, PaperCampaignJob&)> finished;
  /// Called at each run's checkpoints: throws to abandon the campaign (a signal).
  std::function<void()> checkpoint;
  /// True once the campaign is to stop: no further job is taken.
  std::function<bool()> stop_requested;
};

/// Runs `jobs` on `threads` threads (at least 1; a thread that cannot be
/// started leaves its share to the others), `runs_at_once` reduced runs'
/// dense matrices counted against the memory. A job's own failure (a bad
/// mode count, a numerical failure, a reduced run's step above its limit)
/// is recorded in its `error`, and the others go on. Thrown, once every
/// thread has joined, and ending the campaign: the reference's
/// StabilityError (no campaign without its reference), std::bad_alloc, an
/// exception of the row hook or of the checkpoint.
void run_paper_campaign(const Case& c, std::vector<PaperCampaignJob>& jobs, int threads,
                        int runs_at_once, const PaperCampaignHooks& hooks);

/// Reads the next at most `count` entries of a series into `out`; returns
/// how many (0 at its end).
using SeriesReader = std::function<std::size_t(double* out, std::size_t count)>;

/// e2 and e_inf of the series `reduced` against `reference`, read in
/// chunks in order (the same bits as over whole vectors, GapErrorSums).
/// `reference` null: the reference against itself. The caller checks that
/// both have as many entries. Throws std::runtime_error when `reference`
/// ends before `reduced`.
GapErrors chunked_gap_errors(const SeriesReader& reduced, const SeriesReader* reference);

/// Smallest mode count of `method` among the completed jobs whose e2
/// (`errors`, one a job) is at most `target`; -1: none.
int smallest_reaching(const std::vector<PaperCampaignJob>& jobs,
                      const std::vector<GapErrors>& errors, const std::string& method,
                      double target);

} // namespace rsi
