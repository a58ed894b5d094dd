// rsi campaign: the reference and every reduced run of the case file's
// campaign, on two threads, with the error norms of SPEC §4 V6.

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <filesystem>
#include <memory>
#include <sstream>
#include <thread>

#include <unistd.h>


#include <nlohmann/json.hpp>

#include "bladed_disk.hpp"
#include "basis_memory.hpp"
#include "campaign_progress.hpp"
#include "casing.hpp"
#include "casing_memory.hpp"
#include "central_difference.hpp"
#include "commands.hpp"
#include "error_norms.hpp"
#include "failure_remedies.hpp"
#include "interruption.hpp"
#include "output_files.hpp"
#include "reduced_run.hpp"
#include "reference_run.hpp"
#include "report_script.hpp"
#include "run_outputs.hpp"
#include "run_step.hpp"
#include "scratch_series.hpp"
#include "staged_output.hpp"
#include "worker_threads.hpp"

namespace rsi {
namespace {

struct CampaignResult {
  CampaignRun run;
  RunResult result; ///< its history streamed to `history`, not kept
  std::unique_ptr<StreamedTextFile> history; ///< runs/<name>/history.csv, committed at the end
  std::unique_ptr<ScratchSeries> blade1_gap; ///< for the error norms, on disk (scratch_series.hpp)
  std::string error; ///< why the run could not be made (bad mode count, numerical failure)
  int modes_kept = 0; ///< the basis's modes (a selection keeps whole units, rounding down)
};

/// e2 and e_inf of two gap series on disk, read back in chunks.
GapErrors series_gap_errors(ScratchSeries& reduced, ScratchSeries& reference) {
  if (reduced.size() != reference.size())
    throw std::invalid_argument("blade1_gap_errors: the histories have " +
                                std::to_string(reduced.size()) + " and " +
                                std::to_string(reference.size()) + " rows");
  reduced.rewind();
  reference.rewind();
  constexpr std::size_t chunk = 8192;
  std::vector<double> a(chunk), b(chunk);
  GapErrorSums sums;
  const bool itself = &reduced == &reference; // the reference's own row
  for (std::size_t n; (n = reduced.read(a.data(), chunk)) > 0;) {
    if (itself)
      b = a;
    else if (reference.read(b.data(), n) != n)
      throw OutputError("cannot read back the campaign's gap series from its temporary file");
    for (std::size_t i = 0; i < n; ++i)
      sums.add(a[i], b[i]);
  }
  return sums.errors();
}

/// Thrown at a run's checkpoint once another worker has ended the campaign
/// (out of memory, a failed write, the reference's bad step): the run is
/// abandoned, not failed. No std::exception, so no handler of a run takes
/// it for the run's own failure; run_on_threads rethrows the cause.
struct CampaignEnded {};

/// A campaign has no --force: the remedy of a step above a run's limit is
/// the key that set the step.
std::string step_remedy(const CampaignRun& r) {
  if (r.step.kind == StepRule::Kind::given)
    return "a smaller time_step of run " + r.name() +
           " in key 'campaign', dividing the output interval, or \"own\"; a campaign has no "
           "--force";
  return "time.step; a campaign has no --force";
}

std::string run_name(const CampaignRun& r) {
  return r.name();
}

/// Smallest mode count of `method` whose e2 is at most `target` (-1: none).
int smallest_reaching(const std::vector<CampaignResult>& runs, const std::vector<GapErrors>& errors,
                      const std::string& method, double target) {
  int best = -1;
  for (size_t i = 0; i < runs.size(); ++i)
    if (runs[i].run.method == method && runs[i].error.empty() && errors[i].e2 <= target &&
        (best < 0 || runs[i].run.modes < best))
      best = runs[i].run.modes;
  return best;
}

} // namespace

int check_runs_against_model(const Case& c, const std::vector<CampaignRun>& runs,
                             const std::string& where, int runs_at_once) {
  // Mode counts against the model before any run (the case loader only
  // knows [0, 100000]): cb keeps at most the interior dofs, ccm at most the
  // dofs minus the boundary dofs (reduced/craig_bampton, craig_chang_martinez).
  // A given step must divide the output interval: refused before any run.
  for (const CampaignRun& r : runs)
    if (r.step.kind == StepRule::Kind::given)
      run_step(r.step, c.time, 1.0, where + ": time_step of " + r.name());
  const int casing_dofs = assemble_casing(c).n_dofs();
  for (const CampaignRun& r : runs)
    if (r.casing_modes > casing_dofs)
      throw UsageError(where + ": casing_modes " + std::to_string(r.casing_modes) + " of " +
                       r.method + "-" + std::to_string(r.modes) + ": must be in [0, " +
                       std::to_string(casing_dofs) + "] (0: the full casing; its dofs)");
  const BladedDisk bd = assemble_bladed_disk(c);
  const int most = bd.n_dofs() - static_cast<int>(bd.boundary.size());
  for (const CampaignRun& r : runs) {
    if (r.method == "full") continue;
    if (r.method == "guyan" ? r.modes != 0 : r.modes > most)
      throw UsageError(where + ": " + r.method + " with " + std::to_string(r.modes) +
                       " modes: must be in " +
                       (r.method == "guyan" ? std::string("[0, 0] for guyan")
                                            : "[0, " + std::to_string(most) + "] for " +
                                                  r.method + " (dofs minus boundary dofs)"));
    // Its dense basis, as many at once as threads build them (basis_memory.hpp).
    check_dense_basis_fits(where + ": " + r.name(), bd.n_dofs(),
                           static_cast<int>(bd.boundary.size()), r.modes, runs_at_once);
  }
  return bd.n_dofs();
}

void check_case_step_bound(const Case& c, const Casing& casing, const std::string& command) {
  // The step against one dof's Rayleigh quotient of each part (a lower
  // bound of omega_max, run_monitor.hpp): the full runs would each refuse
  // it, after their assembly (issue 13, class 9).
  const BladedDisk bd = assemble_bladed_disk(c);
  try {
    check_time_step_bound(c.time.step, bd.stiffness, bd.mass, false, "bladed disk");
    check_time_step_bound(c.time.step, casing.stiffness, casing.mass, false, "casing");
  } catch (const StabilityError& e) {
    throw without_force(e, "time.step; a " + command + " has no --force");
  }
}

int run_campaign(const CampaignOptions& options, StagedOutput& output) {
  const nlohmann::json document = read_case_document(options.case_path);
  if (is_component_case(document))
    return run_rubbing_campaign(options, parse_component_case(document, options.case_path), output);
  if (!options.load.source_override.empty())
    throw UsageError("--source: only for a component case; " + options.case_path +
                     " is the paper's case");
  const Case c = parse_case(document, options.case_path);
  if (c.campaign.empty())
    throw UsageError(c.source + ": key 'campaign': missing or empty, nothing to run");
  const int jobs = options.jobs == 0 ? 2 : options.jobs;
  if (jobs < 1 || jobs > 64)
    throw UsageError("--jobs: must be in [1, 64], got " + std::to_string(options.jobs));
  const int disk_dofs = check_runs_against_model(
      c, c.campaign, c.source + ": key 'campaign'",
      std::min<int>(jobs, static_cast<int>(c.campaign.size())));
  {
    const Casing casing = assemble_casing(c);
    check_case_step_bound(c, casing, "campaign");
    // The reduced runs' dense casing matrices, as many at once as threads run them.
    check_dense_casing_fits(c, casing.n_dofs(),
                            std::min<int>(jobs, static_cast<int>(c.campaign.size())));
  }
  const std::string stage = output.open(options.out, "--out", campaign_output_set());

  // Job 0 is the reference; the others the reduced runs, taken in turn by the threads.
  std::vector<CampaignResult> runs(c.campaign.size() + 1);
  runs[0].run.method = "full";
  for (size_t i = 0; i < c.campaign.size(); ++i)
    runs[i + 1].run = c.campaign[i];
  std::atomic<size_t> next{0};
  CampaignProgress progress(static_cast<int>(runs.size()), ::isatty(STDERR_FILENO) != 0);
  // Each history is streamed to its file as it is produced (a temporary
  // file, committed only when every run is done: a failed campaign writes
  // none), and the blade-1 gap for the error norms to a scratch file: a
  // campaign's memory does not grow with the histories (issue 13: hundreds
  // of MB at output_every 1).
  for (CampaignResult& r : runs) {
    const std::string dir = stage + "/runs/" + run_name(r.run);
    output.make(dir);
    r.history = std::make_unique<StreamedTextFile>(dir + "/history.csv");
    r.blade1_gap = std::make_unique<ScratchSeries>();
    // The 2D Coulomb law adds one tangential multiplier a tip (run_outputs.hpp).
    const int n_tangents = c.operating_point.friction_law == FrictionLaw::coulomb ? 1 : 0;
    r.history->append(history_csv_header(c.bladed_disk.n_blades, n_tangents));
  }
  std::atomic<bool> failed{false}; // a worker ended the campaign: the others stop
  auto worker = [&]() {
    for (size_t i = next++; i < runs.size() && pending_signal() == 0 && !failed; i = next++) {
      CampaignResult& r = runs[i];
      ReducedRunOptions run_options;
      run_options.step = r.run.step;
      run_options.step_key = c.source + ": campaign run " + run_name(r.run) + ": time_step";
      run_options.modes_key = "campaign run " + run_name(r.run) + ": modes";
      run_options.casing_modes = r.run.casing_modes;
      run_options.selection = r.run.selection;
      run_options.runs_at_once = std::min<int>(jobs, static_cast<int>(c.campaign.size()));
      // A signal abandons the campaign, and so does another worker ending it.
      run_options.run.checkpoint = [&failed] {
        throw_if_interrupted();
        if (failed) throw CampaignEnded();
      };
      run_options.run.progress = [&progress, i](double f) {
        progress.update(static_cast<int>(i), f);
      };
      std::string row;
      run_options.run.history_sink = [&](const HistoryRow& h) {
        row.clear();
        append_history_csv_row(row, h);
        r.history->append(row);
        r.blade1_gap->append(h.gap(0));
      };
      try {
        if (r.run.method == "full") {
          r.result = run_reference(c, run_options.run);
        } else {
          ReducedRunResult reduced = run_reduced(c, r.run.method, r.run.modes, run_options);
          r.modes_kept = reduced.basis.n_modes;
          r.result = std::move(reduced.run);
        }
        if (!r.result.summary.completed) r.error = r.result.summary.status;
      } catch (const std::bad_alloc&) {
        throw; // out of memory ends the campaign (exit 1, --out as it was), not one run
      } catch (const OutputError&) {
        throw; // so does a failed write (exit 2 naming the file): the disk, not the run
      } catch (const StabilityError& e) {
        // The reference's step is bad input (exit 2, as for simulate): no
        // campaign without its reference. A reduced run's own limit fails that run.
        if (i == 0) throw without_force(e, step_remedy(r.run));
        r.error = without_force(std::string(e.what()), step_remedy(r.run));
      } catch (const std::exception& e) {
        r.error = e.what();
      }
      progress.finished(static_cast<int>(i), run_name(r.run),
                        r.error.empty()
                            ? "done in " + std::to_string(r.result.summary.wall_seconds) + " s"
                            : r.error);
    }
  };
  // Every thread joined, whatever happens; the first exception a worker let
  // out (out of memory, a failed write, the reference's bad step) is
  // rethrown here (worker_threads.hpp).
  run_on_threads(std::min<int>(jobs, static_cast<int>(runs.size())), worker, failed);
  throw_if_interrupted();
  if (!runs[0].error.empty()) {
    // Stopped by the monitor (it ran steps), or an exception of the integrator.
    const RunSummary& s = runs[0].result.summary;
    throw IntegrationError(
        "campaign: the reference run failed: " + runs[0].error + "; " +
        (s.steps > 0 ? stopped_run_remedy(s) : "no reduced run is compared without it"));
  }

  const RunResult& reference = runs[0].result;
  std::vector<GapErrors> errors(runs.size());
  std::ostringstream csv;
  csv.precision(10);
  // The first round's columns, then the issue-14 axes: the run's step, mode
  // selection, casing basis, basis build time (not in wall_s) and the
  // speedup counting it in.
  csv << "method,modes,e2,e_inf,wall_s,speedup,dt,selection,casing,basis_s,speedup_with_basis,"
         "run,modes_kept\n";
  for (size_t i = 0; i < runs.size(); ++i) {
    const CampaignResult& r = runs[i];
    const std::string dir = stage + "/runs/" + run_name(r.run);
    if (!r.error.empty()) {
      std::fprintf(stderr, "rsi: campaign run %s failed: %s\n", run_name(r.run).c_str(),
                   r.error.c_str());
      runs[i].history.reset(); // its temporary history removed: the run wrote nothing
      std::error_code ignored;
      std::filesystem::remove(dir, ignored); // empty
      continue;
    }
    errors[i] = series_gap_errors(*r.blade1_gap, *runs[0].blade1_gap);
    r.history->commit();
    write_text_file(dir + "/summary.json", summary_json(r.result.summary));
    const RunSummary& rs = r.result.summary;
    csv << r.run.method << "," << r.run.modes << "," << errors[i].e2 << "," << errors[i].e_inf
        << "," << rs.wall_seconds << "," << reference.summary.wall_seconds / rs.wall_seconds << ","
        << rs.dt << "," << (i == 0 ? "-" : r.run.selection) << "," << rs.casing_basis << ","
        << rs.basis_seconds << ","
        << reference.summary.wall_seconds / (rs.wall_seconds + rs.basis_seconds) << ","
        << run_name(r.run) << "," << r.modes_kept << "\n";
  }
  write_text_file(stage + "/convergence.csv", csv.str());
  // Paper Fig. 3 analogue: the lowest 8 families of the bladed disk.
  write_text_file(
      stage + "/modes-bladed-disk.csv",
      modes_table(c, "bladed-disk", std::min(8 * c.bladed_disk.n_blades, disk_dofs)).csv);

  std::printf("%-34s %10s %10s %9s %8s %10s\n", "run", "e2", "e_inf", "wall_s", "speedup",
              "dt");
  for (size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i].error.empty()) continue;
    std::printf("%-34s %10.4e %10.4e %9.4f %8.2f %10.3e\n", run_name(runs[i].run).c_str(),
                errors[i].e2, errors[i].e_inf, runs[i].result.summary.wall_seconds,
                reference.summary.wall_seconds / runs[i].result.summary.wall_seconds,
                runs[i].result.summary.dt);
  }
  if (options.target_e2 > 0.0) {
    for (const char* method : {"cb", "ccm"}) {
      const int modes = smallest_reaching(runs, errors, method, options.target_e2);
      if (modes < 0)
        std::printf(
            "target e2 <= %g: no %s run of the campaign reaches it; add larger mode counts\n",
            options.target_e2, method);
      else
        std::printf("target e2 <= %g: %s needs %d modes (smallest in the campaign)\n",
                    options.target_e2, method, modes);
    }
  }
  output.announce("wrote " + options.out + "/convergence.csv and " + options.out +
                  "/runs/*/{history.csv,summary.json}\n");
  const bool all_ok = std::all_of(runs.begin(), runs.end(),
                                  [](const CampaignResult& r) { return r.error.empty(); });
  if (options.report) {
    std::fflush(stdout); // the table before the script's own lines
    const int status = run_report_script("make_campaign_report.py", stage);
    if (status != 0) {
      // Exit 1 publishes nothing (staged_output.hpp): --out stays as it was.
      std::fprintf(stderr,
                   "rsi: error: the report generator %s/make_campaign_report.py failed (status "
                   "%d); nothing was written to --out %s; fix it or use --no-report\n",
                   RSI_REPORTS_DIR, status, options.out.c_str());
      return 1;
    }
    output.announce("report: " + options.out + "/report.md\n");
  }
  if (all_ok) return 0;
  // Exit 3: one error line; each failed run's line above says what failed
  // and what to change.
  const long n_failed = std::count_if(runs.begin(), runs.end(),
                                      [](const CampaignResult& r) { return !r.error.empty(); });
  std::fprintf(stderr,
               "rsi: error: numerical failure: %ld of %zu campaign runs failed (the lines 'rsi: "
               "campaign run ... failed' above say why and what to change); the others are in "
               "--out %s\n",
               n_failed, runs.size(), options.out.c_str());
  return 3;
}

} // namespace rsi
