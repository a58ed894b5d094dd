#pragma once
// Assembly of element matrices through general linear dof relations.
//
// Every element dof a is a linear combination of global dofs,
// u_e(a) = sum_j c_aj u(j): an identity for an ordinary node, empty for a
// clamped dof, a rotation for a node with its own frame, and the ring
// kinematics for the rim tie (SPEC §2: a transformation, not a penalty).
// Then K += L^T K_e L with L the (n_e x n) matrix of the c_aj.

#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

/// sum of coefficient * global dof; empty for a clamped (zero) dof.
using DofCombination = std::vector<std::pair<int, double>>;

class Assembler {
public:
  explicit Assembler(int n_dofs)
      : m_n(n_dofs) {}

  /// Adds L^T ke L and L^T me L, row a of L given by map[a].
  void add(const Eigen::Ref<const Eigen::MatrixXd>& ke, const Eigen::Ref<const Eigen::MatrixXd>& me,
           const std::vector<DofCombination>& map);

  Eigen::SparseMatrix<double> stiffness() const { return build(m_k); }
  Eigen::SparseMatrix<double> mass() const { return build(m_m); }

private:
  using Triplets = std::vector<Eigen::Triplet<double>>;
  Eigen::SparseMatrix<double> build(const Triplets& t) const;
  static void scatter(const Eigen::Ref<const Eigen::MatrixXd>& e,
                      const std::vector<DofCombination>& map, Triplets& out);

  int m_n;
  Triplets m_k;
  Triplets m_m;
};

/// diag(a, b): the system matrix of two parts that share no dof.
Eigen::SparseMatrix<double> block_diagonal(const Eigen::SparseMatrix<double>& a,
                                           const Eigen::SparseMatrix<double>& b);

} // namespace rsi
