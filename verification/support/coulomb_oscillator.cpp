#include "coulomb_oscillator.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

namespace rsi::coulomb {

namespace {

constexpr double two_pi = 2.0 * M_PI;
/// Grid points per shortest period in the slip-end search.
constexpr int samples_per_period = 64;
/// Maximum half-cycles of a free vibration, segments of a forced response.
constexpr double max_half_cycles = 1e7;
constexpr std::size_t max_segments = 10000000;

void require(bool condition, const std::string& what) {
  if (!condition) throw std::invalid_argument(what);
}

/// Numerical trouble inside ForcedResponse, turned into its status.
struct NumericalFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// GSL's error handler off for the lifetime of the guard (statuses are checked).
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

double sinc(double z) {
  return std::abs(z) < 1e-4 ? 1.0 - z * z / 6.0 : std::sin(z) / z;
}

struct State {
  double x = 0.0;
  double v = 0.0;
};

/// One slip segment in closed form: from (t0, x0, v0) with friction -s mu N.
/// C(tau) = (cos w tau - cos w0 tau)/(w0^2 - w^2) and
/// S(tau) = (sin w tau - (w/w0) sin w0 tau)/(w0^2 - w^2), rewritten with
/// sigma = w0 + w, delta = w0 - w and sinc(delta tau / 2) (sum-to-product),
/// hold at resonance too; S' = w C.
class SlipArc {
public:
  SlipArc(const Oscillator& o, double t0, State start, int s)
      : m_w0(natural_frequency(o))
      , m_w(o.forcing_frequency)
      , m_p_over_m(o.force_amplitude / o.mass)
      , m_centre(-s * friction_limit(o) / o.stiffness)
      , m_start(start)
      , m_sin0(std::sin(o.forcing_frequency * t0 + o.forcing_phase))
      , m_cos0(std::cos(o.forcing_frequency * t0 + o.forcing_phase)) {}

  State at(double tau) const {
    const double sigma = m_w0 + m_w;
    const double half_delta = 0.5 * (m_w0 - m_w) * tau;
    const double sc = sinc(half_delta);
    const double c_half = std::cos(0.5 * sigma * tau);
    const double s_half = std::sin(0.5 * sigma * tau);
    const double c0 = std::cos(m_w0 * tau);
    const double s0 = std::sin(m_w0 * tau);
    const double big_c = tau / sigma * s_half * sc;
    const double big_s = (s0 / m_w0 - tau * c_half * sc) / sigma;
    const double big_c_dot = (s0 + m_w * tau * c_half * sc) / sigma;
    const double dx = m_start.x - m_centre;
    State out;
    out.x =
        m_centre + dx * c0 + m_start.v / m_w0 * s0 + m_p_over_m * (m_sin0 * big_c + m_cos0 * big_s);
    out.v =
        -dx * m_w0 * s0 + m_start.v * c0 + m_p_over_m * (m_sin0 * big_c_dot + m_cos0 * m_w * big_c);
    return out;
  }

private:
  double m_w0, m_w, m_p_over_m, m_centre;
  State m_start;
  double m_sin0, m_cos0;
};

/// Brent's method (GSL) on [lo, hi] with f(lo) f(hi) < 0, to round-off.
template <class F> double bracketed_root(F& f, double lo, double hi, const char* what) {
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
    if (f(gsl_root_fsolver_root(solver.get())) == 0.0) return gsl_root_fsolver_root(solver.get());
    if (gsl_root_test_interval(a, b, 0.0, 4.0 * DBL_EPSILON) == GSL_SUCCESS)
      return gsl_root_fsolver_root(solver.get());
  }
  throw NumericalFailure(std::string(what) + ": Brent's root on [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "] did not converge (" + gsl_strerror(status) + ")");
}

struct Minimum {
  double t = 0.0;
  double value = 0.0;
};

/// Brent's minimizer (GSL) on [lo, hi] from a grid minimum at mid
/// (f(mid) < f(lo), f(hi)); stops early once the minimum is <= 0. Only the
/// minimum value matters (its sign): the search stops when the bracket is
/// below 1e-7 of the grid step or sqrt(eps) relative (a minimizer's abscissa
/// is no better than that; the value, quadratic there, is exact to O(eps)),
/// or when the best value has not decreased in 8 iterations (round-off).
template <class F> Minimum refine_minimum(F& f, double lo, double mid, double hi) {
  gsl_function fn{[](double t, void* p) { return (*static_cast<F*>(p))(t); }, &f};
  const std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> minimizer(
      gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent), &gsl_min_fminimizer_free);
  GslHandlerOff guard;
  int status = gsl_min_fminimizer_set(minimizer.get(), &fn, mid, lo, hi);
  double best = std::numeric_limits<double>::infinity();
  int stalled = 0;
  for (int i = 0; i < 200 && status == GSL_SUCCESS; ++i) {
    const Minimum m{gsl_min_fminimizer_x_minimum(minimizer.get()),
                    gsl_min_fminimizer_f_minimum(minimizer.get())};
    if (m.value <= 0.0) return m;
    stalled = m.value < best ? 0 : stalled + 1;
    best = std::min(best, m.value);
    const double a = gsl_min_fminimizer_x_lower(minimizer.get());
    const double b = gsl_min_fminimizer_x_upper(minimizer.get());
    if (stalled >= 8 ||
        gsl_min_test_interval(a, b, 1e-7 * (hi - lo), std::sqrt(DBL_EPSILON)) == GSL_SUCCESS)
      return m;
    status = gsl_min_fminimizer_iterate(minimizer.get());
  }
  throw NumericalFailure("slip end: Brent's minimizer on [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "] did not converge (" + gsl_strerror(status) + ")");
}

/// The first tau in (0, tau_max] where s x' changes sign on the arc, if any.
std::optional<double> slip_end(const SlipArc& arc, int s, double step, double tau_max) {
  auto q = [&](double tau) { return s * arc.at(tau).v; };
  double ta = 0.0;
  double qa = q(0.0);
  double tprev = 0.0;
  double qprev = std::numeric_limits<double>::quiet_NaN();
  while (ta < tau_max) {
    const double tb = std::min(ta + step, tau_max);
    const double qb = q(tb);
    if (qb == 0.0) return tb;
    if (qb < 0.0) {
      double lo = ta;
      if (qa <= 0.0) { // from rest at tau = 0: a point with s x' > 0 before tb
        bool found = false;
        for (int k = 1; k <= 60 && !found; ++k) {
          lo = ta + (tb - ta) * std::ldexp(1.0, -k);
          found = q(lo) > 0.0;
        }
        if (!found)
          throw NumericalFailure("slip end: the velocity does not leave 0 in the slip direction");
      }
      return bracketed_root(q, lo, tb, "slip end");
    }
    if (!std::isnan(qprev) && qa < qprev && qa < qb) { // a grid minimum of s x' > 0
      const Minimum m = refine_minimum(q, tprev, ta, tb);
      if (m.value == 0.0) return m.t;
      if (m.value < 0.0) return bracketed_root(q, tprev, m.t, "slip end");
    }
    tprev = ta;
    qprev = qa;
    ta = tb;
    qa = qb;
  }
  return std::nullopt;
}

/// The first time >= ts where g = P sin(w t + phi) - k xs crosses +mu N upwards
/// or -mu N downwards (analytic, asin); +infinity if never (touching included).
/// `released` receives the slip that follows.
double stick_end(const Oscillator& o, double ts, double xs, Motion& released) {
  const double p = o.force_amplitude;
  const double w = o.forcing_frequency;
  const double limit = friction_limit(o);
  double best = std::numeric_limits<double>::infinity();
  if (p == 0.0 || w == 0.0) return best;
  const double theta_s = w * ts + o.forcing_phase;
  // First theta >= theta_s congruent to base modulo 2 pi; a candidate within
  // round-off below theta_s is theta_s itself.
  auto first_after = [&](double base) {
    double cand = base + two_pi * std::floor((theta_s - base) / two_pi);
    if (theta_s - cand > 8.0 * DBL_EPSILON * (std::abs(theta_s) + two_pi)) cand += two_pi;
    return std::max(cand, theta_s);
  };
  const double r_up = (o.stiffness * xs + limit) / p;
  if (std::abs(r_up) < 1.0) { // g = +mu N upwards: sin rising, theta = asin(r)
    const double theta = first_after(std::asin(r_up));
    if (theta < best) {
      best = theta;
      released = Motion::slip_positive;
    }
  }
  const double r_down = (o.stiffness * xs - limit) / p;
  if (std::abs(r_down) < 1.0) { // g = -mu N downwards: sin falling, theta = pi - asin(r)
    const double theta = first_after(M_PI - std::asin(r_down));
    if (theta < best) {
      best = theta;
      released = Motion::slip_negative;
    }
  }
  if (std::isinf(best)) return best;
  return (best - o.forcing_phase) / w;
}

/// The motion of a mass at rest at x at time t, by the force balance.
Motion motion_at_rest(const Oscillator& o, double t, double x) {
  const double a = applied_force(o, t) - o.stiffness * x;
  const double limit = friction_limit(o);
  if (a > limit) return Motion::slip_positive;
  if (a < -limit) return Motion::slip_negative;
  return Motion::stick;
}

double sign(double value) {
  return value > 0.0 ? 1.0 : (value < 0.0 ? -1.0 : 0.0);
}

} // namespace

void validate(const Oscillator& o) {
  require(std::isfinite(o.mass) && o.mass > 0.0,
          "coulomb::Oscillator: mass must be finite and > 0");
  require(std::isfinite(o.stiffness) && o.stiffness > 0.0,
          "coulomb::Oscillator: stiffness must be finite and > 0");
  require(std::isfinite(o.friction_coefficient) && o.friction_coefficient >= 0.0,
          "coulomb::Oscillator: friction_coefficient must be finite and >= 0");
  require(std::isfinite(o.normal_force) && o.normal_force >= 0.0,
          "coulomb::Oscillator: normal_force must be finite and >= 0");
  require(std::isfinite(o.force_amplitude) && o.force_amplitude >= 0.0,
          "coulomb::Oscillator: force_amplitude must be finite and >= 0");
  require(std::isfinite(o.forcing_frequency) && o.forcing_frequency >= 0.0,
          "coulomb::Oscillator: forcing_frequency must be finite and >= 0");
  require(std::isfinite(o.forcing_phase), "coulomb::Oscillator: forcing_phase must be finite");
  require(std::isfinite(o.x0), "coulomb::Oscillator: x0 must be finite");
  require(std::isfinite(o.v0), "coulomb::Oscillator: v0 must be finite");
}

double friction_limit(const Oscillator& o) {
  return o.friction_coefficient * o.normal_force;
}
double natural_frequency(const Oscillator& o) {
  return std::sqrt(o.stiffness / o.mass);
}
double applied_force(const Oscillator& o, double t) {
  return o.force_amplitude * std::sin(o.forcing_frequency * t + o.forcing_phase);
}

const char* to_string(Motion motion) {
  switch (motion) {
  case Motion::stick:
    return "stick";
  case Motion::slip_positive:
    return "slip+";
  case Motion::slip_negative:
    return "slip-";
  }
  return "?";
}

int direction(Motion motion) {
  return motion == Motion::slip_positive ? 1 : (motion == Motion::slip_negative ? -1 : 0);
}

Transitions count_transitions(const std::vector<Segment>& segments) {
  Transitions out;
  for (std::size_t i = 1; i < segments.size(); ++i) {
    const Motion a = segments[i - 1].motion;
    const Motion b = segments[i].motion;
    if (a == b) continue;
    if (a == Motion::stick || b == Motion::stick)
      ++out.stick_slip;
    else
      ++out.reversals;
  }
  return out;
}

// ---------------------------------------------------------------- FreeVibration

FreeVibration::FreeVibration(const Oscillator& o)
    : m_o(o) {
  validate(o);
  require(o.force_amplitude == 0.0, "coulomb::FreeVibration: force_amplitude must be 0");
  require(friction_limit(o) > 0.0,
          "coulomb::FreeVibration: friction_coefficient * normal_force must be > 0");
  m_w0 = natural_frequency(o);
  m_d = friction_limit(o) / o.stiffness;
  const double half_period = M_PI / m_w0;

  // First turning point x_1 at t_1: x - c = A cos(w0 t - psi), A = |(x0 - c, v0/w0)|.
  double t1 = 0.0;
  double x1 = o.x0;
  if (o.v0 != 0.0) {
    const double s = sign(o.v0);
    const double c = -s * m_d;
    const double amplitude = std::hypot(o.x0 - c, o.v0 / m_w0);
    const double psi = std::atan2(o.v0 / m_w0, o.x0 - c); // in (0, pi) for s = +1, (-pi, 0) for -1
    t1 = (s > 0.0 ? psi : psi + M_PI) / m_w0;
    x1 = c + s * amplitude;
    m_segments.push_back(
        {0.0, t1, s > 0.0 ? Motion::slip_positive : Motion::slip_negative, o.x0, o.v0});
  }
  // Half-cycles after x_1: j = ceil((|x1| - d) / 2d) until k|x| <= mu N.
  const double excess = (std::abs(x1) - m_d) / (2.0 * m_d);
  require(excess <= max_half_cycles,
          "coulomb::FreeVibration: (k |x_1| - mu N) / (2 mu N) must be <= 1e7 half-cycles");
  const long n_half = excess > 0.0 ? static_cast<long>(std::ceil(excess)) : 0;
  const double s1 = x1 >= 0.0 ? 1.0 : -1.0;
  for (long j = 0; j <= n_half; ++j) {
    const double position = s1 * (j % 2 == 0 ? 1.0 : -1.0) * (std::abs(x1) - 2.0 * j * m_d);
    const double time = t1 + j * half_period;
    m_turning.push_back({time, position});
    if (j < n_half) {
      // From rest at x_n > d the mass slips towards -sign(x_n).
      const Motion motion = position > 0.0 ? Motion::slip_negative : Motion::slip_positive;
      m_segments.push_back({time, time + half_period, motion, position, 0.0});
    }
  }
  m_segments.push_back(
      {rest_time(), std::numeric_limits<double>::infinity(), Motion::stick, rest_position(), 0.0});
}

double FreeVibration::x(double t) const {
  const double t1 = m_turning.front().time;
  if (t < t1) {
    const double c = -sign(m_o.v0) * m_d;
    return c + (m_o.x0 - c) * std::cos(m_w0 * t) + m_o.v0 / m_w0 * std::sin(m_w0 * t);
  }
  if (t >= rest_time()) return rest_position();
  const std::size_t n =
      std::min(static_cast<std::size_t>((t - t1) * m_w0 / M_PI), m_turning.size() - 2);
  const TurningPoint& tp = m_turning[n];
  const double c = sign(tp.position) * m_d;
  return c + (tp.position - c) * std::cos(m_w0 * (t - tp.time));
}

double FreeVibration::v(double t) const {
  const double t1 = m_turning.front().time;
  if (t < t1) {
    const double c = -sign(m_o.v0) * m_d;
    return -(m_o.x0 - c) * m_w0 * std::sin(m_w0 * t) + m_o.v0 * std::cos(m_w0 * t);
  }
  if (t >= rest_time()) return 0.0;
  const std::size_t n =
      std::min(static_cast<std::size_t>((t - t1) * m_w0 / M_PI), m_turning.size() - 2);
  const TurningPoint& tp = m_turning[n];
  const double c = sign(tp.position) * m_d;
  return -(tp.position - c) * m_w0 * std::sin(m_w0 * (t - tp.time));
}

// ---------------------------------------------------------------- ForcedResponse

ForcedResponse::ForcedResponse(const Oscillator& o, double window_end)
    : m_o(o)
    , m_window_end(window_end) {
  validate(o);
  require(std::isfinite(window_end) && window_end > 0.0,
          "coulomb::ForcedResponse: window_end must be finite and > 0");
  const double step =
      two_pi / (samples_per_period * std::max(natural_frequency(o), o.forcing_frequency));
  double t = 0.0;
  State state{o.x0, o.v0};
  Motion motion = o.v0 > 0.0   ? Motion::slip_positive
                  : o.v0 < 0.0 ? Motion::slip_negative
                               : motion_at_rest(o, 0.0, o.x0);
  try {
    while (t < window_end) {
      if (m_segments.size() >= max_segments)
        throw NumericalFailure("more than 1e7 segments before window_end");
      if (motion == Motion::stick) {
        Motion released = Motion::stick;
        const double end = stick_end(o, t, state.x, released);
        m_segments.push_back({t, std::min(end, window_end), Motion::stick, state.x, 0.0});
        if (end >= window_end) break;
        t = end;
        state.v = 0.0;
        motion = released;
        continue;
      }
      const int s = direction(motion);
      const SlipArc arc(o, t, state, s);
      const std::optional<double> tau = slip_end(arc, s, step, window_end - t);
      if (!tau) {
        m_segments.push_back({t, window_end, motion, state.x, state.v});
        break;
      }
      m_segments.push_back({t, t + *tau, motion, state.x, state.v});
      state = {arc.at(*tau).x, 0.0};
      t += *tau;
      motion = motion_at_rest(o, t, state.x);
    }
  } catch (const NumericalFailure& e) {
    m_failure = "coulomb::ForcedResponse at t = " + std::to_string(t) + ": " + e.what();
  }
}

const Segment& ForcedResponse::segment_at(double t) const {
  if (m_segments.empty() || t < 0.0 || t > solved_until())
    throw std::invalid_argument("coulomb::ForcedResponse: time must lie in [0, solved_until()]");
  auto it = std::upper_bound(m_segments.begin(), m_segments.end(), t,
                             [](double value, const Segment& s) { return value < s.start; });
  return *(it - 1);
}

double ForcedResponse::x(double t) const {
  const Segment& seg = segment_at(t);
  if (seg.motion == Motion::stick) return seg.x_start;
  return SlipArc(m_o, seg.start, {seg.x_start, seg.v_start}, direction(seg.motion))
      .at(t - seg.start)
      .x;
}

double ForcedResponse::v(double t) const {
  const Segment& seg = segment_at(t);
  if (seg.motion == Motion::stick) return 0.0;
  return SlipArc(m_o, seg.start, {seg.x_start, seg.v_start}, direction(seg.motion))
      .at(t - seg.start)
      .v;
}

} // namespace rsi::coulomb
