#include "sweep_driver.hpp"

#include <atomic>
#include <charconv>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "failure_advice.hpp"
#include "sweep_schedule.hpp"
#include "worker_threads.hpp"

namespace rsi {

std::string sweep_speed_text(double speed) {
  char buffer[32]; // sweep.csv's format (run_outputs.hpp append_csv_number)
  const std::to_chars_result r =
      std::to_chars(buffer, buffer + sizeof buffer, speed, std::chars_format::general, 17);
  return std::string(buffer, r.ptr);
}

SweepOutcome drive_sweep(const SweepPoints& points, const SweepRanks& ranks,
                         const SweepDriverOptions& options,
                         const std::function<void(const std::string&)>& write_row) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  const std::vector<double>& speeds = points.speeds();
  const int n_runs = points.n_runs();
  const int n_tasks = static_cast<int>(speeds.size()) * n_runs;
  const auto speed_of = [&](int t) { return speeds[static_cast<size_t>(t / n_runs)]; };
  std::vector<double> cost(static_cast<size_t>(n_tasks));
  for (int t = 0; t < n_tasks; ++t)
    cost[static_cast<size_t>(t)] = points.cost(speed_of(t), t % n_runs);
  const std::vector<int> owner = balance_tasks(cost, ranks.size());
  std::vector<int> mine;
  for (int t = 0; t < n_tasks; ++t)
    if (owner[static_cast<size_t>(t)] == ranks.rank()) mine.push_back(t);

  // This rank's tasks on its worker threads (run_on_threads) under one host
  // thread; the calling thread alone talks to the other ranks and writes.
  std::mutex mutex;
  std::condition_variable wake;
  std::vector<SweepTaskResult> finished;
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  bool host_done = mine.empty();
  std::string fatal; // a worker's error that ends the sweep (signal, out of memory)
  const int threads_n = std::max(1, std::min<int>(options.jobs, static_cast<int>(mine.size())));
  const std::function<void()> worker = [&]() {
    for (size_t i = next++; i < mine.size(); i = next++) {
      if (failed || options.stop_requested()) return;
      const int t = mine[i];
      SweepTaskResult r = points.run(speed_of(t), t % n_runs, t / n_runs == options.inject_speed);
      r.task = t;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        finished.push_back(std::move(r));
      }
      wake.notify_one();
    }
  };
  const auto host = [&]() noexcept {
    std::string error;
    try {
      run_on_threads(threads_n, worker, failed);
    } catch (const std::exception& e) {
      error = failure_message(e);
    } catch (...) {
      error = "a worker thread failed";
    }
    {
      const std::lock_guard<std::mutex> lock(mutex);
      fatal = error;
      host_done = true;
    }
    wake.notify_one();
  };
  std::optional<std::thread> host_thread;
  if (!mine.empty()) {
    try {
      host_thread.emplace(host);
    } catch (const std::system_error&) {
      host(); // no thread for the host: the caller runs the workers, then collects
    }
  }

  // Rank 0: rows kept until every row before them is in, then written.
  SweepOutcome out;
  std::vector<std::optional<std::string>> rows(static_cast<size_t>(n_tasks));
  out.seconds.assign(static_cast<size_t>(n_tasks), 0.0);
  int written = 0, received = 0, ranks_done = 1;
  Clock::time_point last_progress = Clock::now();
  const auto keep = [&](const SweepTaskResult& r, int rank) {
    rows[static_cast<size_t>(r.task)] = r.row;
    out.seconds[static_cast<size_t>(r.task)] = r.seconds;
    ++received;
    if (!r.error.empty())
      out.failures.push_back("speed " + sweep_speed_text(speed_of(r.task)) + " rad/s, run " +
                             points.run_name(r.task % n_runs) + " (rank " + std::to_string(rank) +
                             "): " + r.error);
  };
  bool workers_done = false;
  std::string fatal_seen;
  for (;;) {
    std::vector<SweepTaskResult> batch;
    {
      std::unique_lock<std::mutex> lock(mutex);
      wake.wait_for(lock, std::chrono::milliseconds(20),
                    [&] { return !finished.empty() || host_done; });
      batch.swap(finished);
      workers_done = host_done;
      fatal_seen = fatal;
    }
    for (const SweepTaskResult& r : batch) {
      if (ranks.rank() == 0)
        keep(r, 0);
      else
        ranks.send_task(r.task, r.seconds, r.row + r.error);
    }
    if (ranks.rank() != 0) {
      if (workers_done) break;
      continue;
    }
    for (SweepMessage m; ranks.poll(m);) {
      if (m.kind == SweepMessage::Kind::done) {
        ++ranks_done;
      } else if (m.kind == SweepMessage::Kind::fatal) {
        ++ranks_done;
        // The rank's tasks that never came are failed rows: the sweep goes on.
        // (A row before `written` came and was written: not lost.)
        for (int t = written; t < n_tasks; ++t)
          if (owner[static_cast<size_t>(t)] == m.rank && !rows[static_cast<size_t>(t)]) {
            SweepTaskResult lost;
            lost.task = t;
            lost.row = points.failed_row(speed_of(t), t % n_runs);
            lost.error = "rank " + std::to_string(m.rank) + " stopped: " + m.text;
            keep(lost, m.rank);
          }
      } else {
        SweepTaskResult r;
        r.task = m.task;
        r.seconds = m.seconds;
        const size_t end = m.text.find('\n');
        r.row = m.text.substr(0, end + 1);
        r.error = m.text.substr(end + 1);
        keep(r, m.rank);
      }
    }
    while (written < n_tasks && rows[static_cast<size_t>(written)]) {
      write_row(*rows[static_cast<size_t>(written)]);
      rows[static_cast<size_t>(written)].reset();
      ++written;
    }
    if (!options.quiet && since(last_progress) >= 2.0 && received < n_tasks) {
      last_progress = Clock::now();
      const double elapsed = since(start);
      std::fprintf(stderr, "sweep: %d/%d runs done, %.0f s elapsed, about %.0f s left\n", received,
                   n_tasks, elapsed, received > 0 ? elapsed * (n_tasks - received) / received : 0.0);
    }
    if (workers_done && received == n_tasks && ranks_done == ranks.size()) break;
    if (workers_done && options.stop_requested()) break;
    if (workers_done && !fatal_seen.empty()) break;
  }
  if (host_thread) host_thread->join();
  // A signal between this rank's runs (none of them saw it): rank 0 must
  // hear of it as of a run's, or it waits for rows that never come while
  // this rank waits for it in MPI_Finalize (CI, session 31: a hang). Read
  // once: the one read decides between the fatal word and done, so no
  // signal in between can leave rank 0 without either. (A signal after the
  // last row was sent marks nothing lost: rank 0 publishes every row.)
  if (ranks.rank() != 0 && fatal_seen.empty()) {
    try {
      options.throw_if_stopped();
    } catch (const std::exception& e) {
      fatal_seen = failure_message(e);
    }
  }
  if (!fatal_seen.empty()) {
    if (ranks.rank() != 0) ranks.send_fatal(fatal_seen);
    options.throw_if_stopped();
    throw std::runtime_error("sweep: " + fatal_seen);
  }
  if (ranks.rank() == 0)
    options.throw_if_stopped();
  else
    ranks.send_done(); // a signal from here on ends the process after MPI_Finalize
  return out;
}

} // namespace rsi
