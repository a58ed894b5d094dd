#include "guyan.hpp"

#include <chrono>

#include <Eigen/CholmodSupport>

namespace rsi {

Eigen::MatrixXd constraint_modes(const Eigen::SparseMatrix<double>& stiffness, const Partition& p) {
  const Eigen::SparseMatrix<double> k_ii = sparse_block(stiffness, p.interior, p.interior);
  const Eigen::SparseMatrix<double> k_ib = sparse_block(stiffness, p.interior, p.boundary);
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>> factor(k_ii);
  if (factor.info() != Eigen::Success)
    throw ReductionError(
        "constraint modes: K_II is not positive definite (CHOLMOD); is the hub clamped?");
  const Eigen::MatrixXd psi = -factor.solve(Eigen::MatrixXd(k_ib));
  if (factor.info() != Eigen::Success)
    throw ReductionError("constraint modes: CHOLMOD solve failed");
  return psi;
}

void finish_basis(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int n_boundary,
                  int first_boundary_position, std::chrono::steady_clock::time_point start,
                  ReducedBasis& basis) {
  for (int b = 0; b < n_boundary; ++b)
    basis.boundary_position.push_back(first_boundary_position + b);
  const Eigen::MatrixXd& t = basis.transformation;
  const Eigen::MatrixXd k = t.transpose() * (stiffness * t);
  const Eigen::MatrixXd m = t.transpose() * (mass * t);
  basis.stiffness = 0.5 * (k + k.transpose());
  basis.mass = 0.5 * (m + m.transpose());
  basis.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ReducedBasis guyan(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, const Partition& p) {
  const auto start = std::chrono::steady_clock::now();
  ReducedBasis basis;
  basis.method = "guyan";
  const Eigen::MatrixXd psi = constraint_modes(stiffness, p);
  basis.transformation =
      place_rows(p.n(), p.interior, psi) +
      place_rows(p.n(), p.boundary, Eigen::MatrixXd::Identity(p.n_boundary(), p.n_boundary()));
  finish_basis(stiffness, mass, p.n_boundary(), 0, start, basis);
  return basis;
}

} // namespace rsi
