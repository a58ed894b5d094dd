#pragma once
// The subcommands of `rsi`. Each reads its inputs, computes everything,
// then writes its outputs whole; input errors surface as CaseError or
// UsageError (exit status 2), numerical failures as ModalError (exit 3).

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "casing.hpp"
#include "component_case.hpp"
#include "failure_kinds.hpp"
#include "history.hpp"
#include "modal_analysis.hpp"

namespace rsi {

class StagedOutput;

/// A command-line value outside its allowed range.
class UsageError : public BadInput {
public:
  using BadInput::BadInput;
};

struct ModesOptions {
  std::string case_path;
  std::string part;  ///< empty: the bladed disk, or the component of a component case
  int count = 50;
  std::string out = "out/modes";
  ComponentLoadOptions load;
};

struct ExportOptions {
  std::string case_path;
  std::string out = "out/export";
  ComponentLoadOptions load;
};

struct CalibrateOptions {
  std::string case_path;
  double target_hz = 44.0;
};

struct SimulateOptions {
  std::string case_path;
  std::string method = "full";
  int modes = 0;
  std::string out = "out/simulate";
  bool force = false;
  bool full_field = false;
  std::string time_step = "case"; ///< --time-step: case, own or a step in seconds (reduced methods)
  double step_safety = 0.9;        ///< --step-safety: of --time-step own
  int casing_modes = 0;            ///< --casing-modes: 0 the full casing (reduced methods)
  std::string selection = "lowest"; ///< --selection: mode selection (reduced methods)
  ComponentLoadOptions load; ///< component cases: --source, --ccx-cache
};

struct ReduceOptions {
  std::string case_path;
  std::string method;
  int modes = 0;
  std::string out = "out/reduce";
  ComponentLoadOptions load;
};

struct CampaignOptions {
  std::string case_path;
  std::string out = "out/campaign";
  int jobs = 0; ///< runs in parallel; 0: the default (2 for the paper's case, 1 for a component case)
  double target_e2 = 0.0; ///< report the smallest eta, psi reaching it (0: no)
  bool report = true;     ///< run reports/make_campaign_report.py at the end
  ComponentLoadOptions load; ///< component cases: --source, --ccx-cache
};

struct ModalCampaignOptions {
  std::string case_path;
  std::string out = "out/modal-campaign";
  bool report = true; ///< run reports/make_modal_report.py at the end
  ComponentLoadOptions load;
};

/// The lowest `count` modes of a part ("bladed-disk" or "casing") and their
/// modes.csv text (index,frequency_hz,nodal_diameter). Throws UsageError
/// unless 1 <= count <= the part's dofs.
struct ModesTable {
  Modes modes;
  std::vector<std::optional<int>> diameters; ///< empty where a part has no cyclic structure
  std::string csv;
  int n_dofs = 0;
};
ModesTable modes_table(const Case& c, const std::string& part, int count);

struct SweepOptions {
  std::string case_path;
  std::string out = "out/sweep";
  /// --speeds: "FROM:TO:COUNT" or "W1,W2,..." [rad/s]; empty: the case's sweep.speeds.
  std::string speeds;
  /// --method: one run in place of the case's sweep.runs (empty: the case's).
  std::string method;
  int modes = 0;
  std::string selection = "lowest";
  int casing_modes = 0;
  std::string time_step = "case";
  double step_safety = 0.9;
  int jobs = 0;       ///< threads a process; 0: 2 alone, 1 a rank under mpirun
  bool quiet = false; ///< no progress lines on stderr
  bool report = true; ///< run the case's report generator (reports/) at the end
  ComponentLoadOptions load; ///< component cases: --source, --ccx-cache
  /// The paper-case run options given (--casing-modes, --selection,
  /// --time-step, --step-safety): a component case refuses them.
  std::vector<std::string> paper_run_options;
};

/// --time-step of simulate and sweep: "case", "own" or a step in seconds
/// (> 0, finite); UsageError otherwise.
StepRule parse_step_option(const std::string& text, double safety);

int run_modes(const ModesOptions& options, StagedOutput& output);
int run_export(const ExportOptions& options, StagedOutput& output);
int run_calibrate(const CalibrateOptions& options);
int run_simulate(const SimulateOptions& options, StagedOutput& output);
/// rsi simulate on a component case with a "rubbing" object.
int run_component_simulate(const SimulateOptions& options, const ComponentCase& c,
                           StagedOutput& output);
int run_reduce(const ReduceOptions& options, StagedOutput& output);
int run_campaign(const CampaignOptions& options, StagedOutput& output);
/// rsi campaign on a component case (rubbing.campaign).
int run_rubbing_campaign(const CampaignOptions& options, const ComponentCase& c,
                         StagedOutput& output);

int run_modal_campaign(const ModalCampaignOptions& options, StagedOutput& output);

/// Checks a run list against the model before any run: mode counts (cb:
/// at most the interior dofs, ccm: the dofs minus the boundary's, guyan: 0),
/// casing modes (at most the casing's dofs), given steps (dividing the
/// output interval) and each dense basis against the memory, `runs_at_once`
/// of them (basis_memory.hpp). UsageError or CaseError prefixed by `where`.
/// Returns the bladed disk's dofs.
int check_runs_against_model(const Case& c, const std::vector<CampaignRun>& runs,
                             const std::string& where, int runs_at_once);

/// Refuses time.step, the full run's step, when it is above the stability
/// limit of the bladed disk or of the casing by the cheap lower bound of
/// omega_max (run_monitor.hpp), before any run: each full run would refuse
/// it after its assembly. StabilityError naming time.step; `command` has no
/// --force.
void check_case_step_bound(const Case& c, const Casing& casing, const std::string& command);

/// rsi sweep: the case's runs over its rotation speeds, alone or over MPI ranks.
int run_sweep(const SweepOptions& options, StagedOutput& output);

} // namespace rsi
