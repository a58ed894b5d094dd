#include "run_list_checks.hpp"

#include "basis_memory.hpp"
#include "bladed_disk.hpp"
#include "run_monitor.hpp"
#include "run_step.hpp"

namespace rsi {

int check_runs_against_model(const Case& c, const std::vector<CampaignRun>& runs,
                             const std::string& where, int runs_at_once) {
  // Mode counts against the model before any run (the case loader only
  // knows [0, 100000]): cb keeps at most the interior dofs, ccm at most the
  // dofs minus the boundary dofs (reduced/craig_bampton, craig_chang_martinez).
  // A given step must divide the output interval: refused before any run.
  for (const CampaignRun& r : runs)
    if (r.step.kind == StepRule::Kind::given)
      run_step(r.step, c.time, 1.0, where + ": time_step of " + r.name());
  const int casing_dofs = assemble_casing(c).n_dofs();
  for (const CampaignRun& r : runs)
    if (r.casing_modes > casing_dofs)
      throw CaseError(where + ": casing_modes " + std::to_string(r.casing_modes) + " of " +
                      r.method + "-" + std::to_string(r.modes) + ": must be in [0, " +
                      std::to_string(casing_dofs) + "] (0: the full casing; its dofs)");
  const BladedDisk bd = assemble_bladed_disk(c);
  const int most = bd.n_dofs() - static_cast<int>(bd.boundary.size());
  for (const CampaignRun& r : runs) {
    if (r.method == "full") continue;
    if (r.method == "guyan" ? r.modes != 0 : r.modes > most)
      throw CaseError(where + ": " + r.method + " with " + std::to_string(r.modes) +
                      " modes: must be in " +
                      (r.method == "guyan" ? std::string("[0, 0] for guyan")
                                           : "[0, " + std::to_string(most) + "] for " + r.method +
                                                 " (dofs minus boundary dofs)"));
    // Its dense basis, as many at once as threads build them (basis_memory.hpp).
    check_dense_basis_fits(shown_after(where + ": " + r.name() + ": "), bd.n_dofs(),
                           static_cast<int>(bd.boundary.size()), r.modes, runs_at_once);
  }
  return bd.n_dofs();
}

void check_case_step_bound(const Case& c, const Casing& casing) {
  // The step against one dof's Rayleigh quotient of each part (a lower
  // bound of omega_max, run_monitor.hpp): the full runs would each refuse
  // it, after their assembly.
  const BladedDisk bd = assemble_bladed_disk(c);
  check_time_step_bound(c.time.step, bd.stiffness, bd.mass, false, "bladed disk");
  check_time_step_bound(c.time.step, casing.stiffness, casing.mass, false, "casing");
}

std::optional<ReductionError> keyed_by_entry(const ReductionError& e, const std::string& entry_key,
                                             const std::string& method) {
  FailureAdvice advice = e.advice();
  std::string key;
  if (advice.input == FailedInput::boundary_mode_count)
    key = "modes"; // cc's n_c
  else if (advice.input == FailedInput::mode_count)
    key = method == "cc" ? "fixed_interface_modes" : "modes";
  if (key.empty()) return std::nullopt;
  advice.input = FailedInput::unnamed;
  advice.context += "key '" + entry_key + "." + key + "': ";
  return ReductionError(e.what(), advice);
}

} // namespace rsi
