#include "characteristic_constraint.hpp"

#include <chrono>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "craig_bampton.hpp"

namespace rsi {

ReducedBasis characteristic_constraint(const Eigen::SparseMatrix<double>& stiffness,
                                       const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                       int eta, int n_c, const CyclicBoundary* cyclic) {
  const int n_b = p.n_boundary();
  if (n_c < 1 || n_c > n_b)
    throw ReductionError("characteristic constraint modes: 1 to " + std::to_string(n_b) +
                             " boundary modes (the boundary dofs), got " + std::to_string(n_c),
                         failed_input(FailedInput::boundary_mode_count));
  const auto start = std::chrono::steady_clock::now();
  ReducedBasis basis = craig_bampton(stiffness, mass, p, eta, cyclic);
  // CB's q = (u_eta, u_B): the boundary block is its last n_B rows/columns.
  // Eigen's generalized solver does not report a failed Cholesky of M^_BB:
  // checked here first.
  const Eigen::MatrixXd m_bb = basis.mass.bottomRightCorner(n_b, n_b);
  if (Eigen::LLT<Eigen::MatrixXd>(m_bb).info() != Eigen::Success)
    throw ReductionError("characteristic constraint modes: the boundary's Guyan mass M^_BB is "
                         "not positive definite (a boundary dof without mass)");
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> boundary(
      basis.stiffness.bottomRightCorner(n_b, n_b), m_bb);
  if (boundary.info() != Eigen::Success)
    throw ReductionError("characteristic constraint modes: the boundary's eigenproblem "
                         "(K^_BB, M^_BB) did not converge");
  const Eigen::MatrixXd psi_c = boundary.eigenvectors().leftCols(n_c);
  const int r = eta + n_c;
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(eta + n_b, r);
  s.topLeftCorner(eta, eta).setIdentity();
  s.bottomRightCorner(n_b, n_c) = psi_c;
  basis.transformation = basis.transformation * s;
  const Eigen::MatrixXd k = s.transpose() * basis.stiffness * s;
  const Eigen::MatrixXd m = s.transpose() * basis.mass * s;
  basis.stiffness = 0.5 * (k + k.transpose());
  basis.mass = 0.5 * (m + m.transpose());
  basis.method = "cc";
  basis.boundary_position.clear();
  basis.boundary_shapes = psi_c;
  basis.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return basis;
}

} // namespace rsi
