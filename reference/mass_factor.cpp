#include "mass_factor.hpp"

#include <string>

namespace rsi {

MassFactor::MassFactor(const Eigen::SparseMatrix<double>& mass) {
  const auto n = static_cast<int>(mass.rows());
  cholmod_start(&m_common);
  m_common.supernodal = CHOLMOD_SIMPLICIAL;
  m_common.final_ll = 0; // keep LDL^T
  try {
    Eigen::SparseMatrix<double> lower = mass.triangularView<Eigen::Lower>();
    lower.makeCompressed();
    cholmod_sparse a = Eigen::viewAsCholmod(lower);
    a.stype = -1; // the lower triangle of a symmetric matrix
    m_factor = cholmod_analyze(&a, &m_common);
    if (m_factor == nullptr || !cholmod_factorize(&a, m_factor, &m_common) ||
        m_common.status != CHOLMOD_OK || m_factor->minor < m_factor->n)
      throw MassFactorError(
          "the mass matrix is not positive definite (CHOLMOD factorization failed, status " +
          std::to_string(m_common.status) + ")");
    // Simplicial LDL^T: D_jj is the first entry of column j (permuted order).
    const auto* p = static_cast<const int*>(m_factor->p);
    const auto* x = static_cast<const double*>(m_factor->x);
    const auto* perm = static_cast<const int*>(m_factor->Perm);
    for (int j = 0; j < n; ++j)
      if (!(x[p[j]] > 0.0))
        throw MassFactorError("the mass matrix is not positive definite (LDL^T pivot " +
                              std::to_string(x[p[j]]) + " at dof " + std::to_string(perm[j]) + ")");
    m_position.resize(n);
    for (int k = 0; k < n; ++k)
      m_position(perm[k]) = k;
    m_rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &m_common);
    if (m_rhs == nullptr) throw MassFactorError("CHOLMOD could not allocate a right-hand side");
  } catch (...) {
    cholmod_free_factor(&m_factor, &m_common);
    cholmod_finish(&m_common);
    throw;
  }
}

MassFactor::~MassFactor() {
  cholmod_free_dense(&m_rhs, &m_common);
  cholmod_free_dense(&m_x, &m_common);
  cholmod_free_dense(&m_y, &m_common);
  cholmod_free_dense(&m_e, &m_common);
  cholmod_free_factor(&m_factor, &m_common);
  cholmod_finish(&m_common);
}

Eigen::SparseMatrix<double> MassFactor::permuted(const Eigen::SparseMatrix<double>& a) const {
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p(m_position);
  return p * a * p.inverse();
}

void MassFactor::solve_in_place(Eigen::VectorXd& r) {
  const Eigen::Index n = r.size();
  Eigen::Map<Eigen::VectorXd>(static_cast<double*>(m_rhs->x), n) = r;
  // CHOLMOD_LDLt solves L D L^T x = b without the permutation.
  if (!cholmod_solve2(CHOLMOD_LDLt, m_factor, m_rhs, nullptr, &m_x, nullptr, &m_y, &m_e, &m_common))
    throw MassFactorError("CHOLMOD's solve with the mass factor failed (status " +
                          std::to_string(m_common.status) + ")");
  r = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(m_x->x), n);
}

double MassFactor::nonzeros_l() const {
  const auto* nz = static_cast<const int*>(m_factor->nz);
  double count = 0.0;
  for (size_t j = 0; j < m_factor->n; ++j)
    count += nz[j] - 1; // column j holds D_jj first
  return count;
}

} // namespace rsi
