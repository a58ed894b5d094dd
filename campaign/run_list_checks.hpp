#pragma once
// Checks of the paper's case's run lists (its "campaign", its sweep's
// runs) against the model, before any run: each full or reduced run would
// otherwise refuse its input only after its assembly or its basis.
// And a component case's run lists' refusals named by their entries' keys.

#include <optional>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "casing.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// Checks a run list against the model before any run: mode counts (cb:
/// at most the interior dofs, ccm: the dofs minus the boundary's, guyan: 0),
/// casing modes (at most the casing's dofs), given steps (dividing the
/// output interval) and each dense basis against the memory, `runs_at_once`
/// of them (basis_memory.hpp). CaseError prefixed by `where` (the key that
/// lists the runs). Returns the bladed disk's dofs.
int check_runs_against_model(const Case& c, const std::vector<CampaignRun>& runs,
                             const std::string& where, int runs_at_once);

/// Refuses time.step, the full run's step, when it is above the stability
/// limit of the bladed disk or of the casing by the cheap lower bound of
/// omega_max (run_monitor.hpp), before any run: each full run would refuse
/// it after its assembly. Throws the StabilityError of that check.
void check_case_step_bound(const Case& c, const Casing& casing);

/// A reduction's refusal of a mode count of a component case's run entry
/// `entry_key` ("rubbing.campaign.runs[2]", "sweep.runs[0]") named by the
/// entry's key (modes; a cc entry's eta its fixed_interface_modes), not by
/// the option of rsi simulate the reduction's advice names; nullopt when
/// the refusal is not of a mode count.
std::optional<ReductionError> keyed_by_entry(const ReductionError& e, const std::string& entry_key,
                                             const std::string& method);

} // namespace rsi
