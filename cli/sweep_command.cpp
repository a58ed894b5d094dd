// rsi sweep: the case's runs over its rotation speeds (issue 15), each run
// reduced to a row of indicators (sweep/sweep_indicators.hpp), alone on
// --jobs threads or over MPI ranks (cli/mpi_session.hpp). Rows are written
// in (speed, run) order as soon as the rows before them are in, and a row
// depends only on its (speed, run): one process, threads or ranks give the
// same sweep.csv byte for byte.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "casing.hpp"
#include "casing_memory.hpp"
#include "commands.hpp"
#include "critical_step.hpp"
#include "failure_remedies.hpp"
#include "interaction_lines.hpp"
#include "interruption.hpp"
#include "modal_analysis.hpp"
#include "mpi_session.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "reduced_run.hpp"
#include "reference_run.hpp"
#include "report_script.hpp"
#include "run_outputs.hpp"
#include "run_step.hpp"
#include "staged_output.hpp"
#include "sweep_indicators.hpp"
#include "sweep_schedule.hpp"

namespace rsi {
namespace {

/// One run of the sweep's list, prepared once for every speed: its basis
/// (the rotation enters only through contact) and its expected cost.
struct PreparedRun {
  CampaignRun run;
  std::optional<ReducedBasis> basis; ///< reduced methods
  double basis_seconds = 0.0;
  double cost = 0.0; ///< expected steps x integrated coordinates a speed (the schedule's weight)
};

/// What a task left: its CSV row and, when it failed, why.
struct TaskResult {
  int task = -1;
  double seconds = 0.0;
  std::string row;
  std::string error; ///< empty unless the run failed
};

/// The run's name in sweep.csv: "full", or the campaign's "cb-44-dt-own".
std::string run_name(const CampaignRun& run) {
  return run.method == "full" ? "full" : run.name();
}

/// --speeds "FROM:TO:COUNT" or "W1,W2,...".
std::vector<double> parse_speeds_option(const std::string& text) {
  const auto number = [&](const std::string& s) {
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(x) || x < 0.0 || x >= 1e5)
      throw UsageError("--speeds: each speed must be a number in [0, 100000) rad/s, got '" + s +
                       "' in '" + text + "'");
    return x;
  };
  std::vector<std::string> parts;
  const char separator = text.find(':') != std::string::npos ? ':' : ',';
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);)
    parts.push_back(part);
  if (separator == ',') {
    if (parts.empty() || parts.size() > 100000)
      throw UsageError("--speeds: 1 to 100000 speeds, got '" + text + "'");
    std::vector<double> speeds;
    for (const std::string& p : parts)
      speeds.push_back(number(p));
    return speeds;
  }
  if (parts.size() != 3)
    throw UsageError("--speeds: FROM:TO:COUNT or W1,W2,... [rad/s], got '" + text + "'");
  const double from = number(parts[0]);
  const double to = number(parts[1]);
  char* end = nullptr;
  const long count = std::strtol(parts[2].c_str(), &end, 10);
  if (parts[2].empty() || *end != '\0' || count < 1 || count > 100000)
    throw UsageError("--speeds: COUNT must be an integer in [1, 100000], got '" + parts[2] + "'");
  if (count > 1 && !(to > from))
    throw UsageError("--speeds: TO must be above FROM when COUNT > 1, got '" + text + "'");
  std::vector<double> speeds;
  for (long i = 0; i < count; ++i) // the case file's formula (case_file.cpp read_speeds)
    speeds.push_back(count == 1 ? from : from + (to - from) * static_cast<double>(i) / (count - 1));
  return speeds;
}

/// The case of one speed: the sweep's duration and damping.
Case case_at(const Case& c, double speed) {
  Case out = c;
  out.operating_point.rotation_speed = speed;
  out.time.duration = c.sweep.duration;
  out.damping = c.sweep.damping;
  return out;
}

std::string csv_header() {
  return "speed_rad_s,run,method,modes,status,diverged,rows,max_tip_radial_m,"
         "max_tip_tangential_m,max_contact_force_n,contact_fraction,energy_ratio,f1_hz,a1_m,"
         "f2_hz,a2_m,f3_hz,a3_m\n";
}

std::string csv_row(double speed, const CampaignRun& run, const std::string& status,
                    const SweepIndicators* ind) {
  std::string row;
  append_csv_number(row, speed);
  row += "," + run_name(run) + "," + run.method + "," + std::to_string(run.modes) + "," + status +
         "," + (status == "diverged" ? "1" : "0") + ",";
  if (ind == nullptr) return row + ",,,,,,,,,,,\n";
  row += std::to_string(ind->rows);
  for (double x : {ind->max_tip_radial, ind->max_tip_tangential, ind->max_contact_force,
                   ind->contact_fraction, ind->energy_ratio}) {
    row += ",";
    if (ind->rows > 0) append_csv_number(row, x);
  }
  for (size_t i = 0; i < 3; ++i) {
    row += ",";
    if (i < ind->peaks.size()) append_csv_number(row, ind->peaks[i].frequency_hz);
    row += ",";
    if (i < ind->peaks.size()) append_csv_number(row, ind->peaks[i].amplitude);
  }
  return row + "\n";
}

/// Expected steps x integrated coordinates of one speed: the weight of the
/// rank schedule (sweep_schedule.hpp), not a measurement.
double expected_cost(const Case& c, const PreparedRun& r, int disk_dofs, const Casing& casing,
                     double casing_omega_max) {
  const double interval = c.time.step * c.time.output_every;
  if (r.run.method == "full") return c.sweep.duration / c.time.step * (disk_dofs + casing.n_dofs());
  const int casing_coordinates = r.run.casing_modes > 0 ? r.run.casing_modes + 1 : casing.n_dofs();
  double dt = c.time.step;
  if (r.run.step.kind == StepRule::Kind::given) dt = r.run.step.step;
  if (r.run.step.kind == StepRule::Kind::own) {
    double omega = reduced_omega_max(*r.basis);
    if (r.run.casing_modes == 0) omega = std::max(omega, casing_omega_max);
    dt = interval / std::ceil(interval / (r.run.step.safety * 2.0 / omega));
  }
  return c.sweep.duration / dt * (r.basis->n_reduced() + casing_coordinates);
}

/// One (speed, run): the indicators of its history, or why it failed.
TaskResult run_task(const Case& c, const PreparedRun& r, double speed, bool inject_failure) {
  const Case at = case_at(c, speed);
  SweepIndicatorAccumulator indicators(c.sweep.transient, c.time.step * c.time.output_every);
  ReducedRunOptions options;
  options.step = r.run.step;
  options.step_key = c.source + ": sweep run " + run_name(r.run) + ": time_step";
  options.casing_modes = r.run.casing_modes;
  options.selection = r.run.selection;
  options.run.checkpoint = throw_if_interrupted;
  options.run.tip_displacement = true;
  options.run.history_sink = [&](const HistoryRow& row) { indicators.add(row); };
  TaskResult out;
  try {
    if (inject_failure)
      throw std::runtime_error("injected failure (RSI_SWEEP_FAIL_SPEED, for the tests)");
    const RunResult result =
        r.run.method == "full" ? run_reference(at, options.run) : run_reduced(at, *r.basis, options).run;
    const SweepIndicators ind = indicators.finish();
    out.seconds = result.summary.wall_seconds;
    out.row = csv_row(speed, r.run, result.summary.completed ? "completed" : "diverged", &ind);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw; // out of memory ends the sweep, not one speed
  } catch (const StabilityError& e) {
    // A sweep has no --force: the remedy is the key that set the step.
    out.row = csv_row(speed, r.run, "failed", nullptr);
    out.error = without_force(
        std::string(e.what()),
        r.run.step.kind == StepRule::Kind::given
            ? "a smaller time_step of run " + run_name(r.run) +
                  " (sweep.runs or --time-step), dividing the output interval, or \"own\"; a "
                  "sweep has no --force"
            : "time.step; a sweep has no --force");
  } catch (const std::exception& e) {
    out.row = csv_row(speed, r.run, "failed", nullptr);
    out.error = e.what();
  }
  return out;
}

std::string speed_text(double speed) {
  std::string s;
  append_csv_number(s, speed);
  return s;
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
  Case c = load_case(options.case_path);
  if (!c.sweep.present())
    throw UsageError(c.source + ": key 'sweep': missing; a sweep needs its duration, transient, "
                                "damping and runs (data/README.md)");
  if (!options.speeds.empty()) c.sweep.speeds = parse_speeds_option(options.speeds);
  if (!options.method.empty()) {
    CampaignRun one;
    one.method = options.method;
    one.modes = options.modes;
    one.selection = options.selection;
    one.casing_modes = options.casing_modes;
    one.step = parse_step_option(options.time_step, options.step_safety);
    c.sweep.runs = {one};
  }
  const int jobs = options.jobs == 0 ? (mpi.size() > 1 ? 1 : 2) : options.jobs;
  if (jobs < 1 || jobs > 64)
    throw UsageError("--jobs: must be in [1, 64], got " + std::to_string(options.jobs));
  const int disk_dofs =
      check_runs_against_model(c, c.sweep.runs, c.source + ": key 'sweep.runs'", jobs);
  {
    const Casing casing = assemble_casing(c);
    if (std::any_of(c.sweep.runs.begin(), c.sweep.runs.end(),
                    [](const CampaignRun& r) { return r.method == "full"; }))
      check_case_step_bound(c, casing, "sweep");
    // The reduced runs' dense casing matrices, one a thread (casing_memory.hpp).
    if (std::any_of(c.sweep.runs.begin(), c.sweep.runs.end(),
                    [](const CampaignRun& r) { return r.method != "full"; }))
      check_dense_casing_fits(c, casing.n_dofs(), jobs);
  }
  int inject = -1; // the speed index whose runs fail on purpose (tests only)
  if (const char* text = std::getenv("RSI_SWEEP_FAIL_SPEED")) inject = std::atoi(text);

  // --out is rank 0's alone, opened before any run (a bad --out: exit 2, nothing run).
  std::string stage;
  if (mpi.rank() == 0) stage = output.open(options.out, "--out", sweep_output_set());

  // The bases, once for every speed (on every rank: each needs them).
  const Casing casing = assemble_casing(c);
  const double casing_omega = max_angular_frequency(casing.stiffness, casing.mass);
  std::vector<PreparedRun> runs(c.sweep.runs.size());
  for (size_t j = 0; j < runs.size(); ++j) {
    runs[j].run = c.sweep.runs[j];
    if (runs[j].run.method != "full") {
      const Clock::time_point t = Clock::now();
      runs[j].basis = build_reduced_basis(c, runs[j].run.method, runs[j].run.modes,
                                          runs[j].run.selection);
      runs[j].basis_seconds = seconds_since(t);
    }
    runs[j].cost = expected_cost(c, runs[j], disk_dofs, casing, casing_omega);
  }
  const int n_runs = static_cast<int>(runs.size());
  const int n_tasks = static_cast<int>(c.sweep.speeds.size()) * n_runs;
  std::vector<double> cost(static_cast<size_t>(n_tasks));
  for (int t = 0; t < n_tasks; ++t)
    cost[static_cast<size_t>(t)] = runs[static_cast<size_t>(t % n_runs)].cost;
  const std::vector<int> owner = balance_tasks(cost, mpi.size());
  std::vector<int> mine;
  for (int t = 0; t < n_tasks; ++t)
    if (owner[static_cast<size_t>(t)] == mpi.rank()) mine.push_back(t);

  std::unique_ptr<StreamedTextFile> csv;
  if (mpi.rank() == 0) {
    std::string lines = "family,nodal_diameter,blade_hz,casing_mode,casing_hz,speed_rad_s\n";
    for (const InteractionLine& l : interaction_lines(c, 2, 40)) {
      lines += std::to_string(l.family) + "," + std::to_string(l.nodal_diameter) + ",";
      append_csv_number(lines, l.blade_hz);
      lines += "," + std::to_string(l.casing_mode) + ",";
      append_csv_number(lines, l.casing_hz);
      lines += ",";
      append_csv_number(lines, l.speed_rad_s);
      lines += "\n";
    }
    write_text_file(stage + "/interaction_lines.csv", lines);
    csv = std::make_unique<StreamedTextFile>(stage + "/sweep.csv");
    csv->append(csv_header());
  }

  // Worker threads run this rank's tasks; the calling thread alone talks to
  // MPI and writes (MPI_THREAD_FUNNELED).
  std::mutex mutex;
  std::condition_variable wake;
  std::vector<TaskResult> finished;
  std::atomic<size_t> next{0};
  std::atomic<int> busy{0};
  std::string fatal; // a worker's error that ends the sweep (signal, out of memory)
  const int threads_n = std::max(1, std::min<int>(jobs, static_cast<int>(mine.size())));
  busy = threads_n;
  auto worker = [&]() {
    for (size_t i = next++; i < mine.size(); i = next++) {
      {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!fatal.empty() || pending_signal() != 0) break;
      }
      const int t = mine[i];
      try {
        TaskResult r = run_task(c, runs[static_cast<size_t>(t % n_runs)],
                                c.sweep.speeds[static_cast<size_t>(t / n_runs)], t / n_runs == inject);
        r.task = t;
        const std::lock_guard<std::mutex> lock(mutex);
        finished.push_back(std::move(r));
      } catch (const std::exception& e) {
        const std::lock_guard<std::mutex> lock(mutex);
        fatal = e.what();
      }
      wake.notify_one();
    }
    --busy;
    wake.notify_one();
  };
  std::vector<std::thread> threads;
  for (int i = 0; i < (mine.empty() ? 0 : threads_n); ++i)
    threads.emplace_back(worker);
  if (mine.empty()) busy = 0;

  // Rank 0: rows kept until every row before them is in, then written.
  std::vector<std::optional<std::string>> rows(static_cast<size_t>(n_tasks));
  std::vector<double> seconds(static_cast<size_t>(n_tasks), 0.0);
  std::vector<std::string> failures;
  int written = 0, received = 0, ranks_done = 1;
  Clock::time_point last_progress = Clock::now();
  auto keep = [&](const TaskResult& r, int rank) {
    rows[static_cast<size_t>(r.task)] = r.row;
    seconds[static_cast<size_t>(r.task)] = r.seconds;
    ++received;
    if (!r.error.empty())
      failures.push_back("speed " + speed_text(c.sweep.speeds[static_cast<size_t>(r.task / n_runs)]) +
                         " rad/s, run " + run_name(runs[static_cast<size_t>(r.task % n_runs)].run) +
                         " (rank " + std::to_string(rank) + "): " + r.error);
  };
  for (;;) {
    std::vector<TaskResult> batch;
    bool workers_done = false;
    {
      std::unique_lock<std::mutex> lock(mutex);
      wake.wait_for(lock, std::chrono::milliseconds(20),
                    [&] { return !finished.empty() || busy == 0; });
      batch.swap(finished);
      workers_done = busy == 0;
    }
    for (const TaskResult& r : batch) {
      if (mpi.rank() == 0)
        keep(r, 0);
      else
        mpi.send_task(r.task, r.seconds, r.row + r.error);
    }
    if (mpi.rank() != 0) {
      if (workers_done) break;
      continue;
    }
    for (RankMessage m; mpi.poll(m);) {
      if (m.kind == RankMessage::Kind::done) {
        ++ranks_done;
      } else if (m.kind == RankMessage::Kind::fatal) {
        ++ranks_done;
        // The rank's tasks that never came are failed rows: the sweep goes on.
        // (A row before `written` came and was written: not lost.)
        for (int t = written; t < n_tasks; ++t)
          if (owner[static_cast<size_t>(t)] == m.rank && !rows[static_cast<size_t>(t)]) {
            TaskResult lost;
            lost.task = t;
            lost.row = csv_row(c.sweep.speeds[static_cast<size_t>(t / n_runs)],
                               runs[static_cast<size_t>(t % n_runs)].run, "failed", nullptr);
            lost.error = "rank " + std::to_string(m.rank) + " stopped: " + m.text;
            keep(lost, m.rank);
          }
      } else {
        TaskResult r;
        r.task = m.task;
        r.seconds = m.seconds;
        const size_t end = m.text.find('\n');
        r.row = m.text.substr(0, end + 1);
        r.error = m.text.substr(end + 1);
        keep(r, m.rank);
      }
    }
    while (written < n_tasks && rows[static_cast<size_t>(written)]) {
      csv->append(*rows[static_cast<size_t>(written)]);
      rows[static_cast<size_t>(written)].reset();
      ++written;
    }
    if (!options.quiet && seconds_since(last_progress) >= 2.0 && received < n_tasks) {
      last_progress = Clock::now();
      const double elapsed = seconds_since(start);
      std::fprintf(stderr, "sweep: %d/%d runs done, %.0f s elapsed, about %.0f s left\n", received,
                   n_tasks, elapsed, received > 0 ? elapsed * (n_tasks - received) / received : 0.0);
    }
    if (workers_done && received == n_tasks && ranks_done == mpi.size()) break;
    if (workers_done && pending_signal() != 0) break;
    if (workers_done && !fatal.empty()) break;
  }
  for (std::thread& t : threads)
    t.join();
  if (!fatal.empty()) {
    if (mpi.rank() != 0) mpi.end_reported(fatal);
    throw_if_interrupted();
    throw std::runtime_error("sweep: " + fatal);
  }
  throw_if_interrupted();
  if (mpi.rank() != 0) {
    mpi.send_done();
    return 0;
  }
  csv->commit();

  nlohmann::json summary;
  summary["speeds"] = c.sweep.speeds;
  summary["duration_s"] = c.sweep.duration;
  summary["transient_s"] = c.sweep.transient;
  summary["window"] = "Hann (periodic), t >= transient, blade 1 radial tip displacement, mean "
                      "removed; resolution 1/(rows x output interval)";
  summary["damping"] = {{"rayleigh_alpha", c.sweep.damping.rayleigh.alpha},
                        {"rayleigh_beta", c.sweep.damping.rayleigh.beta},
                        {"modal_ratio", c.sweep.damping.modal_ratio}};
  summary["ranks"] = mpi.size();
  summary["jobs"] = jobs;
  summary["wall_s"] = seconds_since(start);
  summary["failures"] = failures;
  for (int j = 0; j < n_runs; ++j) {
    std::vector<double> per_speed;
    for (int t = j; t < n_tasks; t += n_runs)
      per_speed.push_back(seconds[static_cast<size_t>(t)]);
    double total = 0.0;
    for (double s : per_speed)
      total += s;
    const PreparedRun& r = runs[static_cast<size_t>(j)];
    summary["runs"].push_back({{"name", run_name(r.run)},
                               {"method", r.run.method},
                               {"modes", r.run.modes},
                               {"basis_s", r.basis_seconds},
                               {"wall_s_total", total},
                               {"wall_s_per_speed_median", median(per_speed)},
                               {"expected_cost_per_speed", r.cost}});
  }
  write_text_file(stage + "/sweep_summary.json", summary.dump(2) + "\n");
  std::printf("sweep: %d speeds x %d runs on %d rank(s) x %d thread(s) in %.1f s\n",
              static_cast<int>(c.sweep.speeds.size()), n_runs, mpi.size(), jobs,
              seconds_since(start));
  for (const std::string& f : failures)
    std::fprintf(stderr, "rsi: sweep: failed: %s\n", f.c_str());
  output.announce("wrote " + options.out + "/sweep.csv, " + options.out + "/interaction_lines.csv, " +
                  options.out + "/sweep_summary.json\n");
  if (options.report) {
    std::fflush(stdout);
    const int status = run_report_script("make_sweep_report.py", stage);
    if (status != 0) {
      std::fprintf(stderr,
                   "rsi: error: the report generator %s/make_sweep_report.py failed (status %d); "
                   "nothing was written to --out %s; fix it or use --no-report\n",
                   RSI_REPORTS_DIR, status, options.out.c_str());
      return 1;
    }
    output.announce("report: " + options.out + "/sweep_report.md\n");
  }
  if (!failures.empty()) {
    std::fprintf(stderr,
                 "rsi: error: numerical failure: %zu run(s) of the sweep failed (listed "
                 "above, each with what to change); the other rows are in sweep.csv\n",
                 failures.size());
    return 3;
  }
  return 0;
}

} // namespace rsi
