#pragma once
// A subcommand of `rsi`: it declares its options (CLI11) when main builds
// the command line, and, when the command line chose it, checks the rules
// between its options and runs. main.cpp only registers the commands, runs
// the chosen one and turns what it throws into `rsi: error: ...` and an
// exit status, in one place.
//
// run() returns 0 (done), 3 (a run stopped or failed, its outputs
// published) or 1 (a failed report script, nothing published), and
// throws BadInput (exit 2) or NumericalFailure (exit 3) for the rest.
// Everything it writes goes through `output` (staged_output.hpp).

#include <memory>

namespace CLI {
class App;
}

namespace rsi {

class StagedOutput;

class Command {
public:
  explicit Command(CLI::App& command)
      : m_command(command) {}
  virtual ~Command() = default;
  Command(const Command&) = delete;
  Command& operator=(const Command&) = delete;

  /// The command line chose this command (after parsing).
  bool chosen() const;
  virtual int run(StagedOutput& output) = 0;

protected:
  CLI::App& m_command; ///< the subcommand's CLI11 app (owned by main's app)
};

// Each declares its subcommand on `app` (in this order, the order of `rsi
// --help`) and binds its options to the returned command.
std::unique_ptr<Command> add_modes_command(CLI::App& app);
std::unique_ptr<Command> add_export_command(CLI::App& app);
std::unique_ptr<Command> add_calibrate_command(CLI::App& app);
std::unique_ptr<Command> add_simulate_command(CLI::App& app);
std::unique_ptr<Command> add_reduce_command(CLI::App& app);
std::unique_ptr<Command> add_campaign_command(CLI::App& app);
std::unique_ptr<Command> add_sweep_command(CLI::App& app);
std::unique_ptr<Command> add_modal_campaign_command(CLI::App& app);

} // namespace rsi
