// Streamed output (issue 6): a run that hands its history rows to a
// HistorySink as they are produced (what `rsi simulate` does, so its memory
// stays flat) gives the same history.csv, byte for byte, as the in-memory
// History formatted by history_csv (what `rsi campaign` and the tests use),
// keeps nothing in RunResult::history, and closes the same summary. Checked
// on a completed run with contact, on a run stopped by a blow-up (the sprag
// case, whose history simulate still writes), and on a reduced run with its
// full field.

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "reduced_run.hpp"
#include "reference_run.hpp"
#include "run_outputs.hpp"

namespace rsi {
namespace {

Case short_case() {
  Case c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  // 5 ms: blade 1 is in contact from 3.96 ms. A row every 7 steps, so the
  // last step (10000) is a row only through the final-step rule.
  c.time.duration = 0.005;
  c.time.output_every = 7;
  return c;
}

/// A sink that formats every row as simulate does, into one string.
struct StreamedCsv {
  std::string csv;
  int rows = 0;
  HistorySink sink() {
    return [this](const HistoryRow& row) {
      if (rows++ == 0)
        csv = history_csv_header(static_cast<int>(row.gap.size()), history_csv_tangents(row));
      append_history_csv_row(csv, row);
    };
  }
};

/// Position of the first differing byte (npos: equal).
size_t first_difference(const std::string& a, const std::string& b) {
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (a[i] != b[i]) return i;
  return a.size() == b.size() ? std::string::npos : std::min(a.size(), b.size());
}

void expect_same_summary(const RunSummary& kept, const RunSummary& streamed) {
  EXPECT_EQ(kept.status, streamed.status);
  EXPECT_EQ(kept.steps, streamed.steps);
  EXPECT_EQ(kept.max_penetration, streamed.max_penetration);
  EXPECT_EQ(kept.min_lambda, streamed.min_lambda);
  EXPECT_EQ(kept.max_complementarity, streamed.max_complementarity);
  EXPECT_EQ(kept.energy_balance_error, streamed.energy_balance_error);
  EXPECT_EQ(kept.final_external_work, streamed.final_external_work);
  EXPECT_EQ(kept.final_contact_work, streamed.final_contact_work);
  EXPECT_EQ(kept.contact_intervals_blade_1, streamed.contact_intervals_blade_1);
}

void expect_same_csv(const RunResult& kept, const RunResult& streamed, const StreamedCsv& csv) {
  const std::string whole = history_csv(kept.history);
  const size_t at = first_difference(whole, csv.csv);
  std::printf("%s: %d rows kept, %d streamed, %zu and %zu bytes, first difference at %s\n",
              kept.summary.status.c_str(), kept.history.n_rows(), csv.rows, whole.size(),
              csv.csv.size(), at == std::string::npos ? "none" : std::to_string(at).c_str());
  EXPECT_EQ(at, std::string::npos);
  EXPECT_EQ(streamed.history.n_rows(), 0) << "a streamed run must keep no rows";
  EXPECT_EQ(csv.rows, kept.history.n_rows());
  expect_same_summary(kept.summary, streamed.summary);
}

TEST(StreamedHistory, CompletedReferenceRunStreamsTheSameBytes) {
  const Case c = short_case();
  const RunResult kept = run_reference(c, {});
  StreamedCsv csv;
  RunOptions options;
  options.history_sink = csv.sink();
  const RunResult streamed = run_reference(c, options);
  ASSERT_TRUE(kept.summary.completed) << kept.summary.status;
  ASSERT_GT(kept.summary.first_contact_step, 0) << "the short case must reach contact";
  EXPECT_EQ(kept.history.n_rows(), 1 + 10000 / 7 + 1);
  expect_same_csv(kept, streamed, csv);
}

TEST(StreamedHistory, StoppedRunStreamsTheSameBytes) {
  // The sprag case (kink reversed) blows up at 6.6 ms; the rows up to the
  // stop, the row of the stopping step included, are streamed as kept.
  Case c = short_case();
  c.bladed_disk.kink_angle = -c.bladed_disk.kink_angle;
  c.time.duration = 0.008;
  const RunResult kept = run_reference(c, {});
  StreamedCsv csv;
  RunOptions options;
  options.history_sink = csv.sink();
  const RunResult streamed = run_reference(c, options);
  ASSERT_FALSE(kept.summary.completed) << "the sprag case must blow up";
  expect_same_csv(kept, streamed, csv);
}

TEST(StreamedHistory, ReducedRunStreamsHistoryAndField) {
  const Case c = short_case();
  ReducedRunOptions kept_options;
  kept_options.full_field = true;
  const ReducedRunResult kept = run_reduced(c, "cb", 10, kept_options);

  StreamedCsv csv;
  Eigen::MatrixXd field(kept.field.rows(), kept.field.cols());
  std::vector<double> field_time;
  ReducedRunOptions options;
  options.full_field = true;
  options.run.history_sink = csv.sink();
  options.field_sink = [&](double t, const Eigen::VectorXd& u) {
    ASSERT_LT(static_cast<Eigen::Index>(field_time.size()), field.rows());
    field.row(static_cast<Eigen::Index>(field_time.size())) = u.transpose();
    field_time.push_back(t);
  };
  const ReducedRunResult streamed = run_reduced(c, "cb", 10, options);
  ASSERT_TRUE(kept.run.summary.completed) << kept.run.summary.status;
  expect_same_csv(kept.run, streamed.run, csv);

  EXPECT_EQ(streamed.field.size(), 0) << "a streamed field must not be kept";
  ASSERT_EQ(static_cast<int>(field_time.size()), kept.run.history.n_rows());
  EXPECT_EQ(field_time, kept.run.history.time);
  const double d = (field - kept.field).cwiseAbs().maxCoeff();
  std::printf("field: %zu rows of %td dofs, max |streamed - kept| = %.3e m\n", field_time.size(),
              field.cols(), d);
  EXPECT_EQ(d, 0.0);
}

} // namespace
} // namespace rsi
