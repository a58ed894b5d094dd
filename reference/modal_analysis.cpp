#include "modal_analysis.hpp"

#include <cmath>
#include <string>

#include <lapacke.h>

namespace rsi {

double Modes::frequency_hz(int i) const {
  const double w2 = omega_squared(i);
  return std::copysign(std::sqrt(std::abs(w2)), w2) / (2.0 * M_PI);
}

Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                   int count) {
  const int n = static_cast<int>(stiffness.rows());
  if (count < 1 || count > n)
    throw std::invalid_argument("lowest_modes: count must be in [1, " + std::to_string(n) + "], got " +
                                std::to_string(count));
  Eigen::MatrixXd a = Eigen::MatrixXd(stiffness);
  Eigen::MatrixXd b = Eigen::MatrixXd(mass);
  Eigen::VectorXd w(n);
  const lapack_int info = LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', n, a.data(), n, b.data(), n, w.data());
  if (info > n)
    throw ModalError("modal analysis: the mass matrix is not positive definite (LAPACKE_dsygvd info " +
                     std::to_string(info) + ", leading minor " + std::to_string(info - n) + ")");
  if (info != 0)
    throw ModalError("modal analysis: LAPACKE_dsygvd failed (info " + std::to_string(info) + ")");
  Modes modes;
  modes.omega_squared = w.head(count);
  modes.shapes = a.leftCols(count);
  modes.omega_max = std::sqrt(std::max(w(n - 1), 0.0));
  return modes;
}

} // namespace rsi
