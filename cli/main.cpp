// rsi: component mode synthesis in rotor/stator contact, reference and
// reduced solvers with their verification (see README.md and SPEC).
//
// Exit status: 0 success, 2 bad input (case file, option, output
// directory), 3 numerical failure, 1 anything else (out of memory included).

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <gsl/gsl_errno.h>

#include "case_file.hpp"
#include "central_difference.hpp"
#include "commands.hpp"
#include "component.hpp"
#include "component_integrator.hpp"
#include "interruption.hpp"
#include "modal_analysis.hpp"
#include "output_files.hpp"
#include "reduced_integrator.hpp"
#include "reference_run.hpp"
#include "staged_output.hpp"

namespace {

// Option checks run by CLI11 on the text of a value, before its conversion,
// so a bad value gets one message naming the option (CLI11 prefixes its
// name) and what is allowed, instead of CLI11's bare "Could not convert".

/// An integer in [lo, hi]; `allowed` describes the range in words.
CLI::Validator integer_in(long lo, long hi, const std::string& allowed) {
  return CLI::Validator(
      [lo, hi, allowed](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long value = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || errno == ERANGE || value < lo || value > hi)
          return "must be " + allowed + ", got '" + text + "'";
        return {};
      },
      "INT");
}

/// A finite number above `lo`.
CLI::Validator number_above(double lo, const std::string& allowed) {
  return CLI::Validator(
      [lo, allowed](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > lo))
          return "must be " + allowed + ", got '" + text + "'";
        return {};
      },
      "NUMBER");
}

/// One of `names`.
CLI::Validator one_of(const std::vector<std::string>& names) {
  std::string allowed;
  for (size_t i = 0; i < names.size(); ++i)
    allowed += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return CLI::Validator(
      [names, allowed](std::string& text) -> std::string {
        for (const std::string& name : names)
          if (text == name) return {};
        return "must be " + allowed + ", got '" + text + "'";
      },
      "NAME");
}

/// A path that must not be empty (`--out ""` would put files at the root).
CLI::Validator nonempty_path() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        return path.empty() ? "must be a directory path that can be created and written, got ''"
                            : std::string();
      },
      "DIR");
}

/// The case file argument: an existing file, not a directory (load_case
/// reports a file it cannot read, and everything about its content).
CLI::Validator case_file() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        std::error_code error;
        const auto status = std::filesystem::status(path, error);
        if (!std::filesystem::exists(status))
          return "'" + path + "': no such file; must be a JSON case file";
        if (std::filesystem::is_directory(status))
          return "'" + path + "' is a directory; must be a JSON case file";
        return {};
      },
      "CASE");
}

/// Name of the subcommand on the command line, for the --help hint.
std::string help_hint(const CLI::App& app) {
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  return parsed.empty() ? "rsi --help" : "rsi " + parsed.front()->get_name() + " --help";
}

/// For "NAME is required": ": " and the description of option NAME (what it takes).
std::string required_allowed(const CLI::App& app, const std::string& message) {
  for (const CLI::App* sub : app.get_subcommands())
    for (const CLI::Option* option : sub->get_options())
      if (message == option->get_name() + " is required") return ": " + option->get_description();
  return {};
}

/// --source and --ccx-cache of the commands that take a component case.
void add_component_options(CLI::App& command, rsi::ComponentLoadOptions& load) {
  command
      .add_option("--source", load.source_override,
                  "component case only: the deck or Matrix Market folder to read instead of "
                  "the case's component.source")
      ->check(nonempty_path());
  command
      .add_option("--ccx-cache", load.ccx_cache,
                  "folder of cached ccx runs (matrices of CalculiX decks)")
      ->capture_default_str()
      ->check(nonempty_path());
}

} // namespace

int main(int argc, char** argv) {
  // GSL's default error handler aborts the process; rsi checks the status
  // every GSL call returns and reports it (exit 2 or 3) instead.
  gsl_set_error_handler_off();
  rsi::install_interruption_handlers();
  CLI::App app{"rsi: component mode synthesis for blade-tip/casing contact (Batailly et al. 2007)"};
  app.require_subcommand(0, 1);

  const std::string modes_allowed =
      "an integer in [0, the method's maximum] (cb, ccm: the dofs minus the 44 boundary dofs, "
      "638 for the default case; macneal: the same, from 1; guyan: 0)";

  rsi::ModesOptions modes;
  CLI::App* modes_cmd = app.add_subcommand("modes", "Lowest modes of one component -> DIR/modes.csv");
  modes_cmd->add_option("case", modes.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  modes_cmd->add_option("--part", modes.part,
                        "bladed-disk (default) or casing for the paper's case; a component "
                        "case has one part, its name");
  modes_cmd->add_option("--count", modes.count, "number of modes, 1..number of dofs")
      ->capture_default_str()
      ->check(integer_in(1, 1000000000, "an integer in [1, the part's number of dofs]"));
  modes_cmd->add_option("--out", modes.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  add_component_options(*modes_cmd, modes.load);

  rsi::ExportOptions export_options;
  CLI::App* export_cmd = app.add_subcommand(
      "export", "K.mtx, M.mtx, dofs.csv, nodes.csv of each component -> DIR/<component>/");
  export_cmd->add_option("case", export_options.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  export_cmd->add_option("--out", export_options.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  add_component_options(*export_cmd, export_options.load);

  rsi::CalibrateOptions calibrate;
  CLI::App* calibrate_cmd = app.add_subcommand(
      "calibrate", "Blade thickness that centres the first family of frequencies on a target");
  calibrate_cmd->add_option("case", calibrate.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  calibrate_cmd->add_option("--target-hz", calibrate.target_hz, "target mean frequency [Hz], > 0")
      ->capture_default_str()
      ->check(number_above(0.0, "a finite number of Hz above 0"));

  rsi::SimulateOptions simulate;
  CLI::App* simulate_cmd = app.add_subcommand(
      "simulate", "One contact run -> DIR/history.csv, DIR/summary.json (exit 3 on blow-up)");
  simulate_cmd->add_option("case", simulate.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  simulate_cmd
      ->add_option("--method", simulate.method,
                   "full (reference), cb, ccm or guyan; macneal for a component case")
      ->capture_default_str()
      ->check(one_of({"full", "cb", "ccm", "guyan", "macneal"}));
  CLI::Option* simulate_modes =
      simulate_cmd->add_option("--modes", simulate.modes, "modes kept by cb (eta) or ccm (psi)")
          ->capture_default_str()
          ->check(integer_in(0, 1000000000, modes_allowed));
  simulate_cmd->add_flag(
      "--full-field", simulate.full_field,
      "reduced methods: also write field.csv, every bladed-disk dof (u = T q) per history row");
  CLI::Option* simulate_step =
      simulate_cmd
          ->add_option("--time-step", simulate.time_step,
                       "reduced methods: case (time.step), own (the reduced system's stable "
                       "step times --step-safety) or a step in seconds dividing the output "
                       "interval; rows at the case's output times")
          ->capture_default_str();
  CLI::Option* simulate_safety =
      simulate_cmd
          ->add_option("--step-safety", simulate.step_safety,
                       "with --time-step own: the fraction of 2/omega_max, in (0, 1)")
          ->capture_default_str()
          ->check(CLI::Range(0.0, 1.0));
  CLI::Option* simulate_casing =
      simulate_cmd
          ->add_option("--casing-modes", simulate.casing_modes,
                       "reduced methods: 0 (the full casing) or N_c, the casing in its lowest "
                       "N_c modes plus a static correction for the forcing")
          ->capture_default_str()
          ->check(integer_in(0, 1000000000, "0 (the full casing) or the casing modes kept"));
  CLI::Option* simulate_selection =
      simulate_cmd
          ->add_option("--selection", simulate.selection,
                       "reduced methods: how the kept modes are chosen: lowest, families "
                       "(whole nodal-diameter families), forced (the forcing's diameters and "
                       "their aliases first) or participation (boundary participation)")
          ->capture_default_str()
          ->check(one_of({"lowest", "families", "forced", "participation"}));
  simulate_cmd->add_option("--out", simulate.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  simulate_cmd->add_flag("--force", simulate.force,
                         "integrate even with a time step above the stability limit");
  add_component_options(*simulate_cmd, simulate.load);

  rsi::ReduceOptions reduce;
  CLI::App* reduce_cmd = app.add_subcommand(
      "reduce", "Reduction basis of a component -> DIR/{K.mtx,M.mtx,T.mtx,basis.json}");
  reduce_cmd->add_option("case", reduce.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  reduce_cmd->add_option("--method", reduce.method, "cb, ccm, guyan or macneal")
      ->required()
      ->check(one_of({"cb", "ccm", "guyan", "macneal"}));
  reduce_cmd
      ->add_option("--modes", reduce.modes, "fixed-interface (cb) or free (ccm, macneal) modes")
      ->capture_default_str()
      ->check(integer_in(0, 1000000000, modes_allowed));
  reduce_cmd->add_option("--out", reduce.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  add_component_options(*reduce_cmd, reduce.load);

  rsi::CampaignOptions campaign;
  CLI::App* campaign_cmd = app.add_subcommand(
      "campaign",
      "Reference + every reduced run of the case's campaign -> DIR/convergence.csv, DIR/runs/*/");
  campaign_cmd->add_option("case", campaign.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  campaign_cmd->add_option("--out", campaign.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  campaign_cmd->add_option("--jobs", campaign.jobs,
                           "runs in parallel (threads), 1..64; default 2 (a component case: 1)")
      ->check(integer_in(1, 64, "an integer in [1, 64]"));
  campaign_cmd
      ->add_option("--target-e2", campaign.target_e2,
                   "report the smallest eta and psi of the campaign with e2 at most this")
      ->check(number_above(0.0, "a finite number above 0"));
  campaign_cmd->add_flag("!--no-report", campaign.report,
                         "skip the report (reports/make_campaign_report.py, python3 + matplotlib)");
  add_component_options(*campaign_cmd, campaign.load);

  rsi::SweepOptions sweep;
  CLI::App* sweep_cmd = app.add_subcommand(
      "sweep", "The case's sweep runs over rotation speeds -> DIR/sweep.csv, "
               "DIR/interaction_lines.csv, DIR/sweep_report.md; under mpirun the speeds are "
               "shared by the ranks");
  sweep_cmd->add_option("case", sweep.case_path, "case file (JSON) with a \"sweep\" object")
      ->required()
      ->check(case_file());
  sweep_cmd->add_option("--out", sweep.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  CLI::Option* sweep_speeds = sweep_cmd->add_option("--speeds", sweep.speeds,
                        "FROM:TO:COUNT or W1,W2,... [rad/s] in place of the case's sweep.speeds");
  CLI::Option* sweep_method =
      sweep_cmd
          ->add_option("--method", sweep.method,
                       "one run in place of the case's sweep.runs: full, cb, ccm, guyan, or "
                       "macneal (a component case only)")
          ->check(one_of({"full", "cb", "ccm", "guyan", "macneal"}));
  CLI::Option* sweep_modes =
      sweep_cmd->add_option("--modes", sweep.modes, "with --method cb, ccm or macneal: modes kept")
          ->check(integer_in(0, 1000000000, modes_allowed));
  CLI::Option* sweep_step =
      sweep_cmd->add_option("--time-step", sweep.time_step,
                            "with a reduced --method: case, own or a step dividing the output "
                            "interval");
  CLI::Option* sweep_safety =
      sweep_cmd->add_option("--step-safety", sweep.step_safety,
                            "with --time-step own: the fraction of 2/omega_max, in (0, 1)")
          ->check(CLI::Range(0.0, 1.0));
  CLI::Option* sweep_casing =
      sweep_cmd
          ->add_option("--casing-modes", sweep.casing_modes,
                       "with a reduced --method: 0 (the full casing) or N_c casing modes")
          ->check(integer_in(0, 1000000000, "0 (the full casing) or the casing modes kept"));
  CLI::Option* sweep_selection =
      sweep_cmd
          ->add_option("--selection", sweep.selection,
                       "with a reduced --method: lowest, families, forced or participation")
          ->check(one_of({"lowest", "families", "forced", "participation"}));
  sweep_cmd->add_option("--jobs", sweep.jobs,
                        "threads a process (default 2 alone, 1 a rank under mpirun)")
      ->check(integer_in(1, 64, "an integer in [1, 64]"));
  sweep_cmd->add_flag("--quiet", sweep.quiet, "no progress lines on stderr");
  sweep_cmd->add_flag("!--no-report", sweep.report,
                      "skip the report (reports/make_sweep_report.py or, for a component case, "
                      "make_component_sweep_report.py; python3 + matplotlib)");
  add_component_options(*sweep_cmd, sweep.load);

  rsi::ModalCampaignOptions modal_campaign;
  CLI::App* modal_campaign_cmd = app.add_subcommand(
      "modal-campaign",
      "Modal convergence of every reduction of a component (no contact): reduced against full "
      "frequencies -> DIR/{modal_convergence.csv,modal_errors.csv,modal_report.md}");
  modal_campaign_cmd->add_option("case", modal_campaign.case_path, "component case file (JSON)")
      ->required()
      ->check(case_file());
  modal_campaign_cmd->add_option("--out", modal_campaign.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  modal_campaign_cmd->add_flag("!--no-report", modal_campaign.report,
                               "write the tables only, not modal_report.md and its figure");
  add_component_options(*modal_campaign_cmd, modal_campaign.load);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Every malformed command line: one line, exit 2.
    std::fprintf(stderr, "rsi: error: %s%s (%s lists the options)\n", e.what(),
                 required_allowed(app, e.what()).c_str(), help_hint(app).c_str());
    return 2;
  }

  if (app.get_subcommands().empty()) {
    std::fprintf(stderr, "rsi: error: a subcommand is required: modes, export, calibrate, "
                         "reduce, simulate, campaign, modal-campaign or sweep (see rsi --help)\n");
    return 2;
  }
  // Everything a command writes goes to a staging folder, published as one
  // set only when the command returns 0 or 3 (staged_output.hpp).
  rsi::StagedOutput output;
  // Exit status by exception kind: 2 bad input, 3 numerical failure, 1 else.
  // Messages name the paths the user gave, never the staging folder.
  auto failure = [&output](const char* kind, const std::exception& e, int status) {
    std::fprintf(stderr, "rsi: %s: %s\n", kind, output.shown(e.what()).c_str());
    return status;
  };
  auto command = [&]() -> int {
    if (*modes_cmd) return rsi::run_modes(modes, output);
    if (*export_cmd) return rsi::run_export(export_options, output);
    if (*calibrate_cmd) return rsi::run_calibrate(calibrate);
    if (*simulate_cmd) {
      // An option the method does not use is refused, not ignored (cb,
      // ccm and guyan check theirs when the basis is built).
      if (simulate_modes->count() > 0 && simulate.method == "full")
        throw rsi::UsageError("--modes: only for a reduced method (the full reference keeps "
                              "no modes); drop it");
      for (const CLI::Option* o :
           {simulate_step, simulate_safety, simulate_casing, simulate_selection})
        if (o->count() > 0 && simulate.method == "full")
          throw rsi::UsageError(o->get_name() +
                                ": only for a reduced method (the full reference runs the whole "
                                "model at time.step); drop it");
      if (simulate_safety->count() > 0 && simulate.time_step != "own")
        throw rsi::UsageError("--step-safety: only with --time-step own; drop it");
      return rsi::run_simulate(simulate, output);
    }
    if (*reduce_cmd) return rsi::run_reduce(reduce, output);
    if (*campaign_cmd) return rsi::run_campaign(campaign, output);
    if (*modal_campaign_cmd) return rsi::run_modal_campaign(modal_campaign, output);
    if (*sweep_cmd) {
      // The run options describe the one --method run: refused without it.
      for (const CLI::Option* o :
           {sweep_modes, sweep_step, sweep_safety, sweep_casing, sweep_selection}) {
        if (o->count() > 0 && sweep.method.empty())
          throw rsi::UsageError(o->get_name() +
                                ": only with --method (it describes that one run); add "
                                "--method or drop it");
        if (o->count() > 0 && sweep.method == "full")
          throw rsi::UsageError(o->get_name() +
                                ": only for a reduced --method (the full reference runs the whole "
                                "model at time.step); drop it");
      }
      if (sweep_safety->count() > 0 && sweep.time_step != "own")
        throw rsi::UsageError("--step-safety: only with --time-step own; drop it");
      if (sweep_speeds->count() > 0 && sweep.speeds.empty())
        throw rsi::UsageError("--speeds: FROM:TO:COUNT or W1,W2,... [rad/s], 1 to 100000 speeds, "
                              "got ''");
      for (const CLI::Option* o : {sweep_casing, sweep_selection, sweep_step, sweep_safety})
        if (o->count() > 0) sweep.paper_run_options.push_back(o->get_name());
      (void)sweep_method;
      return rsi::run_sweep(sweep, output);
    }
    return 1;
  };
  auto run = [&]() -> int {
    try {
      int status = 0;
      try {
        status = command();
      } catch (const rsi::Interrupted&) {
        throw;
      } catch (...) {
        // A child killed by the same signal (Ctrl-C reaches the whole
        // process group: ccx, gmsh, the report script) fails its step
        // first; the interruption is the cause.
        rsi::throw_if_interrupted();
        throw;
      }
      // Work that polls no checkpoint (eigensolvers, bases, the children)
      // returns after the signal: interrupted all the same, nothing published.
      rsi::throw_if_interrupted();
      // 0, or 3 returned by a run that stopped (its history and summary say
      // why): this run's output replaces the previous one. Exit 1 (a failed
      // report script) publishes nothing.
      if (status == 0 || status == 3) output.publish();
      return status;
    } catch (const rsi::Interrupted& e) {
      return failure("error", e, e.exit_status());
    } catch (const rsi::OutputError& e) {
      return failure("error", e, 2);
    } catch (const rsi::BadInput& e) {
      // failure_kinds.hpp: the case, an import, a reduction, a step or modes
      // no solver resolves, the command line.
      return failure("error", e, 2);
    } catch (const rsi::NumericalFailure& e) {
      // A factorization, a modal check or an integrator's monitor failed.
      return failure("error: numerical failure", e, 3);
    } catch (const std::bad_alloc&) {
      // Every allocation failure arrives here as std::bad_alloc: operator
      // new's, and the C libraries' out-of-memory statuses (CHOLMOD,
      // LAPACKE), which rsi turns into it. By now the command's memory is
      // released (the stack is unwound), and the message is a literal.
      std::fputs("rsi: error: out of memory: an allocation failed; nothing was written to "
                 "--out; free memory or raise the limit (ulimit -v), or make the model or "
                 "the run smaller (elements, modes, --jobs)\n",
                 stderr);
      return 1;
    } catch (const std::exception& e) {
      return failure("error", e, 1);
    }
  };
  const int status = run();
  // Unless published: the staging folder and the lock removed, and every
  // directory the command created and left empty (--out as it was).
  output.abandon();
  return status;
}
