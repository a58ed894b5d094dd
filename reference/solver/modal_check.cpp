#include "modal_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>

#include "cholmod_shift_invert.hpp"
#include "energy_resolution.hpp"
#include "stored_digits.hpp"
#include "symmetric_inertia.hpp"
#include "transpose_product.hpp"

namespace rsi {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", x);
  return text;
}

/// max_j sum_i |a_ij|: the 1-norm (and the infinity norm of a symmetric a).
double norm_1(const Eigen::SparseMatrix<double>& a) {
  double norm = 0.0;
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    double column = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it)
      column += std::abs(it.value());
    norm = std::max(norm, column);
  }
  return norm;
}

/// The most stored entries in a column (a row, for a symmetric matrix).
int row_terms(const Eigen::SparseMatrix<double>& a) {
  int p = 0;
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    int count = 0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it)
      ++count;
    p = std::max(p, count);
  }
  return p;
}

Eigen::SparseMatrix<double> absolute(const Eigen::SparseMatrix<double>& a) {
  Eigen::SparseMatrix<double> b = a.cwiseAbs();
  b.makeCompressed();
  return b;
}

/// The lower triangle of K - tau M, compressed.
Eigen::SparseMatrix<double> shifted_lower(const Eigen::SparseMatrix<double>& k,
                                          const Eigen::SparseMatrix<double>& m, double tau) {
  const Eigen::SparseMatrix<double> lk = k.triangularView<Eigen::Lower>();
  const Eigen::SparseMatrix<double> lm = m.triangularView<Eigen::Lower>();
  Eigen::SparseMatrix<double> a = lk - tau * lm;
  a.makeCompressed();
  return a;
}

/// K - tau M + rho Z Z^T, rho = ||K||_1 + |tau| ||M||_1 (dense; z: directions
/// without stiffness or mass, or none).
Eigen::MatrixXd shifted_dense(const Eigen::SparseMatrix<double>& k,
                              const Eigen::SparseMatrix<double>& m, double tau,
                              const Eigen::MatrixXd& z) {
  Eigen::MatrixXd a = Eigen::MatrixXd(k) - tau * Eigen::MatrixXd(m);
  if (z.cols() > 0) {
    const double rho = norm_1(k) + std::abs(tau) * norm_1(m);
    a += rho * z * z.transpose();
  }
  return a;
}

/// Solves with A = K - sigma M, dense (LLT) or sparse (CHOLMOD); `ok` false
/// if A is not positive definite.
class ShiftedSolve {
public:
  ShiftedSolve(const Eigen::SparseMatrix<double>& k, const Eigen::SparseMatrix<double>& m,
               double sigma, bool dense, const Eigen::MatrixXd& z) {
    if (dense) {
      m_dense = std::make_unique<Eigen::LLT<Eigen::MatrixXd>>(shifted_dense(k, m, sigma, z));
      m_ok = m_dense->info() == Eigen::Success;
    } else {
      m_sparse = std::make_unique<CholmodShiftInvert>(k, m);
      m_sparse->set_shift(sigma);
      m_ok = m_sparse->factorized();
    }
  }
  bool ok() const { return m_ok; }
  bool solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) const {
    if (!m_ok) return false;
    if (m_dense) {
      x = m_dense->solve(b);
      return true;
    }
    x.resize(b.rows(), b.cols());
    return m_sparse->solve(b, x);
  }

private:
  std::unique_ptr<Eigen::LLT<Eigen::MatrixXd>> m_dense;
  std::unique_ptr<CholmodShiftInvert> m_sparse;
  bool m_ok = false;
};

/// Negative pivots of K - tau M; retried once a little higher if tau sits on
/// an eigenvalue to working precision. -1 if no count could be made.
int count_below(const Eigen::SparseMatrix<double>& k, const Eigen::SparseMatrix<double>& m,
                double tau, double nudge, bool dense, const Eigen::MatrixXd& z, std::string& why) {
  for (int attempt = 0; attempt < 2; ++attempt, tau += nudge) {
    const Inertia inertia = dense ? dense_inertia(shifted_dense(k, m, tau, z))
                                  : sparse_inertia(shifted_lower(k, m, tau));
    if (inertia.factorized) return inertia.negative;
    why = inertia.why;
  }
  return -1;
}

} // namespace

bool check_modes(const Eigen::SparseMatrix<double>& stiffness,
                 const Eigen::SparseMatrix<double>& mass, std::optional<double> solver_shift,
                 Modes& modes, const ModalCheckTolerances& tolerances) {
  const Eigen::Index n = stiffness.rows();
  const int count = modes.n_modes();
  if (stiffness.cols() != n || mass.rows() != n || mass.cols() != n ||
      modes.shapes.rows() != n || modes.shapes.cols() != count)
    throw std::invalid_argument("check_modes: K, M and the mode shapes must be of one size");
  ModalAccuracy& a = modes.accuracy;
  const std::string solver = a.solver;
  const std::string replaced = a.replaced;
  const Eigen::MatrixXd null_directions = a.null_directions;
  a = ModalAccuracy{};
  a.solver = solver;
  a.replaced = replaced;
  a.null_directions = null_directions;
  a.checked = true;
  // The pencil of the bounds: (M, K - sigma M) with K - sigma M positive
  // definite to working precision (a factor of a singular K "succeeds" with
  // pivots at round-off, and its bounds are noise).
  const double sigma = solver_shift ? *solver_shift
                       : check_positive_definite(stiffness, mass).positive_definite()
                           ? 0.0
                           : shift_below_spectrum(stiffness, mass);
  a.shift = sigma;
  // Directions without stiffness or mass (a singular pencil, left out by
  // the dense solver) make K - tau M singular for every tau: the counts and
  // the bounds take K - tau M + rho Z Z^T (rho = ||K||_1 + |tau| ||M||_1),
  // positive on them and unchanged on the rest (dense).
  const Eigen::MatrixXd& z = null_directions;
  const bool dense = n <= dense_check_limit || z.cols() > 0;
  if (count == 0) {
    a.passed = true;
    return true;
  }
  const Eigen::VectorXd& lambda = modes.omega_squared;
  const Eigen::MatrixXd& phi = modes.shapes;
  const Eigen::MatrixXd k_phi = transpose_product(stiffness, phi);
  const Eigen::MatrixXd m_phi = transpose_product(mass, phi);
  const Eigen::MatrixXd abs_phi = phi.cwiseAbs();
  const Eigen::MatrixXd abs_k_phi = transpose_product(absolute(stiffness), abs_phi);
  const Eigen::MatrixXd abs_m_phi = transpose_product(absolute(mass), abs_phi);
  const double k_norm = norm_1(stiffness);
  const double m_norm = norm_1(mass);
  const double gamma_n = static_cast<double>(n) * kEps;
  const int p = std::max(row_terms(stiffness), row_terms(mass));
  const double gamma_p = p * kEps / (1.0 - p * kEps);
  a.input_digits = std::min(stored_digits(stiffness), stored_digits(mass));
  a.input_rounding = digits_rounding(a.input_digits);

  // 1. Residuals, and the rounding part of each uncertainty.
  a.residual.resize(count);
  a.residual_bound.resize(count);
  a.rounding.resize(count);
  Eigen::MatrixXd residuals(n, count);
  for (int i = 0; i < count; ++i) {
    residuals.col(i) = k_phi.col(i) - lambda(i) * m_phi.col(i);
    const double scale = k_phi.col(i).norm() + std::abs(lambda(i)) * m_phi.col(i).norm();
    const double r = residuals.col(i).norm();
    a.residual(i) = scale > 0.0 ? r / scale : (r > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
    const double kappa = scale > 0.0 ? (k_norm + std::abs(lambda(i)) * m_norm) * phi.col(i).norm() / scale
                                     : std::numeric_limits<double>::infinity();
    a.residual_bound(i) = tolerances.residual + gamma_n * kappa;
    a.rounding(i) = (a.input_rounding + gamma_p) * (abs_phi.col(i).dot(abs_k_phi.col(i)) +
                                                    std::abs(lambda(i)) *
                                                        abs_phi.col(i).dot(abs_m_phi.col(i)));
  }

  // 2. M-orthonormality.
  const Eigen::MatrixXd gram = phi.transpose() * m_phi;
  a.orthonormality = (gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff();
  a.orthonormality_bound =
      tolerances.orthonormality + gamma_n * m_norm * phi.colwise().squaredNorm().maxCoeff();

  // The solver's part: the residual bound of the pencil (M, K - sigma M).
  const double shift = sigma;
  const ShiftedSolve solve(stiffness, mass, shift, dense, z);
  if (!solve.ok()) {
    a.failure = "K - sigma M is not positive definite at sigma = " + number(sigma) +
                " (K or M not positive semi-definite)";
    return false;
  }
  // Rayleigh quotients and their residuals (the bounds hold at the Rayleigh quotient).
  Eigen::VectorXd rq(count), mu(count), delta(count);
  Eigen::MatrixXd rq_residuals(n, count);
  for (int i = 0; i < count; ++i) {
    const double mass_norm = phi.col(i).dot(m_phi.col(i));
    rq(i) = phi.col(i).dot(k_phi.col(i)) / mass_norm;
    rq_residuals.col(i) = k_phi.col(i) - rq(i) * m_phi.col(i);
  }
  Eigen::MatrixXd a_inverse_residuals;
  if (!solve.solve(rq_residuals, a_inverse_residuals)) {
    a.failure = "the solve with K - sigma M failed";
    return false;
  }
  for (int i = 0; i < count; ++i) {
    const double energy = phi.col(i).dot(k_phi.col(i)) - shift * phi.col(i).dot(m_phi.col(i));
    mu(i) = 1.0 / (rq(i) - shift);
    const double e = std::sqrt(std::max(rq_residuals.col(i).dot(a_inverse_residuals.col(i)), 0.0) /
                               std::max(energy, std::numeric_limits<double>::min()));
    delta(i) = mu(i) * e;
  }

  // 3. Sturm count about the highest returned eigenvalue.
  Eigen::Index top = 0;
  lambda.maxCoeff(&top);
  const double lambda_top = lambda(top);
  // First-order bound of the top eigenvalue for the window (before the gaps are known).
  const auto first_order = [&](int i) {
    const double d = delta(i) / mu(i);
    return d < 1.0 ? (rq(i) - shift) * d / (1.0 - d) + std::abs(lambda(i) - rq(i))
                   : std::numeric_limits<double>::infinity();
  };
  const double u_top = a.rounding(top) + first_order(static_cast<int>(top));
  const double w = std::max(2.0 * u_top, 1e-12 * (std::abs(lambda_top) + std::abs(shift)));
  std::string why;
  a.sturm_shift = lambda_top + w;
  a.sturm_count = std::isfinite(w) ? count_below(stiffness, mass, a.sturm_shift, w, dense, z, why) : -1;
  bool top_gap_known = false; // no unreturned eigenvalue below lambda_top + w
  if (a.sturm_count < 0) {
    a.failure = "Sturm count: no L D L^T of K - tau M at tau = " + number(a.sturm_shift) + " (" +
                why + ")";
  } else if (a.sturm_count < count) {
    a.failure = "Sturm count: " + std::to_string(count) + " modes returned below tau = " +
                number(a.sturm_shift) + ", where the pencil has " +
                std::to_string(a.sturm_count) + " eigenvalues (a mode returned twice?)";
  } else if (a.sturm_count == count) {
    top_gap_known = true;
  } else {
    a.sturm_shift_below = lambda_top - w;
    a.returned_below = static_cast<int>((lambda.array() < a.sturm_shift_below).count());
    a.sturm_count_below = count_below(stiffness, mass, a.sturm_shift_below, -w, dense, z, why);
    if (a.sturm_count_below != a.returned_below)
      a.failure = "Sturm count: the pencil has " + std::to_string(a.sturm_count_below) +
                  " eigenvalues below tau = " + number(a.sturm_shift_below) + ", " +
                  std::to_string(a.returned_below) + " were returned there (" +
                  (a.sturm_count_below > a.returned_below ? "a mode was missed" : "a spurious mode") +
                  (a.sturm_count_below < 0 ? ": " + why : "") + ")";
  }

  // The solver's bound b_i, with the gap (Kato-Temple) where it is known.
  a.solver_error.resize(count);
  const double mu_window = std::isfinite(w) ? 1.0 / (lambda_top + w - shift) : 0.0;
  for (int i = 0; i < count; ++i) {
    double gap = top_gap_known ? mu(i) - mu_window : 0.0;
    for (int j = 0; j < count; ++j)
      if (j != i) gap = std::min(gap, std::abs(mu(i) - mu(j)) - delta(j));
    double bound = delta(i);
    if (gap > delta(i)) bound = std::min(bound, delta(i) * delta(i) / gap);
    const double d = bound / mu(i);
    a.solver_error(i) = d < 1.0 ? (rq(i) - shift) * d / (1.0 - d) + std::abs(lambda(i) - rq(i))
                                : std::numeric_limits<double>::infinity();
  }
  a.uncertainty = a.rounding + a.solver_error;
  a.zero.assign(count, false);
  for (int i = 0; i < count; ++i) {
    a.zero[i] = std::abs(lambda(i)) <= a.uncertainty(i);
    if (a.zero[i]) ++a.n_zero;
  }

  // Which check failed first, in the order of the header (the Sturm
  // count's message, if any, stands unless an earlier check failed). A
  // residual above its bound passes when the solver's error bound, first
  // order, is within the input's rounding: the pair is as good as the data
  // (a rigid-body mode's K phi is the rounding of the solve with K - sigma M).
  {
    std::string first;
    for (int i = 0; i < count && first.empty(); ++i)
      if (!(a.residual(i) <= a.residual_bound(i)) && !(first_order(i) <= a.rounding(i)))
        first = "relative residual |K phi - lambda M phi| / (|K phi| + |lambda| |M phi|) of mode " +
                std::to_string(i + 1) + " (lambda " + number(lambda(i)) + ") is " +
                number(a.residual(i)) + ", above its bound " + number(a.residual_bound(i));
    if (first.empty() && !(a.orthonormality <= a.orthonormality_bound))
      first = "M-orthonormality max |Phi^T M Phi - I| is " + number(a.orthonormality) +
              ", above its bound " + number(a.orthonormality_bound);
    for (int i = 0; i < count && first.empty(); ++i)
      if (!std::isfinite(a.solver_error(i)))
        first = "mode " + std::to_string(i + 1) + " (lambda " + number(lambda(i)) +
                ") has no error bound: its residual is as large as the distance to the shift";
    for (int i = 0; i < count && first.empty(); ++i)
      if (lambda(i) < -a.uncertainty(i))
        first = "mode " + std::to_string(i + 1) + " has the negative eigenvalue " +
                number(lambda(i)) + " beyond its uncertainty " + number(a.uncertainty(i)) +
                " (K not positive semi-definite)";
    if (!first.empty()) a.failure = first;
  }
  a.passed = a.failure.empty();
  return a.passed;
}

void require_passed(const Modes& modes, const std::string& what) {
  if (modes.accuracy.passed) return;
  throw ModalCheckError("modal analysis: " + what +
                            " returned modes that fail their check: " + modes.accuracy.failure,
                        remedied_by({Remedy::fewer_modes_or_report}));
}

} // namespace rsi
