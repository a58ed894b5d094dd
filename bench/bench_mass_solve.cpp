// Per-step building blocks of the reference integrator on the default
// system (bladed disk + casing, 838 dofs): M^-1 r through Eigen's
// SimplicialLLT / SimplicialLDLT, CHOLMOD (simplicial, supernodal, and
// cholmod_solve2 on its LDL^T), Eigen's triangular solves on rsi's factor
// and rsi::MassFactor's own; the sparse matrix-vector product K u, column-
// vs row-major storage and rsi::SparseRows; and the predictor's whole
// M^-1 (f - K u) as the integrator forms it.
// Run: build/bench/bench_mass_solve (Release).

#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include "assembler.hpp"
#include "bladed_disk.hpp"
#include "casing.hpp"
#include "mass_factor.hpp"
#include "sparse_rows.hpp"

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

/// CHOLMOD's simplicial LDL^T in its AMD order, applied by cholmod_solve2
/// with its workspace reused (the integrator's mass solve until 2026-11-22).
void cholmod_ldlt_solve2(benchmark::State& state) {
  const SpMat& m = default_system().m;
  cholmod_common common;
  cholmod_start(&common);
  common.supernodal = CHOLMOD_SIMPLICIAL;
  common.final_ll = 0;
  SpMat lower = m.triangularView<Eigen::Lower>();
  lower.makeCompressed();
  cholmod_sparse a = Eigen::viewAsCholmod(lower);
  a.stype = -1;
  cholmod_factor* factor = cholmod_analyze(&a, &common);
  const auto n = static_cast<size_t>(m.rows());
  cholmod_dense* rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &common);
  cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  if (factor == nullptr || rhs == nullptr || !cholmod_factorize(&a, factor, &common))
    state.SkipWithError("CHOLMOD failed");
  const Eigen::VectorXd r = Eigen::VectorXd::Random(m.rows());
  Eigen::VectorXd out(m.rows());
  for (auto _ : state) {
    Eigen::Map<Eigen::VectorXd>(static_cast<double*>(rhs->x), m.rows()) = r;
    cholmod_solve2(CHOLMOD_LDLt, factor, rhs, nullptr, &x, nullptr, &y, &e, &common);
    out = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), m.rows());
    benchmark::DoNotOptimize(out.data());
  }
  cholmod_free_dense(&rhs, &common);
  cholmod_free_dense(&x, &common);
  cholmod_free_dense(&y, &common);
  cholmod_free_dense(&e, &common);
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
}

/// rsi::MassFactor's L and D (CHOLMOD's, renumbered by block and level)
/// through Eigen's sparse triangular solves: L by columns and L^T by columns
/// (both solves in column / axpy form), or both by rows (dot form).
template <int Storage> void eigen_triangular_on_rsi_factor(benchmark::State& state) {
  const rsi::MassFactor factor(default_system().m);
  const Eigen::SparseMatrix<double, Storage> l = factor.strictly_lower_l();
  const Eigen::SparseMatrix<double, Storage> lt = factor.strictly_lower_l().transpose();
  const Eigen::VectorXd r = Eigen::VectorXd::Random(l.rows());
  Eigen::VectorXd x(l.rows());
  for (auto _ : state) {
    x = r;
    l.template triangularView<Eigen::UnitLower>().solveInPlace(x);
    x.array() *= factor.inverse_d().array();
    lt.template triangularView<Eigen::UnitUpper>().solveInPlace(x);
    benchmark::DoNotOptimize(x.data());
  }
}

/// reference/mass_factor (used by the integrator): CHOLMOD's factor applied
/// by rsi's own row-form triangular solves (reference/sparse_rows).
void mass_factor(benchmark::State& state) {
  const SpMat& m = default_system().m;
  const rsi::MassFactor factor(m);
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

/// reference/sparse_rows (used by the integrator for K'u).
void sparse_rows_product(benchmark::State& state) {
  const rsi::RowMajorMatrix k = default_system().k;
  const rsi::SparseRows rows(k);
  const Eigen::VectorXd u = Eigen::VectorXd::Random(k.rows());
  Eigen::VectorXd y(k.rows());
  for (auto _ : state) {
    rows.multiply(u, y);
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["nnz"] = static_cast<double>(k.nonZeros());
}

/// The predictor's M'^-1 (f - K'u) in the integrator's coordinates, as the
/// integrator forms it: K'u by rsi::SparseRows, then rsi::MassFactor's solve.
void predictor(benchmark::State& state) {
  const rsi::MassFactor factor(default_system().m);
  const rsi::RowMajorMatrix k = factor.permuted(default_system().k);
  const rsi::SparseRows k_rows(k);
  const Eigen::VectorXd u = Eigen::VectorXd::Random(k.rows());
  const Eigen::VectorXd f = Eigen::VectorXd::Random(k.rows());
  Eigen::VectorXd x(k.rows());
  for (auto _ : state) {
    k_rows.multiply(u, x);
    x = f - x;
    factor.solve_in_place(x);
    benchmark::DoNotOptimize(x.data());
  }
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
BENCHMARK(cholmod_ldlt_solve2)->Name("mass_solve/cholmod_ldlt_solve2");
BENCHMARK(eigen_triangular_on_rsi_factor<Eigen::ColMajor>)
    ->Name("mass_solve/eigen_triangular_columns_on_rsi_factor");
BENCHMARK(eigen_triangular_on_rsi_factor<Eigen::RowMajor>)
    ->Name("mass_solve/eigen_triangular_rows_on_rsi_factor");
BENCHMARK(mass_factor)->Name("mass_solve/rsi_mass_factor");
BENCHMARK(product<Eigen::ColMajor>)->Name("stiffness_product/col_major");
BENCHMARK(product<Eigen::RowMajor>)->Name("stiffness_product/row_major");
BENCHMARK(sparse_rows_product)->Name("stiffness_product/rsi_sparse_rows");
BENCHMARK(predictor)->Name("predictor/rsi_sparse_rows_then_mass_factor");

} // namespace

BENCHMARK_MAIN();
