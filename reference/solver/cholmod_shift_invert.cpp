#include "cholmod_shift_invert.hpp"
#include "interruption_flag.hpp"

#include <stdexcept>

namespace rsi {

namespace {

/// The lower triangle of a, its explicit zeros dropped.
Eigen::SparseMatrix<double> nonzero_lower(const Eigen::SparseMatrix<double>& a) {
  Eigen::SparseMatrix<double> lower = a.triangularView<Eigen::Lower>();
  lower.prune([](Eigen::Index, Eigen::Index, double value) { return value != 0.0; });
  lower.makeCompressed();
  return lower;
}

} // namespace

CholmodShiftInvert::CholmodShiftInvert(const Eigen::SparseMatrix<double>& stiffness,
                                       const Eigen::SparseMatrix<double>& mass,
                                       CholmodFactor::Method method)
    : m_factor(method) {
  const Eigen::Index n = stiffness.rows();
  if (stiffness.cols() != n || mass.rows() != n || mass.cols() != n)
    throw std::invalid_argument(
        "CholmodShiftInvert: K and M must be square matrices of the same size");
  const Eigen::SparseMatrix<double> k = nonzero_lower(stiffness);
  const Eigen::SparseMatrix<double> m = nonzero_lower(mass);
  // Both on the union of the two patterns (a sum keeps every stored position).
  m_lower_k = k + 0.0 * m;
  m_lower_m = m + 0.0 * k;
  m_lower_k.makeCompressed();
  m_lower_m.makeCompressed();
  m_lower = m_lower_k;
}

void CholmodShiftInvert::set_shift(double sigma) {
  if (factorized() && sigma == m_sigma) return; // the factor of K - sigma M is there
  m_sigma = sigma;
  Eigen::Map<Eigen::VectorXd>(m_lower.valuePtr(), m_lower.nonZeros()) =
      Eigen::Map<const Eigen::VectorXd>(m_lower_k.valuePtr(), m_lower_k.nonZeros()) -
      sigma * Eigen::Map<const Eigen::VectorXd>(m_lower_m.valuePtr(), m_lower_m.nonZeros());
  m_factor.factorize(m_lower);
}

void CholmodShiftInvert::perform_op(const double* x_in, double* y_out) const {
  const Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
  Eigen::Map<Eigen::VectorXd> y(y_out, rows());
  if (!factorized())
    throw std::runtime_error("CholmodShiftInvert: no factor of K - sigma M (" + message() + ")");
  if (!solve(x, y)) throw std::runtime_error("CholmodShiftInvert: the CHOLMOD solve failed");
}

bool CholmodShiftInvert::solve(const Eigen::Ref<const Eigen::MatrixXd>& b,
                               Eigen::Ref<Eigen::MatrixXd> x) const {
  throw_if_interrupted(); // every block step of the block method solves here
  m_n_solves += b.cols();
  return m_factor.solve(CholmodFactor::System::a, b, x);
}

} // namespace rsi
