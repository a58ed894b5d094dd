#include "critical_step.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "partition.hpp"
#include "reduced_integrator.hpp"

namespace rsi {
namespace {

/// What to change when (K^, M^) has no eigenpairs (issue 13, class 8).
const std::string kBasisRemedy = " (M^ = T^T M T not positive definite, or not finite)";
const FailureAdvice kBasisAdvice = remedied_by({Remedy::fewer_modes_or_another_method});

/// (K^, M^) or, with a massless boundary, the condensed pair on the massed coordinates.
struct FiniteProblem {
  Eigen::MatrixXd stiffness;
  Eigen::MatrixXd mass;
};

FiniteProblem finite_problem(const ReducedBasis& basis) {
  if (!basis.massless_boundary) return {basis.stiffness, basis.mass};
  const int r = basis.n_reduced();
  std::vector<bool> is_boundary(r, false);
  for (int b : basis.boundary_position)
    is_boundary[b] = true;
  std::vector<int> massed;
  for (int i = 0; i < r; ++i)
    if (!is_boundary[i]) massed.push_back(i);
  const std::vector<int>& boundary = basis.boundary_position;
  // Dense blocks A(rows, cols) through the row gather of partition.hpp.
  const auto block = [](const Eigen::MatrixXd& a, const std::vector<int>& rows,
                        const std::vector<int>& cols) {
    return Eigen::MatrixXd(
        take_rows(Eigen::MatrixXd(take_rows(a, rows).transpose()), cols).transpose());
  };
  assert(block(basis.mass, boundary, boundary).cwiseAbs().maxCoeff() == 0.0);
  assert(block(basis.mass, massed, boundary).cwiseAbs().maxCoeff() == 0.0);
  const Eigen::LLT<Eigen::MatrixXd> k_bb(block(basis.stiffness, boundary, boundary));
  if (k_bb.info() != Eigen::Success)
    throw ReducedIntegrationError("reduced model: the stiffness K^_BB of the massless boundary is "
                                  "not positive definite (static condensation failed)",
                                  remedied_by({Remedy::massed_boundary_method}));
  const Eigen::MatrixXd k_br = block(basis.stiffness, boundary, massed);
  const Eigen::MatrixXd condensed =
      block(basis.stiffness, massed, massed) - k_br.transpose() * k_bb.solve(k_br);
  return {0.5 * (condensed + condensed.transpose()), block(basis.mass, massed, massed)};
}

} // namespace

Eigen::VectorXd reduced_eigenvalues(const ReducedBasis& basis) {
  const FiniteProblem problem = finite_problem(basis);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(
      problem.stiffness, problem.mass, Eigen::EigenvaluesOnly);
  if (eigen.info() != Eigen::Success)
    throw ReducedIntegrationError(
        "reduced model: the generalized eigenproblem (K^, M^) failed" + kBasisRemedy, kBasisAdvice);
  return eigen.eigenvalues();
}

double reduced_omega_max(const ReducedBasis& basis) {
  return std::sqrt(std::max(reduced_eigenvalues(basis).maxCoeff(), 0.0));
}

double ReducedModes::omega_max() const {
  return std::sqrt(std::max(omega_squared.maxCoeff(), 0.0));
}

ReducedModes reduced_modes(const ReducedBasis& basis) {
  if (basis.massless_boundary)
    throw ReducedIntegrationError("reduced model: " + basis.method +
                                  " has a massless boundary; its coordinates have no modes");
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(basis.stiffness,
                                                                        basis.mass);
  if (eigen.info() != Eigen::Success)
    throw ReducedIntegrationError(
        "reduced model: the generalized eigenproblem (K^, M^) failed" + kBasisRemedy, kBasisAdvice);
  return {eigen.eigenvectors(), eigen.eigenvalues()};
}

} // namespace rsi
