// Cost per step of the full reference integrator and of the reduced one
// (Craig-Bampton with 44 fixed-interface modes, Craig-Chang-Martinez with
// 44 free modes) as the model grows (SPEC §6):
// blades refined (9, 18, 36, 72 elements per blade) and more blades (22,
// 44, 88). Steps are taken from rest under the casing forcing, so contact
// (rare in the first steps) does not weigh on the numbers.
// Run: build/bench/bench_step_scaling --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <string>

#include <Eigen/SparseCholesky>

#include "assembler.hpp"
#include "bladed_disk.hpp"
#include "casing.hpp"
#include "casing_forcing.hpp"
#include "central_difference.hpp"
#include "modal_analysis.hpp"
#include "reduced_integrator.hpp"
#include "reduction.hpp"
#include "tip_casing_contact.hpp"

namespace {

using SpMat = Eigen::SparseMatrix<double>;

rsi::Case scaled_case(int blade_elements, int blades) {
  rsi::Case c = rsi::load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  c.bladed_disk.n_blade_elements = blade_elements;
  c.bladed_disk.n_blades = blades;
  c.casing.radius = c.bladed_disk.tip_radius + 0.1;
  const rsi::BladedDisk bd = rsi::assemble_bladed_disk(c);
  const rsi::Casing casing = rsi::assemble_casing(c);
  c.time.step = 0.4 / std::max(rsi::max_angular_frequency(bd.stiffness, bd.mass),
                               rsi::max_angular_frequency(casing.stiffness, casing.mass));
  return c;
}

void full_step(benchmark::State& state) {
  const rsi::Case c =
      scaled_case(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const rsi::BladedDisk bd = rsi::assemble_bladed_disk(c);
  const rsi::Casing casing = rsi::assemble_casing(c);
  const rsi::TipCasingContact law(bd, casing, c);
  rsi::CentralDifference cd(rsi::block_diagonal(bd.stiffness, casing.stiffness),
                            rsi::block_diagonal(bd.mass, casing.mass), c.time.step, law);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(bd.n_dofs() + casing.n_dofs());
  f.tail(casing.n_dofs()) = rsi::casing_forcing(casing, c.forcing);
  cd.start(f);
  for (auto _ : state)
    benchmark::DoNotOptimize(cd.step());
  const int n = bd.n_dofs() + casing.n_dofs();
  const double flops = cd.flops_per_step(); // counted by the integrator
  state.counters["dofs"] = n;
  state.counters["flops_per_step"] = flops;
  state.counters["GFLOPs"] = benchmark::Counter(
      flops * static_cast<double>(state.iterations()) / 1e9, benchmark::Counter::kIsRate);
}

void reduced_step(benchmark::State& state, const std::string& method) {
  const rsi::Case c =
      scaled_case(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const rsi::BladedDisk bd = rsi::assemble_bladed_disk(c);
  const rsi::Casing casing = rsi::assemble_casing(c);
  const rsi::ReducedBasis basis = rsi::reduce_bladed_disk(bd, method, 44);
  const rsi::ReducedTipContact contact(basis, casing, c);
  rsi::ReducedIntegrator integrator(basis, casing, c.time.step, contact);
  const Eigen::VectorXd f = rsi::casing_forcing(casing, c.forcing);
  integrator.start(f);
  for (auto _ : state)
    benchmark::DoNotOptimize(integrator.step()); // under f, held since start
  const double r = basis.n_reduced();
  const double nc = casing.n_dofs();
  const double flops = integrator.flops_per_step(); // counted by the integrator
  const double casing_flops = integrator.casing_flops_per_step();
  state.counters["dofs"] = bd.n_dofs() + casing.n_dofs();
  state.counters["reduced_dofs"] = r + nc;
  state.counters["flops_per_step"] = flops;
  state.counters["casing_flop_share"] = casing_flops / flops;
  state.counters["GFLOPs"] = benchmark::Counter(
      flops * static_cast<double>(state.iterations()) / 1e9, benchmark::Counter::kIsRate);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int elements : {9, 18, 36, 72})
    b->Args({elements, 22});
  for (int blades : {44, 88})
    b->Args({9, blades});
  b->Unit(benchmark::kMicrosecond);
}

BENCHMARK(full_step)->Apply(sizes);
BENCHMARK_CAPTURE(reduced_step, cb44, std::string("cb"))->Apply(sizes);
BENCHMARK_CAPTURE(reduced_step, ccm44, std::string("ccm"))->Apply(sizes);

} // namespace

BENCHMARK_MAIN();
