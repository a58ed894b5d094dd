#include "participation.hpp"

namespace rsi {

Eigen::VectorXd effective_interface_mass(const Eigen::SparseMatrix<double>& mass,
                                         const Partition& p,
                                         const Eigen::Ref<const Eigen::MatrixXd>& constraint,
                                         const Eigen::Ref<const Eigen::MatrixXd>& fixed_shapes) {
  const Eigen::SparseMatrix<double> m_ii = sparse_block(mass, p.interior, p.interior);
  const Eigen::SparseMatrix<double> m_ib = sparse_block(mass, p.interior, p.boundary);
  const Eigen::MatrixXd coupling = m_ii * constraint + Eigen::MatrixXd(m_ib); // n_I x n_B
  const Eigen::MatrixXd l = fixed_shapes.transpose() * coupling;              // P x n_B
  return l.rowwise().squaredNorm();
}

Eigen::VectorXd
craig_bampton_participation(const Eigen::SparseMatrix<double>& mass, const Partition& p,
                            const Eigen::Ref<const Eigen::MatrixXd>& constraint,
                            const Eigen::Ref<const Eigen::MatrixXd>& fixed_shapes,
                            const Eigen::Ref<const Eigen::VectorXd>& omega_squared) {
  return effective_interface_mass(mass, p, constraint, fixed_shapes).cwiseQuotient(omega_squared);
}

Eigen::VectorXd
craig_chang_martinez_participation(const Partition& p,
                                   const Eigen::Ref<const Eigen::MatrixXd>& free_shapes,
                                   const Eigen::Ref<const Eigen::VectorXd>& omega_squared) {
  const Eigen::MatrixXd phi_b = take_rows(free_shapes, p.boundary); // n_B x P
  const Eigen::VectorXd omega_6 =
      omega_squared.cwiseProduct(omega_squared).cwiseProduct(omega_squared);
  return phi_b.colwise().squaredNorm().transpose().cwiseQuotient(omega_6);
}

} // namespace rsi
