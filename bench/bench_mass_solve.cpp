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
#include "mass_factor.hpp"

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

/// The integrator's way (reference/central_difference): the system kept in
/// the AMD-permuted coordinates, L (stored by rows), D and L^T applied in place.
void eigen_ldlt_in_place(benchmark::State& state) {
  const SpMat& m = default_system().m;
  const Eigen::SimplicialLDLT<SpMat> solver(m);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> l_rows = solver.matrixL();
  const Eigen::VectorXd inverse_d = solver.vectorD().cwiseInverse();
  const Eigen::VectorXd r = Eigen::VectorXd::Random(m.rows());
  Eigen::VectorXd x(m.rows());
  for (auto _ : state) {
    x = r;
    l_rows.triangularView<Eigen::UnitLower>().solveInPlace(x);
    x.array() *= inverse_d.array();
    solver.matrixU().solveInPlace(x);
    benchmark::DoNotOptimize(x.data());
  }
}

/// reference/mass_factor (used by the integrator): CHOLMOD's simplicial
/// LDL^T in its own AMD order, cholmod_solve2 with its workspace reused.
void mass_factor(benchmark::State& state) {
  const SpMat& m = default_system().m;
  rsi::MassFactor factor(m);
  const Eigen::VectorXd r = Eigen::VectorXd::Random(m.rows());
  Eigen::VectorXd x(m.rows());
  for (auto _ : state) {
    x = r;
    factor.solve_in_place(x);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["nnz_L"] = factor.nonzeros_l();
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
BENCHMARK(eigen_ldlt_in_place)->Name("mass_solve/eigen_ldlt_permuted_in_place");
BENCHMARK(mass_factor)->Name("mass_solve/rsi_mass_factor_cholmod_ldlt_solve2");
BENCHMARK(product<Eigen::ColMajor>)->Name("stiffness_product/col_major");
BENCHMARK(product<Eigen::RowMajor>)->Name("stiffness_product/row_major");

} // namespace

BENCHMARK_MAIN();
