// The lowest 50 modes K phi = omega^2 M phi of the NASA Rotor 37 blade
// (CalculiX model, 61,098 dofs, K with 7.1 M nonzeros), and their parts:
//  - CHOLMOD's analysis and factorization of K, supernodal and simplicial;
//  - CHOLMOD's factorization of M (what lowest_modes pays for omega_max);
//  - the Sturm count of lowest_modes' check, by UMFPACK and by CHOLMOD's simplicial L D L^T;
//  - Spectra's shift-invert Lanczos on Eigen's SparseLU (the sparse path before this round) and on
//    the CHOLMOD factor (CholmodShiftInvert), for several ncv;
//  - the block Krylov-Schur method (block_shift_invert), for several block sizes and bases;
//  - lowest_modes (the project's entry point: the block method and omega_max).
// Time: wall (real_time) and the CPU time of the whole process (all BLAS
// threads). Counters: right-hand sides solved, the method's own split of the time, and
// the process's peak resident memory so far (getrusage; run one benchmark a
// process, --benchmark_filter, for the peak of each).
//
// Matrices: RSI_ROTOR37_MATRICES=PREFIX reads PREFIX.sti and PREFIX.mas, as
// written by ccx's *FREQUENCY, SOLVER=MATRIXSTORAGE: one entry a line,
// "row col value", 1-based, upper triangle. Without it every benchmark says
// it skipped. With RSI_ROTOR37_CCX_DAT=FILE (the .dat of ccx's own
// *FREQUENCY run, EIGENVALUE OUTPUT table) the summary at the end compares
// the frequencies with ccx's.
//
// Run (Release), one line:
//   RSI_ROTOR37_MATRICES=/tmp/r37/matonly RSI_ROTOR37_CCX_DAT=/tmp/r37/lanczos.dat
//   build/bench/bench_rotor37_modes
// Results: bench/RESULTS.md, "Rotor 37: the lowest 50 modes".

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include "block_shift_invert.hpp"
#include "cholmod_factor.hpp"
#include "cholmod_shift_invert.hpp"
#include "modal_analysis.hpp"
#include "symmetric_inertia.hpp"

namespace {

using SpMat = Eigen::SparseMatrix<double>;
constexpr int wanted = 50;

/// "row col value" a line, 1-based, upper triangle (ccx's .sti / .mas) -> full symmetric storage.
SpMat load_upper_triangle(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot open " + path);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::vector<Eigen::Triplet<double>> entries;
  const char* p = text.data();
  const char* end = p + text.size();
  auto skip = [&] {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n'))
      ++p;
  };
  int n = 0;
  for (skip(); p < end; skip()) {
    int i = 0;
    int j = 0;
    double value = 0.0;
    auto r = std::from_chars(p, end, i);
    p = r.ptr;
    skip();
    auto c = std::from_chars(p, end, j);
    p = c.ptr;
    skip();
    auto v = std::from_chars(p, end, value);
    p = v.ptr;
    if (r.ec != std::errc() || c.ec != std::errc() || v.ec != std::errc() || i < 1 || j < 1)
      throw std::runtime_error(path + ": not \"row col value\" near byte " +
                               std::to_string(p - text.data()));
    n = std::max({n, i, j});
    entries.emplace_back(i - 1, j - 1, value);
    if (i != j) entries.emplace_back(j - 1, i - 1, value);
  }
  SpMat a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  return a;
}

struct Rotor37 {
  SpMat k;
  SpMat m;
};

/// The matrices, loaded once; empty if RSI_ROTOR37_MATRICES is not set.
const std::optional<Rotor37>& rotor37() {
  static const std::optional<Rotor37> model = []() -> std::optional<Rotor37> {
    const char* prefix = std::getenv("RSI_ROTOR37_MATRICES");
    if (prefix == nullptr || *prefix == '\0') return std::nullopt;
    Rotor37 r{load_upper_triangle(std::string(prefix) + ".sti"),
              load_upper_triangle(std::string(prefix) + ".mas")};
    if (r.k.rows() != r.m.rows())
      throw std::runtime_error("RSI_ROTOR37_MATRICES: K and M differ in size");
    return r;
  }();
  return model;
}

const Rotor37* model_or_skip(benchmark::State& state) {
  if (!rotor37()) {
    state.SkipWithError("skipped: set RSI_ROTOR37_MATRICES=PREFIX (PREFIX.sti, PREFIX.mas)");
    return nullptr;
  }
  return &*rotor37();
}

/// Each benchmark here: one run, in seconds, the wall time and the CPU time
/// of the whole process (all BLAS threads).
void one_timed_run(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kSecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();
}

double peak_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// Results kept for the accuracy summary printed after the benchmarks.
struct Kept {
  std::optional<Eigen::VectorXd> spectra_values;
  std::optional<rsi::BlockShiftInvertResult> block;
};
Kept& kept() {
  static Kept k;
  return k;
}

SpMat lower_triangle(const SpMat& a) {
  SpMat lower = a.triangularView<Eigen::Lower>();
  lower.prune([](Eigen::Index, Eigen::Index, double value) { return value != 0.0; });
  lower.makeCompressed();
  return lower;
}

/// Analysis and numeric factorization of K (argument 0: supernodal, 1: simplicial).
void cholmod_factor_k(benchmark::State& state) {
  const Rotor37* r = model_or_skip(state);
  if (!r) return;
  const auto method = state.range(0) == 0 ? rsi::CholmodFactor::Method::supernodal
                                          : rsi::CholmodFactor::Method::simplicial;
  const SpMat lower = lower_triangle(r->k);
  for (auto _ : state) {
    rsi::CholmodFactor factor(method);
    if (factor.factorize(lower) != rsi::CholmodFactor::Status::successful)
      state.SkipWithError(("K: " + factor.message()).c_str());
    state.counters["nnz_L"] = factor.nonzeros_l();
    state.counters["GFlop"] = factor.factorization_flops() * 1e-9;
  }
  state.counters["peak_MB"] = peak_megabytes();
}
BENCHMARK(cholmod_factor_k)->ArgName("simplicial")->Arg(0)->Arg(1)->Apply(one_timed_run);

/// CHOLMOD's supernodal L L^T of M (explicit zeros dropped): for omega_max.
void cholmod_factor_m(benchmark::State& state) {
  const Rotor37* r = model_or_skip(state);
  if (!r) return;
  const SpMat lower = lower_triangle(r->m);
  for (auto _ : state) {
    rsi::CholmodFactor factor;
    factor.factorize(lower);
    state.counters["positive_definite"] =
        factor.info() == rsi::CholmodFactor::Status::successful ? 1.0 : 0.0;
    if (factor.info() != rsi::CholmodFactor::Status::successful)
      state.SetLabel("M " + factor.message());
  }
  state.counters["peak_MB"] = peak_megabytes();
}
BENCHMARK(cholmod_factor_m)->Apply(one_timed_run);

/// The Sturm count of lowest_modes' check: the inertia of K - tau M, tau =
/// (2 pi 18,800 Hz)^2 just above the 50th mode (18,713 Hz), by
/// sparse_inertia (argument 0: UMFPACK's multifrontal LU) and by
/// simplicial_inertia (1: CHOLMOD's simplicial L D L^T, the only count
/// until session 29). Counter "below": the count (50 expected).
void sturm_count(benchmark::State& state) {
  const Rotor37* r = model_or_skip(state);
  if (!r) return;
  const double tau = std::pow(2.0 * M_PI * 18800.0, 2);
  SpMat lower = lower_triangle(r->k) - tau * lower_triangle(r->m);
  lower.makeCompressed();
  for (auto _ : state) {
    const rsi::Inertia inertia =
        state.range(0) == 0 ? rsi::sparse_inertia(lower) : rsi::simplicial_inertia(lower);
    if (!inertia.factorized) state.SkipWithError((inertia.method + ": " + inertia.why).c_str());
    state.counters["below"] = inertia.negative;
    state.SetLabel(inertia.method);
  }
  state.counters["peak_MB"] = peak_megabytes();
}
BENCHMARK(sturm_count)->ArgName("simplicial")->Arg(0)->Arg(1)->Apply(one_timed_run);

/// Spectra's SymGEigsShiftSolver on CholmodShiftInvert, ncv = range(0),
/// tolerance 1e-12 (lowest_modes' Lanczos setting); the time includes the
/// factorization of K.
void spectra_cholmod(benchmark::State& state) {
  const Rotor37* r = model_or_skip(state);
  if (!r) return;
  const int ncv = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    rsi::CholmodShiftInvert op(r->k, r->m);
    op.set_shift(0.0);
    if (!op.factorized()) {
      state.SkipWithError(("K: " + op.message()).c_str());
      return;
    }
    state.counters["factor_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Spectra::SparseSymMatProd<double> bop(r->m);
    Spectra::SymGEigsShiftSolver<rsi::CholmodShiftInvert, Spectra::SparseSymMatProd<double>,
                                 Spectra::GEigsMode::ShiftInvert>
        solver(op, bop, wanted, ncv, 0.0);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
    if (solver.info() != Spectra::CompInfo::Successful) {
      state.SkipWithError("Spectra did not converge");
      return;
    }
    state.counters["solves"] = static_cast<double>(op.n_solves());
    state.counters["restarts"] = static_cast<double>(solver.num_iterations());
    Eigen::VectorXd values = solver.eigenvalues();
    std::sort(values.data(), values.data() + values.size());
    kept().spectra_values = values;
  }
  state.counters["peak_MB"] = peak_megabytes();
}
BENCHMARK(spectra_cholmod)->ArgName("ncv")->Arg(100)->Arg(150)->Apply(one_timed_run);

/// What lowest_modes did before this round: Spectra's shift-invert Lanczos
/// on Spectra's SymShiftInvert (Eigen's SparseLU of K), ncv 101 as
/// lowest_modes chose it for 50 modes. About a minute: run it alone.
void spectra_sparselu(benchmark::State& state) {
  const Rotor37* r = model_or_skip(state);
  if (!r) return;
  using ShiftInvert = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
  for (auto _ : state) {
    ShiftInvert op(r->k, r->m);
    Spectra::SparseSymMatProd<double> bop(r->m);
    Spectra::SymGEigsShiftSolver<ShiftInvert, Spectra::SparseSymMatProd<double>,
                                 Spectra::GEigsMode::ShiftInvert>
        solver(op, bop, wanted, 2 * wanted + 1, 0.0);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
    if (solver.info() != Spectra::CompInfo::Successful) {
      state.SkipWithError("Spectra did not converge");
      return;
    }
    state.counters["solves"] = static_cast<double>(solver.num_operations());
  }
  state.counters["peak_MB"] = peak_megabytes();
}
BENCHMARK(spectra_sparselu)->Apply(one_timed_run);

/// block_shift_invert with block size range(0), n_kept = 50 + range(1),
/// max_basis = range(2); tolerance 1e-9 (the default).
void block_krylov_schur(benchmark::State& state) {
  const Rotor37* r = model_or_skip(state);
  if (!r) return;
  rsi::BlockShiftInvertOptions options;
  options.block_size = static_cast<int>(state.range(0));
  options.n_kept = wanted + static_cast<int>(state.range(1));
  options.max_basis = static_cast<int>(state.range(2));
  for (auto _ : state) {
    rsi::BlockShiftInvertResult result = rsi::block_shift_invert(r->k, r->m, wanted, options);
    if (result.status != rsi::BlockShiftInvertResult::Status::successful) {
      state.SkipWithError(result.message.c_str());
      return;
    }
    state.counters["solves"] = static_cast<double>(result.n_solves);
    state.counters["block_solves"] = result.n_block_solves;
    state.counters["restarts"] = result.n_restarts;
    state.counters["factor_s"] = result.seconds.factorization;
    state.counters["solve_s"] = result.seconds.solves;
    state.counters["product_s"] = result.seconds.products;
    state.counters["orth_s"] = result.seconds.orthogonalization;
    state.counters["rr_s"] = result.seconds.rayleigh_ritz;
    kept().block = std::move(result);
  }
  state.counters["peak_MB"] = peak_megabytes();
}
BENCHMARK(block_krylov_schur)
    ->ArgNames({"b", "extra", "max_basis"})
    ->Args({12, 6, 296})
    ->Args({16, 8, 218})
    ->Args({16, 8, 298})
    ->Args({16, 8, 378})
    ->Args({20, 10, 300})
    ->Args({24, 12, 302})
    ->Args({32, 16, 402})
    ->Args({48, 24, 410})
    ->Args({64, 32, 402})
    ->Apply(one_timed_run);

/// rsi::lowest_modes(K, M, 50, sparse): the block method with its default
/// parameters, then omega_max (infinite here: CalculiX's M of Rotor 37 is
/// singular, its Cholesky factorization stops at a zero pivot).
void lowest_modes_sparse(benchmark::State& state) {
  const Rotor37* r = model_or_skip(state);
  if (!r) return;
  for (auto _ : state) {
    const rsi::Modes modes = rsi::lowest_modes(r->k, r->m, wanted, rsi::ModalSolver::sparse);
    state.counters["f1_Hz"] = modes.frequency_hz(0);
    state.counters["f50_Hz"] = modes.frequency_hz(wanted - 1);
    state.counters["omega_max"] = modes.omega_max;
  }
  state.counters["peak_MB"] = peak_megabytes();
}
BENCHMARK(lowest_modes_sparse)->Apply(one_timed_run);

/// ccx's frequencies [Hz] from the EIGENVALUE OUTPUT table of its .dat file.
std::vector<double> ccx_frequencies(const std::string& path) {
  std::ifstream file(path);
  std::vector<double> hz;
  std::string line;
  bool table = false;
  while (std::getline(file, line)) {
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) {
      table = true;
      continue;
    }
    if (!table) continue;
    std::istringstream fields(line);
    int mode = 0;
    double eigenvalue = 0.0, omega = 0.0, frequency = 0.0;
    if (fields >> mode >> eigenvalue >> omega >> frequency)
      hz.push_back(frequency);
    else if (!hz.empty())
      break;
  }
  return hz;
}

/// The defining identities of the block method's last result, and its
/// agreement with Spectra's and ccx's.
void print_accuracy() {
  const Kept& k = kept();
  if (!rotor37() || !k.block) return;
  const rsi::BlockShiftInvertResult& b = *k.block;
  const SpMat& km = rotor37()->k;
  const SpMat& mm = rotor37()->m;
  const Eigen::MatrixXd k_phi = km * b.eigenvectors;
  const Eigen::MatrixXd m_phi = mm * b.eigenvectors;
  double identity = 0.0;
  for (int i = 0; i < wanted; ++i)
    identity = std::max(identity, (k_phi.col(i) - b.eigenvalues(i) * m_phi.col(i)).norm() /
                                      k_phi.col(i).norm());
  const Eigen::MatrixXd gram = b.eigenvectors.transpose() * m_phi;
  std::printf("\nblock method, last run: max |K phi - lambda M phi| / |K phi| = %.3e "
              "(its rounding floor up to %.3e); max |Phi^T M Phi - I| = %.3e\n",
              identity, b.residual_floors.maxCoeff(),
              (gram - Eigen::MatrixXd::Identity(wanted, wanted)).cwiseAbs().maxCoeff());
  if (k.spectra_values) {
    const Eigen::VectorXd& s = *k.spectra_values;
    std::printf("max |lambda_block - lambda_spectra| / lambda_spectra = %.3e\n",
                (b.eigenvalues - s).cwiseAbs().cwiseQuotient(s).maxCoeff());
  }
  const char* dat = std::getenv("RSI_ROTOR37_CCX_DAT");
  const std::vector<double> ccx = dat ? ccx_frequencies(dat) : std::vector<double>();
  if (static_cast<int>(ccx.size()) >= wanted) {
    double largest = 0.0;
    int where = 0;
    for (int i = 0; i < wanted; ++i) {
      const double f = std::sqrt(b.eigenvalues(i)) / (2.0 * M_PI);
      const double d = std::abs(f - ccx[i]) / ccx[i];
      if (d > largest) largest = d, where = i;
    }
    int same = 0; // rounded to ccx's 7 significant digits, the same number
    for (int i = 0; i < wanted; ++i) {
      char ours[32], theirs[32];
      std::snprintf(ours, sizeof ours, "%.6e", std::sqrt(b.eigenvalues(i)) / (2.0 * M_PI));
      std::snprintf(theirs, sizeof theirs, "%.6e", ccx[i]);
      same += std::string(ours) == theirs;
    }
    std::printf("max |f - f_ccx| / f_ccx = %.3e (mode %d: %.10g Hz against ccx's %.7g, which "
                "prints 7 digits); %d of %d frequencies rounded to 7 digits equal ccx's\n",
                largest, where + 1, std::sqrt(b.eigenvalues(where)) / (2.0 * M_PI), ccx[where],
                same, wanted);
  }
}

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  print_accuracy();
  benchmark::Shutdown();
  return 0;
}
