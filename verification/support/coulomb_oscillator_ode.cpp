#include "coulomb_oscillator_ode.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

namespace rsi::coulomb {

namespace {

constexpr double two_pi = 2.0 * M_PI;
/// Largest step as a fraction of the shortest period (sign changes of x' are
/// checked after every step), and the stick scan's grid per forcing period.
constexpr int steps_per_period = 32;
constexpr int stick_samples_per_period = 64;
/// GSL's standard control accepts a step when |err_i| <= 1.1 D_i.
constexpr double control_acceptance = 1.1;

struct OdeFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class GslHandlerOff {
public:
  GslHandlerOff()
      : m_previous(gsl_set_error_handler_off()) {}
  ~GslHandlerOff() { gsl_set_error_handler(m_previous); }
  GslHandlerOff(const GslHandlerOff&) = delete;
  GslHandlerOff& operator=(const GslHandlerOff&) = delete;

private:
  gsl_error_handler_t* m_previous;
};

/// Right-hand side of a slip with direction s: x' = v, v' = (F - k x - s mu N)/m.
struct SlipSystem {
  const Oscillator* o = nullptr;
  int s = 0;
};

int slip_rhs(double t, const double y[], double dydt[], void* params) {
  const SlipSystem& sys = *static_cast<const SlipSystem*>(params);
  const Oscillator& o = *sys.o;
  dydt[0] = y[1];
  dydt[1] = (o.force_amplitude * std::sin(o.forcing_frequency * t + o.forcing_phase) -
             o.stiffness * y[0] - sys.s * o.friction_coefficient * o.normal_force) /
            o.mass;
  return GSL_SUCCESS;
}

template <class F> double brent(F& f, double lo, double hi, const char* what) {
  gsl_function fn{[](double t, void* p) { return (*static_cast<F*>(p))(t); }, &f};
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  GslHandlerOff guard;
  int status = gsl_root_fsolver_set(solver.get(), &fn, lo, hi);
  for (int i = 0; i < 200 && status == GSL_SUCCESS; ++i) {
    status = gsl_root_fsolver_iterate(solver.get());
    if (status != GSL_SUCCESS) break;
    const double a = gsl_root_fsolver_x_lower(solver.get());
    const double b = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(a, b, 0.0, 4.0 * DBL_EPSILON) == GSL_SUCCESS)
      return gsl_root_fsolver_root(solver.get());
  }
  throw OdeFailure(std::string(what) + ": Brent's root did not converge (" + gsl_strerror(status) +
                   ")");
}

/// The force-balance decision for a mass at rest (written here again on
/// purpose: the two computations share no code beyond the types).
Motion at_rest(const Oscillator& o, double t, double x) {
  const double a =
      o.force_amplitude * std::sin(o.forcing_frequency * t + o.forcing_phase) - o.stiffness * x;
  const double limit = o.friction_coefficient * o.normal_force;
  if (a > limit) return Motion::slip_positive;
  if (a < -limit) return Motion::slip_negative;
  return Motion::stick;
}

/// The integrator state shared by the slip segments.
class Integrator {
public:
  Integrator(const Oscillator& o, const OdeTolerances& tol)
      : m_o(o)
      , m_tol(tol)
      , m_step(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2))
      , m_probe(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2))
      , m_control(gsl_odeiv2_control_y_new(tol.eps_abs, tol.eps_rel))
      , m_evolve(gsl_odeiv2_evolve_alloc(2)) {
    if (!m_step || !m_probe || !m_control || !m_evolve)
      throw OdeFailure("gsl_odeiv2 allocation failed");
  }
  ~Integrator() {
    gsl_odeiv2_evolve_free(m_evolve);
    gsl_odeiv2_control_free(m_control);
    gsl_odeiv2_step_free(m_probe);
    gsl_odeiv2_step_free(m_step);
  }
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  /// 1.1 ||(D_x, D_v)|| in the energy norm for the state y.
  double local_bound(const double y[2]) const {
    const double dx = m_tol.eps_abs + m_tol.eps_rel * std::abs(y[0]);
    const double dv = m_tol.eps_abs + m_tol.eps_rel * std::abs(y[1]);
    return control_acceptance * std::sqrt(m_o.stiffness * dx * dx + m_o.mass * dv * dv);
  }

  const Oscillator& m_o;
  const OdeTolerances& m_tol;
  gsl_odeiv2_step* m_step;
  gsl_odeiv2_step* m_probe;
  gsl_odeiv2_control* m_control;
  gsl_odeiv2_evolve* m_evolve;
};

} // namespace

OdeSolution::OdeSolution(const Oscillator& o, double window_end, const std::vector<double>& samples,
                         const OdeTolerances& tol) {
  validate(o);
  if (!(std::isfinite(window_end) && window_end > 0.0))
    throw std::invalid_argument("coulomb::OdeSolution: window_end must be finite and > 0");
  if (!(tol.eps_abs > 0.0 && tol.eps_rel >= 0.0 && std::isfinite(tol.eps_abs) &&
        std::isfinite(tol.eps_rel)))
    throw std::invalid_argument("coulomb::OdeSolution: eps_abs must be > 0, eps_rel >= 0");
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!(samples[i] >= 0.0 && samples[i] <= window_end &&
          (i == 0 || samples[i] >= samples[i - 1])))
      throw std::invalid_argument(
          "coulomb::OdeSolution: sample_times must be sorted and lie in [0, window_end]");

  const double w0 = std::sqrt(o.stiffness / o.mass);
  const double w = o.forcing_frequency;
  const double limit = o.friction_coefficient * o.normal_force;
  const double h_max = two_pi / (steps_per_period * std::max(w0, w));
  Integrator integ(o, tol);
  std::size_t next = 0;
  auto record = [&](double t_upto, double x, double v) {
    while (next < samples.size() && samples[next] <= t_upto) {
      m_x.push_back(x);
      m_v.push_back(v);
      ++next;
    }
  };

  double t = 0.0;
  double y[2] = {o.x0, o.v0};
  Motion motion = o.v0 > 0.0   ? Motion::slip_positive
                  : o.v0 < 0.0 ? Motion::slip_negative
                               : at_rest(o, 0.0, o.x0);
  try {
    GslHandlerOff guard;
    while (t < window_end) {
      if (motion == Motion::stick) {
        // Scan g = F - k x_s for |g| > mu N, then Brent on g -+ mu N.
        const double xs = y[0];
        auto g = [&](double time) {
          return o.force_amplitude * std::sin(w * time + o.forcing_phase) - o.stiffness * xs;
        };
        double end = window_end;
        Motion released = Motion::stick;
        if (o.force_amplitude > 0.0 && w > 0.0) {
          const double grid = two_pi / (stick_samples_per_period * w);
          for (double ta = t; ta < window_end;) {
            const double tb = std::min(ta + grid, window_end);
            const double gb = g(tb);
            if (std::abs(gb) > limit) {
              const double level = gb > 0.0 ? limit : -limit;
              auto excess = [&](double time) { return g(time) - level; };
              end = excess(ta) == 0.0 ? ta : brent(excess, ta, tb, "stick end");
              released = gb > 0.0 ? Motion::slip_positive : Motion::slip_negative;
              break;
            }
            ta = tb;
          }
        }
        m_segments.push_back({t, end, Motion::stick, xs, 0.0});
        record(end, xs, 0.0);
        if (released == Motion::stick) break;
        t = end;
        y[1] = 0.0;
        motion = released;
        continue;
      }

      const int s = direction(motion);
      SlipSystem params{&o, s};
      gsl_odeiv2_system sys{&slip_rhs, nullptr, 2, &params};
      gsl_odeiv2_evolve_reset(integ.m_evolve);
      gsl_odeiv2_step_reset(integ.m_step);
      Segment seg{t, window_end, motion, y[0], y[1]};
      double h = h_max / 8.0;
      bool event = false;
      while (t < window_end) {
        record(t, y[0], y[1]);
        const double target =
            std::min({t + h_max, window_end, next < samples.size() ? samples[next] : window_end});
        const double t_old = t;
        const double y_old[2] = {y[0], y[1]};
        const int status = gsl_odeiv2_evolve_apply(integ.m_evolve, integ.m_control, integ.m_step,
                                                   &sys, &t, target, &h, y);
        if (status != GSL_SUCCESS)
          throw OdeFailure(std::string("rk8pd step failed (") + gsl_strerror(status) + ")");
        if (s * y[1] > 0.0) {
          ++m_n_steps;
          m_error_bound += integ.local_bound(y);
          continue;
        }
        // x' changed sign in [t_old, t]: Brent on the one-step map.
        double y_probe[2];
        double y_err[2];
        auto one_step = [&](double tau) {
          y_probe[0] = y_old[0];
          y_probe[1] = y_old[1];
          gsl_odeiv2_step_reset(integ.m_probe);
          const int st = gsl_odeiv2_step_apply(integ.m_probe, t_old, tau, y_probe, y_err, nullptr,
                                               nullptr, &sys);
          if (st != GSL_SUCCESS)
            throw OdeFailure(std::string("rk8pd event step failed (") + gsl_strerror(st) + ")");
          return s * y_probe[1];
        };
        const double full = t - t_old;
        double tau = full;
        if (y[1] != 0.0) {
          double lo = 0.0;
          if (s * y_old[1] <= 0.0) { // from rest: a point with s x' > 0 first
            bool found = false;
            for (int k = 1; k <= 60 && !found; ++k) {
              lo = full * std::ldexp(1.0, -k);
              found = one_step(lo) > 0.0;
            }
            if (!found) throw OdeFailure("slip from rest: x' does not leave 0 in its direction");
          }
          tau = brent(one_step, lo, full, "slip end");
        }
        one_step(tau);
        const double bound = integ.local_bound(y_probe);
        if (std::sqrt(o.stiffness * y_err[0] * y_err[0] + o.mass * y_err[1] * y_err[1]) > bound)
          throw OdeFailure("event step: the rk8pd error estimate exceeds the tolerance");
        ++m_n_steps;
        m_error_bound += bound;
        t = t_old + tau;
        y[0] = y_probe[0];
        y[1] = 0.0;
        event = true;
        break;
      }
      seg.end = t;
      m_segments.push_back(seg);
      if (!event) break;
      motion = at_rest(o, t, y[0]);
    }
    record(window_end, y[0], y[1]);
  } catch (const OdeFailure& e) {
    m_failure = "coulomb::OdeSolution at t = " + std::to_string(t) + ": " + e.what();
  }
}

} // namespace rsi::coulomb
