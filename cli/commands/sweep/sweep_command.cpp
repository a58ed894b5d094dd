// rsi sweep: the case's runs over its rotation speeds, each run
// reduced to a row of indicators, alone on --jobs threads or over MPI ranks
// (cli/support/mpi_session.hpp). The kind of case (the paper's bladed disk in its
// flexible casing, or a component rubbing on its rigid casing) is read
// once, where the case is loaded (case_kinds.hpp): from there on the
// command and the driver (sweep/sweep_driver.hpp) see only its SweepPoints.
// Rows are written in (speed, run) order and a row depends only on its
// (speed, run): one process, threads or ranks give the same sweep.csv.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "blas_threads.hpp"
#include "case_kinds.hpp"
#include "command.hpp"
#include "command_options.hpp"
#include "failure_advice.hpp"

#include "interruption.hpp"
#include "mpi_session.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "sweep_case_options.hpp"
#include "report_script.hpp"
#include "run_monitor.hpp"
#include "staged_output.hpp"
#include "sweep_driver.hpp"
#include "sweep_options.hpp"
#include "usage_error.hpp"

namespace rsi {
namespace {

class SweepCommand : public Command {
public:
  explicit SweepCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  /// The run options describe the one --method run: refused without it,
  /// and for the full reference.
  void check_option_rules();

  SweepOptions m_options;
  CLI::Option* m_speeds = nullptr;
  CLI::Option* m_modes = nullptr;
  CLI::Option* m_boundary_modes = nullptr;
  CLI::Option* m_step = nullptr;
  CLI::Option* m_safety = nullptr;
  CLI::Option* m_casing = nullptr;
  CLI::Option* m_selection = nullptr;
};

SweepCommand::SweepCommand(CLI::App& app)
    : Command(*app.add_subcommand(
          "sweep", "The case's sweep runs over rotation speeds -> DIR/sweep.csv, "
                   "DIR/interaction_lines.csv, DIR/sweep_report.md; under mpirun the speeds are "
                   "shared by the ranks")) {
  SweepOptions& sweep = m_options;
  m_command.add_option("case", sweep.case_path, "case file (JSON) with a \"sweep\" object")
      ->required()
      ->check(case_file());
  m_command.add_option("--out", sweep.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  m_speeds = m_command.add_option(
      "--speeds", sweep.speeds,
      "FROM:TO:COUNT or W1,W2,... [rad/s] in place of the case's sweep.speeds");
  m_command
      .add_option("--method", sweep.method,
                  "one run in place of the case's sweep.runs: full, cb, ccm or guyan; a "
                  "component case also macneal or cc")
      ->check(one_of({"full", "cb", "ccm", "guyan", "macneal", "cc"}));
  m_modes = m_command.add_option("--modes", sweep.modes,
                                 "with --method cb, ccm or macneal: modes kept; cc: its eta")
                ->check(integer_in(0, 1000000000, modes_allowed));
  m_boundary_modes =
      m_command
          .add_option("--boundary-modes", sweep.boundary_modes,
                      "with --method cc: the characteristic constraint modes kept of the "
                      "boundary (n_c, 1 to the boundary dofs)")
          ->check(integer_in(0, 1000000000, "the characteristic constraint modes kept"));
  m_step = m_command.add_option("--time-step", sweep.time_step,
                                "with a reduced --method: case, own or a step dividing the output "
                                "interval");
  m_safety = m_command
                 .add_option("--step-safety", sweep.step_safety,
                             "with --time-step own: the fraction of 2/omega_max, in (0, 1)")
                 ->check(CLI::Range(0.0, 1.0));
  m_casing = m_command
                 .add_option("--casing-modes", sweep.casing_modes,
                             "with a reduced --method: 0 (the full casing) or N_c casing modes")
                 ->check(integer_in(0, 1000000000, "0 (the full casing) or the casing modes kept"));
  m_selection = m_command
                    .add_option("--selection", sweep.selection,
                                "with a reduced --method: lowest, families, forced or participation")
                    ->check(one_of({"lowest", "families", "forced", "participation"}));
  m_command.add_option("--jobs", sweep.jobs,
                       "threads a process (default 2 alone, 1 a rank under mpirun)")
      ->check(integer_in(1, 64, "an integer in [1, 64]"));
  m_command.add_flag("--quiet", sweep.quiet, "no progress lines on stderr");
  m_command.add_flag("!--no-report", sweep.report,
                     "skip the report (reports/make_sweep_report.py or, for a component case, "
                     "make_component_sweep_report.py; against a flexible casing "
                     "make_system_sweep_report.py; python3 + matplotlib)");
  add_component_options(m_command, sweep.load);
}

void SweepCommand::check_option_rules() {
  SweepOptions& sweep = m_options;
  if (m_boundary_modes->count() > 0 && sweep.method != "cc")
    throw UsageError("--boundary-modes: only with --method cc (characteristic constraint "
                     "modes); drop it");
  for (const CLI::Option* o : {m_modes, m_step, m_safety, m_casing, m_selection}) {
    if (o->count() > 0 && sweep.method.empty())
      throw UsageError(o->get_name() +
                       ": only with --method (it describes that one run); add "
                       "--method or drop it");
    if (o->count() > 0 && sweep.method == "full")
      throw UsageError(o->get_name() +
                       ": only for a reduced --method (the full reference runs the whole "
                       "model at time.step); drop it");
  }
  if (m_safety->count() > 0 && sweep.time_step != "own")
    throw UsageError("--step-safety: only with --time-step own; drop it");
  if (m_speeds->count() > 0 && sweep.speeds.empty())
    throw UsageError("--speeds: FROM:TO:COUNT or W1,W2,... [rad/s], 1 to 100000 speeds, "
                     "got ''");
  sweep.paper_run_options.clear();
  for (const CLI::Option* o : {m_casing, m_selection, m_step, m_safety})
    if (o->count() > 0) sweep.paper_run_options.push_back(o->get_name());
}


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

/// The case's sweep, checked (case_kinds.hpp reads which kind of case it is).
std::unique_ptr<SweepPoints> sweep_points_of(const SweepOptions& options, int jobs) {
  return visit_case(options.case_path, options.load,
                    [&](const auto& c) { return case_sweep(c, options, jobs); });
}

double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const size_t n = x.size();
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

} // namespace

int SweepCommand::run(StagedOutput& output) {
  check_option_rules();
  single_threaded_blas(); // rows independent of the cores a rank gets (blas_threads.hpp)
  const SweepOptions& options = m_options;
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
  // On every rank: each runs its share. A rank other than 0 stopped while it
  // builds its bases (a signal an eigensolver polled, out of memory) tells
  // rank 0 and ends, as a stopped run does (sweep_driver.cpp): leaving by
  // the exception, it would wait in MPI_Finalize for rank 0, which waits
  // for its rows.
  try {
    points->prepare();
  } catch (const std::exception& e) {
    if (mpi.rank() != 0) mpi.end_reported(failure_message(e));
    throw;
  }
  std::unique_ptr<StreamedTextFile> csv;
  std::string written = options.out + "/sweep.csv"; // the files the last line names
  if (mpi.rank() == 0) {
    for (const auto& [name, text] : points->side_files()) {
      write_text_file(stage + "/" + name, text);
      written += ", " + options.out + "/" + name;
    }
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
  output.announce("wrote " + written + ", " + options.out + "/sweep_summary.json\n");
  if (options.report) {
    if (!write_report(points->report_script(), stage, options.out)) return 1;
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

std::unique_ptr<Command> add_sweep_command(CLI::App& app) {
  return std::make_unique<SweepCommand>(app);
}

} // namespace rsi
