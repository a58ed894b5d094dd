#include "ring_element.hpp"

#include <memory>
#include <new>

#include <gsl/gsl_integration.h>

namespace rsi {
namespace {

using Row8 = Eigen::Matrix<double, 1, 8>;

Eigen::Vector4d hermite_first(double xi, double l) {
  return Eigen::Vector4d(-6 * xi + 6 * xi * xi, l * (1 - 4 * xi + 3 * xi * xi),
                         6 * xi - 6 * xi * xi, l * (-2 * xi + 3 * xi * xi)) /
         l;
}

Eigen::Vector4d hermite_second(double xi, double l) {
  return Eigen::Vector4d(-6 + 12 * xi, l * (-4 + 6 * xi), 6 - 12 * xi, l * (-2 + 6 * xi)) / (l * l);
}

/// Scatters the four Hermite coefficients of u (offset 0) or v (offset 2)
/// into the element dof order (u1, u1_s, v1, v1_s, u2, u2_s, v2, v2_s).
Row8 spread(const Eigen::Vector4d& n, int offset) {
  Row8 row = Row8::Zero();
  row(offset) = n(0);
  row(offset + 1) = n(1);
  row(offset + 4) = n(2);
  row(offset + 5) = n(3);
  return row;
}

struct GaussTable {
  std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)>
      table{gsl_integration_glfixed_table_alloc(4), &gsl_integration_glfixed_table_free};
};

/// Sum over the Gauss points of w * f(xi) on [0, 1].
template <typename F> Matrix8d integrate(const F& integrand) {
  const GaussTable gauss;
  if (!gauss.table) throw std::bad_alloc(); // GSL's allocation failed (its handler is off)
  Matrix8d sum = Matrix8d::Zero();
  for (size_t i = 0; i < 4; ++i) {
    double xi = 0.0;
    double w = 0.0;
    gsl_integration_glfixed_point(0.0, 1.0, i, &xi, &w, gauss.table.get());
    sum += w * integrand(xi);
  }
  return sum;
}

} // namespace

Eigen::Vector4d hermite_values(double xi, double l) {
  return Eigen::Vector4d(1 - 3 * xi * xi + 2 * xi * xi * xi, l * (xi - 2 * xi * xi + xi * xi * xi),
                         3 * xi * xi - 2 * xi * xi * xi, l * (-xi * xi + xi * xi * xi));
}

Matrix8d ring_stiffness(const BeamProperties& p, double radius, double arc_length) {
  const double l = arc_length;
  const double R = radius;
  return integrate([&](double xi) -> Matrix8d {
    const Row8 eps = spread(hermite_first(xi, l), 2) + spread(hermite_values(xi, l), 0) / R;
    const Row8 kappa = spread(hermite_second(xi, l), 0) - spread(hermite_first(xi, l), 2) / R;
    return l * (p.EA * eps.transpose() * eps + p.EI * kappa.transpose() * kappa);
  });
}

Matrix8d ring_mass(const BeamProperties& p, double arc_length) {
  const double l = arc_length;
  return integrate([&](double xi) -> Matrix8d {
    const Row8 u = spread(hermite_values(xi, l), 0);
    const Row8 v = spread(hermite_values(xi, l), 2);
    return l * p.rhoA * (u.transpose() * u + v.transpose() * v);
  });
}

} // namespace rsi
