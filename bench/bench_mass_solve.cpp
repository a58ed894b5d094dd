// Per-step building blocks of the reference integrator on the default
// system (bladed disk + casing, 838 dofs): M^-1 r through Eigen's
// SimplicialLLT / SimplicialLDLT and CHOLMOD (simplicial, supernodal), and
// the sparse matrix-vector product K u, column- vs row-major storage.
// Run: build/bench/bench_mass_solve (Release).

#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include "assembler.hpp"
#include "bladed_disk.hpp"
#include "casing.hpp"

namespace {

using SpMat = Eigen::SparseMatrix<double>;

struct System {
  SpMat k;
  SpMat m;
  System() {
    const rsi::Case c =
        rsi::load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
    const rsi::BladedDisk bd = rsi::assemble_bladed_disk(c);
    const rsi::Casing casing = rsi::assemble_casing(c);
    k = rsi::block_diagonal(bd.stiffness, casing.stiffness);
    m = rsi::block_diagonal(bd.mass, casing.mass);
  }
};

const System& default_system() {
  static const System s;
  return s;
}

template <typename Solver> void solve(benchmark::State& state) {
  const SpMat& m = default_system().m;
  Solver solver;
  solver.compute(m);
  if (solver.info() != Eigen::Success) state.SkipWithError("factorization failed");
  if constexpr (std::is_base_of_v<Eigen::SimplicialCholeskyBase<Solver>, Solver>)
    state.counters["nnz_L"] = static_cast<double>(solver.matrixL().nestedExpression().nonZeros());
  const Eigen::VectorXd r = Eigen::VectorXd::Random(m.rows());
  Eigen::VectorXd x(m.rows());
  for (auto _ : state) {
    x = solver.solve(r);
    benchmark::DoNotOptimize(x.data());
  }
}

void cholmod_supernodal(benchmark::State& state) {
  const SpMat& m = default_system().m;
  Eigen::CholmodSupernodalLLT<SpMat> solver;
  solver.compute(m);
  const Eigen::VectorXd r = Eigen::VectorXd::Random(m.rows());
  Eigen::VectorXd x(m.rows());
  for (auto _ : state) {
    x = solver.solve(r);
    benchmark::DoNotOptimize(x.data());
  }
}

template <int Options> void product(benchmark::State& state) {
  const Eigen::SparseMatrix<double, Options> k = default_system().k;
  const Eigen::VectorXd u = Eigen::VectorXd::Random(k.rows());
  Eigen::VectorXd y(k.rows());
  for (auto _ : state) {
    y.noalias() = k * u;
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["nnz"] = static_cast<double>(k.nonZeros());
}

BENCHMARK(solve<Eigen::SimplicialLLT<SpMat>>)->Name("mass_solve/eigen_simplicial_llt");
BENCHMARK(solve<Eigen::SimplicialLDLT<SpMat>>)->Name("mass_solve/eigen_simplicial_ldlt");
BENCHMARK(solve<Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::NaturalOrdering<int>>>)
    ->Name("mass_solve/eigen_simplicial_ldlt_natural");
BENCHMARK(solve<Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::COLAMDOrdering<int>>>)
    ->Name("mass_solve/eigen_simplicial_ldlt_colamd");
BENCHMARK(solve<Eigen::CholmodSimplicialLLT<SpMat>>)->Name("mass_solve/cholmod_simplicial_llt");
BENCHMARK(cholmod_supernodal)->Name("mass_solve/cholmod_supernodal_llt");
BENCHMARK(product<Eigen::ColMajor>)->Name("stiffness_product/col_major");
BENCHMARK(product<Eigen::RowMajor>)->Name("stiffness_product/row_major");

} // namespace

BENCHMARK_MAIN();
