#include "calibration.hpp"

#include <memory>
#include <new>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "bladed_disk.hpp"
#include "modal_analysis.hpp"

namespace rsi {
namespace {

struct Problem {
  Case c;
  double target_hz;
};

double family_error(double thickness, void* params) {
  auto* problem = static_cast<Problem*>(params);
  problem->c.bladed_disk.blade.thickness = thickness;
  return first_family_mean_hz(problem->c) - problem->target_hz;
}

} // namespace

double first_family_mean_hz(const Case& c) {
  const BladedDisk bd = assemble_bladed_disk(c);
  const Modes modes = lowest_modes(bd.stiffness, bd.mass, bd.n_sectors);
  double sum = 0.0;
  for (int i = 0; i < modes.n_modes(); ++i)
    sum += modes.frequency_hz(i);
  return sum / modes.n_modes();
}

double calibrate_blade_thickness(const Case& c, double target_hz, double low, double high) {
  Problem problem{c, target_hz};
  if (family_error(low, &problem) * family_error(high, &problem) > 0.0)
    throw std::invalid_argument("calibrate_blade_thickness: " + std::to_string(target_hz) +
                                " Hz is not reached for blade thickness in [" +
                                std::to_string(low) + ", " + std::to_string(high) + "] m");
  gsl_function f{&family_error, &problem};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) throw std::bad_alloc(); // GSL's allocation failed (its handler is off)
  // GSL reports failure by status (the CLI turns its aborting default
  // handler off, cli/main.cpp): a non-finite frequency on the way.
  auto check = [&](int status) {
    if (status != GSL_SUCCESS)
      throw std::runtime_error(std::string("calibrate_blade_thickness: GSL root finder: ") +
                               gsl_strerror(status));
  };
  check(gsl_root_fsolver_set(solver.get(), &f, low, high));
  for (int iteration = 0; iteration < 100; ++iteration) {
    check(gsl_root_fsolver_iterate(solver.get()));
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()),
                               gsl_root_fsolver_x_upper(solver.get()), 1e-12, 0.0) == GSL_SUCCESS)
      break;
  }
  return gsl_root_fsolver_root(solver.get());
}

} // namespace rsi
