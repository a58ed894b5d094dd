#include "modal_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/SparseLU>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <Spectra/SymGEigsSolver.h>
#include <lapacke.h>

#include "block_shift_invert.hpp"
#include "cholmod_factor.hpp"
#include "cholmod_shift_invert.hpp"
#include "energy_resolution.hpp"

namespace rsi {
namespace {

// What to change, for the messages of ModalError (issue 13, class 8). The
// paper's case checks K and M of its parts when it loads (exit 2 naming the
// keys), so these are mostly about a component's imported matrices.
const std::string kMassRemedy =
    "; the modes need M positive definite: correct the component's mass (component.source) or "
    "set component.mass to \"lumped\" (HRZ)";
const std::string kStiffnessRemedy =
    "; support the part against rigid motions (a clamped boundary in component.source) or make "
    "it less slender (thicker sections, fewer elements)";
const std::string kSolverRemedy =
    "; ask for fewer modes (--count, --modes) or make the model coarser (fewer elements)";

Modes dense_modes(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int count) {
  const int n = static_cast<int>(stiffness.rows());
  Eigen::MatrixXd a = Eigen::MatrixXd(stiffness);
  Eigen::MatrixXd b = Eigen::MatrixXd(mass);
  Eigen::VectorXd w(n);
  const lapack_int info =
      LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', n, a.data(), n, b.data(), n, w.data());
  // LAPACKE's workspace allocation failed: out of memory, not a property of (K, M).
  if (info == LAPACK_WORK_MEMORY_ERROR || info == LAPACK_TRANSPOSE_MEMORY_ERROR)
    throw std::bad_alloc();
  if (info > n)
    throw ModalError(
        "modal analysis: the mass matrix is not positive definite (LAPACKE_dsygvd info " +
        std::to_string(info) + ", leading minor " + std::to_string(info - n) + ")" + kMassRemedy);
  if (info != 0)
    throw ModalError("modal analysis: LAPACKE_dsygvd failed (info " + std::to_string(info) + ")" +
                     kSolverRemedy);
  Modes modes;
  modes.omega_squared = w.head(count);
  modes.shapes = a.leftCols(count);
  modes.omega_max = std::sqrt(std::max(w(n - 1), 0.0));
  return modes;
}

/// M = P^T L L^T P by CHOLMOD (supernodal), for Spectra's Cholesky mode:
/// lower_triangular_solve y = L^-1 P x, upper_triangular_solve y = P^T L^-T x.
class CholmodCholesky {
public:
  using Scalar = double;
  explicit CholmodCholesky(const Eigen::SparseMatrix<double>& mass) {
    Eigen::SparseMatrix<double> lower = mass.triangularView<Eigen::Lower>();
    lower.prune([](Eigen::Index, Eigen::Index, double value) { return value != 0.0; });
    lower.makeCompressed();
    m_factor.factorize(lower);
  }
  bool factorized() const { return m_factor.info() == CholmodFactor::Status::successful; }
  const std::string& message() const { return m_factor.message(); }
  Eigen::Index rows() const { return m_factor.rows(); }
  Eigen::Index cols() const { return m_factor.rows(); }
  void lower_triangular_solve(const double* x, double* y) const {
    solve(CholmodFactor::System::l_p, x, y);
  }
  void upper_triangular_solve(const double* x, double* y) const {
    solve(CholmodFactor::System::pt_lt, x, y);
  }

private:
  void solve(CholmodFactor::System system, const double* x, double* y) const {
    const Eigen::Map<const Eigen::VectorXd> b(x, rows());
    Eigen::Map<Eigen::VectorXd> z(y, rows());
    if (!m_factor.solve(system, b, z))
      throw ModalError("modal analysis: the CHOLMOD solve with the mass factor failed" +
                       kSolverRemedy);
  }
  CholmodFactor m_factor;
};

/// Largest eigenvalue of K phi = lambda M phi by Lanczos on L^-1 P K P^T L^-T
/// (M = P^T L L^T P); +infinity if M is not positive definite to working
/// precision (its Cholesky factorization fails, `why` says where).
double sparse_largest_eigenvalue(const Eigen::SparseMatrix<double>& stiffness,
                                 const Eigen::SparseMatrix<double>& mass, std::string& why) {
  CholmodCholesky bop(mass);
  if (!bop.factorized()) {
    why = bop.message();
    return std::numeric_limits<double>::infinity();
  }
  Spectra::SparseSymMatProd<double> op(stiffness);
  const int n = static_cast<int>(stiffness.rows());
  // A cyclic model's largest eigenvalue sits in a cluster of n_sectors
  // nearly equal ones (22 identical blade tips vibrating alone); with 30
  // Lanczos vectors the residual of the top Ritz pair stalls when the
  // cluster is wide of the subspace (72 elements per blade: no convergence
  // in 10000 restarts). The retry keeps a subspace of 128, over five times
  // a 22-fold cluster; the first attempt is kept as it was (capped at 1000
  // restarts: a stalled one costs minutes), so models that converged before
  // get the same value, and a retried one the same to the tolerance.
  for (const auto& [ncv, restarts] : {std::pair<int, int>{30, 1000}, {128, 10000}}) {
    Spectra::SymGEigsSolver<Spectra::SparseSymMatProd<double>, CholmodCholesky,
                            Spectra::GEigsMode::Cholesky>
        solver(op, bop, 1, std::min(n, ncv));
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, restarts, 1e-12);
    if (solver.info() == Spectra::CompInfo::Successful) return solver.eigenvalues()(0);
    if (ncv >= n) break;
  }
  throw ModalError("modal analysis: Lanczos for omega_max did not converge (30 vectors and 1000 "
                   "restarts, then 128 and 10000)" +
                   kSolverRemedy);
}

/// The block method's parameters for `count` modes (measured on Rotor 37,
/// bench/RESULTS.md), or block_size 0 if its basis would take more than
/// half the space.
BlockShiftInvertOptions block_options(int count, int n) {
  BlockShiftInvertOptions options; // block size 24
  options.n_kept = count + options.block_size / 2;
  options.max_basis = options.n_kept + 10 * options.block_size;
  if (2 * (options.max_basis + options.block_size) > n) options.block_size = 0;
  return options;
}

/// The `count` lowest eigenpairs by the block method (large models); false
/// if it did not converge (the caller takes Lanczos instead).
bool block_modes(const Eigen::SparseMatrix<double>& stiffness,
                 const Eigen::SparseMatrix<double>& mass, int count,
                 const BlockShiftInvertOptions& options, const CholmodShiftInvert* factorized,
                 Modes& modes) {
  const BlockShiftInvertResult result =
      block_shift_invert(stiffness, mass, count, options, factorized);
  using Status = BlockShiftInvertResult::Status;
  switch (result.status) {
  case Status::successful:
    break;
  case Status::stiffness_not_positive_definite:
    throw ModalError("modal analysis: the stiffness matrix is singular or indefinite (" +
                     result.message + ")" + kStiffnessRemedy);
  case Status::mass_not_semidefinite:
    throw ModalError("modal analysis: the mass matrix is not positive semi-definite (" +
                     result.message + ")" + kMassRemedy);
  case Status::not_converged:
    return false;
  case Status::failed:
    throw ModalError("modal analysis: block shift-invert failed (" + result.message + ")" +
                     kSolverRemedy);
  }
  modes.omega_squared = result.eigenvalues;
  modes.shapes = result.eigenvectors;
  return true;
}

/// Spectra's SymShiftInvert reports any failed SparseLU factorization as
/// std::invalid_argument, and Eigen's SparseLU turns a failed allocation
/// into such a failure (it catches std::bad_alloc). Factorizing K - 0 M
/// again exactly as Spectra does (SymShiftInvertHelper: the selfadjoint
/// views of the lower triangles, A - sigma B, SparseLU marked symmetric)
/// tells them apart: the same arithmetic fails the same way on a singular
/// K, so a failure for lack of memory (SparseLU's message names it) or a
/// success this time is thrown as std::bad_alloc; anything else is the
/// singular K the caller reports.
void throw_if_sparse_lu_out_of_memory(const Eigen::SparseMatrix<double>& stiffness,
                                      const Eigen::SparseMatrix<double>& mass) {
  const Eigen::SparseMatrix<double> a = stiffness.selfadjointView<Eigen::Lower>();
  const Eigen::SparseMatrix<double> b = mass.selfadjointView<Eigen::Lower>();
  const Eigen::SparseMatrix<double> shifted = a - 0.0 * b;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.isSymmetric(true);
  lu.compute(shifted);
  if (lu.info() == Eigen::Success || lu.lastErrorMessage().find("MEMORY") != std::string::npos)
    throw std::bad_alloc();
}

/// The `count` lowest eigenpairs by Spectra's shift-invert Lanczos on `op`
/// ((K - sigma M)^-1, sigma = 0). `factorization_failed` is called first
/// when the factorization of K fails (it may throw something more precise).
template <class ShiftInvert, class OnFailure>
void lanczos_modes(ShiftInvert& op, const Eigen::SparseMatrix<double>& mass, int count,
                   Modes& modes, const OnFailure& factorization_failed) {
  const int n = static_cast<int>(mass.rows());
  using MassProduct = Spectra::SparseSymMatProd<double>;
  MassProduct bop(mass);
  const int ncv = std::min(n, std::max(2 * count + 1, count + 20));
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  try {
    Spectra::SymGEigsShiftSolver<ShiftInvert, MassProduct, Spectra::GEigsMode::ShiftInvert> solver(
        op, bop, count, ncv, 0.0);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 10000, 1e-12);
    if (solver.info() != Spectra::CompInfo::Successful)
      throw ModalError("modal analysis: shift-invert Lanczos did not converge for the lowest " +
                       std::to_string(count) + " modes" + kSolverRemedy);
    values = solver.eigenvalues();
    vectors = solver.eigenvectors();
  } catch (const std::invalid_argument& e) { // Spectra's SymShiftInvert: factorization failed
    factorization_failed();
    throw ModalError(
        std::string("modal analysis: the stiffness matrix is singular (shift-invert about 0): ") +
        e.what() + kStiffnessRemedy);
  }
  // Spectra returns them in decreasing 1/lambda, i.e. increasing lambda: reverse to be sure.
  std::vector<int> order(count);
  for (int i = 0; i < count; ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) < values(b); });
  modes.omega_squared.resize(count);
  modes.shapes.resize(n, count);
  for (int i = 0; i < count; ++i) {
    modes.omega_squared(i) = values(order[i]);
    modes.shapes.col(i) = vectors.col(order[i]);
  }
}

/// `factorized`: a factor of K at shift 0 the caller made, or null.
Modes sparse_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count,
                   CholmodShiftInvert* factorized) {
  const int n = static_cast<int>(stiffness.rows());
  Modes modes;
  const BlockShiftInvertOptions options = block_options(count, n);
  if (factorized == nullptr && n < block_method_min_dofs) {
    Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse> op(stiffness, mass);
    lanczos_modes(op, mass, count, modes,
                  [&] { throw_if_sparse_lu_out_of_memory(stiffness, mass); });
  } else if (options.block_size > 0 &&
             block_modes(stiffness, mass, count, options, factorized, modes)) {
    // The block method's true-residual test is strict: some refined
    // models stall above it (block_shift_invert.hpp); Spectra's Lanczos on
    // the same factor below then gives their modes, checked as any.
  } else {
    std::optional<CholmodShiftInvert> own;
    if (factorized == nullptr) own.emplace(stiffness, mass);
    CholmodShiftInvert& op = factorized != nullptr ? *factorized : *own;
    op.set_shift(0.0);
    if (!op.factorized())
      throw ModalError("modal analysis: the stiffness matrix is singular or indefinite (" +
                       op.message() + ")" + kStiffnessRemedy);
    lanczos_modes(op, mass, count, modes, [] {});
  }
  std::string why;
  const double largest = sparse_largest_eigenvalue(stiffness, mass, why);
  modes.omega_max = std::sqrt(std::max(largest, 0.0));
  // A singular K that the factorization takes anyway (pivots at round-off)
  // returns its null vector as the lowest mode, and a K too stiff for double
  // precision (a casing of 30,000 elements: its smooth modes bend with an
  // energy 1e17 times smaller than the terms it is summed from) a mode that
  // is rounding. Either way the lowest mode's energy phi^T K phi = lambda is
  // not resolved: not above its rounding gamma_p |phi|^T |K| |phi|
  // (linalg/energy_resolution, the test the paper's parts pass when they
  // are built), whereas an elastic mode of a refined model stands clear of
  // it: issue 13's 500-element blades (lambda_min 390 rad^2/s^2 under n eps
  // lambda_max = 3900, which the first test here compared), and a casing of
  // 10,000 elements, which the product-rounding test that followed called
  // singular (|K phi| under 4 gamma_p | |K| |phi| |, a bound in the
  // infinity norm five times wider than this one for smooth modes).
  // The lowest mode by its vector's own energy phi^T K phi (M-normalised):
  // exact for the vector, where the eigenvalue shift-invert gives with it
  // is 1/theta, garbage for a theta under theta's rounding (below).
  const Eigen::VectorXd energies =
      (modes.shapes.transpose() * (stiffness * modes.shapes)).diagonal();
  Eigen::Index first = 0;
  energies.minCoeff(&first);
  const EnergyResolution lowest = energy_resolution(stiffness, modes.shapes.col(first));
  if (!lowest.resolved()) {
    std::ostringstream message;
    message << "modal analysis: the stiffness matrix is singular or not positive definite to "
               "working precision (the lowest mode, eigenvalue "
            << modes.omega_squared(first)
            << " rad^2/s^2, has the energy phi^T K phi = " << lowest.energy
            << ", not above its rounding gamma_p |phi|^T |K| |phi| = " << lowest.rounding
            << "): a part not supported against a rigid motion, or too stiff for double precision"
            << kStiffnessRemedy;
    throw ModalError(message.str());
  }
  // Shift-invert about 0 computes theta = 1/lambda, each to within p(n) eps
  // theta_max = p(n) eps / lambda_min (backward stable on K^-1 M; the mirror
  // of dense_resolution), so it resolves eigenvalues only below lambda_min /
  // (n eps), lambda_min the lowest mode's resolved energy. A highest mode
  // asked past it, or a theta at or below 0 (under its rounding), is not a
  // result.
  const double resolution =
      lowest.energy / (static_cast<double>(n) * std::numeric_limits<double>::epsilon());
  if (!(modes.omega_squared(0) > 0.0) || !(modes.omega_squared(count - 1) < resolution)) {
    std::ostringstream message;
    message << "modal analysis: the " << count
            << " lowest modes are not all resolved by shift-invert about 0: eigenvalues from "
            << modes.omega_squared(0) << " to " << modes.omega_squared(count - 1)
            << " rad^2/s^2, where it resolves those in (0, lambda_min / (n eps)) = (0, "
            << resolution << ") only; ask for fewer modes";
    throw ModalResolutionError(message.str());
  }
  return modes;
}

} // namespace

double dense_resolution(const Modes& modes) {
  const double n = static_cast<double>(modes.shapes.rows());
  return n * std::numeric_limits<double>::epsilon() * modes.omega_max * modes.omega_max;
}

double max_angular_frequency(const Eigen::SparseMatrix<double>& stiffness,
                             const Eigen::SparseMatrix<double>& mass) {
  std::string why;
  const double largest = sparse_largest_eigenvalue(stiffness, mass, why);
  if (!std::isfinite(largest))
    throw ModalError("modal analysis: the mass matrix is not positive definite (" + why + ")" +
                     kMassRemedy);
  return std::sqrt(std::max(largest, 0.0));
}

double Modes::frequency_hz(int i) const {
  const double w2 = omega_squared(i);
  return std::copysign(std::sqrt(std::abs(w2)), w2) / (2.0 * M_PI);
}

Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count, ModalSolver solver) {
  const int n = static_cast<int>(stiffness.rows());
  if (count < 1 || count > n)
    throw std::invalid_argument("lowest_modes: count must be in [1, " + std::to_string(n) +
                                "], got " + std::to_string(count));
  const bool dense =
      solver == ModalSolver::dense || (solver == ModalSolver::automatic && n <= dense_limit);
  if (!dense && count >= n)
    throw std::invalid_argument("lowest_modes: the sparse solver needs count < " +
                                std::to_string(n));
  if (!dense) return sparse_modes(stiffness, mass, count, nullptr);
  Modes modes = dense_modes(stiffness, mass, count);
  if (solver == ModalSolver::dense) return modes; // as the dense solver gives them
  const double resolution = dense_resolution(modes);
  if (modes.omega_squared(0) > resolution) return modes;
  if (count < n) return sparse_modes(stiffness, mass, count, nullptr);
  std::ostringstream message;
  message << "modal analysis: all " << n
          << " modes need the dense solver, which does not resolve the lowest ones (lowest "
             "eigenvalue "
          << modes.omega_squared(0)
          << " rad^2/s^2 <= its resolution n eps lambda_max = " << resolution
          << "); ask for fewer modes (shift-invert resolves the lowest ones)";
  throw ModalResolutionError(message.str());
}

Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count,
                   CholmodShiftInvert& factorized) {
  const int n = static_cast<int>(stiffness.rows());
  if (count < 1 || count >= n)
    throw std::invalid_argument("lowest_modes: count must be in [1, " + std::to_string(n - 1) +
                                "], got " + std::to_string(count));
  if (factorized.rows() != n)
    throw std::invalid_argument("lowest_modes: the factor given is of another matrix size");
  return sparse_modes(stiffness, mass, count, &factorized);
}

} // namespace rsi
