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

/// CHOLMOD's simplicial LDL^T of the AMD-permuted M (natural ordering, no
/// postordering), solved by cholmod_solve2 with its workspace reused.
class ExposedCholmodLdlt : public Eigen::CholmodSimplicialLDLT<SpMat> {
public:
  cholmod_factor* factor() { return m_cholmodFactor; }
};

void cholmod_ldlt_solve2(benchmark::State& state) {
  const SpMat& m = default_system().m;
  const Eigen::SimplicialLDLT<SpMat> amd(m);
  const SpMat permuted = amd.permutationP() * m * amd.permutationP().inverse();
  ExposedCholmodLdlt solver;
  cholmod_common& common = solver.cholmod();
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_NATURAL;
  common.postorder = 0;
  solver.compute(permuted);
  if (solver.info() != Eigen::Success) state.SkipWithError("factorization failed");
  const auto n = static_cast<size_t>(m.rows());
  cholmod_dense* b = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &common);
  const Eigen::VectorXd r = Eigen::VectorXd::Random(m.rows());
  Eigen::Map<Eigen::VectorXd>(static_cast<double*>(b->x), m.rows()) = r;
  cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  for (auto _ : state) {
    cholmod_solve2(CHOLMOD_LDLt, solver.factor(), b, nullptr, &x, nullptr, &y, &e, &common);
    benchmark::DoNotOptimize(x->x);
  }
  // Same answer as Eigen's factor of the same permuted matrix.
  const Eigen::VectorXd reference =
      amd.permutationP() * Eigen::VectorXd(amd.solve(amd.permutationP().inverse() * r));
  const Eigen::VectorXd got = Eigen::Map<Eigen::VectorXd>(static_cast<double*>(x->x), m.rows());
  state.counters["relative_difference"] = (got - reference).norm() / reference.norm();
  cholmod_free_dense(&x, &common);
  cholmod_free_dense(&y, &common);
  cholmod_free_dense(&e, &common);
  cholmod_free_dense(&b, &common);
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
BENCHMARK(cholmod_ldlt_solve2)->Name("mass_solve/cholmod_ldlt_permuted_solve2");
BENCHMARK(product<Eigen::ColMajor>)->Name("stiffness_product/col_major");
BENCHMARK(product<Eigen::RowMajor>)->Name("stiffness_product/row_major");

} // namespace

BENCHMARK_MAIN();
