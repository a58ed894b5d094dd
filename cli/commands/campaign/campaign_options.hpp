#pragma once
// The options of `rsi campaign`, and its run on a component case
// (component_campaign.cpp); the paper's case runs in campaign_command.cpp.

#include <string>

#include "component_case.hpp"

namespace rsi {

class StagedOutput;

struct CampaignOptions {
  std::string case_path;
  std::string out = "out/campaign";
  int jobs =
      0; ///< runs in parallel; 0: the default (2 for the paper's case, 1 for a component case)
  double target_e2 = 0.0;    ///< report the smallest eta, psi reaching it (0: no)
  bool report = true;        ///< run reports/make_campaign_report.py at the end
  ComponentLoadOptions load; ///< component cases: --source, --ccx-cache
};

/// rsi campaign on a component case (rubbing.campaign, rubbing_campaign.hpp).
int campaign_component_case(const CampaignOptions& options, const ComponentCase& c,
                            StagedOutput& output);

} // namespace rsi
