// The sweep driver's talk between ranks when a signal comes (sweep_driver.hpp),
// on a rank of its own with recorded messages instead of MPI: a rank other
// than 0 that stops must tell rank 0 whenever the signal came, during a run
// or between two. CI (session 31) hung when it came between: rank 1 left
// without a word, rank 0 waited for its rows, rank 1 for rank 0 in
// MPI_Finalize (sweep_mpi_interrupted.sh, the end-to-end test).

#include <atomic>
#include <csignal>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "interruption_flag.hpp"
#include "sweep_driver.hpp"

namespace rsi {
namespace {

/// Tasks that finish at once; the signal "comes" after `signal_after` of
/// them have finished, before the next starts (or never, if -1).
class SignalledPoints : public SweepPoints {
public:
  SignalledPoints(int n_speeds, int signal_after)
      : m_signal_after(signal_after) {
    for (int s = 0; s < n_speeds; ++s)
      m_speeds.push_back(100.0 + s);
  }
  bool signalled() const { return m_signal_after >= 0 && m_finished >= m_signal_after; }
  int finished() const { return m_finished; }

  const std::vector<double>& speeds() const override { return m_speeds; }
  int n_runs() const override { return 1; }
  std::string run_name(int) const override { return "run"; }
  void prepare() override {}
  double cost(double, int) const override { return 1.0; }
  std::string csv_header() const override { return "speed\n"; }
  SweepTaskResult run(double speed, int, bool) const override {
    SweepTaskResult r;
    r.row = std::to_string(speed) + "\n";
    ++m_finished;
    return r;
  }
  std::string failed_row(double speed, int) const override { return std::to_string(speed) + "\n"; }
  std::vector<std::pair<std::string, std::string>> side_files() const override { return {}; }
  nlohmann::json summary() const override { return {}; }
  nlohmann::json run_summary(int) const override { return {}; }
  std::string report_script() const override { return ""; }

private:
  std::vector<double> m_speeds;
  int m_signal_after;
  mutable std::atomic<int> m_finished{0};
};

/// Rank `rank` of `size`, recording what it sends to rank 0.
class RecordingRanks : public SweepRanks {
public:
  RecordingRanks(int rank, int size)
      : m_rank(rank)
      , m_size(size) {}
  int rank() const override { return m_rank; }
  int size() const override { return m_size; }
  void send_task(int, double, const std::string&) const override { ++tasks; }
  void send_done() const override { ++dones; }
  void send_fatal(const std::string& what) const override { fatals.push_back(what); }
  bool poll(SweepMessage&) const override { return false; }

  mutable int tasks = 0;
  mutable int dones = 0;
  mutable std::vector<std::string> fatals;

private:
  int m_rank;
  int m_size;
};

SweepDriverOptions signal_options(const SignalledPoints& points) {
  SweepDriverOptions options;
  options.jobs = 1;
  options.quiet = true;
  options.stop_requested = [&points] { return points.signalled(); };
  options.throw_if_stopped = [&points] {
    if (points.signalled()) throw Interrupted(SIGTERM);
  };
  return options;
}

void no_row(const std::string&) {}

TEST(SweepDriver, RankStoppedBetweenRunsTellsRankZero) {
  // 8 speeds of equal cost on 2 ranks: 4 are rank 1's (sweep_schedule.hpp);
  // the signal after its first, before its second.
  const SignalledPoints points(8, 1);
  const RecordingRanks ranks(1, 2);
  EXPECT_THROW(drive_sweep(points, ranks, signal_options(points), no_row), Interrupted);
  EXPECT_EQ(points.finished(), 1) << "no run starts after the signal";
  EXPECT_EQ(ranks.tasks, 1);
  EXPECT_EQ(ranks.dones, 0);
  ASSERT_EQ(ranks.fatals.size(), 1u) << "rank 0 is told once";
  EXPECT_NE(ranks.fatals[0].find("interrupted by SIGTERM"), std::string::npos) << ranks.fatals[0];
}

TEST(SweepDriver, RankStoppedAfterItsLastRunTellsRankZero) {
  // The signal after all 4 of rank 1's runs, before the rank ends.
  const SignalledPoints points(8, 4);
  const RecordingRanks ranks(1, 2);
  EXPECT_THROW(drive_sweep(points, ranks, signal_options(points), no_row), Interrupted);
  EXPECT_EQ(ranks.tasks, 4);
  EXPECT_EQ(ranks.dones, 0);
  ASSERT_EQ(ranks.fatals.size(), 1u);
  EXPECT_NE(ranks.fatals[0].find("interrupted by SIGTERM"), std::string::npos) << ranks.fatals[0];
}

TEST(SweepDriver, RankWithoutSignalSendsItsRowsAndDone) {
  const SignalledPoints points(8, -1);
  const RecordingRanks ranks(1, 2);
  drive_sweep(points, ranks, signal_options(points), no_row);
  EXPECT_EQ(ranks.tasks, 4);
  EXPECT_EQ(ranks.dones, 1);
  EXPECT_TRUE(ranks.fatals.empty());
}

TEST(SweepDriver, OneProcessStoppedBetweenRunsThrowsAndSendsNothing) {
  const SignalledPoints points(4, 2);
  const RecordingRanks ranks(0, 1);
  std::vector<std::string> rows;
  EXPECT_THROW(drive_sweep(points, ranks, signal_options(points),
                           [&](const std::string& row) { rows.push_back(row); }),
               Interrupted);
  EXPECT_EQ(points.finished(), 2);
  EXPECT_TRUE(ranks.fatals.empty());
  EXPECT_EQ(ranks.dones, 0);
}

} // namespace
} // namespace rsi
