// rsi reduce: a reduction basis of a component -> K.mtx, M.mtx, T.mtx, basis.json.

#include <chrono>
#include <cstdio>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "command.hpp"
#include "command_options.hpp"
#include "usage_error.hpp"
#include "component_input.hpp"
#include "critical_step.hpp"
#include "output_files.hpp"
#include "reduced_run.hpp"
#include "reduction.hpp"
#include "staged_output.hpp"
#include "terminal_progress.hpp"

namespace rsi {
namespace {

struct ReduceOptions {
  std::string case_path;
  std::string method;
  int modes = 0;
  std::string out = "out/reduce";
  ComponentLoadOptions load;
};

class ReduceCommand : public Command {
public:
  explicit ReduceCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  ReduceOptions m_options;
};

ReduceCommand::ReduceCommand(CLI::App& app)
    : Command(*app.add_subcommand(
          "reduce", "Reduction basis of a component -> DIR/{K.mtx,M.mtx,T.mtx,basis.json}")) {
  ReduceOptions& reduce = m_options;
  m_command.add_option("case", reduce.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  m_command.add_option("--method", reduce.method, "cb, ccm, guyan or macneal")
      ->required()
      ->check(one_of({"cb", "ccm", "guyan", "macneal"}));
  m_command
      .add_option("--modes", reduce.modes, "fixed-interface (cb) or free (ccm, macneal) modes")
      ->capture_default_str()
      ->check(integer_in(0, 1000000000, modes_allowed));
  m_command.add_option("--out", reduce.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  add_component_options(m_command, reduce.load);
}

} // namespace

int ReduceCommand::run(StagedOutput& output) {
  const ReduceOptions& options = m_options;
  if (options.method != "cb" && options.method != "ccm" && options.method != "guyan" &&
      options.method != "macneal")
    throw UsageError("--method: must be cb, ccm, guyan or macneal, got '" + options.method + "'");
  const auto start = std::chrono::steady_clock::now();
  TerminalStage stage("reduce: loading " + options.case_path + " and building the " +
                      options.method + " basis");
  const ComponentInput input = load_component_input(options.case_path, "", options.load);
  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Component& c = input.component;
  if (c.boundary.empty())
    throw UsageError(input.case_source + ": the component " + c.name +
                     " has no boundary dofs to keep; a reduction needs them");
  const ReducedBasis basis =
      reduce(c, options.method, options.modes, 0);
  // With a massless boundary (MacNeal) the boundary is condensed first (critical_step.hpp).
  const double omega_max = reduced_omega_max(basis);
  stage.done();
  const std::string dir = output.open(options.out, "--out", reduce_output_set());
  write_symmetric_matrix_market(dir + "/K.mtx", basis.stiffness.sparseView());
  write_symmetric_matrix_market(dir + "/M.mtx", basis.mass.sparseView());
  write_general_matrix_market(dir + "/T.mtx", basis.transformation.sparseView());
  nlohmann::ordered_json j;
  j["component"] = c.name;
  j["method"] = basis.method;
  j["modes"] = basis.n_modes;
  j["full_dofs"] = c.n_dofs();
  j["boundary_dofs"] = static_cast<int>(c.boundary.size());
  j["reduced_dofs"] = basis.n_reduced();
  j["boundary_position"] = basis.boundary_position;
  j["omega_max"] = omega_max;
  j["critical_dt"] = 2.0 / omega_max;
  if (basis.massless_boundary) j["massless_boundary"] = true;
  if (basis.method == "ccm" || basis.method == "macneal") j["cond_RB"] = basis.cond_rb;
  j["load_seconds"] = load_seconds;
  j["build_seconds"] = basis.build_seconds;
  j["peak_memory_bytes"] = peak_memory_bytes();
  write_text_file(dir + "/basis.json", j.dump(2) + "\n");
  std::printf("%s: %s, %s with %d modes: %d -> %d dofs; omega_max %.6e rad/s, critical step "
              "%.6e s",
              input.case_source.c_str(), c.name.c_str(), basis.method.c_str(), basis.n_modes,
              c.n_dofs(), basis.n_reduced(), omega_max, 2.0 / omega_max);
  if (basis.method == "ccm" || basis.method == "macneal")
    std::printf(", cond(R_B) %.3e", basis.cond_rb);
  if (basis.massless_boundary)
    std::printf(", massless boundary (omega_max of the condensed model)");
  std::printf("; loaded in %.3f s, built in %.3f s, peak memory %.0f MB\n", load_seconds,
              basis.build_seconds, peak_memory_bytes() / 1048576.0);
  output.announce("wrote " + options.out + "/{K.mtx,M.mtx,T.mtx,basis.json}\n");
  return 0;
}

std::unique_ptr<Command> add_reduce_command(CLI::App& app) {
  return std::make_unique<ReduceCommand>(app);
}

} // namespace rsi
