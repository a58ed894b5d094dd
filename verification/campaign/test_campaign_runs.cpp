// The campaign library (campaign/): the chunked gap norms the paper's
// campaign reads back from disk, the component campaign's norms, and what
// ends one run of the worker pool against what ends the whole campaign.

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "case_file.hpp"
#include "error_norms.hpp"
#include "paper_campaign.hpp"
#include "rubbing_campaign.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// A series in memory read in chunks, as the campaign reads its scratch files.
SeriesReader reader_of(const std::vector<double>& x, std::size_t& at) {
  return [&x, &at](double* out, std::size_t count) {
    std::size_t n = 0;
    for (; n < count && at < x.size(); ++n)
      out[n] = x[at++];
    return n;
  };
}

std::vector<double> wave(std::size_t n, double amplitude, double phase) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = amplitude * std::sin(1e-3 * static_cast<double>(i) + phase);
  return x;
}

TEST(ChunkedGapErrors, SameBitsAsTheWholeSeries) {
  // 20,001 rows: two full chunks of 8192 and a partial one.
  const std::vector<double> reference = wave(20001, 1e-4, 0.0);
  const std::vector<double> reduced = wave(20001, 1.02e-4, 0.01);
  std::size_t a = 0, b = 0;
  const SeriesReader read_reduced = reader_of(reduced, a);
  const SeriesReader read_reference = reader_of(reference, b);
  const GapErrors chunked = chunked_gap_errors(read_reduced, &read_reference);
  // error_norms.hpp: the same sums in the same order give the same bits.
  const GapErrors whole = gap_errors(reduced, reference);
  std::printf("e2 %.17g vs %.17g, e_inf %.17g vs %.17g\n", chunked.e2, whole.e2, chunked.e_inf,
              whole.e_inf);
  EXPECT_EQ(chunked.e2, whole.e2);
  EXPECT_EQ(chunked.e_inf, whole.e_inf);
  EXPECT_GT(whole.e2, 0.0);
}

TEST(ChunkedGapErrors, ReferenceAgainstItselfIsZero) {
  const std::vector<double> reference = wave(9000, 1e-4, 0.3);
  std::size_t a = 0;
  const GapErrors e = chunked_gap_errors(reader_of(reference, a), nullptr);
  std::printf("e2 %.3g, e_inf %.3g, rows read %zu\n", e.e2, e.e_inf, a);
  // e2 = ||g - g|| / ||g||: exactly 0 for a nonzero series.
  EXPECT_EQ(e.e2, 0.0);
  EXPECT_EQ(e.e_inf, 0.0);
  EXPECT_EQ(a, reference.size());
}

TEST(ChunkedGapErrors, ReferenceShorterThanTheRunIsRefused) {
  const std::vector<double> reduced = wave(100, 1.0, 0.0);
  const std::vector<double> reference = wave(99, 1.0, 0.0);
  std::size_t a = 0, b = 0;
  const SeriesReader read_reference = reader_of(reference, b);
  EXPECT_THROW(chunked_gap_errors(reader_of(reduced, a), &read_reference), std::runtime_error);
}

TEST(RubbingErrorNorms, ScaledRunGivesTheScale) {
  // x = 1.01 x_ref and Lambda = 1.01 Lambda_ref: every norm of
  // rubbing_campaign.hpp is 0.01. Each difference 1.01 x - x is exact
  // (Sterbenz) after the product's rounding (eps |1.01 x|), so relative to
  // 0.01 |x| it is off by at most 101 eps; the sums and the square root add
  // a few eps: |e - 0.01| <= 0.01 x 200 eps.
  RubbingCampaignRun ref, run;
  for (int j = 0; j < 500; ++j) {
    const double x = std::sin(0.05 * j) + 2.0;
    Eigen::VectorXd lambda(3);
    lambda << x, 0.5 * x, 0.0;
    ref.response.push_back(x);
    ref.lambda_n.push_back(lambda);
    run.response.push_back(1.01 * x);
    run.lambda_n.push_back(1.01 * lambda);
  }
  const RubbingErrorNorms e = rubbing_error_norms(run, ref);
  std::printf("e2_response %.17g, einf_response %.17g, e2_lambda %.17g, einf_lambda %.17g\n",
              e.e2_response, e.einf_response, e.e2_lambda, e.einf_lambda);
  const double tolerance = 0.01 * 200 * eps;
  EXPECT_NEAR(e.e2_response, 0.01, tolerance);
  EXPECT_NEAR(e.einf_response, 0.01, tolerance);
  EXPECT_NEAR(e.e2_lambda, 0.01, tolerance);
  EXPECT_NEAR(e.einf_lambda, 0.01, tolerance);
  // With no rows (a run refused before its first step) there is no norm.
  const RubbingErrorNorms none = rubbing_error_norms(RubbingCampaignRun{}, ref);
  EXPECT_TRUE(std::isnan(none.e2_response));
}

/// The paper's case over 200 steps (4 history rows): the reference and two
/// reduced runs, one of them with more modes than the model has.
Case short_campaign() {
  Case c = load_case(RSI_SOURCE_DIR "/data/cases/batailly2007.json");
  c.time.duration = 200 * c.time.step;
  CampaignRun cb;
  cb.method = "cb";
  cb.modes = 10;
  CampaignRun too_many = cb;
  too_many.modes = 100000; // above the interior dofs: the basis is refused
  c.campaign = {cb, too_many};
  return c;
}

PaperCampaignHooks quiet_hooks() {
  PaperCampaignHooks hooks;
  hooks.row = [](std::size_t, const HistoryRow&) {};
  hooks.progress = [](std::size_t, double) {};
  hooks.finished = [](std::size_t, PaperCampaignJob&) {};
  hooks.checkpoint = [] {};
  hooks.stop_requested = [] { return false; };
  return hooks;
}

TEST(PaperCampaign, ARunsOwnFailureIsRecordedAndTheOthersGoOn) {
  const Case c = short_campaign();
  std::vector<PaperCampaignJob> jobs = paper_campaign_jobs(c);
  ASSERT_EQ(jobs.size(), 3u);
  std::vector<int> rows(jobs.size(), 0);
  PaperCampaignHooks hooks = quiet_hooks();
  hooks.row = [&rows](std::size_t job, const HistoryRow&) { ++rows[job]; };
  run_paper_campaign(c, jobs, 2, 2, hooks);
  for (std::size_t i = 0; i < jobs.size(); ++i)
    std::printf("job %zu %s: %d rows, error '%s'\n", i, jobs[i].run.name().c_str(), rows[i],
                jobs[i].error.c_str());
  EXPECT_EQ(jobs[0].run.method, "full");
  EXPECT_TRUE(jobs[0].error.empty());
  EXPECT_TRUE(jobs[1].error.empty());
  EXPECT_EQ(jobs[1].modes_kept, 10);
  EXPECT_FALSE(jobs[2].error.empty()); // the refused basis, recorded
  EXPECT_FALSE(jobs[2].step_refused);
  // 200 steps, a row every 50 and the initial one: 5 rows each run.
  EXPECT_EQ(rows[0], 5);
  EXPECT_EQ(rows[1], 5);
  EXPECT_EQ(rows[2], 0);
}

TEST(PaperCampaign, AFailedRowHookEndsTheCampaign) {
  // A failed write (the disk, not the run) must end the campaign, thrown
  // to the caller, not be recorded as that run's failure.
  const Case c = short_campaign();
  std::vector<PaperCampaignJob> jobs = paper_campaign_jobs(c);
  PaperCampaignHooks hooks = quiet_hooks();
  hooks.row = [](std::size_t job, const HistoryRow&) {
    if (job == 1) throw std::runtime_error("disk full");
  };
  try {
    run_paper_campaign(c, jobs, 1, 1, hooks);
    ADD_FAILURE() << "no exception; job 1 error '" << jobs[1].error << "'";
  } catch (const std::runtime_error& e) {
    std::printf("thrown: %s\n", e.what());
    EXPECT_STREQ(e.what(), "disk full");
  }
}

} // namespace
} // namespace rsi
