#include "paper_campaign.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <new>
#include <stdexcept>

#include "failure_advice.hpp"
#include "reduced_run.hpp"
#include "run_monitor.hpp"
#include "worker_threads.hpp"

namespace rsi {
namespace {

/// Thrown at a run's checkpoint once another worker has ended the campaign
/// (out of memory, a failed write, the reference's bad step): the run is
/// abandoned, not failed. No std::exception, so no handler of a run takes
/// it for the run's own failure; run_on_threads rethrows the cause.
struct CampaignEnded {};

} // namespace

std::vector<PaperCampaignJob> paper_campaign_jobs(const Case& c) {
  std::vector<PaperCampaignJob> jobs(c.campaign.size() + 1);
  jobs[0].run.method = "full";
  for (size_t i = 0; i < c.campaign.size(); ++i)
    jobs[i + 1].run = c.campaign[i];
  return jobs;
}

void run_paper_campaign(const Case& c, std::vector<PaperCampaignJob>& jobs, int threads,
                        int runs_at_once, const PaperCampaignHooks& hooks) {
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false}; // a worker ended the campaign: the others stop
  auto worker = [&]() {
    for (size_t i = next++; i < jobs.size() && !hooks.stop_requested() && !failed; i = next++) {
      PaperCampaignJob& r = jobs[i];
      ReducedRunOptions run_options;
      run_options.step = r.run.step;
      run_options.step_key = c.source + ": campaign run " + r.run.name() + ": time_step";
      run_options.modes_key = "campaign run " + r.run.name() + ": modes";
      run_options.casing_modes = r.run.casing_modes;
      run_options.selection = r.run.selection;
      run_options.runs_at_once = runs_at_once;
      // A signal abandons the campaign, and so does another worker ending it.
      run_options.run.checkpoint = [&hooks, &failed] {
        hooks.checkpoint();
        if (failed) throw CampaignEnded();
      };
      run_options.run.progress = [&hooks, i](double f) { hooks.progress(i, f); };
      bool sink_failed = false; // the row hook threw: the campaign ends, not the run
      run_options.run.history_sink = [&](const HistoryRow& h) {
        try {
          hooks.row(i, h);
        } catch (...) {
          sink_failed = true;
          throw;
        }
      };
      try {
        if (r.run.method == "full") {
          r.result = run_reference(c, run_options.run);
        } else {
          ReducedRunResult reduced = run_reduced(c, r.run.method, r.run.modes, run_options);
          r.modes_kept = reduced.basis.n_modes;
          r.result = std::move(reduced.run);
        }
        if (!r.result.summary.completed) r.error = run_status(r.result.summary);
      } catch (const std::bad_alloc&) {
        throw; // out of memory ends the campaign (exit 1, --out as it was), not one run
      } catch (const StabilityError& e) {
        // The reference's step is bad input (exit 2, as for simulate): no
        // campaign without its reference. A reduced run's own limit fails that run.
        if (i == 0) throw;
        r.error = failure_message(e);
        r.step_refused = true;
      } catch (const std::exception& e) {
        if (sink_failed) throw; // a failed write (exit 2 naming the file): the disk, not the run
        r.error = failure_message(e);
      }
      hooks.finished(i, r);
    }
  };
  // Every thread joined, whatever happens; the first exception a worker let
  // out (out of memory, a failed write, the reference's bad step) is
  // rethrown here (worker_threads.hpp).
  run_on_threads(std::min<int>(threads, static_cast<int>(jobs.size())), worker, failed);
}

GapErrors chunked_gap_errors(const SeriesReader& reduced, const SeriesReader* reference) {
  constexpr std::size_t chunk = 8192;
  std::vector<double> a(chunk), b(chunk);
  GapErrorSums sums;
  for (std::size_t n; (n = reduced(a.data(), chunk)) > 0;) {
    if (reference == nullptr)
      b = a;
    else if ((*reference)(b.data(), n) != n)
      throw std::runtime_error("the reference's gap series ended before the run's");
    for (std::size_t i = 0; i < n; ++i)
      sums.add(a[i], b[i]);
  }
  return sums.errors();
}

int smallest_reaching(const std::vector<PaperCampaignJob>& jobs,
                      const std::vector<GapErrors>& errors, const std::string& method,
                      double target) {
  int best = -1;
  for (size_t i = 0; i < jobs.size(); ++i)
    if (jobs[i].run.method == method && jobs[i].error.empty() && errors[i].e2 <= target &&
        (best < 0 || jobs[i].run.modes < best))
      best = jobs[i].run.modes;
  return best;
}

} // namespace rsi
