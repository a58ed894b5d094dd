#include "blade_geometry.hpp"

#include <cmath>
#include <memory>
#include <new>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

namespace rsi {
namespace {

/// Tip position in the sector frame for blade elements of length `length`.
Eigen::Vector2d tip_position(const BladedDiskSpec& spec, double length) {
  Eigen::Vector2d p(spec.rim_radius, 0.0);
  for (int i = 0; i < spec.n_blade_elements; ++i)
    p += length * Eigen::Vector2d(std::cos(-i * spec.kink_angle), std::sin(-i * spec.kink_angle));
  return p;
}

double tip_radius_error(double length, void* params) {
  const auto* spec = static_cast<const BladedDiskSpec*>(params);
  return tip_position(*spec, length).norm() - spec->tip_radius;
}

double solve_element_length(const BladedDiskSpec& spec) {
  // At L = 0 the tip is at the rim (error < 0); a straight blade needs
  // (R_t - r_r)/n, a kinked one more, so grow the bracket until it changes sign.
  double low = 0.0;
  double high = (spec.tip_radius - spec.rim_radius) / spec.n_blade_elements;
  BladedDiskSpec copy = spec;
  while (tip_radius_error(high, &copy) < 0.0) {
    low = high;
    high *= 1.5;
    if (high > 100.0 * (spec.tip_radius - spec.rim_radius))
      throw CaseError("bladed_disk.kink_angle_deg: the blade curls too much for its tip to reach "
                      "tip_radius; use a smaller |kink angle|");
  }
  gsl_function f{&tip_radius_error, &copy};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) throw std::bad_alloc(); // GSL's allocation failed (its handler is off)
  // GSL reports failure by status (the CLI turns GSL's aborting default
  // handler off, cli/main.cpp); a failure here means the geometry is
  // degenerate (a non-finite tip radius), which the case must not ask for.
  auto fail = [&](int status) {
    throw CaseError(std::string("bladed_disk: no blade element length puts the tip at "
                                "tip_radius (GSL root finder: ") +
                    gsl_strerror(status) +
                    "); check tip_radius, rim_radius, n_blade_elements and kink_angle_deg");
  };
  if (const int status = gsl_root_fsolver_set(solver.get(), &f, low, high); status != GSL_SUCCESS)
    fail(status);
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (const int status = gsl_root_fsolver_iterate(solver.get()); status != GSL_SUCCESS)
      fail(status);
    const double a = gsl_root_fsolver_x_lower(solver.get());
    const double b = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(a, b, 0.0, 1e-15) == GSL_SUCCESS) break;
  }
  return gsl_root_fsolver_root(solver.get());
}

} // namespace

BladeGeometry blade_geometry(const BladedDiskSpec& spec) {
  BladeGeometry g;
  g.disk_length = spec.rim_radius - spec.hub_radius;
  g.element_length = solve_element_length(spec);
  g.nodes.emplace_back(spec.hub_radius, 0.0);
  g.nodes.emplace_back(spec.rim_radius, 0.0);
  for (int i = 0; i < spec.n_blade_elements; ++i) {
    const double angle = -i * spec.kink_angle;
    g.element_angles.push_back(angle);
    g.nodes.push_back(g.nodes.back() +
                      g.element_length * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  g.tip_angle = std::atan2(g.nodes.back().y(), g.nodes.back().x());
  return g;
}

} // namespace rsi
