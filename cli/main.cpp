// rsi: component mode synthesis in rotor/stator contact, reference and
// reduced solvers with their verification (see README.md and SPEC).
//
// Exit status: 0 success, 2 bad input (case file, option, output
// directory), 3 numerical failure, 1 anything else.

#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "case_file.hpp"
#include "central_difference.hpp"
#include "commands.hpp"
#include "modal_analysis.hpp"
#include "output_files.hpp"
#include "reduced_integrator.hpp"
#include "reference_run.hpp"

int main(int argc, char** argv) {
  CLI::App app{"rsi: component mode synthesis for blade-tip/casing contact (Batailly et al. 2007)"};
  app.require_subcommand(0, 1);

  rsi::ModesOptions modes;
  CLI::App* modes_cmd = app.add_subcommand("modes", "Lowest modes of one part -> DIR/modes.csv");
  modes_cmd->add_option("case", modes.case_path, "case file (JSON)")->required();
  modes_cmd->add_option("--part", modes.part, "bladed-disk or casing")->capture_default_str();
  modes_cmd->add_option("--count", modes.count, "number of modes, 1..number of dofs")
      ->capture_default_str();
  modes_cmd->add_option("--out", modes.out, "output directory")->capture_default_str();

  rsi::ExportOptions export_options;
  CLI::App* export_cmd = app.add_subcommand(
      "export", "K.mtx, M.mtx, dofs.csv of both parts -> DIR/{bladed-disk,casing}/");
  export_cmd->add_option("case", export_options.case_path, "case file (JSON)")->required();
  export_cmd->add_option("--out", export_options.out, "output directory")->capture_default_str();

  rsi::CalibrateOptions calibrate;
  CLI::App* calibrate_cmd = app.add_subcommand(
      "calibrate", "Blade thickness that centres the first family of frequencies on a target");
  calibrate_cmd->add_option("case", calibrate.case_path, "case file (JSON)")->required();
  calibrate_cmd->add_option("--target-hz", calibrate.target_hz, "target mean frequency [Hz]")
      ->capture_default_str();

  rsi::SimulateOptions simulate;
  CLI::App* simulate_cmd = app.add_subcommand(
      "simulate", "One contact run -> DIR/history.csv, DIR/summary.json (exit 3 on blow-up)");
  simulate_cmd->add_option("case", simulate.case_path, "case file (JSON)")->required();
  simulate_cmd->add_option("--method", simulate.method, "full (reference), cb, ccm or guyan")
      ->capture_default_str();
  simulate_cmd->add_option("--modes", simulate.modes, "modes kept by cb (eta) or ccm (psi)")
      ->capture_default_str();
  simulate_cmd->add_flag(
      "--full-field", simulate.full_field,
      "reduced methods: also write field.csv, every bladed-disk dof (u = T q) per history row");
  simulate_cmd->add_option("--out", simulate.out, "output directory")->capture_default_str();
  simulate_cmd->add_flag("--force", simulate.force,
                         "integrate even with a time step above the stability limit");

  rsi::ReduceOptions reduce;
  CLI::App* reduce_cmd = app.add_subcommand(
      "reduce", "Reduction basis of the bladed disk -> DIR/{K.mtx,M.mtx,T.mtx,basis.json}");
  reduce_cmd->add_option("case", reduce.case_path, "case file (JSON)")->required();
  reduce_cmd->add_option("--method", reduce.method, "cb, ccm or guyan")->required();
  reduce_cmd->add_option("--modes", reduce.modes, "fixed-interface (cb) or free (ccm) modes")
      ->capture_default_str();
  reduce_cmd->add_option("--out", reduce.out, "output directory")->capture_default_str();

  rsi::CampaignOptions campaign;
  CLI::App* campaign_cmd = app.add_subcommand(
      "campaign",
      "Reference + every reduced run of the case's campaign -> DIR/convergence.csv, DIR/runs/*/");
  campaign_cmd->add_option("case", campaign.case_path, "case file (JSON)")->required();
  campaign_cmd->add_option("--out", campaign.out, "output directory")->capture_default_str();
  campaign_cmd->add_option("--jobs", campaign.jobs, "runs in parallel (threads), 1..64")
      ->capture_default_str();
  campaign_cmd->add_option("--target-e2", campaign.target_e2,
                           "report the smallest eta and psi of the campaign with e2 at most this");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every malformed command line exits 2.
    const int status = app.exit(e);
    return status == 0 ? 0 : 2;
  }

  if (app.get_subcommands().empty()) {
    std::fprintf(
        stderr,
        "rsi: error: a subcommand is required: modes, export or calibrate (see rsi --help)\n");
    return 2;
  }
  try {
    if (*modes_cmd) return rsi::run_modes(modes);
    if (*export_cmd) return rsi::run_export(export_options);
    if (*calibrate_cmd) return rsi::run_calibrate(calibrate);
    if (*simulate_cmd) return rsi::run_simulate(simulate);
    if (*reduce_cmd) return rsi::run_reduce(reduce);
    if (*campaign_cmd) return rsi::run_campaign(campaign);
  } catch (const rsi::CaseError& e) {
    std::fprintf(stderr, "rsi: error: %s\n", e.what());
    return 2;
  } catch (const rsi::UsageError& e) {
    std::fprintf(stderr, "rsi: error: %s\n", e.what());
    return 2;
  } catch (const rsi::OutputError& e) {
    std::fprintf(stderr, "rsi: error: %s\n", e.what());
    return 2;
  } catch (const rsi::ReductionError& e) {
    std::fprintf(stderr, "rsi: error: %s\n", e.what());
    return 2;
  } catch (const rsi::ReducedIntegrationError& e) {
    std::fprintf(stderr, "rsi: numerical failure: %s\n", e.what());
    return 3;
  } catch (const rsi::StabilityError& e) {
    std::fprintf(stderr, "rsi: error: %s\n", e.what());
    return 2;
  } catch (const rsi::IntegrationError& e) {
    std::fprintf(stderr, "rsi: numerical failure: %s\n", e.what());
    return 3;
  } catch (const rsi::ModalError& e) {
    std::fprintf(stderr, "rsi: numerical failure: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rsi: error: %s\n", e.what());
    return 1;
  }
  return 1;
}
