// rsi simulate: one contact run -> history.csv, summary.json.

#include <chrono>
#include <cstdio>
#include <unistd.h>

#include "commands.hpp"
#include "output_files.hpp"
#include "reference_run.hpp"
#include "run_outputs.hpp"

namespace rsi {
namespace {

/// Progress on stderr, only when it is a terminal and the run has lasted a second.
std::function<void(double)> terminal_progress() {
  if (!::isatty(STDERR_FILENO)) return {};
  const auto start = std::chrono::steady_clock::now();
  return [start](double fraction) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > 1.0) std::fprintf(stderr, "\r%5.1f%% (%.1f s)", 100.0 * fraction, elapsed);
  };
}

} // namespace

int run_simulate(const SimulateOptions& options) {
  const Case c = load_case(options.case_path);
  if (options.method != "full")
    throw UsageError(
        "--method: must be full (cb, ccm and guyan come with the reduced solver), got '" +
        options.method + "'");
  make_output_directory(options.out, "--out");
  RunOptions run;
  run.force = options.force;
  run.progress = terminal_progress();
  const RunResult result = run_reference(c, run);
  if (run.progress) std::fprintf(stderr, "\n");
  write_text_file(options.out + "/history.csv", history_csv(result.history));
  write_text_file(options.out + "/summary.json", summary_json(result.summary));
  if (result.casing_u_at_first_contact.size() > 0)
    write_text_file(
        options.out + "/casing_first_contact.csv",
        casing_snapshot_csv(result.casing_u_at_first_contact, result.casing_v_at_first_contact));
  const RunSummary& s = result.summary;
  std::printf("%s: method %s, %d dofs, %d of %d steps in %.3f s (integration %.3f s)\n",
              c.source.c_str(), s.method.c_str(), s.n_dofs, s.steps, s.steps_requested,
              s.wall_seconds, s.integration_seconds);
  std::printf("status: %s\n", s.status.c_str());
  std::printf(
      "max penetration %.3e m, min lambda %.3e N, max lambda %.3e N, max |lambda g| %.3e N m, "
      "sliding reversals %d\n",
      s.max_penetration, s.min_lambda, s.max_lambda, s.max_complementarity, s.sliding_reversals);
  std::printf("energy balance error %.3e J (scale %.3e J); W_ext %.6e J, W_contact %.6e J\n",
              s.energy_balance_error, s.energy_scale, s.final_external_work, s.final_contact_work);
  std::printf("blade 1 contact intervals:");
  for (const auto& [a, b] : s.contact_intervals_blade_1)
    std::printf(" [%.4f, %.4f] ms", 1e3 * a, 1e3 * b);
  std::printf("\nwrote %s/history.csv, %s/summary.json\n", options.out.c_str(),
              options.out.c_str());
  return s.completed ? 0 : 3;
}

} // namespace rsi
