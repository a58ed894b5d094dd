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
#include "interruption_flag.hpp"
#include "modal_check.hpp"
#include "stored_digits.hpp"
#include "symmetric_inertia.hpp"

namespace rsi {
namespace {

// What to change, for the messages of ModalError (issue 13, class 8). The
// paper's case checks K and M of its parts when it loads (exit 2 naming the
// keys), so these are mostly about a component's imported matrices.
const std::string kMassWhy = "; the modes need M positive semi-definite";
/// omega_max (the explicit integrators' stability limit) needs M^-1.
const std::string kOmegaMaxWhy = "; omega_max needs M positive definite";
const FailureAdvice kMassAdvice = remedied_by({Remedy::corrected_or_lumped_mass});
const std::string kStiffnessRemedy =
    "; support the part against rigid motions (a clamped boundary in component.source) or make "
    "it less slender (thicker sections, fewer elements)";
const FailureAdvice kSolverAdvice = remedied_by({Remedy::fewer_modes_or_coarser_model});

/// K phi = lambda M phi by LAPACKE dsygvd on (K, M): false if M is not
/// positive definite (its Cholesky factorization fails), the caller then
/// takes the shift-invert form below.
bool dense_direct(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int count, Modes& modes) {
  const int n = static_cast<int>(stiffness.rows());
  Eigen::MatrixXd a = Eigen::MatrixXd(stiffness);
  Eigen::MatrixXd b = Eigen::MatrixXd(mass);
  Eigen::VectorXd w(n);
  const lapack_int info =
      LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', n, a.data(), n, b.data(), n, w.data());
  // LAPACKE's workspace allocation failed: out of memory, not a property of (K, M).
  if (info == LAPACK_WORK_MEMORY_ERROR || info == LAPACK_TRANSPOSE_MEMORY_ERROR)
    throw std::bad_alloc();
  if (info > n) return false;
  if (info != 0)
    throw ModalError("modal analysis: LAPACKE_dsygvd failed (info " + std::to_string(info) + ")",
                     kSolverAdvice);
  modes.omega_squared = w.head(count);
  modes.shapes = a.leftCols(count);
  modes.omega_max = std::sqrt(std::max(w(n - 1), 0.0));
  modes.accuracy.solver = "the dense solver (LAPACKE dsygvd on K, M)";
  return true;
}

/// The shift for the shift-invert forms: 0 if K is positive definite to
/// working precision (its CHOLMOD factor and the energy of its lowest mode,
/// linalg/energy_resolution), else below every eigenvalue
/// (shift_below_spectrum): a free part.
double shift_for(const Eigen::SparseMatrix<double>& stiffness,
                 const Eigen::SparseMatrix<double>& mass) {
  return check_positive_definite(stiffness, mass).positive_definite()
             ? 0.0
             : shift_below_spectrum(stiffness, mass);
}

/// The `count` lowest modes by LAPACKE dsygvd on the pencil (M, A), A = K -
/// sigma M positive definite: M x = mu A x, mu = 1 / (lambda - sigma). M
/// only needs to be positive semi-definite (a massless direction is mu = 0,
/// an infinite lambda), K only semi-definite (sigma < 0: a rigid motion is
/// mu = -1/sigma). The solver is backward stable on C = L^-1 M L^-T
/// (A = L L^T): every mu to within n eps mu_max, so the lowest lambda are
/// the best resolved (the mirror image of dsygvd on (K, M)); a mu at or
/// below n eps' mu_max is a massless direction, one below -n eps' mu_max an
/// indefinite M (eps' the larger of eps and the input's rounding,
/// stored_digits).
/// When A is singular for every sigma, K and M share null directions z
/// (K z = 0 and M z = 0: a reduced-integration element's zero-energy
/// mode that carries no mass either, as C3D20R's can), and (K, M) has no
/// eigenvalue there, only 0/0: those directions are the eigenvectors of A
/// with eigenvalues within n eps' of zero (LAPACKE dsyevd); they are left
/// out (modes.accuracy.null_directions) and the pencil solved on the rest,
/// where A is positive definite. Such a direction can also let the
/// Cholesky factor of A succeed (its eigenvalue a rounding error above
/// zero) and then shows as a mu far below -n eps' mu_max (M's rounding
/// over A's): the same split is tried before M is called indefinite, and
/// taken when the null directions of A carry no mass (z^T M z within
/// n eps' |M|_1).
Modes dense_shift_invert(const Eigen::SparseMatrix<double>& stiffness,
                         const Eigen::SparseMatrix<double>& mass, int count, double sigma) {
  const int n = static_cast<int>(stiffness.rows());
  const double input = digits_rounding(std::min(stored_digits(mass), stored_digits(stiffness)));
  const double resolution =
      static_cast<double>(n) * std::max(std::numeric_limits<double>::epsilon(), input);
  const Eigen::MatrixXd m_full = Eigen::MatrixXd(mass);
  const Eigen::MatrixXd a_full = Eigen::MatrixXd(stiffness) - sigma * m_full;
  Eigen::MatrixXd x = m_full; // the eigenvectors, A-normalised
  Eigen::MatrixXd a = a_full;
  Eigen::VectorXd mu(n);
  const lapack_int info =
      LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', n, x.data(), n, a.data(), n, mu.data());
  if (info == LAPACK_WORK_MEMORY_ERROR || info == LAPACK_TRANSPOSE_MEMORY_ERROR)
    throw std::bad_alloc();
  if (info != 0 && info <= n)
    throw ModalError("modal analysis: LAPACKE_dsygvd failed (info " + std::to_string(info) + ")",
                     kSolverAdvice);
  Eigen::MatrixXd null_directions;
  const bool failed_cholesky =
      info > n; // A not positive definite: shared null directions, or K indefinite
  const bool negative_mu = info == 0 && mu(0) < -resolution * std::abs(mu(n - 1));
  if (failed_cholesky || negative_mu) {
    Eigen::MatrixXd v = a_full;
    Eigen::VectorXd w(n);
    const lapack_int e = LAPACKE_dsyevd(LAPACK_COL_MAJOR, 'V', 'L', n, v.data(), n, w.data());
    if (e == LAPACK_WORK_MEMORY_ERROR || e == LAPACK_TRANSPOSE_MEMORY_ERROR) throw std::bad_alloc();
    if (e != 0)
      throw ModalError("modal analysis: LAPACKE_dsyevd failed (info " + std::to_string(e) + ")",
                       kSolverAdvice);
    const double tolerance = resolution * std::max(std::abs(w(0)), std::abs(w(n - 1)));
    int z = 0;
    while (z < n && w(z) <= tolerance)
      ++z;
    const double mass_floor = resolution * m_full.cwiseAbs().colwise().sum().maxCoeff();
    bool massless = z > 0 && z < n;
    for (int i = 0; i < z && massless; ++i)
      massless = v.col(i).dot(m_full * v.col(i)) <= mass_floor;
    if (failed_cholesky && (w(0) < -tolerance || z == 0 || z == n)) {
      std::ostringstream message;
      message << "modal analysis: K - sigma M is not positive definite at sigma = " << sigma
              << " (its lowest eigenvalue " << w(0) << ", resolution " << tolerance
              << "): the stiffness matrix is not positive semi-definite" << kStiffnessRemedy;
      throw ModalError(message.str());
    }
    if (massless || failed_cholesky) {
      null_directions = v.leftCols(z);
      // On the rest, A = diag(w): C = W^-1/2 Q^T M Q W^-1/2, x = Q W^-1/2 y.
      const Eigen::MatrixXd q =
          v.rightCols(n - z) * w.tail(n - z).cwiseSqrt().cwiseInverse().asDiagonal();
      Eigen::MatrixXd c = q.transpose() * m_full * q;
      c = 0.5 * (c + c.transpose()).eval();
      mu.resize(n - z);
      const lapack_int f =
          LAPACKE_dsyevd(LAPACK_COL_MAJOR, 'V', 'L', n - z, c.data(), n - z, mu.data());
      if (f == LAPACK_WORK_MEMORY_ERROR || f == LAPACK_TRANSPOSE_MEMORY_ERROR)
        throw std::bad_alloc();
      if (f != 0)
        throw ModalError("modal analysis: LAPACKE_dsyevd failed (info " + std::to_string(f) + ")",
                         kSolverAdvice);
      x = q * c;
    }
  }
  const int r = static_cast<int>(mu.size());
  // The resolution of mu: the solver's n eps mu_max, and the rounding of
  // M's entries (stored_digits: CalculiX writes 14 digits, and a singular
  // consistent mass written so is semi-definite only to that rounding).
  const double mu_max = mu(r - 1);
  const double floor = resolution * mu_max;
  if (mu(0) < -floor) {
    std::ostringstream message;
    message << "modal analysis: the mass matrix is not positive definite, nor semi-definite: the "
               "pencil (M, K - sigma M) has the eigenvalue "
            << mu(0) << " < -n eps mu_max = " << -floor << kMassWhy;
    throw ModalError(message.str(), kMassAdvice);
  }
  int finite = 0; // mu above the solver's resolution: finite eigenvalues lambda
  for (int i = 0; i < r; ++i)
    if (mu(i) > floor) ++finite;
  if (count > finite) {
    std::ostringstream message;
    message << "modal analysis: the mass matrix is singular: the model has " << finite
            << " finite eigenvalues (" << n - finite
            << " directions are massless or without stiffness and mass), " << count
            << " modes were asked; ask for at most " << finite;
    throw ModalResolutionError(message.str());
  }
  Modes modes;
  modes.omega_squared.resize(count);
  modes.shapes.resize(n, count);
  for (int i = 0; i < count; ++i) {
    const int j = r - 1 - i; // the largest mu: the lowest lambda
    modes.omega_squared(i) = sigma + 1.0 / mu(j);
    // x^T A x = 1, so x^T M x = mu: M-normalised by 1 / sqrt(mu).
    modes.shapes.col(i) = x.col(j) / std::sqrt(mu(j));
  }
  modes.omega_max = finite < n ? std::numeric_limits<double>::infinity()
                               : std::sqrt(std::max(sigma + 1.0 / mu(0), 0.0));
  std::ostringstream solver;
  solver << "the dense shift-invert solver (LAPACKE dsygvd on M, K - sigma M, sigma = " << sigma
         << ")";
  if (null_directions.cols() > 0)
    solver << ", " << null_directions.cols()
           << " directions without stiffness or mass left out (0/0: no eigenvalue)";
  modes.accuracy.solver = solver.str();
  modes.accuracy.null_directions = null_directions;
  return modes;
}

/// The dense shift-invert solve, checked; ModalCheckError if it fails.
Modes checked_dense_shift_invert(const Eigen::SparseMatrix<double>& stiffness,
                                 const Eigen::SparseMatrix<double>& mass, int count,
                                 const std::string& before) {
  const double sigma = shift_for(stiffness, mass);
  Modes modes = dense_shift_invert(stiffness, mass, count, sigma);
  modes.accuracy.replaced = before;
  check_modes(stiffness, mass, sigma, modes);
  if (!modes.accuracy.passed && !before.empty())
    modes.accuracy.failure += " (and before it " + before + ")";
  require_passed(modes, modes.accuracy.solver);
  return modes;
}

/// M = P^T L L^T P by CHOLMOD (supernodal), for Spectra's Cholesky mode:
/// lower_triangular_solve y = L^-1 P x, upper_triangular_solve y = P^T L^-T x.
/// Spectra's sparse product y = A x, polling the interruption flag before
/// each product: every Lanczos step makes one, so a SIGINT or SIGTERM stops
/// an eigensolve within one step (one solve with the factor and one
/// product) rather than after its restarts.
class PolledMatProd {
public:
  using Scalar = double;
  explicit PolledMatProd(const Eigen::SparseMatrix<double>& a) : m_product(a) {}
  Eigen::Index rows() const { return m_product.rows(); }
  Eigen::Index cols() const { return m_product.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    throw_if_interrupted();
    m_product.perform_op(x_in, y_out);
  }

private:
  Spectra::SparseSymMatProd<double> m_product;
};

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
      throw ModalError("modal analysis: the CHOLMOD solve with the mass factor failed",
                       kSolverAdvice);
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
  PolledMatProd op(stiffness);
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
    Spectra::SymGEigsSolver<PolledMatProd, CholmodCholesky,
                            Spectra::GEigsMode::Cholesky>
        solver(op, bop, 1, std::min(n, ncv));
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, restarts, 1e-12);
    if (solver.info() == Spectra::CompInfo::Successful) return solver.eigenvalues()(0);
    if (ncv >= n) break;
  }
  throw ModalError("modal analysis: Lanczos for omega_max did not converge (30 vectors and 1000 "
                   "restarts, then 128 and 10000)",
                   kSolverAdvice);
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

/// The largest model the checks fall back to the dense shift-invert solver
/// for, when a sparse solve fails its check (2 n^2 doubles: 256 MB).
constexpr int dense_fallback_limit = 4000;

/// K - sigma M not positive definite about a shift below the spectrum (K
/// indefinite, or K and M sharing null directions): the dense solver takes
/// the latter up to dense_fallback_limit dofs.
class ShiftNotDefinite : public ModalError {
public:
  using ModalError::ModalError;
};

/// Why a sparse solve at a shift did not give modes: K - sigma M singular
/// (to retry with a shift below the spectrum), or the block method not
/// converged (to take Lanczos on the same factor).
enum class SparseOutcome { solved, singular, not_converged };

/// The `count` lowest eigenpairs by the block method (large models).
SparseOutcome block_modes(const Eigen::SparseMatrix<double>& stiffness,
                          const Eigen::SparseMatrix<double>& mass, int count,
                          const BlockShiftInvertOptions& options,
                          const CholmodShiftInvert& factorized, Modes& modes, std::string& why) {
  const BlockShiftInvertResult result =
      block_shift_invert(stiffness, mass, count, options, &factorized);
  using Status = BlockShiftInvertResult::Status;
  switch (result.status) {
  case Status::successful:
    break;
  case Status::stiffness_not_positive_definite:
    why = result.message;
    return SparseOutcome::singular;
  case Status::mass_not_semidefinite:
    throw ModalError("modal analysis: the mass matrix is not positive semi-definite (" +
                         result.message + ")" + kMassWhy,
                     kMassAdvice);
  case Status::not_converged:
    return SparseOutcome::not_converged;
  case Status::failed:
    throw ModalError("modal analysis: block shift-invert failed (" + result.message + ")",
                     kSolverAdvice);
  }
  modes.omega_squared = result.eigenvalues;
  modes.shapes = result.eigenvectors;
  modes.accuracy.solver = "the block Krylov-Schur solver (CHOLMOD)";
  return SparseOutcome::solved;
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

/// The power of 4 nearest x > 0: scaling M by it is exact in binary
/// floating point, and so are the square roots of the B-norms that Spectra
/// takes (sqrt(4^k v) = 2^k sqrt(v)).
double power_of_four_near(double x) {
  return std::pow(4.0, std::round(std::log(x) / std::log(4.0)));
}

/// The scale s of the mass Spectra's Lanczos sees, so that the wanted
/// theta = 1 / (lambda - sigma) are of order one: s near the smallest
/// (K_ii - sigma M_ii) / M_ii, a Rayleigh quotient, so at least
/// lambda_1 - sigma. Spectra's Lanczos tests some quantities against
/// absolute thresholds (a residual norm below eps sqrt(n) is taken for a
/// breakdown and the vector restarted at random: Lanczos.h, Arnoldi.h of
/// Spectra 1.0.1); a model in N, mm, t, s has theta = 1 / lambda about
/// 1e-11 to 1e-14, and every Lanczos vector past the third then restarted
/// (a C3D10 and C3D20 deck tied by *TIE: 7 of 10 modes up to 17 % off, with
/// residuals of order one). Scaled, nothing is near those thresholds, and
/// where they did not act the scale changes no bit (a power of 4).
double lanczos_mass_scale(const Eigen::SparseMatrix<double>& stiffness,
                          const Eigen::SparseMatrix<double>& mass, double sigma) {
  double smallest = std::numeric_limits<double>::infinity();
  const Eigen::VectorXd kd = stiffness.diagonal();
  const Eigen::VectorXd md = mass.diagonal();
  for (Eigen::Index i = 0; i < kd.size(); ++i)
    if (md(i) > 0.0) {
      const double q = (kd(i) - sigma * md(i)) / md(i);
      if (q > 0.0) smallest = std::min(smallest, q);
    }
  return std::isfinite(smallest) ? power_of_four_near(smallest) : 1.0;
}

/// The `count` lowest eigenpairs by Spectra's shift-invert Lanczos on `op`
/// ((K - sigma M)^-1 for the mass `scaled_mass` = s M, at the shift sigma /
/// s). `factorization_failed` is called when the factorization fails (it
/// may throw something more precise); false then (K - sigma M singular).
template <class ShiftInvert, class OnFailure>
bool lanczos_modes(ShiftInvert& op, const Eigen::SparseMatrix<double>& scaled_mass, double scale,
                   double sigma, int count, Modes& modes, const OnFailure& factorization_failed) {
  const int n = static_cast<int>(scaled_mass.rows());
  using MassProduct = PolledMatProd;
  MassProduct bop(scaled_mass);
  const int ncv = std::min(n, std::max(2 * count + 1, count + 20));
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  try {
    Spectra::SymGEigsShiftSolver<ShiftInvert, MassProduct, Spectra::GEigsMode::ShiftInvert> solver(
        op, bop, count, ncv, sigma / scale);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 10000, 1e-12);
    if (solver.info() != Spectra::CompInfo::Successful)
      throw ModalError("modal analysis: shift-invert Lanczos did not converge for the lowest " +
                           std::to_string(count) + " modes",
                       kSolverAdvice);
    values = solver.eigenvalues();
    vectors = solver.eigenvectors();
  } catch (const std::invalid_argument&) { // Spectra's SymShiftInvert: factorization failed
    factorization_failed();
    return false;
  }
  // Spectra returns them in decreasing 1/lambda, i.e. increasing lambda: reverse to be sure.
  std::vector<int> order(count);
  for (int i = 0; i < count; ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) < values(b); });
  modes.omega_squared.resize(count);
  modes.shapes.resize(n, count);
  // Back to (K, M): lambda = s lambda', phi = sqrt(s) phi' (exact for s a power of 4).
  const double root = std::sqrt(scale);
  for (int i = 0; i < count; ++i) {
    modes.omega_squared(i) = scale * values(order[i]);
    modes.shapes.col(i) = root * vectors.col(order[i]);
  }
  return true;
}

/// Lanczos on a CHOLMOD factor of K - sigma M: the caller's (`factorized`,
/// of these K and M at shift 0) or its own.
SparseOutcome cholmod_lanczos_modes(const Eigen::SparseMatrix<double>& stiffness,
                                    const Eigen::SparseMatrix<double>& mass, int count,
                                    double sigma, CholmodShiftInvert* factorized, Modes& modes,
                                    std::string& why) {
  const double scale = lanczos_mass_scale(stiffness, mass, sigma);
  const Eigen::SparseMatrix<double> scaled_mass = scale * mass;
  std::optional<CholmodShiftInvert> own;
  if (factorized == nullptr || sigma != 0.0) own.emplace(stiffness, scaled_mass);
  CholmodShiftInvert& op = own ? *own : *factorized;
  op.set_shift(own ? sigma / scale : 0.0);
  if (!op.factorized()) {
    why = "CHOLMOD: " + op.message();
    return SparseOutcome::singular;
  }
  // The caller's factor is of K at shift 0, K^-1 (s M x) = s K^-1 M x: the
  // same operator for any mass scale; Spectra sets shift 0 again, a no-op.
  lanczos_modes(op, scaled_mass, scale, sigma, count, modes, [] {});
  modes.accuracy.solver = "Lanczos (Spectra) on a CHOLMOD factor";
  return SparseOutcome::solved;
}

/// The `count` lowest eigenpairs by the sparse path at the shift sigma
/// (K - sigma M must be positive definite; `factorized`: a factor of K at
/// shift 0 the caller made, or null): Spectra's Lanczos on SparseLU for a
/// supported part under block_method_min_dofs (unless `block`), else the
/// block method where its basis fits (a free part's at any size: Lanczos
/// with one vector missed a mode of a free cube's multiple eigenvalues),
/// else Lanczos on a CHOLMOD factor.
SparseOutcome sparse_solve(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, int count, double sigma,
                           CholmodShiftInvert* factorized, bool block, Modes& modes,
                           std::string& why) {
  const int n = static_cast<int>(stiffness.rows());
  if (!block && factorized == nullptr && n < block_method_min_dofs && sigma == 0.0) {
    const double scale = lanczos_mass_scale(stiffness, mass, 0.0);
    const Eigen::SparseMatrix<double> scaled_mass = scale * mass;
    Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse> op(stiffness, scaled_mass);
    if (!lanczos_modes(op, scaled_mass, scale, 0.0, count, modes,
                       [&] { throw_if_sparse_lu_out_of_memory(stiffness, mass); })) {
      why = "Eigen's SparseLU of K failed";
      return SparseOutcome::singular;
    }
    modes.accuracy.solver = "Lanczos (Spectra) on Eigen's SparseLU";
    return SparseOutcome::solved;
  }
  BlockShiftInvertOptions options = block_options(count, n);
  if (options.block_size > 0) {
    std::optional<CholmodShiftInvert> own;
    if (factorized == nullptr || sigma != 0.0) {
      own.emplace(stiffness, mass);
      own->set_shift(sigma);
      if (!own->factorized()) {
        why = "CHOLMOD: " + own->message();
        return SparseOutcome::singular;
      }
    }
    const SparseOutcome outcome =
        block_modes(stiffness, mass, count, options, own ? *own : *factorized, modes, why);
    // The block method's true-residual test is strict: some refined
    // models stall above it (block_shift_invert.hpp); Spectra's Lanczos on
    // the same factor below then gives their modes, checked as any.
    if (outcome != SparseOutcome::not_converged) return outcome;
  }
  return cholmod_lanczos_modes(stiffness, mass, count, sigma, factorized, modes, why);
}

/// The sparse path: shift-invert about 0 on a factor of K, or, for a K
/// singular to working precision (a free part), about a shift below the
/// spectrum (shift_below_spectrum); `sigma` returns the one used.
Modes sparse_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count,
                   CholmodShiftInvert* factorized, bool block, double& sigma) {
  const int n = static_cast<int>(stiffness.rows());
  Modes modes;
  std::string why;
  sigma = 0.0;
  std::string singular; // why K is taken for singular
  // Below the block method's size, K's definiteness is decided first (a
  // CHOLMOD factor and its lowest mode's energy, as the block method decides
  // it for itself): Eigen's SparseLU factorizes a singular K with pivots at
  // round-off, and Spectra's Lanczos on it can end in NaN.
  SparseOutcome outcome = SparseOutcome::singular;
  if (factorized == nullptr && n < block_method_min_dofs &&
      !check_positive_definite(stiffness, mass).positive_definite())
    singular = "K is not positive definite to working precision (its CHOLMOD factor, or the "
               "energy of its lowest mode)";
  else
    outcome = sparse_solve(stiffness, mass, count, 0.0, factorized, block, modes, why);
  if (!singular.empty()) {
  } else if (outcome == SparseOutcome::singular) {
    singular = why;
  } else {
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
    // is 1/theta, garbage for a theta under theta's rounding.
    const Eigen::VectorXd energies =
        (modes.shapes.transpose() * (stiffness * modes.shapes)).diagonal();
    Eigen::Index first = 0;
    energies.minCoeff(&first);
    const EnergyResolution lowest = energy_resolution(stiffness, modes.shapes.col(first));
    if (!lowest.resolved()) {
      std::ostringstream message;
      message << "the lowest mode (eigenvalue " << modes.omega_squared(first)
              << " rad^2/s^2) has the energy phi^T K phi = " << lowest.energy
              << ", not above its rounding gamma_p |phi|^T |K| |phi| = " << lowest.rounding;
      singular = message.str();
    } else {
      // Shift-invert about 0 computes theta = 1/lambda, each to within p(n)
      // eps theta_max = p(n) eps / lambda_min (backward stable on K^-1 M; the
      // mirror of dense_resolution), so it resolves eigenvalues only below
      // lambda_min / (n eps), lambda_min the lowest mode's resolved energy. A
      // highest mode asked past it, or a theta at or below 0 (under its
      // rounding), is not a result.
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
    }
  }
  if (!singular.empty()) {
    // K singular to working precision: a free part (rigid-body modes at
    // lambda = 0) or one too stiff for double precision. Shift-invert about
    // sigma below the spectrum, K - sigma M positive definite, finds its
    // modes either way; the check reports those zero to their uncertainty.
    sigma = shift_below_spectrum(stiffness, mass);
    modes = Modes{};
    outcome = sparse_solve(stiffness, mass, count, sigma, nullptr, block, modes, why);
    if (outcome != SparseOutcome::solved) {
      // K indefinite, or K and M sharing null directions (no eigenvalue
      // there): the negative pivots of K - sigma M tell them apart.
      Eigen::SparseMatrix<double> lower =
          Eigen::SparseMatrix<double>(stiffness.triangularView<Eigen::Lower>()) -
          sigma * Eigen::SparseMatrix<double>(mass.triangularView<Eigen::Lower>());
      lower.makeCompressed();
      const Inertia inertia = sparse_inertia(lower);
      std::ostringstream message;
      message << "modal analysis: the stiffness matrix is singular or indefinite (" << singular
              << "), and K - sigma M is not positive definite at sigma = " << sigma << " either ("
              << why << "): ";
      if (inertia.factorized && inertia.negative > 0)
        message << "it has " << inertia.negative
                << " negative eigenvalues (L D L^T pivots): K is not positive semi-definite"
                << kStiffnessRemedy;
      else
        message << "K and M share null directions (no stiffness and no mass, as a "
                   "reduced-integration element's zero-energy mode can be), where the pencil has "
                   "no eigenvalue; the dense solver leaves them out up to "
                << dense_fallback_limit << " dofs, this model has " << n;
      throw ShiftNotDefinite(message.str());
    }
    // Shift-invert about sigma resolves (lambda - sigma) only below (lambda_1 -
    // sigma) / (n eps), as about 0.
    const double resolution =
        sigma + (std::max(modes.omega_squared(0), 0.0) - sigma) /
                    (static_cast<double>(n) * std::numeric_limits<double>::epsilon());
    if (!(modes.omega_squared(count - 1) < resolution)) {
      std::ostringstream message;
      message << "modal analysis: the " << count
              << " lowest modes are not all resolved by shift-invert about " << sigma
              << ": the highest, " << modes.omega_squared(count - 1)
              << " rad^2/s^2, is above its resolution " << resolution << "; ask for fewer modes";
      throw ModalResolutionError(message.str());
    }
  }
  std::string largest_why;
  const double largest = sparse_largest_eigenvalue(stiffness, mass, largest_why);
  modes.omega_max = std::sqrt(std::max(largest, 0.0));
  return modes;
}

/// The sparse path, checked. When its answer fails the check: the block
/// method, if Lanczos gave it and the block basis fits (a block of 24
/// vectors holds a multiple eigenvalue that one Lanczos vector can miss),
/// then the dense shift-invert solver up to dense_fallback_limit dofs; a
/// failure left is ModalCheckError.
Modes checked_sparse_modes(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, int count,
                           CholmodShiftInvert* factorized) {
  const int n = static_cast<int>(stiffness.rows());
  double sigma = 0.0;
  Modes modes;
  try {
    modes = sparse_modes(stiffness, mass, count, factorized, false, sigma);
  } catch (const ShiftNotDefinite& e) {
    if (n > dense_fallback_limit) throw;
    return checked_dense_shift_invert(stiffness, mass, count,
                                      std::string("the sparse path: ") + e.what());
  }
  if (check_modes(stiffness, mass, sigma, modes)) return modes;
  std::string before = modes.accuracy.solver + ": " + modes.accuracy.failure;
  if (modes.accuracy.solver.find("block") == std::string::npos &&
      block_options(count, n).block_size > 0) {
    Modes block = sparse_modes(stiffness, mass, count, factorized, true, sigma);
    block.accuracy.replaced = before;
    if (check_modes(stiffness, mass, sigma, block)) return block;
    before =
        block.accuracy.solver + ": " + block.accuracy.failure + " (and before it " + before + ")";
    modes = block;
  }
  if (n <= dense_fallback_limit) return checked_dense_shift_invert(stiffness, mass, count, before);
  modes.accuracy.failure = before;
  require_passed(modes, modes.accuracy.solver);
  return modes;
}

} // namespace

double shift_below_spectrum(const Eigen::SparseMatrix<double>& stiffness,
                            const Eigen::SparseMatrix<double>& mass) {
  double smallest = std::numeric_limits<double>::infinity();
  const Eigen::VectorXd kd = stiffness.diagonal();
  const Eigen::VectorXd md = mass.diagonal();
  for (Eigen::Index i = 0; i < kd.size(); ++i)
    if (md(i) > 0.0 && kd(i) > 0.0) smallest = std::min(smallest, kd(i) / md(i));
  const double fourth_root_eps = std::pow(std::numeric_limits<double>::epsilon(), 0.25);
  return std::isfinite(smallest) ? -power_of_four_near(fourth_root_eps * smallest) : -1.0;
}

bool positive_definite_mass(const Eigen::SparseMatrix<double>& mass) {
  return CholmodCholesky(mass).factorized();
}

double dense_resolution(const Modes& modes) {
  if (!std::isfinite(modes.omega_max)) // the shift-invert form (M singular): the check's bound
    return modes.accuracy.checked && modes.n_modes() > 0 ? modes.accuracy.uncertainty(0)
                                                         : std::numeric_limits<double>::infinity();
  const double n = static_cast<double>(modes.shapes.rows());
  return n * std::numeric_limits<double>::epsilon() * modes.omega_max * modes.omega_max;
}

double max_angular_frequency(const Eigen::SparseMatrix<double>& stiffness,
                             const Eigen::SparseMatrix<double>& mass) {
  std::string why;
  const double largest = sparse_largest_eigenvalue(stiffness, mass, why);
  if (!std::isfinite(largest))
    throw ModalError("modal analysis: the mass matrix is not positive definite (" + why + ")" +
                         kOmegaMaxWhy,
                     kMassAdvice);
  return std::sqrt(std::max(largest, 0.0));
}

double Modes::frequency_hz(int i) const {
  const double w2 = omega_squared(i);
  return std::copysign(std::sqrt(std::abs(w2)), w2) / (2.0 * M_PI);
}

bool Modes::is_zero(int i) const {
  return accuracy.checked && static_cast<size_t>(i) < accuracy.zero.size() && accuracy.zero[i];
}

double Modes::claimed_frequency_hz(int i) const {
  return is_zero(i) ? 0.0 : frequency_hz(i);
}

double Modes::uncertainty_hz(int i) const {
  if (!accuracy.checked || i >= accuracy.uncertainty.size())
    return std::numeric_limits<double>::quiet_NaN();
  const double u = accuracy.uncertainty(i);
  const double lambda = omega_squared(i);
  if (is_zero(i)) return std::sqrt(std::abs(lambda) + u) / (2.0 * M_PI);
  return u / (2.0 * std::abs(lambda)) * std::abs(frequency_hz(i));
}

int Modes::digits(int i) const {
  if (is_zero(i) || !accuracy.checked) return 0;
  const double relative = accuracy.uncertainty(i) / (2.0 * std::abs(omega_squared(i)));
  if (!(relative > 0.0)) return 17;
  return std::clamp(static_cast<int>(std::floor(-std::log10(relative))), 0, 17);
}

Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count, ModalSolver solver) {
  const int n = static_cast<int>(stiffness.rows());
  if (count < 1 || count > n)
    throw std::invalid_argument("lowest_modes: count must be in [1, " + std::to_string(n) +
                                "], got " + std::to_string(count));
  const bool many_modes = count > n / 4 && n <= dense_many_modes_limit;
  const bool dense = solver == ModalSolver::dense ||
                     (solver == ModalSolver::automatic && (n <= dense_limit || many_modes));
  if (!dense && count >= n)
    throw ModalResolutionError(
        "modal analysis: all " + std::to_string(n) +
        " modes need the dense solver, which takes parts of at most " +
        std::to_string(dense_many_modes_limit) + " dofs; ask for at most " +
        std::to_string(n - 1) + " modes");
  if (!dense) return checked_sparse_modes(stiffness, mass, count, nullptr);
  Modes modes;
  if (!dense_direct(stiffness, mass, count, modes)) // M not positive definite
    return checked_dense_shift_invert(stiffness, mass, count, "");
  if (solver == ModalSolver::automatic) {
    const double resolution = dense_resolution(modes);
    if (!(modes.omega_squared(0) > resolution)) {
      if (count < n) return checked_sparse_modes(stiffness, mass, count, nullptr);
      std::ostringstream message;
      message << "modal analysis: all " << n
              << " modes need the dense solver, which does not resolve the lowest ones (lowest "
                 "eigenvalue "
              << modes.omega_squared(0)
              << " rad^2/s^2 <= its resolution n eps lambda_max = " << resolution
              << "); ask for fewer modes (shift-invert resolves the lowest ones)";
      throw ModalResolutionError(message.str());
    }
  }
  if (check_modes(stiffness, mass, std::nullopt, modes)) return modes;
  // An ill-conditioned M: the dense solver is backward stable on L^-1 K
  // L^-T (M = L L^T), not on the pencil; the shift-invert form factorizes
  // K - sigma M instead.
  return checked_dense_shift_invert(stiffness, mass, count,
                                    modes.accuracy.solver + ": " + modes.accuracy.failure);
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
  return checked_sparse_modes(stiffness, mass, count, &factorized);
}

} // namespace rsi
