#pragma once
// The mass matrix of an explicit integrator, factorized once and applied
// every step: CHOLMOD's simplicial LDL^T of P M P^T with its own
// fill-reducing order P (AMD), applied by cholmod_solve2 in the permuted
// coordinates u' = P u with its workspace reused. The integrator keeps its
// state in those coordinates, so no permutation is applied per step.
// bench/bench_mass_solve found this solve the fastest of those it compares
// on the default system (bench/RESULTS.md).

#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

/// The mass matrix is not symmetric positive definite.
class MassFactorError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class MassFactor {
public:
  /// Factorizes M (symmetric, full storage); throws MassFactorError if it is
  /// not positive definite (a pivot D_jj <= 0).
  explicit MassFactor(const Eigen::SparseMatrix<double>& mass);
  ~MassFactor();
  MassFactor(const MassFactor&) = delete;
  MassFactor& operator=(const MassFactor&) = delete;

  /// u'(position(i)) = u(i): where physical dof i sits in the permuted order.
  const Eigen::VectorXi& position() const { return m_position; }
  /// P A P^T for a matrix A of the same size (K, M in the integrator's coordinates).
  Eigen::SparseMatrix<double> permuted(const Eigen::SparseMatrix<double>& a) const;
  /// r <- (P M P^T)^-1 r.
  void solve_in_place(Eigen::VectorXd& r);
  /// Entries of L below its unit diagonal: the solve does 4 flops per entry, plus n for D.
  double nonzeros_l() const;

private:
  cholmod_common m_common;
  cholmod_factor* m_factor = nullptr;
  cholmod_dense* m_rhs = nullptr;
  cholmod_dense* m_x = nullptr; // solve2's result and workspace, reused
  cholmod_dense* m_y = nullptr;
  cholmod_dense* m_e = nullptr;
  Eigen::VectorXi m_position;
};

} // namespace rsi
