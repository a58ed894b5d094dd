#include "modal_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Spectra/MatOp/SparseCholesky.h>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <Spectra/SymGEigsSolver.h>
#include <lapacke.h>

namespace rsi {
namespace {

Modes dense_modes(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int count) {
  const int n = static_cast<int>(stiffness.rows());
  Eigen::MatrixXd a = Eigen::MatrixXd(stiffness);
  Eigen::MatrixXd b = Eigen::MatrixXd(mass);
  Eigen::VectorXd w(n);
  const lapack_int info =
      LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', n, a.data(), n, b.data(), n, w.data());
  if (info > n)
    throw ModalError(
        "modal analysis: the mass matrix is not positive definite (LAPACKE_dsygvd info " +
        std::to_string(info) + ", leading minor " + std::to_string(info - n) + ")");
  if (info != 0)
    throw ModalError("modal analysis: LAPACKE_dsygvd failed (info " + std::to_string(info) + ")");
  Modes modes;
  modes.omega_squared = w.head(count);
  modes.shapes = a.leftCols(count);
  modes.omega_max = std::sqrt(std::max(w(n - 1), 0.0));
  return modes;
}

/// Largest eigenvalue of K phi = lambda M phi by Lanczos on L^-1 K L^-T (M = L L^T).
double sparse_largest_eigenvalue(const Eigen::SparseMatrix<double>& stiffness,
                                 const Eigen::SparseMatrix<double>& mass) {
  Spectra::SparseSymMatProd<double> op(stiffness);
  Spectra::SparseCholesky<double> bop(mass);
  if (bop.info() != Spectra::CompInfo::Successful)
    throw ModalError(
        "modal analysis: the mass matrix is not positive definite (sparse Cholesky failed)");
  const int n = static_cast<int>(stiffness.rows());
  Spectra::SymGEigsSolver<Spectra::SparseSymMatProd<double>, Spectra::SparseCholesky<double>,
                          Spectra::GEigsMode::Cholesky>
      solver(op, bop, 1, std::min(n, 30));
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, 10000, 1e-12);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw ModalError("modal analysis: Lanczos for omega_max did not converge");
  return solver.eigenvalues()(0);
}

Modes sparse_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, int count) {
  const int n = static_cast<int>(stiffness.rows());
  using ShiftInvert = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
  using MassProduct = Spectra::SparseSymMatProd<double>;
  ShiftInvert op(stiffness, mass);
  MassProduct bop(mass);
  const int ncv = std::min(n, std::max(2 * count + 1, count + 20));
  Spectra::SymGEigsShiftSolver<ShiftInvert, MassProduct, Spectra::GEigsMode::ShiftInvert> solver(
      op, bop, count, ncv, 0.0);
  solver.init();
  try {
    solver.compute(Spectra::SortRule::LargestMagn, 10000, 1e-12);
  } catch (const std::invalid_argument& e) {
    throw ModalError(
        std::string("modal analysis: the stiffness matrix is singular (shift-invert about 0): ") +
        e.what());
  }
  if (solver.info() != Spectra::CompInfo::Successful)
    throw ModalError("modal analysis: shift-invert Lanczos did not converge for the lowest " +
                     std::to_string(count) + " modes");
  // Spectra returns them in decreasing 1/lambda, i.e. increasing lambda: reverse to be sure.
  Modes modes;
  const Eigen::VectorXd values = solver.eigenvalues();
  const Eigen::MatrixXd vectors = solver.eigenvectors();
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
  const double largest = sparse_largest_eigenvalue(stiffness, mass);
  modes.omega_max = std::sqrt(std::max(largest, 0.0));
  // A singular K (a mechanism, a missing support) leaves eigenvalues at the
  // round-off level n eps lambda_max, where shift-invert about 0 is meaningless.
  if (modes.omega_squared(0) < n * std::numeric_limits<double>::epsilon() * largest)
    throw ModalError("modal analysis: the stiffness matrix is singular to working precision "
                     "(lowest eigenvalue " +
                     std::to_string(modes.omega_squared(0)) + " rad^2/s^2 against " +
                     std::to_string(largest) +
                     " for the largest): the part is not supported against a rigid motion");
  return modes;
}

} // namespace

double max_angular_frequency(const Eigen::SparseMatrix<double>& stiffness,
                             const Eigen::SparseMatrix<double>& mass) {
  return std::sqrt(std::max(sparse_largest_eigenvalue(stiffness, mass), 0.0));
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
  return dense ? dense_modes(stiffness, mass, count) : sparse_modes(stiffness, mass, count);
}

} // namespace rsi
