#include "modal_damping.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rsi {

Eigen::VectorXd modal_damping(const ReducedBasis& basis, double zeta) {
  if (!(std::isfinite(zeta) && zeta >= 0.0 && zeta < 1.0))
    throw std::invalid_argument("modal_damping: damping.modal_ratio must be in [0, 1), got " +
                                std::to_string(zeta));
  const int r = basis.n_reduced();
  Eigen::VectorXd c = Eigen::VectorXd::Zero(r);
  if (zeta == 0.0) return c;
  // The boundary's coordinates, undamped: u_B's entries of q, or the
  // characteristic constraint modes' q_c (the last n_c entries).
  std::vector<char> boundary(r, 0);
  for (int j : basis.boundary_position)
    boundary.at(j) = 1;
  for (Eigen::Index j = r - basis.boundary_shapes.cols(); j < r; ++j)
    boundary.at(j) = 1;
  const int n_modes = r - static_cast<int>(std::count(boundary.begin(), boundary.end(), 1));
  if (basis.mode_omega.size() != n_modes)
    throw std::invalid_argument("modal_damping: the " + basis.method + " basis has " +
                                std::to_string(n_modes) + " modal coordinates but " +
                                std::to_string(basis.mode_omega.size()) +
                                " mode frequencies (mode_omega)");
  int i = 0;
  for (int j = 0; j < r; ++j)
    if (!boundary[j]) c(j) = 2.0 * zeta * basis.mode_omega(i++);
  return c;
}

} // namespace rsi
