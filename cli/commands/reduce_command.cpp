// rsi reduce: a reduction basis of a component -> K.mtx, M.mtx, T.mtx, basis.json.

#include <chrono>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "component_input.hpp"
#include "critical_step.hpp"
#include "output_files.hpp"
#include "reduced_run.hpp"
#include "reduction.hpp"
#include "staged_output.hpp"
#include "terminal_progress.hpp"

namespace rsi {

int run_reduce(const ReduceOptions& options, StagedOutput& output) {
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
      reduce(c.stiffness, c.mass, c.boundary, options.method, options.modes);
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

} // namespace rsi
