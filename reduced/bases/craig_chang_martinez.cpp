#include "craig_chang_martinez.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

#include <Eigen/Eigenvalues>

#include "energy_resolution.hpp"
#include "guyan.hpp"
#include "modal_analysis.hpp"
#include "turned_residual_flexibility.hpp"

namespace rsi {
namespace {

std::string square_size(int n) {
  return std::to_string(n) + " x " + std::to_string(n);
}

const char* const stiffness_remedy =
    "the residual flexibility K^-1 - Phi_1 Omega_1^-1 Phi_1^T needs K invertible, a supported "
    "part (is the hub clamped?); a free part takes cb or guyan, whose constraint modes need only "
    "K_II positive definite (the boundary holding the part)";

} // namespace

FreeInterfacePool free_interface_pool(const Eigen::SparseMatrix<double>& stiffness,
                                      const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                      int count, const std::string& name,
                                      const std::vector<int>* flexibility_columns) {
  const int n = p.n();
  const int nb = p.n_boundary();
  FreeInterfacePool pool;
  pool.count = count;
  // With few free modes (Lanczos): R by eq. 14, K^-1 E_B - Phi_1 Omega_1^-1
  // Phi_1B^T. With many, the dense solver has every mode anyway, and the
  // subtraction would cancel R_B down to its round-off floor (Bladh et al.
  // 2003): R is then summed over the discarded modes instead, Phi_2
  // Omega_2^-1 Phi_2B^T, the same R without cancellation.
  // The tail sum needs every mode, n finite ones: M positive definite. A
  // singular M (massless dofs: consistent masses of C3D20R, C3D10, ...) has
  // fewer, and its massless directions carry static flexibility that no
  // mode holds; R is then K^-1 E_B minus the kept modes, below.
  if (few_modes(count, n) == ModalSolver::dense && positive_definite_mass(mass)) {
    pool.complete = true;
    pool.modes = lowest_modes(stiffness, mass, n, ModalSolver::dense);
    // The tail sum needs no K^-1, but it is R only for a nonsingular K, and
    // 1/lambda_min in it is noise unless the dense solver resolves lambda_min:
    // it does not at or below its resolution n eps lambda_max
    // (dense_resolution, modal_analysis.hpp), where a rigid motion's
    // eigenvalue sits, and so does the elastic lambda_min of a valid but stiff
    // model (blades 2e-6 m thick; issue 13: such models were called singular
    // here). A factor of K tells the two apart, and the message says which
    // (the factorized path below resolves the stiff model with fewer modes;
    // with this many, shift-invert would not reach the highest ones).
    if (!(pool.modes.omega_squared(0) > dense_resolution(pool.modes))) {
      const std::string singular =
          unresolved(check_positive_definite(stiffness, Eigen::SparseMatrix<double>()));
      std::ostringstream message;
      message << name << ": the bladed-disk stiffness K (" << square_size(n) << ") ";
      if (!singular.empty())
        message << "is singular or indefinite (" << singular << "); " << stiffness_remedy;
      else
        message << "is positive definite to working precision, but with psi = " << count
                << " free modes (n/4 or more) every mode comes from the dense solver, which "
                   "does not resolve its lowest eigenvalue "
                << pool.modes.omega_squared(0)
                << " rad^2/s^2 (<= n eps lambda_max = " << dense_resolution(pool.modes)
                << "); use at most " << (n - 1) / 4
                << " free modes (the factorized path resolves them)";
      throw ReductionError(message.str());
    }
    return pool;
  }
  const std::string k_name = name + ": the bladed-disk stiffness K (" + square_size(n) + ")";
  const auto unit = [&] {
    if (flexibility_columns == nullptr)
      return place_rows(n, p.boundary, Eigen::MatrixXd::Identity(nb, nb));
    Eigen::MatrixXd e =
        Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(flexibility_columns->size()));
    for (Eigen::Index i = 0; i < e.cols(); ++i)
      e(p.boundary[static_cast<size_t>((*flexibility_columns)[static_cast<size_t>(i)])], i) = 1.0;
    return e;
  };
  if (count > 0 && shares_factor(n)) {
    const auto factor = factor_positive_definite(stiffness, mass, k_name, stiffness_remedy);
    pool.flexibility = solve_with(*factor, stiffness, unit(), k_name);
    pool.modes = lowest_modes(stiffness, mass, count, *factor);
  } else {
    pool.flexibility = solve_positive_definite(stiffness, unit(), k_name, stiffness_remedy);
    // Many modes of a singular M: the dense (shift-invert) solver.
    if (count > 0) pool.modes = lowest_modes(stiffness, mass, count, few_modes(count, n));
  }
  return pool;
}

double residual_flexibility_condition(const Eigen::MatrixXd& r_b, int n, const std::string& name) {
  // R_B is symmetric positive semi-definite in exact arithmetic.
  const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
                                  0.5 * (r_b + r_b.transpose()), Eigen::EigenvaluesOnly)
                                  .eigenvalues();
  const Eigen::Index nb = r_b.rows();
  const double cond = eig(0) > 0.0 ? eig(nb - 1) / eig(0) : std::numeric_limits<double>::infinity();
  const double limit = 1.0 / (n * std::numeric_limits<double>::epsilon());
  if (!(cond < limit)) {
    std::ostringstream message;
    message << name
            << ": the residual flexibility R_B of the boundary set is "
               "numerically singular, "
               "cond(R_B) = "
            << cond << " >= 1/(n eps) = " << limit
            << "; attachment modes on rotation dofs or too many free modes cause this (paper §5.3)";
    throw ReductionError(message.str());
  }
  return cond;
}

ResidualFlexibilityTransformation residual_flexibility_transformation(const Partition& p,
                                                                      const FreeInterfacePool& pool,
                                                                      const std::vector<int>& kept,
                                                                      const std::string& name) {
  const int n = p.n();
  const int nb = p.n_boundary();
  const int psi = static_cast<int>(kept.size());
  ResidualFlexibilityTransformation out;

  // R(:, B), boundary columns only.
  Eigen::MatrixXd phi1;
  AccurateMatrix r; // r.low: what K^-1 E_B misses below its last bit (sparse path)
  if (psi > 0) {
    phi1 = take_columns(pool.modes.shapes, kept);
    out.mode_omega = take_entries(pool.modes.omega_squared, kept).cwiseSqrt();
  }
  if (pool.complete) {
    std::vector<bool> is_kept(n, false);
    for (int i : kept)
      is_kept[i] = true;
    std::vector<int> dropped;
    for (int i = 0; i < n; ++i)
      if (!is_kept[i]) dropped.push_back(i);
    const Eigen::MatrixXd phi2 = take_columns(pool.modes.shapes, dropped);
    r.value = phi2 * take_entries(pool.modes.omega_squared, dropped).cwiseInverse().asDiagonal() *
              take_rows(phi2, p.boundary).transpose();
  } else {
    r = pool.flexibility;
    if (psi > 0)
      r.value -= phi1 * take_entries(pool.modes.omega_squared, kept).cwiseInverse().asDiagonal() *
                 take_rows(phi1, p.boundary).transpose();
  }
  const Eigen::MatrixXd r_b = take_rows(r.value, p.boundary);
  out.cond_rb = residual_flexibility_condition(r_b, n, name);
  const Eigen::LDLT<Eigen::MatrixXd> r_b_factor(r_b);
  // Columns for q_B: R(:, B) R_B^-1, identity on the boundary rows (exactly,
  // so q_B is u_B); interior rows A_I from R_B^T A_I^T = R_I^T, refined to the
  // last bit with R known to twice working precision: with psi = 0 they are
  // then the constraint modes rounded, as CB's (SPEC V4).
  // (Rows of R or of its low part, transposed; an empty low part stays empty.)
  const auto transposed_rows = [](const Eigen::MatrixXd& a, const std::vector<int>& rows) {
    return a.size() > 0 ? Eigen::MatrixXd(take_rows(a, rows).transpose()) : a;
  };
  const Eigen::MatrixXd attachment_interior =
      accurate_solve(
          r_b.transpose().sparseView(), transposed_rows(r.low, p.boundary),
          {transposed_rows(r.value, p.interior), transposed_rows(r.low, p.interior)},
          [&](const Eigen::MatrixXd& rhs) { return Eigen::MatrixXd(r_b_factor.solve(rhs)); },
          name + ": the attachment modes R(:, B) R_B^-1")
          .value.transpose();
  const Eigen::MatrixXd attachment = place_rows(n, p.interior, attachment_interior) +
                                     place_rows(n, p.boundary, Eigen::MatrixXd::Identity(nb, nb));
  Eigen::MatrixXd t(n, nb + psi);
  t.leftCols(nb) = attachment;
  if (psi > 0) t.rightCols(psi) = phi1 - attachment * take_rows(phi1, p.boundary);
  // The modal columns vanish on the boundary rows to round-off; set them
  // exactly so q_B is u_B.
  for (int b : p.boundary)
    t.row(b).tail(psi).setZero();
  out.transformation = t;
  return out;
}

ResidualFlexibilityTransformation
residual_flexibility_transformation(const Eigen::SparseMatrix<double>& stiffness,
                                    const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                    int psi, const std::string& name) {
  const FreeInterfacePool pool = free_interface_pool(stiffness, mass, p, psi, name);
  std::vector<int> kept(psi);
  std::iota(kept.begin(), kept.end(), 0);
  return residual_flexibility_transformation(p, pool, kept, name);
}

void check_free_interface_count(const Partition& p, int psi) {
  const int available = p.n() - p.n_boundary();
  if (psi < 0 || psi > available)
    throw ReductionError("Craig-Chang-Martinez takes 0 to " + std::to_string(available) +
                             " free-interface modes (dofs minus boundary dofs), got " +
                             std::to_string(psi),
                         failed_input(FailedInput::mode_count));
}

ReducedBasis craig_chang_martinez(const Eigen::SparseMatrix<double>& stiffness,
                                  const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                  const FreeInterfacePool& pool, const std::vector<int>& kept,
                                  std::chrono::steady_clock::time_point start) {
  const int psi = static_cast<int>(kept.size());
  check_free_interface_count(p, psi);
  ReducedBasis basis;
  basis.method = "ccm";
  basis.n_modes = psi;
  basis.requested_modes = psi;
  basis.candidate_modes = pool.count;
  basis.mode_index = kept;
  ResidualFlexibilityTransformation t =
      residual_flexibility_transformation(p, pool, kept, "Craig-Chang-Martinez");
  basis.transformation = std::move(t.transformation);
  basis.cond_rb = t.cond_rb;
  basis.mode_omega = std::move(t.mode_omega);
  finish_basis(stiffness, mass, p.n_boundary(), 0, start, basis);
  return basis;
}

ReducedBasis craig_chang_martinez(const Eigen::SparseMatrix<double>& stiffness,
                                  const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                  int psi, const CyclicBoundary* cyclic) {
  check_free_interface_count(p, psi);
  const auto start = std::chrono::steady_clock::now();
  if (cyclic != nullptr && few_modes(psi, p.n()) == ModalSolver::sparse) {
    const char* const name = "Craig-Chang-Martinez";
    const std::vector<int> representatives = cyclic->orbits.representative_positions();
    ReducedBasis basis = turned_residual_flexibility(
        stiffness, mass, p, free_interface_pool(stiffness, mass, p, psi, name, &representatives),
        *cyclic, name);
    basis.method = "ccm";
    basis.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return basis;
  }
  const FreeInterfacePool pool =
      free_interface_pool(stiffness, mass, p, psi, "Craig-Chang-Martinez");
  std::vector<int> kept(psi);
  std::iota(kept.begin(), kept.end(), 0);
  return craig_chang_martinez(stiffness, mass, p, pool, kept, start);
}

} // namespace rsi
