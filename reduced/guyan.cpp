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

void project(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
             ReducedBasis& basis) {
  const Eigen::MatrixXd& t = basis.transformation;
  const Eigen::MatrixXd kt = stiffness * t;
  const Eigen::MatrixXd mt = mass * t;
  const Eigen::MatrixXd k = t.transpose() * kt;
  const Eigen::MatrixXd m = t.transpose() * mt;
  basis.stiffness = 0.5 * (k + k.transpose());
  basis.mass = 0.5 * (m + m.transpose());
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
  for (int b = 0; b < p.n_boundary(); ++b)
    basis.boundary_position.push_back(b);
  project(stiffness, mass, basis);
  basis.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return basis;
}

} // namespace rsi
