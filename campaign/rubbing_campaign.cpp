#include "rubbing_campaign.hpp"

#include "failure_advice.hpp"
#include "run_list_checks.hpp"

#include <algorithm>

namespace rsi {

std::vector<RubbingCampaignRun> rubbing_campaign_runs(const RubbingSetup& setup) {
  std::vector<RubbingCampaignRun> runs;
  const auto run_of = [](const std::string& method, int modes, int fixed_interface_modes, int entry) {
    RubbingCampaignRun r;
    r.method = method;
    r.modes = modes;
    r.fixed_interface_modes = fixed_interface_modes;
    r.entry = entry;
    return r;
  };
  if (setup.full_revolutions > 0.0) runs.push_back(run_of("full", 0, 0, -1));
  for (size_t i = 0; i < setup.campaign.size(); ++i)
    for (int modes : setup.campaign[i].modes)
      runs.push_back(run_of(setup.campaign[i].method, modes,
                            setup.campaign[i].fixed_interface_modes, static_cast<int>(i)));
  return runs;
}

std::string rubbing_campaign_run_name(const RubbingCampaignRun& r) {
  return r.method == "full" ? "full" : r.method + "-" + std::to_string(r.modes);
}

bool run_rubbing_campaign_entry(const RubbingModel& model, RubbingCampaignRun& entry,
                                const ComponentRowSink& sink,
                                const std::function<void()>& checkpoint,
                                const std::function<void(double)>& progress) {
  const bool keep_gaps = model.setup().casing.has_value();
  const ComponentRowSink keep = [&](const HistoryRow& row, double response) {
    sink(row, response);
    entry.response.push_back(response);
    entry.lambda_n.push_back(row.lambda);
    if (keep_gaps) entry.gap.push_back(row.gap);
  };
  RubbingRunOptions o;
  o.method = entry.method;
  o.modes = entry.method == "cc" ? entry.fixed_interface_modes : entry.modes;
  if (entry.method == "cc") o.boundary_modes = entry.modes;
  o.revolutions = entry.method == "full" ? model.setup().full_revolutions : model.setup().revolutions;
  if (entry.method == "full") o.revolutions_key = "rubbing.campaign.full_revolutions";
  o.checkpoint = checkpoint;
  o.progress = progress;
  try {
    entry.run = run_rubbing(model, o, keep);
  } catch (const ReductionError& e) {
    const std::optional<ReductionError> keyed =
        entry.entry < 0 ? std::nullopt
                        : keyed_by_entry(e, "rubbing.campaign.runs[" + std::to_string(entry.entry) + "]",
                                         entry.method);
    entry.error = failure_message(keyed ? *keyed : e);
    return false;
  }
  if (!entry.run.summary.completed) entry.error = run_status(entry.run.summary);
  return true;
}

RubbingErrorNorms rubbing_error_norms(const RubbingCampaignRun& r, const RubbingCampaignRun& ref,
                                      bool same_window) {
  const size_t n = std::min(r.response.size(), ref.response.size());
  double dx2 = 0, x2 = 0, dxi = 0, xi = 0, dl2 = 0, l2 = 0, dli = 0, li = 0;
  for (size_t j = 0; j < n; ++j) {
    const double d = r.response[j] - ref.response[j];
    dx2 += d * d;
    x2 += ref.response[j] * ref.response[j];
    dxi = std::max(dxi, std::abs(d));
    xi = std::max(xi, std::abs(ref.response[j]));
    const Eigen::VectorXd dl = r.lambda_n[j] - ref.lambda_n[j];
    dl2 += dl.squaredNorm();
    l2 += ref.lambda_n[j].squaredNorm();
    dli = std::max(dli, dl.cwiseAbs().maxCoeff());
    li = std::max(li, ref.lambda_n[j].cwiseAbs().maxCoeff());
  }
  RubbingErrorNorms e;
  if (n == 0) return e;
  if (r.gap.size() >= n && ref.gap.size() >= n) {
    double dg2 = 0, g2 = 0, dgi = 0, gi = 0;
    for (size_t j = 0; j < n; ++j) {
      dg2 += (r.gap[j] - ref.gap[j]).squaredNorm();
      g2 += ref.gap[j].squaredNorm();
      dgi = std::max(dgi, (r.gap[j] - ref.gap[j]).cwiseAbs().maxCoeff());
      gi = std::max(gi, ref.gap[j].cwiseAbs().maxCoeff());
    }
    e.e2_gap = g2 > 0 ? std::sqrt(dg2 / g2) : NAN;
    e.einf_gap = gi > 0 ? dgi / gi : NAN;
  }
  e.e2_response = std::sqrt(dx2 / x2);
  e.einf_response = dxi / xi;
  e.e2_lambda = l2 > 0 ? std::sqrt(dl2 / l2) : NAN;
  e.einf_lambda = li > 0 ? dli / li : NAN;
  const std::vector<double>& p = r.run.wear;
  const std::vector<double>& pr = ref.run.wear;
  if (same_window && !p.empty() && p.size() == pr.size()) {
    double dp2 = 0, p2 = 0, dpi = 0, pi = 0;
    for (size_t k = 0; k < p.size(); ++k) {
      dp2 += (p[k] - pr[k]) * (p[k] - pr[k]);
      p2 += pr[k] * pr[k];
      dpi = std::max(dpi, std::abs(p[k] - pr[k]));
      pi = std::max(pi, pr[k]);
    }
    e.e2_wear = p2 > 0 ? std::sqrt(dp2 / p2) : NAN;
    e.einf_wear = pi > 0 ? dpi / pi : NAN;
  }
  return e;
}

} // namespace rsi
