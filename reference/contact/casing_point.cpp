#include "casing_point.hpp"

#include <cmath>

#include "ring_element.hpp"

namespace rsi {

CasingPoint casing_point(double alpha, int n_elements, double radius,
                         const std::vector<int>& node_dof) {
  const double pitch = 2.0 * M_PI / n_elements;
  alpha = std::fmod(alpha, 2.0 * M_PI);
  if (alpha < 0.0) alpha += 2.0 * M_PI;
  int element = static_cast<int>(std::floor(alpha / pitch));
  double xi = alpha / pitch - element;
  if (element >= n_elements) { // alpha within round-off of 2 pi
    element = n_elements - 1;
    xi = 1.0;
  }
  CasingPoint p;
  p.shape = hermite_values(xi, radius * pitch);
  for (int node = 0; node < 2; ++node) {
    const int j = element + node == n_elements ? 0 : element + node;
    if (node_dof[j] < 0) continue; // the clamped node: zero displacement
    p.first[p.n_nodes] = node_dof[j];
    p.shape_offset[p.n_nodes++] = 2 * node;
  }
  return p;
}

} // namespace rsi
