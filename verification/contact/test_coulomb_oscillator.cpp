// Issue 12, verification point 5 (first half): exact solutions of the
// single-dof oscillator with Coulomb friction, stick and slip
// (coulomb_oscillator.hpp), checked against
// - hand arithmetic and the classical properties of free vibration with
//   Coulomb friction (the turning points fall by 2 mu N/k each half-cycle,
//   half-periods stay pi sqrt(m/k), the mass sticks at the first turning
//   point with k|x| <= mu N);
// - Den Hartog (1931)'s non-stop steady-state amplitude;
// - the frictionless harmonic oscillator (mu -> 0);
// - an independent GSL odeiv2 (rk8pd) integration with its own event
//   location (coulomb_oscillator_ode.hpp), within its error bound.
//
// Round-off tolerance of the closed forms (rounding()): each slip segment
// evaluates x and x' as sums of at most 8 terms, each bounded by the motion
// scale A = max|x| + max|x'|/w0 + mu N/k (+ P/k-sized forced terms, included
// in max|x|); each evaluation is off by <= 8 eps A, for x and x' alike, and
// a segment's end state seeds the next one (the exact flow does not amplify
// differences in the energy norm), so after n segments the error is
// <= 16 eps A (n + 1).

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "coulomb_oscillator.hpp"
#include "coulomb_oscillator_ode.hpp"

namespace rsi::coulomb {
namespace {

constexpr double eps = DBL_EPSILON;

/// m = 2 kg, k = 50 N/m (w0 = 5 rad/s), mu N = 0.2 x 10 = 2 N (mu N/k = 0.04 m).
Oscillator base() {
  Oscillator o;
  o.mass = 2.0;
  o.stiffness = 50.0;
  o.friction_coefficient = 0.2;
  o.normal_force = 10.0;
  return o;
}

std::vector<double> grid(double end, int n) {
  std::vector<double> t(n + 1);
  for (int i = 0; i <= n; ++i)
    t[i] = end * i / n;
  return t;
}

/// Motion scale A = max|x| + max|x'|/w0 + mu N/k over the samples.
double motion_scale(const Oscillator& o, const std::vector<double>& x,
                    const std::vector<double>& v) {
  double xm = 0.0;
  double vm = 0.0;
  for (double value : x)
    xm = std::max(xm, std::abs(value));
  for (double value : v)
    vm = std::max(vm, std::abs(value));
  return xm + vm / natural_frequency(o) + friction_limit(o) / o.stiffness;
}

/// 16 eps A (n + 1): the closed forms' round-off after n segments (header).
double rounding(double scale, std::size_t n_segments) {
  return 16.0 * eps * scale * static_cast<double>(n_segments + 1);
}

/// Acceleration just before a slip segment ends at rest at (t, x): (g - s mu N)/m.
double end_acceleration(const Oscillator& o, const Segment& s, double x_end) {
  return (applied_force(o, s.end) - o.stiffness * x_end - direction(s.motion) * friction_limit(o)) /
         o.mass;
}

// ------------------------------------------------------------ bad arguments

TEST(CoulombOscillator, BadArgumentsThrow) {
  auto expect_throw = [](Oscillator o, const char* name) {
    try {
      ForcedResponse r(o, 1.0);
      ADD_FAILURE() << name << " accepted";
    } catch (const std::invalid_argument& e) {
      std::printf("%s -> %s\n", name, e.what());
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  Oscillator o = base();
  o.mass = 0.0;
  expect_throw(o, "mass");
  o = base();
  o.stiffness = -1.0;
  expect_throw(o, "stiffness");
  o = base();
  o.friction_coefficient = -0.1;
  expect_throw(o, "friction_coefficient");
  o = base();
  o.normal_force = -1.0;
  expect_throw(o, "normal_force");
  o = base();
  o.force_amplitude = -1.0;
  expect_throw(o, "force_amplitude");
  o = base();
  o.forcing_frequency = -1.0;
  expect_throw(o, "forcing_frequency");
  o = base();
  o.forcing_phase = NAN;
  expect_throw(o, "forcing_phase");
  o = base();
  o.x0 = INFINITY;
  expect_throw(o, "x0");
  o = base();
  o.v0 = NAN;
  expect_throw(o, "v0");
  EXPECT_THROW(ForcedResponse(base(), 0.0), std::invalid_argument);
  EXPECT_THROW(OdeSolution(base(), 1.0, {0.5, 0.2}, {}), std::invalid_argument);
  EXPECT_THROW(OdeSolution(base(), 1.0, {2.0}, {}), std::invalid_argument);
  OdeTolerances bad;
  bad.eps_abs = 0.0;
  EXPECT_THROW(OdeSolution(base(), 1.0, {}, bad), std::invalid_argument);
  o = base();
  o.force_amplitude = 1.0;
  EXPECT_THROW(FreeVibration{o}, std::invalid_argument);
  o = base();
  o.friction_coefficient = 0.0;
  EXPECT_THROW(FreeVibration{o}, std::invalid_argument);
  const ForcedResponse r(base(), 1.0);
  EXPECT_THROW(r.x(1.5), std::invalid_argument);
}

// ------------------------------------------------------------ free vibration

// Hand arithmetic: d = mu N/k = 0.04, from x0 = 0.21 at rest the turning
// points reflect about +-d: 0.21 -> -(0.21 - 0.08) = -0.13 -> 0.05 -> 2(0.04)
// - 0.05 = 0.03, where k|x| = 1.5 <= mu N = 2: rest at 3 pi/w0 = 3 pi/5.
TEST(CoulombFree, HandComputedTurningPoints) {
  Oscillator o = base();
  o.x0 = 0.21;
  const FreeVibration f(o);
  const std::vector<double> expected = {0.21, -0.13, 0.05, 0.03};
  ASSERT_EQ(f.turning_points().size(), expected.size());
  // |x_n| = |x1| - 2 n d: 3 operations on numbers <= 0.21, 4 eps 0.21 each.
  const double tol = 4.0 * eps * 0.21 * 4;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const TurningPoint& tp = f.turning_points()[i];
    std::printf("turning point %zu: t = %.15f x = %.15f (hand %.2f)\n", i, tp.time, tp.position,
                expected[i]);
    EXPECT_NEAR(tp.position, expected[i], tol);
    EXPECT_NEAR(tp.time, i * M_PI / 5.0, 4.0 * eps * 3.0 * M_PI / 5.0); // t_n = n pi/w0
  }
  EXPECT_NEAR(f.rest_time(), 3.0 * M_PI / 5.0, 4.0 * eps * 3.0 * M_PI / 5.0);
  // three slips (-, +, -), then the stick: 2 reversals, 1 slip -> stick.
  EXPECT_EQ(f.transitions().reversals, 2);
  EXPECT_EQ(f.transitions().stick_slip, 1);
  // A mass released inside the stick band never moves (k|x0| = 1.5 <= 2).
  o.x0 = 0.03;
  const FreeVibration still(o);
  EXPECT_EQ(still.turning_points().size(), 1u);
  EXPECT_EQ(still.rest_time(), 0.0);
  EXPECT_EQ(still.transitions().stick_slip + still.transitions().reversals, 0);
}

// Hand arithmetic at the edge of the stick band: from x0 = -0.2002 at rest
// the turning points are -0.2002, 0.1202, -0.0402 (k|x| = 2.01 > mu N = 2:
// the mass must reverse), then 2(-0.04) + 0.0402 = -0.0398 (k|x| = 1.99:
// rest). The event solver (force balance at each stop) must agree.
TEST(CoulombFree, ReversesJustOutsideStickBand) {
  Oscillator o = base();
  o.x0 = -0.2002;
  const ForcedResponse r(o, 2.0);
  ASSERT_TRUE(r.ok()) << r.failure();
  const std::vector<double> expected = {-0.2002, 0.1202, -0.0402, -0.0398};
  const std::vector<Motion> motions = {Motion::slip_positive, Motion::slip_negative,
                                       Motion::slip_positive, Motion::stick};
  ASSERT_EQ(r.segments().size(), expected.size());
  // Each stop is a reflection about +-d (2 operations on numbers <= 0.21,
  // 2 eps 0.21 each) plus the slip closed form's round-off (16 eps A per segment).
  const double tol = rounding(0.21 + 0.04, expected.size()) + 4.0 * eps * 0.21 * 4;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Segment& s = r.segments()[i];
    std::printf("segment %zu: %s from t = %.15f at x = %.15f (hand %.4f)\n", i, to_string(s.motion),
                s.start, s.x_start, expected[i]);
    EXPECT_EQ(s.motion, motions[i]);
    EXPECT_NEAR(s.x_start, expected[i], tol);
  }
}

/// The free-vibration properties on any segment list ending at rest:
/// per slip segment between turning points, the amplitude about its centre
/// c = -s d is kept (|x_end - c| = |x_start - c|), the next half-cycle's
/// amplitude is 2d smaller (4d per cycle), each half-cycle lasts pi/w0, and
/// the mass sticks at the first turning point with k|x| <= mu N.
void check_free_properties(const Oscillator& o, const std::vector<Segment>& segs, double tol_x,
                           double tol_t_per_unit_speed, const char* who) {
  const double d = friction_limit(o) / o.stiffness;
  const double w0 = natural_frequency(o);
  double worst_amp = 0.0;
  double worst_drop = 0.0;
  double worst_period = 0.0;
  double prev_amplitude = NAN;
  std::size_t n_half = 0;
  for (std::size_t i = 0; i + 1 < segs.size(); ++i) {
    const Segment& s = segs[i];
    ASSERT_NE(s.motion, Motion::stick) << who << ": stick before the final rest at " << s.start;
    const double x_end = segs[i + 1].x_start;
    const double c = -direction(s.motion) * d;
    const bool from_rest = s.v_start == 0.0;
    const bool last = segs[i + 1].motion == Motion::stick;
    // Sticks for good exactly at the first turning point with k|x| <= mu N.
    if (last)
      EXPECT_LE(std::abs(x_end), d + tol_x) << who;
    else
      EXPECT_GT(std::abs(x_end), d - tol_x) << who;
    if (!from_rest) continue; // the first slip from v0 != 0 starts off a turning point
    ++n_half;
    const double amplitude = std::abs(s.x_start - c);
    worst_amp = std::max(worst_amp, std::abs(std::abs(x_end - c) - amplitude));
    if (!std::isnan(prev_amplitude))
      worst_drop = std::max(worst_drop, std::abs(prev_amplitude - 2.0 * d - amplitude));
    prev_amplitude = amplitude;
    // Time error of an event: the velocity error over |x''| = w0^2 amplitude.
    const double tol_t = 2.0 * tol_t_per_unit_speed / (w0 * w0 * amplitude);
    worst_period = std::max(worst_period, std::abs(s.end - s.start - M_PI / w0) / tol_t);
  }
  EXPECT_EQ(segs.back().motion, Motion::stick) << who;
  std::printf("%s: %zu half-cycles; max | |x_end - c| - |x_start - c| | = %.3e, "
              "max |A_n - 2d - A_n+1| = %.3e (tol %.3e); max |half-period - pi/w0| / tol = %.3f\n",
              who, n_half, worst_amp, worst_drop, 2.0 * tol_x, worst_period);
  EXPECT_GE(n_half, 3u) << who; // the cases below have several half-cycles
  EXPECT_LE(worst_amp, 2.0 * tol_x) << who;
  EXPECT_LE(worst_drop, 2.0 * tol_x) << who;
  EXPECT_LE(worst_period, 1.0) << who;
}

Oscillator free_case() {
  Oscillator o = base();
  o.x0 = 0.3;
  o.v0 = -1.2; // A ~ 0.38: 4 to 5 half-cycles before rest
  return o;
}

// The event solver (root finding on x', force balance at rest) with P = 0
// reproduces the closed form's turning points, rest and counts.
TEST(CoulombFree, EventSolverMatchesClosedForm) {
  const Oscillator o = free_case();
  const FreeVibration f(o);
  const double window = f.rest_time() + 1.0;
  const ForcedResponse r(o, window);
  ASSERT_TRUE(r.ok()) << r.failure();
  const std::vector<double> t = grid(window, 2000);
  std::vector<double> xf, vf;
  for (double ti : t) {
    xf.push_back(f.x(ti));
    vf.push_back(f.v(ti));
  }
  const double scale = motion_scale(o, xf, vf);
  const double w0 = natural_frequency(o);
  const double tol_x = rounding(scale, f.segments().size());
  // Time error: the velocity's round-off (tol_x w0) over |x''| at the event.
  ASSERT_EQ(r.segments().size(), f.segments().size());
  double worst_t = 0.0;
  for (std::size_t i = 0; i + 1 < f.segments().size(); ++i) {
    const Segment& a = f.segments()[i];
    const Segment& b = r.segments()[i];
    EXPECT_EQ(a.motion, b.motion) << "segment " << i;
    const double acc = std::abs(end_acceleration(o, a, f.segments()[i + 1].x_start));
    const double tol_t = tol_x * w0 / acc + 4.0 * eps * a.end;
    worst_t = std::max(worst_t, std::abs(a.end - b.end) / tol_t);
    EXPECT_NEAR(f.segments()[i + 1].x_start, r.segments()[i + 1].x_start, 2.0 * tol_x);
  }
  double dx = 0.0, dv = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    dx = std::max(dx, std::abs(xf[i] - r.x(t[i])));
    dv = std::max(dv, std::abs(vf[i] - r.v(t[i])));
  }
  std::printf("free, closed form vs event solver: %zu segments, max |dx| = %.3e, max |dv| = "
              "%.3e, tol_x = %.3e, max |d t_event| / tol = %.3f\n",
              f.segments().size(), dx, dv, 2.0 * tol_x, worst_t);
  EXPECT_LE(worst_t, 1.0);
  EXPECT_LE(dx, 2.0 * tol_x);
  EXPECT_LE(dv, 2.0 * tol_x * w0);
  EXPECT_EQ(r.transitions().reversals, f.transitions().reversals);
  EXPECT_EQ(r.transitions().stick_slip, f.transitions().stick_slip);
  check_free_properties(o, r.segments(), tol_x, tol_x * w0, "event solver");
}

// The same properties on the rk8pd integration, whose tolerances follow
// from its error bound (coulomb_oscillator_ode.hpp).
TEST(CoulombFree, OdePropertiesAndMatch) {
  const Oscillator o = free_case();
  const FreeVibration f(o);
  const double window = f.rest_time() + 1.0;
  const std::vector<double> t = grid(window, 2000);
  const OdeSolution ode(o, window, t, {});
  ASSERT_TRUE(ode.ok()) << ode.failure();
  const double tol_x = ode.error_bound() / std::sqrt(o.stiffness);
  const double tol_v = ode.error_bound() / std::sqrt(o.mass);
  double dx = 0.0, dv = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    dx = std::max(dx, std::abs(f.x(t[i]) - ode.x()[i]));
    dv = std::max(dv, std::abs(f.v(t[i]) - ode.v()[i]));
  }
  std::printf("free, closed form vs rk8pd: %ld steps, max |dx| = %.3e (tol %.3e), max |dv| = "
              "%.3e (tol %.3e)\n",
              ode.n_steps(), dx, tol_x, dv, tol_v);
  EXPECT_LE(dx, tol_x);
  EXPECT_LE(dv, tol_v);
  EXPECT_EQ(ode.transitions().reversals, f.transitions().reversals);
  EXPECT_EQ(ode.transitions().stick_slip, f.transitions().stick_slip);
  check_free_properties(o, ode.segments(), tol_x, tol_v, "rk8pd");
}

// ------------------------------------------------------------ forced response

// A mass at rest at x = 0 under F = P sin(w t), P = 2 mu N: g = F sticks
// until sin(w t) = mu N / P = 1/2, t = pi/(6 w) (force balance), then slips +.
TEST(CoulombForced, StickFromRestReleasesWhereForceReachesMuN) {
  Oscillator o = base();
  o.force_amplitude = 2.0 * friction_limit(o);
  o.forcing_frequency = 2.0;
  const ForcedResponse r(o, 3.0);
  ASSERT_TRUE(r.ok()) << r.failure();
  ASSERT_GE(r.segments().size(), 2u);
  const double expected = M_PI / 6.0 / 2.0;
  std::printf("release at %.17f, pi/(6 w) = %.17f\n", r.segments()[0].end, expected);
  EXPECT_EQ(r.segments()[0].motion, Motion::stick);
  EXPECT_NEAR(r.segments()[0].end, expected, 4.0 * eps * expected); // asin, / w: a few ulps
  EXPECT_EQ(r.segments()[1].motion, Motion::slip_positive);
}

// P < mu N from rest at x = 0: |g| <= P < mu N, the mass never moves.
TEST(CoulombForced, NeverSlipsBelowFrictionLimit) {
  Oscillator o = base();
  o.force_amplitude = 0.9 * friction_limit(o);
  o.forcing_frequency = 3.0;
  o.forcing_phase = 0.4;
  const std::vector<double> t = grid(20.0, 400);
  const ForcedResponse r(o, 20.0);
  const OdeSolution ode(o, 20.0, t, {});
  ASSERT_TRUE(r.ok() && ode.ok()) << r.failure() << ode.failure();
  double worst = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i)
    worst = std::max({worst, std::abs(r.x(t[i])), std::abs(r.v(t[i])), std::abs(ode.x()[i])});
  std::printf("P = 0.9 mu N: %zu segment(s), max |x|, |x'| = %.3e\n", r.segments().size(), worst);
  EXPECT_EQ(r.segments().size(), 1u);
  EXPECT_EQ(ode.segments().size(), 1u);
  EXPECT_EQ(worst, 0.0); // a stick holds x_s exactly
}

// Grazing (decision, coulomb_oscillator.hpp): P = mu N exactly, x = 0, the
// applied force touches mu N tangentially at its maxima: the mass stays stuck.
TEST(CoulombForced, GrazingForceStaysStuck) {
  Oscillator o = base();
  o.force_amplitude = friction_limit(o);
  o.forcing_frequency = 3.0;
  const ForcedResponse r(o, 20.0);
  ASSERT_TRUE(r.ok()) << r.failure();
  std::printf("P = mu N: %zu segment(s), first %s\n", r.segments().size(),
              to_string(r.segments()[0].motion));
  EXPECT_EQ(r.segments().size(), 1u);
  EXPECT_EQ(r.segments()[0].motion, Motion::stick);
}

// Den Hartog (1931), continuous motion with two stops per cycle: with
// beta = w/w0, V = 1/(1 - beta^2), U = sin(pi/beta)/(beta (1 + cos(pi/beta))),
// r = mu N/P, the amplitude is X0 = (P/k) sqrt(V^2 - r^2 U^2), and (from the
// same derivation) sin(phi) = -X0/X, cos(phi) = -d U/X with X = (P/k) V,
// d = mu N/k, for a response starting at x = -X0 at rest at t = 0. The
// closed form must then stop exactly at t = n pi/w, at x = +-X0 alternately.
TEST(CoulombForced, DenHartogNonStopAmplitude) {
  for (double beta : {0.8, 2.0}) {
    Oscillator o = base();
    o.force_amplitude = 10.0;
    o.forcing_frequency = beta * natural_frequency(o);
    const double big_v = 1.0 / (1.0 - beta * beta);
    const double big_u = std::sin(M_PI / beta) / (beta * (1.0 + std::cos(M_PI / beta)));
    const double r_ratio = friction_limit(o) / o.force_amplitude;
    const double x_static = o.force_amplitude / o.stiffness;
    const double amplitude =
        x_static * std::sqrt(big_v * big_v - r_ratio * r_ratio * big_u * big_u);
    const double big_x = x_static * big_v;
    const double d = friction_limit(o) / o.stiffness;
    o.forcing_phase = std::atan2(-amplitude / big_x, -d * big_u / big_x);
    o.x0 = -amplitude;
    const double half = M_PI / o.forcing_frequency;
    const int n_half = 6;
    const ForcedResponse r(o, n_half * half);
    ASSERT_TRUE(r.ok()) << r.failure();
    ASSERT_EQ(r.segments().size(), static_cast<std::size_t>(n_half)) << "beta " << beta;
    // A = X0 + |X| + d: the amplitudes of the homogeneous, forced and friction parts.
    const double scale = amplitude + std::abs(big_x) + d;
    const double tol_x = rounding(scale, r.segments().size());
    double worst_x = 0.0;
    double worst_t = 0.0;
    for (int i = 0; i < n_half; ++i) {
      const Segment& s = r.segments()[i];
      EXPECT_EQ(s.motion, i % 2 == 0 ? Motion::slip_positive : Motion::slip_negative);
      const double x_end = i + 1 < n_half ? r.segments()[i + 1].x_start : r.x(s.end);
      const double expected = i % 2 == 0 ? amplitude : -amplitude;
      worst_x = std::max(worst_x, std::abs(x_end - expected));
      if (i + 1 < n_half) {
        // Event time: velocity round-off (tol_x w) over |x''| at the stop.
        const double acc = std::abs(end_acceleration(o, s, x_end));
        const double tol_t =
            tol_x * (natural_frequency(o) + o.forcing_frequency) / acc + 4.0 * eps * s.end;
        worst_t = std::max(worst_t, std::abs(s.end - (i + 1) * half) / tol_t);
      }
    }
    std::printf("Den Hartog beta = %.1f: X0 = %.15f, max |x_stop -+ X0| = %.3e (tol %.3e), "
                "max |t_stop - n pi/w| / tol = %.3f\n",
                beta, amplitude, worst_x, 2.0 * tol_x, worst_t);
    EXPECT_LE(worst_x, 2.0 * tol_x);
    EXPECT_LE(worst_t, 1.0);
  }
}

// mu -> 0: the frictionless oscillator x_h = A cos w0 t + B sin w0 t + X
// sin(w t + phi), X = P/(k - m w^2). The friction force f, |f| <= mu N, makes
// e = x - x_h solve m e'' + k e = f from rest, so by Duhamel
// |e(t)| <= mu N t / (m w0); with mu = 0 only round-off remains.
TEST(CoulombForced, FrictionlessLimit) {
  Oscillator o = base();
  o.force_amplitude = 3.0;
  o.forcing_frequency = 4.0;
  o.forcing_phase = 0.7;
  o.x0 = 0.05;
  o.v0 = 0.3;
  const double window = 10.0;
  const double w0 = natural_frequency(o);
  const double w = o.forcing_frequency;
  const double big_x = o.force_amplitude / (o.stiffness - o.mass * w * w);
  const double a = o.x0 - big_x * std::sin(o.forcing_phase);
  const double b = (o.v0 - big_x * w * std::cos(o.forcing_phase)) / w0;
  auto x_h = [&](double t) {
    return a * std::cos(w0 * t) + b * std::sin(w0 * t) + big_x * std::sin(w * t + o.forcing_phase);
  };
  const std::vector<double> t = grid(window, 1000);
  for (double limit : {0.0, 3e-2, 3e-3, 3e-4}) {
    o.friction_coefficient = limit / o.normal_force;
    const ForcedResponse r(o, window);
    ASSERT_TRUE(r.ok()) << r.failure();
    double worst = 0.0;
    double bound_ratio = 0.0;
    std::vector<double> xs, vs;
    for (double ti : t) {
      const double e = std::abs(r.x(ti) - x_h(ti));
      worst = std::max(worst, e);
      xs.push_back(r.x(ti));
      vs.push_back(r.v(ti));
      if (ti > 0.0) bound_ratio = std::max(bound_ratio, e / (limit * ti / (o.mass * w0)));
    }
    const double round_off =
        rounding(motion_scale(o, xs, vs) + std::abs(big_x), r.segments().size());
    std::printf("mu N = %.0e: %zu segments, max |x - x_h| = %.3e, max |e| / (mu N t/(m w0)) = "
                "%.3f, round-off tol %.3e\n",
                limit, r.segments().size(), worst, limit > 0.0 ? bound_ratio : 0.0, round_off);
    if (limit == 0.0)
      EXPECT_LE(worst, round_off);
    else
      EXPECT_LE(worst, limit * window / (o.mass * w0) + round_off);
  }
}

// Exact resonance w = w0 without friction: the textbook solution
// x = x0 cos w0 t + B sin w0 t - P t cos(w0 t + phi)/(2 m w0),
// B = (v0 + P cos(phi)/(2 m w0))/w0, against the closed form's sinc
// formulation of C and S at w = w0 (coulomb_oscillator.cpp).
TEST(CoulombForced, ResonantFrictionless) {
  Oscillator o = base();
  o.friction_coefficient = 0.0;
  o.force_amplitude = 3.0;
  o.forcing_frequency = natural_frequency(o);
  o.forcing_phase = 0.7;
  o.x0 = 0.05;
  o.v0 = 0.3;
  const double w0 = natural_frequency(o);
  const double p = o.force_amplitude;
  const double b = (o.v0 + p * std::cos(o.forcing_phase) / (2.0 * o.mass * w0)) / w0;
  auto x_h = [&](double t) {
    return o.x0 * std::cos(w0 * t) + b * std::sin(w0 * t) -
           p * t * std::cos(w0 * t + o.forcing_phase) / (2.0 * o.mass * w0);
  };
  const double window = 10.0;
  const ForcedResponse r(o, window);
  ASSERT_TRUE(r.ok()) << r.failure();
  const std::vector<double> t = grid(window, 1000);
  std::vector<double> xs, vs;
  double worst = 0.0;
  for (double ti : t) {
    xs.push_back(r.x(ti));
    vs.push_back(r.v(ti));
    worst = std::max(worst, std::abs(xs.back() - x_h(ti)));
  }
  const double tol = rounding(motion_scale(o, xs, vs), r.segments().size());
  std::printf("resonance w = w0, mu = 0: %zu segments, max |x - x_h| = %.3e (tol %.3e), "
              "max |x| = %.3f\n",
              r.segments().size(), worst, tol, *std::max_element(xs.begin(), xs.end()));
  EXPECT_LE(worst, tol);
}

// ------------------------------------------------------------ against rk8pd

struct OdeCase {
  const char* name;
  double force_amplitude;
  double forcing_frequency;
  double forcing_phase;
  double x0;
  double v0;
  double window;
};

void PrintTo(const OdeCase& c, std::ostream* os) {
  *os << c.name;
}

class CoulombVsOde : public ::testing::TestWithParam<OdeCase> {};

// Segments (kinds, count, event times), positions and velocities of the
// closed form against the rk8pd integration, within its error bound
// (coulomb_oscillator_ode.hpp): |dx| <= E/sqrt(k), |dv| <= E/sqrt(m);
// slip-end times within (E/sqrt(m))/|x''|, stick-end times within
// k (E/sqrt(k))/|g'|, plus the closed form's round-off.
TEST_P(CoulombVsOde, Matches) {
  const OdeCase& c = GetParam();
  Oscillator o = base();
  o.force_amplitude = c.force_amplitude;
  o.forcing_frequency = c.forcing_frequency;
  o.forcing_phase = c.forcing_phase;
  o.x0 = c.x0;
  o.v0 = c.v0;
  const std::vector<double> t = grid(c.window, 4000);
  const ForcedResponse r(o, c.window);
  const OdeSolution ode(o, c.window, t, {});
  ASSERT_TRUE(r.ok()) << r.failure();
  ASSERT_TRUE(ode.ok()) << ode.failure();
  std::vector<double> xr, vr;
  for (double ti : t) {
    xr.push_back(r.x(ti));
    vr.push_back(r.v(ti));
  }
  const double round_off = rounding(motion_scale(o, xr, vr), r.segments().size());
  const double w0 = natural_frequency(o);
  const double err_x = ode.error_bound() / std::sqrt(o.stiffness) + round_off;
  const double err_v = ode.error_bound() / std::sqrt(o.mass) + round_off * w0;
  double dx = 0.0, dv = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    dx = std::max(dx, std::abs(xr[i] - ode.x()[i]));
    dv = std::max(dv, std::abs(vr[i] - ode.v()[i]));
  }
  const std::vector<Segment>& a = r.segments();
  const std::vector<Segment>& b = ode.segments();
  std::size_t n_stick = 0;
  for (const Segment& s : a)
    n_stick += s.motion == Motion::stick;
  ASSERT_EQ(a.size(), b.size()) << c.name;
  double worst_t = 0.0;
  double dt = 0.0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    EXPECT_EQ(a[i].motion, b[i].motion) << c.name << " segment " << i;
    double tol_t = 0.0;
    if (a[i].motion == Motion::stick) {
      const double slope = std::abs(o.force_amplitude * o.forcing_frequency *
                                    std::cos(o.forcing_frequency * a[i].end + o.forcing_phase));
      tol_t = o.stiffness * err_x / slope;
    } else {
      tol_t = err_v / std::abs(end_acceleration(o, a[i], a[i + 1].x_start));
    }
    tol_t += 4.0 * eps * a[i].end;
    dt = std::max(dt, std::abs(a[i].end - b[i].end));
    worst_t = std::max(worst_t, std::abs(a[i].end - b[i].end) / tol_t);
  }
  EXPECT_EQ(a.back().motion, b.back().motion) << c.name;
  std::printf("%s: %zu segments (%zu sticks), transitions stick/slip %d, reversals %d; rk8pd %ld "
              "steps, bound E = %.3e\n  max |dx| = %.3e (tol %.3e), max |dv| = %.3e (tol %.3e), "
              "max |dt_event| = %.3e, max |dt_event| / tol = %.3f\n",
              c.name, a.size(), n_stick, r.transitions().stick_slip, r.transitions().reversals,
              ode.n_steps(), ode.error_bound(), dx, err_x, dv, err_v, dt, worst_t);
  EXPECT_LE(dx, err_x);
  EXPECT_LE(dv, err_v);
  EXPECT_LE(worst_t, 1.0);
  EXPECT_EQ(r.transitions().stick_slip, ode.transitions().stick_slip);
  EXPECT_EQ(r.transitions().reversals, ode.transitions().reversals);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CoulombVsOde,
    ::testing::Values(
        // w = w0/10, P = 3 mu N: the mass follows the force with long sticks.
        OdeCase{"long_sticks", 6.0, 0.5, 0.0, 0.0, 0.0, 4.0 * 2.0 * M_PI / 0.5},
        // below resonance from rest: stick from t = 0, then stick-slip.
        OdeCase{"below_resonance", 6.0, 4.0, 0.0, 0.0, 0.0, 10.0},
        // w = w0 with P = 2.4 > mu N = 2 > pi P/4 = 1.88 (Den Hartog's bounded resonance).
        OdeCase{"resonance", 2.4, 5.0, 0.3, 0.0, 0.0, 20.0},
        // above resonance, started moving.
        OdeCase{"above_resonance", 10.0, 11.0, 0.3, 0.1, -0.5, 10.0},
        // P = 1.05 mu N: short slips near the force maxima.
        OdeCase{"near_grazing", 2.1, 2.0, 0.0, 0.0, 0.0, 10.0},
        // free vibration to rest, then the final stick.
        OdeCase{"free", 0.0, 0.0, 0.0, 0.3, -1.2, 5.0}),
    [](const ::testing::TestParamInfo<OdeCase>& info) { return std::string(info.param.name); });

} // namespace
} // namespace rsi::coulomb
