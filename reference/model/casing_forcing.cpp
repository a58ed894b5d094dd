#include "casing_forcing.hpp"

#include <cmath>

namespace rsi {

Eigen::VectorXd casing_forcing(const Casing& casing, const Forcing& forcing) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(casing.n_dofs());
  for (int j = 0; j < casing.n_elements; ++j) {
    const int first = casing.node_first_dof[j];
    if (first >= 0)
      f(first) = forcing.amplitude * std::cos(forcing.nodal_diameter * casing.node_angle(j));
  }
  return f;
}

} // namespace rsi
