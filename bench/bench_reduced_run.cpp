// One whole reduced run of the 72-element model (issue 14's 1000x goal):
// the basis and the casing basis built once outside the timing, then
// run_reduced as `rsi campaign` times it (its RunSummary::wall_seconds),
// history rows kept in memory as a campaign does. The full reference of the
// same model is timed by `rsi campaign data/cases/batailly2007-72el.json`;
// this benchmark locates the reduced run's cost, it does not replace the
// ratio measured in one campaign.
// Run: build/bench/bench_reduced_run --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <string>

#include "case_file.hpp"
#include "reduced_run.hpp"

namespace {

void reduced_run_72el(benchmark::State& state, const std::string& method) {
  const rsi::Case c =
      rsi::load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007-72el.json");
  const int modes = static_cast<int>(state.range(0));
  const rsi::ReducedBasis basis = rsi::build_reduced_basis(c, method, modes, "lowest");
  rsi::ReducedRunOptions options;
  options.casing_modes = static_cast<int>(state.range(1));
  options.step.kind = rsi::StepRule::Kind::own; // safety 0.9, the campaign's default
  double wall = 0.0;
  double integration = 0.0;
  for (auto _ : state) {
    const rsi::ReducedRunResult r = rsi::run_reduced(c, basis, options);
    wall += r.run.summary.wall_seconds;
    integration += r.run.summary.integration_seconds;
    benchmark::DoNotOptimize(r.run.summary.steps);
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["run_wall_ms"] = 1e3 * wall / n;
  state.counters["integration_ms"] = 1e3 * integration / n;
}

void counts(benchmark::internal::Benchmark* b) {
  for (int modes : {44, 66, 88})
    b->Args({modes, 40});
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(reduced_run_72el, cb, std::string("cb"))->Apply(counts);
BENCHMARK_CAPTURE(reduced_run_72el, ccm, std::string("ccm"))->Apply(counts);

} // namespace

BENCHMARK_MAIN();
