// rsi: component mode synthesis in rotor/stator contact, reference and
// reduced solvers with their verification (see README.md and SPEC).
//
// This file registers the commands (cli/commands/: each declares its
// options and runs) and is the one place that turns what a command throws
// into `rsi: error: ...` and an exit status: 0 success, 2 bad input (case
// file, option, output directory), 3 numerical failure, 128 + the signal
// for an interruption, 1 anything else (out of memory included).

#include <cstdio>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <gsl/gsl_errno.h>

#include "command.hpp"
#include "failure_advice.hpp"
#include "failure_kinds.hpp"
#include "huge_page_heap.hpp"
#include "interruption.hpp"
#include "output_files.hpp"
#include "staged_output.hpp"

namespace {

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

/// Runs `command`, publishing its output when it returns 0 or 3; what it
/// throws becomes one `rsi: error:` line and the exit status of its kind.
/// Messages name the paths the user gave, never the staging folder.
int run_command(rsi::Command& command, rsi::StagedOutput& output) {
  auto failure = [&output](const char* kind, const std::exception& e, int status) {
    std::fprintf(stderr, "rsi: %s: %s\n", kind, output.shown(rsi::failure_message(e)).c_str());
    return status;
  };
  try {
    int status = 0;
    try {
      status = command.run(output);
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
}

} // namespace

int main(int argc, char** argv) {
  // Before anything else: the process may be replaced (huge_page_heap.hpp).
  rsi::run_on_huge_page_heap(argv);
  // GSL's default error handler aborts the process; rsi checks the status
  // every GSL call returns and reports it (exit 2 or 3) instead.
  gsl_set_error_handler_off();
  rsi::install_interruption_handlers();
  CLI::App app{"rsi: component mode synthesis for blade-tip/casing contact (Batailly et al. 2007)"};
  app.require_subcommand(0, 1);

  // In the order `rsi --help` lists them.
  std::vector<std::unique_ptr<rsi::Command>> commands;
  commands.push_back(rsi::add_modes_command(app));
  commands.push_back(rsi::add_export_command(app));
  commands.push_back(rsi::add_calibrate_command(app));
  commands.push_back(rsi::add_simulate_command(app));
  commands.push_back(rsi::add_reduce_command(app));
  commands.push_back(rsi::add_campaign_command(app));
  commands.push_back(rsi::add_sweep_command(app));
  commands.push_back(rsi::add_modal_campaign_command(app));

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

  rsi::Command* chosen = nullptr;
  for (const std::unique_ptr<rsi::Command>& command : commands)
    if (command->chosen()) chosen = command.get();
  if (chosen == nullptr) {
    std::fprintf(stderr, "rsi: error: a subcommand is required: modes, export, calibrate, "
                         "reduce, simulate, campaign, modal-campaign or sweep (see rsi --help)\n");
    return 2;
  }
  // Everything a command writes goes to a staging folder, published as one
  // set only when the command returns 0 or 3 (staged_output.hpp).
  rsi::StagedOutput output;
  const int status = run_command(*chosen, output);
  // Unless published: the staging folder and the lock removed, and every
  // directory the command created and left empty (--out as it was).
  output.abandon();
  return status;
}
