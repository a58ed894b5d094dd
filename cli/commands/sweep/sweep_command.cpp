// rsi sweep: the case's runs over its rotation speeds (issue 15), each run
// reduced to a row of indicators, alone on --jobs threads or over MPI ranks
// (cli/mpi_session.hpp). The kind of case (the paper's bladed disk in its
// flexible casing, or a component rubbing on its rigid casing) is read
// once, where the case is loaded (sweep_points_of): from there on the
// command and the driver (sweep/sweep_driver.hpp) see only its SweepPoints.
// Rows are written in (speed, run) order and a row depends only on its
// (speed, run): one process, threads or ranks give the same sweep.csv.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "component_sweep_points.hpp"
#include "interruption.hpp"
#include "mpi_session.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "paper_sweep_points.hpp"
#include "report_script.hpp"
#include "run_monitor.hpp"
#include "staged_output.hpp"
#include "sweep_driver.hpp"

namespace rsi {
namespace {

/// The MPI session as the sweep driver sees its ranks.
class MpiRanks : public SweepRanks {
public:
  explicit MpiRanks(MpiSession& mpi) : m_mpi(mpi) {}
  int rank() const override { return m_mpi.rank(); }
  int size() const override { return m_mpi.size(); }
  void send_task(int task, double seconds, const std::string& text) const override {
    m_mpi.send_task(task, seconds, text);
  }
  void send_done() const override { m_mpi.send_done(); }
  /// Ends this rank with status 0 once rank 0 knows (MpiSession::end_reported).
  void send_fatal(const std::string& what) const override { m_mpi.end_reported(what); }
  bool poll(SweepMessage& message) const override {
    RankMessage m;
    if (!m_mpi.poll(m)) return false;
    message.kind = m.kind == RankMessage::Kind::done    ? SweepMessage::Kind::done
                   : m.kind == RankMessage::Kind::fatal ? SweepMessage::Kind::fatal
                                                        : SweepMessage::Kind::task;
    message.rank = m.rank;
    message.task = m.task;
    message.seconds = m.seconds;
    message.text = m.text;
    return true;
  }

private:
  MpiSession& m_mpi;
};

/// The case's sweep, checked: the one place that reads which kind of case
/// it is.
std::unique_ptr<SweepPoints> sweep_points_of(const SweepOptions& options, int jobs) {
  const nlohmann::json document = read_case_document(options.case_path);
  if (is_component_case(document))
    return component_sweep_points(parse_component_case(document, options.case_path), options);
  if (!options.load.source_override.empty())
    throw UsageError("--source: only for a component case; " + options.case_path +
                     " is the paper's case");
  if (options.method == "macneal")
    throw UsageError("--method: must be full, cb, ccm or guyan for the paper's case (macneal: "
                     "component cases), got 'macneal'");
  return paper_sweep_points(parse_case(document, options.case_path), options, jobs);
}

double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const size_t n = x.size();
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

} // namespace

int run_sweep(const SweepOptions& options, StagedOutput& output) {
  MpiSession mpi;
  // Declared after `mpi`: an error or a signal removes the staged output
  // before MPI_Finalize, which waits for the other ranks (mpirun kills a
  // rank that waits too long: nothing of its --out must be left then).
  const StagedOutput::AbandonOnThrow abandon_before_finalize(output);
  const Clock::time_point start = Clock::now();
  const int jobs = options.jobs == 0 ? (mpi.size() > 1 ? 1 : 2) : options.jobs;
  if (jobs < 1 || jobs > 64)
    throw UsageError("--jobs: must be in [1, 64], got " + std::to_string(options.jobs));
  const std::unique_ptr<SweepPoints> points = sweep_points_of(options, jobs);
  SweepDriverOptions driver;
  driver.jobs = jobs;
  driver.quiet = options.quiet;
  // The speed index whose runs fail on purpose (tests only).
  if (const char* text = std::getenv("RSI_SWEEP_FAIL_SPEED")) driver.inject_speed = std::atoi(text);
  driver.stop_requested = [] { return pending_signal() != 0; };
  driver.throw_if_stopped = throw_if_interrupted;

  // --out is rank 0's alone, opened before any run (a bad --out: exit 2, nothing run).
  std::string stage;
  if (mpi.rank() == 0) stage = output.open(options.out, "--out", sweep_output_set());
  points->prepare(); // on every rank: each runs its share
  std::unique_ptr<StreamedTextFile> csv;
  if (mpi.rank() == 0) {
    for (const auto& [name, text] : points->side_files())
      write_text_file(stage + "/" + name, text);
    csv = std::make_unique<StreamedTextFile>(stage + "/sweep.csv");
    csv->append(points->csv_header());
  }
  const MpiRanks ranks(mpi);
  const SweepOutcome outcome =
      drive_sweep(*points, ranks, driver, [&](const std::string& row) { csv->append(row); });
  if (mpi.rank() != 0) return 0;
  csv->commit();

  const int n_runs = points->n_runs();
  const int n_tasks = static_cast<int>(points->speeds().size()) * n_runs;
  nlohmann::json summary = points->summary();
  summary["speeds"] = points->speeds();
  summary["ranks"] = mpi.size();
  summary["jobs"] = jobs;
  summary["wall_s"] = seconds_since(start);
  summary["failures"] = outcome.failures;
  for (int j = 0; j < n_runs; ++j) {
    std::vector<double> per_speed;
    for (int t = j; t < n_tasks; t += n_runs)
      per_speed.push_back(outcome.seconds[static_cast<size_t>(t)]);
    double total = 0.0;
    for (double s : per_speed)
      total += s;
    nlohmann::json run = points->run_summary(j);
    run["name"] = points->run_name(j);
    run["wall_s_total"] = total;
    run["wall_s_per_speed_median"] = median(per_speed);
    run["expected_cost_per_speed"] = points->cost(points->speeds().front(), j);
    summary["runs"].push_back(run);
  }
  write_text_file(stage + "/sweep_summary.json", summary.dump(2) + "\n");
  std::printf("sweep: %d speeds x %d runs on %d rank(s) x %d thread(s) in %.1f s\n",
              static_cast<int>(points->speeds().size()), n_runs, mpi.size(), jobs,
              seconds_since(start));
  for (const std::string& f : outcome.failures)
    std::fprintf(stderr, "rsi: sweep: failed: %s\n", f.c_str());
  output.announce("wrote " + options.out + "/sweep.csv, " + options.out + "/interaction_lines.csv, " +
                  options.out + "/sweep_summary.json\n");
  if (options.report) {
    std::fflush(stdout);
    const std::string script = points->report_script();
    const int status = run_report_script(script, stage);
    if (status != 0) {
      std::fprintf(stderr,
                   "rsi: error: the report generator %s/%s failed (status %d); nothing was "
                   "written to --out %s; fix it or use --no-report\n",
                   RSI_REPORTS_DIR, script.c_str(), status, options.out.c_str());
      return 1;
    }
    output.announce("report: " + options.out + "/sweep_report.md\n");
  }
  if (!outcome.failures.empty()) {
    std::fprintf(stderr,
                 "rsi: error: numerical failure: %zu run(s) of the sweep failed (listed "
                 "above, each with what to change); the other rows are in sweep.csv\n",
                 outcome.failures.size());
    return 3;
  }
  return 0;
}

} // namespace rsi
