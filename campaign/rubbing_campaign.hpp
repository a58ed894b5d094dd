#pragma once
// A component case's campaign (its rubbing.campaign): the full-order
// reference over rubbing.campaign.full_revolutions and every reduced run of
// rubbing.campaign.runs over rubbing.revolutions, each at its own stable
// step and sampled at the same instants (rubbing_run.hpp), one after the
// other (their wall times are the cost table), with the error norms of the
// response dof and of the contact forces over the reference's window.
//
// Norms over the rows j of the window (the reference's rows), x the
// response dof, Lambda the normal multipliers of every contact:
//   e2_response = ||x - x_ref||_2 / ||x_ref||_2,
//   einf_response = max_j |x_j - x_ref,j| / max_j |x_ref,j|,
//   e2_lambda = ||Lambda - Lambda_ref||_F / ||Lambda_ref||_F,
//   einf_lambda = max |Lambda - Lambda_ref| / max |Lambda_ref|.
// With an abradable liner, the final wear profiles p (one depth a cell)
// compare the same way, when both runs cover the same revolutions:
//   e2_wear = ||p - p_ref||_2 / ||p_ref||_2,
//   einf_wear = max |p - p_ref| / max p_ref.

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "rubbing_run.hpp"

namespace rsi {

/// One run of the campaign, and what it left (its rows kept for the norms).
struct RubbingCampaignRun {
  std::string method;
  int modes = 0;                 ///< cc: n_c, the boundary's characteristic constraint modes
  int fixed_interface_modes = 0; ///< cc: eta
  int entry = -1;                ///< its entry's index in rubbing.campaign.runs (-1: the full run)
  RubbingRun run;
  std::vector<double> response;
  std::vector<Eigen::VectorXd> lambda_n;
  /// Every contact's gap per row, kept against the flexible casing only
  /// (the issue-27 norms; a rigid casing's campaign keeps its memory).
  std::vector<Eigen::VectorXd> gap;
  std::string error; ///< why the run could not be made, or its stop (empty: completed)
};

/// The full run first when rubbing.campaign.full_revolutions > 0, then each
/// method of rubbing.campaign with each of its mode counts.
std::vector<RubbingCampaignRun> rubbing_campaign_runs(const RubbingSetup& setup);

/// "full" or "<method>-<modes>": its folder under runs/ and its name in messages.
std::string rubbing_campaign_run_name(const RubbingCampaignRun& r);

/// Runs `entry` over its revolutions (the reference's or the reduced
/// runs'), each row to `sink` and kept for the norms. Returns false, with
/// `entry.error` set, when its reduction is refused (a bad mode count:
/// nothing ran); true when it ran, `entry.error` then set if it stopped.
bool run_rubbing_campaign_entry(const RubbingModel& model, RubbingCampaignRun& entry,
                                const ComponentRowSink& sink,
                                const std::function<void()>& checkpoint,
                                const std::function<void(double)>& progress);

struct RubbingErrorNorms {
  double e2_response = NAN, einf_response = NAN, e2_lambda = NAN, einf_lambda = NAN;
  double e2_wear = NAN, einf_wear = NAN; ///< NaN without a liner or with unequal windows
  /// Over every contact's gap: sqrt(sum |g - g_ref|^2 / sum |g_ref|^2) and
  /// max |g - g_ref| / max |g_ref|; NaN unless both runs kept their gaps.
  double e2_gap = NAN, einf_gap = NAN;
};

/// The norms above of `r` against `ref` over their common rows (NaN with
/// none; the lambda norms NaN when the reference has no contact force);
/// the wear norms when both runs have a worn liner and `same_window`.
RubbingErrorNorms rubbing_error_norms(const RubbingCampaignRun& r, const RubbingCampaignRun& ref,
                                      bool same_window = false);

} // namespace rsi
