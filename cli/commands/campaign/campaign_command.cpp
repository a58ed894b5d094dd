// rsi campaign: the reference and every reduced run of the case file's
// campaign, on two threads, with the error norms of SPEC §4 V6: its
// options, and the paper's case's outputs (the runs themselves:
// campaign/paper_campaign.hpp; a component case: component_campaign.cpp).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "campaign_options.hpp"
#include "campaign_progress.hpp"
#include "case_kinds.hpp"
#include "casing.hpp"
#include "casing_memory.hpp"
#include "central_difference.hpp"
#include "command.hpp"
#include "command_options.hpp"
#include "failure_advice.hpp"
#include "interruption.hpp"
#include "modes_table.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "paper_campaign.hpp"
#include "report_script.hpp"
#include "run_list_checks.hpp"
#include "run_monitor.hpp"
#include "run_outputs.hpp"
#include "scratch_series.hpp"
#include "staged_output.hpp"
#include "usage_error.hpp"

namespace rsi {
namespace {

class CampaignCommand : public Command {
public:
  explicit CampaignCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  int campaign(const Case& c, StagedOutput& output) const;
  int campaign(const ComponentCase& c, StagedOutput& output) const {
    return campaign_component_case(m_options, c, output);
  }

  CampaignOptions m_options;
};

CampaignCommand::CampaignCommand(CLI::App& app)
    : Command(*app.add_subcommand(
          "campaign",
          "Reference + every reduced run of the case's campaign -> DIR/convergence.csv, "
          "DIR/runs/*/")) {
  CampaignOptions& campaign = m_options;
  m_command.add_option("case", campaign.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  m_command.add_option("--out", campaign.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  m_command.add_option("--jobs", campaign.jobs,
                       "runs in parallel (threads), 1..64; default 2 (a component case: 1)")
      ->check(integer_in(1, 64, "an integer in [1, 64]"));
  m_command
      .add_option("--target-e2", campaign.target_e2,
                  "report the smallest eta and psi of the campaign with e2 at most this")
      ->check(number_above(0.0, "a finite number above 0"));
  m_command.add_flag("!--no-report", campaign.report,
                     "skip the report (reports/make_campaign_report.py, python3 + matplotlib)");
  add_component_options(m_command, campaign.load);
}

/// A campaign has no --force: the remedy of a step above a run's limit is
/// the key that set the step.
std::string step_remedy(const CampaignRun& r) {
  if (r.step.kind == StepRule::Kind::given)
    return "a smaller time_step of run " + r.name() +
           " in key 'campaign', dividing the output interval, or \"own\"; a campaign has no "
           "--force";
  return "time.step; a campaign has no --force";
}

/// What each run leaves while it runs: its history streamed to a temporary
/// runs/<name>/history.csv (committed only when every run is done: a failed
/// campaign writes none), and its blade-1 gap for the error norms to a
/// scratch file: a campaign's memory does not grow with the histories
/// (hundreds of MB at output_every 1).
struct RunFiles {
  std::unique_ptr<StreamedTextFile> history;
  std::unique_ptr<ScratchSeries> blade1_gap; ///< scratch_series.hpp
  std::string row;                           ///< the line being formatted
};

/// e2 and e_inf of a run's gap series on disk against the reference's.
GapErrors series_gap_errors(ScratchSeries& reduced, ScratchSeries& reference) {
  if (reduced.size() != reference.size())
    throw std::invalid_argument("blade1_gap_errors: the histories have " +
                                std::to_string(reduced.size()) + " and " +
                                std::to_string(reference.size()) + " rows");
  reduced.rewind();
  reference.rewind();
  const SeriesReader read_reduced = [&reduced](double* out, std::size_t count) {
    return reduced.read(out, count);
  };
  const SeriesReader read_reference = [&reference](double* out, std::size_t count) {
    const std::size_t n = reference.read(out, count);
    if (n != count)
      throw OutputError("cannot read back the campaign's gap series from its temporary file");
    return n;
  };
  // The reference's own row: its series against itself, read once.
  return chunked_gap_errors(read_reduced, &reduced == &reference ? nullptr : &read_reference);
}

} // namespace

int CampaignCommand::run(StagedOutput& output) {
  return visit_case(m_options.case_path, m_options.load,
                    [&](const auto& c) { return campaign(c, output); });
}

int CampaignCommand::campaign(const Case& c, StagedOutput& output) const {
  const CampaignOptions& options = m_options;
  if (c.campaign.empty())
    throw UsageError(c.source + ": key 'campaign': missing or empty, nothing to run");
  const int jobs = options.jobs == 0 ? 2 : options.jobs;
  if (jobs < 1 || jobs > 64)
    throw UsageError("--jobs: must be in [1, 64], got " + std::to_string(options.jobs));
  const int runs_at_once = std::min<int>(jobs, static_cast<int>(c.campaign.size()));
  const int disk_dofs =
      check_runs_against_model(c, c.campaign, c.source + ": key 'campaign'", runs_at_once);
  {
    const Casing casing = assemble_casing(c);
    try {
      check_case_step_bound(c, casing);
    } catch (const StabilityError& e) {
      throw without_force(e, "time.step; a campaign has no --force");
    }
    // The reduced runs' dense casing matrices, as many at once as threads run them.
    check_dense_casing_fits(c, casing.n_dofs(), runs_at_once);
  }
  const std::string stage = output.open(options.out, "--out", campaign_output_set());

  // Job 0 is the reference; the others the reduced runs, taken in turn by the threads.
  std::vector<PaperCampaignJob> runs = paper_campaign_jobs(c);
  CampaignProgress progress(static_cast<int>(runs.size()), ::isatty(STDERR_FILENO) != 0);
  std::vector<RunFiles> files(runs.size());
  for (size_t i = 0; i < runs.size(); ++i) {
    const std::string dir = stage + "/runs/" + runs[i].run.name();
    output.make(dir);
    files[i].history = std::make_unique<StreamedTextFile>(dir + "/history.csv");
    files[i].blade1_gap = std::make_unique<ScratchSeries>();
    // The 2D Coulomb law adds one tangential multiplier a tip (run_outputs.hpp).
    const int n_tangents = c.operating_point.friction_law == FrictionLaw::coulomb ? 1 : 0;
    files[i].history->append(history_csv_header(c.bladed_disk.n_blades, n_tangents));
  }
  PaperCampaignHooks hooks;
  hooks.row = [&files](std::size_t i, const HistoryRow& h) {
    RunFiles& f = files[i];
    f.row.clear();
    append_history_csv_row(f.row, h);
    f.history->append(f.row);
    f.blade1_gap->append(h.gap(0));
  };
  hooks.progress = [&progress](std::size_t i, double f) {
    progress.update(static_cast<int>(i), f);
  };
  hooks.finished = [&progress](std::size_t i, PaperCampaignJob& r) {
    if (r.step_refused) r.error = without_force(r.error, step_remedy(r.run));
    progress.finished(static_cast<int>(i), r.run.name(),
                      r.error.empty()
                          ? "done in " + std::to_string(r.result.summary.wall_seconds) + " s"
                          : r.error);
  };
  hooks.checkpoint = throw_if_interrupted;
  hooks.stop_requested = [] { return pending_signal() != 0; };
  try {
    run_paper_campaign(c, runs, jobs, runs_at_once, hooks);
  } catch (const StabilityError& e) {
    // The reference's step is bad input (exit 2, as for simulate).
    throw without_force(e, step_remedy(runs[0].run));
  }
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
  // The first round's columns, then the second's axes: the run's step, mode
  // selection, casing basis, basis build time (not in wall_s) and the
  // speedup counting it in.
  csv << "method,modes,e2,e_inf,wall_s,speedup,dt,selection,casing,basis_s,speedup_with_basis,"
         "run,modes_kept\n";
  for (size_t i = 0; i < runs.size(); ++i) {
    const PaperCampaignJob& r = runs[i];
    const std::string dir = stage + "/runs/" + r.run.name();
    if (!r.error.empty()) {
      std::fprintf(stderr, "rsi: campaign run %s failed: %s\n", r.run.name().c_str(),
                   r.error.c_str());
      files[i].history.reset(); // its temporary history removed: the run wrote nothing
      std::error_code ignored;
      std::filesystem::remove(dir, ignored); // empty
      continue;
    }
    errors[i] = series_gap_errors(*files[i].blade1_gap, *files[0].blade1_gap);
    files[i].history->commit();
    write_text_file(dir + "/summary.json", summary_json(r.result.summary));
    const RunSummary& rs = r.result.summary;
    csv << r.run.method << "," << r.run.modes << "," << errors[i].e2 << "," << errors[i].e_inf
        << "," << rs.wall_seconds << "," << reference.summary.wall_seconds / rs.wall_seconds << ","
        << rs.dt << "," << (i == 0 ? "-" : r.run.selection) << "," << rs.casing_basis << ","
        << rs.basis_seconds << ","
        << reference.summary.wall_seconds / (rs.wall_seconds + rs.basis_seconds) << ","
        << r.run.name() << "," << r.modes_kept << "\n";
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
    std::printf("%-34s %10.4e %10.4e %9.4f %8.2f %10.3e\n", runs[i].run.name().c_str(),
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
                                  [](const PaperCampaignJob& r) { return r.error.empty(); });
  if (options.report) {
    if (!write_report("make_campaign_report.py", stage, options.out)) return 1;
    output.announce("report: " + options.out + "/report.md\n");
  }
  if (all_ok) return 0;
  // Exit 3: one error line; each failed run's line above says what failed
  // and what to change.
  const long n_failed = std::count_if(runs.begin(), runs.end(),
                                      [](const PaperCampaignJob& r) { return !r.error.empty(); });
  std::fprintf(stderr,
               "rsi: error: numerical failure: %ld of %zu campaign runs failed (the lines 'rsi: "
               "campaign run ... failed' above say why and what to change); the others are in "
               "--out %s\n",
               n_failed, runs.size(), options.out.c_str());
  return 3;
}

std::unique_ptr<Command> add_campaign_command(CLI::App& app) {
  return std::make_unique<CampaignCommand>(app);
}

} // namespace rsi
