#include "casing_pressure.hpp"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace rsi {
namespace {

/// Dunavant's 6-point rule, degree 4: (xi, eta, weight), weights summing to
/// 1/2, the reference triangle's area.
struct GaussPoint {
  double xi, eta, weight;
};
constexpr double a1 = 0.445948490915965, b1 = 1.0 - 2.0 * a1, w1 = 0.223381589678011 / 2.0;
constexpr double a2 = 0.091576213509771, b2 = 1.0 - 2.0 * a2, w2 = 0.109951743655322 / 2.0;
constexpr std::array<GaussPoint, 6> kRule = {
    {{a1, a1, w1}, {a1, b1, w1}, {b1, a1, w1}, {a2, a2, w2}, {a2, b2, w2}, {b2, a2, w2}}};

} // namespace

Eigen::VectorXd casing_pressure_forces(const CasingSurface& surface, const Component& casing,
                                       double p0, int nodal_diameters) {
  if (!std::isfinite(p0)) throw std::invalid_argument("casing_pressure_forces: p0 must be finite");
  if (nodal_diameters < 0)
    throw std::invalid_argument("casing_pressure_forces: nodal_diameters = " +
                                std::to_string(nodal_diameters) + ", allowed >= 0");
  const std::map<int, std::array<int, 3>> dofs = node_translations(casing.dofs);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(casing.n_dofs());
  for (int face = 0; face < surface.n_faces(); ++face) {
    const std::array<Eigen::Vector3d, 6>& x = surface.face_positions(face);
    const std::array<int, 6>& ids = surface.face_nodes(face);
    for (const GaussPoint& g : kRule) {
      const std::array<double, 6> n = triangle6_shape_functions(g.xi, g.eta);
      const std::array<std::array<double, 6>, 2> d = triangle6_derivatives(g.xi, g.eta);
      Eigen::Vector3d point = Eigen::Vector3d::Zero(), dxi = Eigen::Vector3d::Zero(),
                      deta = Eigen::Vector3d::Zero();
      for (int i = 0; i < 6; ++i) {
        point += n[i] * x[i];
        dxi += d[0][i] * x[i];
        deta += d[1][i] * x[i];
      }
      const double theta = std::atan2(point.y(), point.x());
      const Eigen::Vector3d traction = p0 * std::cos(nodal_diameters * theta) *
                                       Eigen::Vector3d(std::cos(theta), std::sin(theta), 0.0);
      const double area = g.weight * dxi.cross(deta).norm();
      for (int i = 0; i < 6; ++i) {
        const auto node = dofs.find(ids[i]);
        if (node == dofs.end()) continue; // clamped
        for (int k = 0; k < 3; ++k) {
          const int dof = node->second[static_cast<size_t>(k)];
          if (dof < 0)
            throw std::invalid_argument("casing_pressure_forces: casing node " +
                                        std::to_string(ids[i]) +
                                        " is partly clamped (a translation missing)");
          f(dof) += n[i] * area * traction(k);
        }
      }
    }
  }
  return f;
}

} // namespace rsi
