#pragma once
// Exact solutions of the single-dof oscillator with Coulomb friction, with
// stick and slip (issue 12, verification point 5): oracles for the explicit
// integrators once their contact laws have a stick state.
//
// Equation (SI units):
//
//     m x'' + k x = P sin(w t + phi) + f(t),      |f| <= mu N,
//
// static and kinetic coefficients equal (mu). Write F(t) = P sin(w t + phi)
// for the applied force, g(t) = F(t) - k x for the force on the mass
// without friction, d = mu N / k for the friction offset, w0 = sqrt(k/m).
//
// - Slip, x' != 0 with direction s = sign(x'): f = -s mu N. The slip segment
//   from (t0, x0, v0) is the closed form of the linear ODE with the constant
//   force -s mu N, centre c = -s d, tau = t - t0, theta0 = w t0 + phi:
//       x = c + (x0 - c) cos(w0 tau) + (v0/w0) sin(w0 tau)
//           + (P/m) [sin(theta0) C(tau) + cos(theta0) S(tau)],
//   C and S the zero-initial-condition responses of y'' + w0^2 y to
//   cos(w tau) and sin(w tau), written with sinc((w0 - w) tau / 2) so that
//   they hold uniformly, resonance w = w0 included (coulomb_oscillator.cpp).
//   The segment ends at the first time x' changes sign.
// - Stick, x' = 0 over an interval at x_s: f = -g(t), which holds while
//   |g(t)| = |F(t) - k x_s| <= mu N. The stick ends where g crosses +mu N
//   upwards or -mu N downwards; the time is found analytically
//   (w t + phi = asin((k x_s +- mu N)/P) modulo 2 pi).
// - Event logic at a time t_e where the mass is at rest at x_e (t = 0 with
//   v0 = 0, or the end of a slip segment): a = g(t_e) = F(t_e) - k x_e;
//   a > mu N: slip+, a < -mu N: slip-, |a| <= mu N: stick (the friction
//   balances a). At t = 0 with v0 != 0 the mass slips in the direction of v0.
//   At the end of a stick it slips in the direction of g (g = +-mu N there).
// - Grazing (decisions of this file): a stick ends only where |g| CROSSES
//   mu N. Where |g| touches mu N tangentially (|k x_s +- mu N| = P exactly, a
//   maximum of |g| equal to mu N) the mass stays stuck: friction balances
//   g there with |f| = mu N, and slipping would be reversed at once. Likewise
//   a slip segment ends only where x' changes sign: a velocity that touches 0
//   without changing sign (there |a| = mu N exactly and the mass would
//   restart in the same direction at once) is not an event. The slip-end
//   search samples s x' on a grid of 64 points per shortest period
//   (2 pi / max(w0, w)) and refines every grid minimum of s x' with GSL's
//   Brent minimizer, so that a pair of sign changes closer than the grid
//   spacing is found unless two minima of s x' lie within one grid step.
//
// Mapping to a mass pressed on a rigid plane (the lead's integrator runs):
// one node of mass m, pressed against a rigid plane by a constant normal
// force N (for example a constant load -N along the plane normal n, so that
// lambda_n = N at equilibrium); x is its displacement along a tangent t of
// the plane, k a spring (or a boundary stiffness) along t tied to ground,
// P sin(w t + phi) a load along t, the plane at rest. Friction acts along t
// only: f = lambda_t, |lambda_t| <= mu lambda_n = mu N. The normal motion
// is static (gap 0, lambda_n = N exactly) and does not couple to x. Slip+
// is sliding along +t (lambda_t = -mu N), stick is a zero tangential
// increment. For lambda_n = N from the first step, start the node at gap 0
// with zero normal velocity and the normal load applied from t = 0 (an
// initial normal impact would make lambda_n differ from N). In 3D, put the
// spring and P along one tangent t1 and nothing along t2: the exact slip
// direction is then +-t1, so the 3D law's slip direction (in the tangent
// plane) is checked as well; the lead's x is the node's t1 displacement
// relative to the (fixed) plane. Counts: stick_slip counts stick <-> slip changes, reversals
// counts slip+ <-> slip- changes (summary.json's stick_slip_transitions and
// sliding_reversals).
//
// Error channels: bad parameters throw std::invalid_argument("Where:
// what, allowed range"); numerical trouble (a bracket that cannot be made,
// a GSL solver that does not converge) is a status: ok() false, failure()
// says what and where, and the solution is valid up to solved_until().

#include <string>
#include <vector>

namespace rsi::coulomb {

/// Parameters and initial state of m x'' + k x = P sin(w t + phi) + f.
struct Oscillator {
  double mass = 1.0;                 ///< m > 0 [kg]
  double stiffness = 1.0;            ///< k > 0 [N/m]
  double friction_coefficient = 0.0; ///< mu >= 0, static = kinetic [-]
  double normal_force = 0.0;         ///< N >= 0 [N]
  double force_amplitude = 0.0;      ///< P >= 0 [N]
  double forcing_frequency = 0.0;    ///< w >= 0 [rad/s]
  double forcing_phase = 0.0;        ///< phi, finite [rad]
  double x0 = 0.0;                   ///< x(0), finite [m]
  double v0 = 0.0;                   ///< x'(0), finite [m/s]
};

/// Throws std::invalid_argument naming the first parameter out of range.
void validate(const Oscillator& oscillator);
/// mu N [N].
double friction_limit(const Oscillator& oscillator);
/// w0 = sqrt(k/m) [rad/s].
double natural_frequency(const Oscillator& oscillator);
/// F(t) = P sin(w t + phi) [N].
double applied_force(const Oscillator& oscillator, double time);

enum class Motion { stick, slip_positive, slip_negative };
const char* to_string(Motion motion);
/// +1 for slip+, -1 for slip-, 0 for stick.
int direction(Motion motion);

/// One piece of the solution: [start, end], its motion and its initial state.
struct Segment {
  double start = 0.0;
  double end = 0.0;
  Motion motion = Motion::stick;
  double x_start = 0.0;
  double v_start = 0.0;
};

/// Changes of motion between consecutive segments.
struct Transitions {
  int stick_slip = 0; ///< stick -> slip or slip -> stick
  int reversals = 0;  ///< slip+ -> slip- or slip- -> slip+
};
Transitions count_transitions(const std::vector<Segment>& segments);

/// A turning point: the mass at rest at the end of a slip segment.
struct TurningPoint {
  double time = 0.0;
  double position = 0.0;
};

/// Free vibration (P = 0) in closed form. From the first turning point x_1
/// on, each half-cycle of length pi/w0 reflects the position about the
/// slip centre c = sign(x_n) d: x_{n+1} = 2 c - x_n (|x_{n+1}| = |x_n| - 2d while
/// it slips on), until the first turning point with k |x_n| <= mu N, where it sticks
/// for good. Before x_1 (v0 != 0) the slip is the closed form with
/// s = sign(v0). Requires P = 0 and mu N > 0 (the motion then stops after
/// finitely many half-cycles, at most 1e7 of them).
class FreeVibration {
public:
  explicit FreeVibration(const Oscillator& oscillator);

  double x(double time) const;
  double v(double time) const;
  /// The turning points in time order, the last one the final rest.
  const std::vector<TurningPoint>& turning_points() const { return m_turning; }
  double rest_time() const { return m_turning.back().time; }
  double rest_position() const { return m_turning.back().position; }
  /// Segments over [0, rest_time()], then the final stick up to +infinity.
  const std::vector<Segment>& segments() const { return m_segments; }
  Transitions transitions() const { return count_transitions(m_segments); }

private:
  Oscillator m_o;
  double m_w0 = 0.0;
  double m_d = 0.0; ///< mu N / k
  std::vector<TurningPoint> m_turning;
  std::vector<Segment> m_segments;
};

/// The forced response (Den Hartog 1931 without viscous damping), event by
/// event over [0, window_end], as described at the top of this file.
class ForcedResponse {
public:
  /// window_end: T > 0, finite.
  ForcedResponse(const Oscillator& oscillator, double window_end);

  /// x and x' at 0 <= time <= solved_until().
  double x(double time) const;
  double v(double time) const;
  const std::vector<Segment>& segments() const { return m_segments; }
  Transitions transitions() const { return count_transitions(m_segments); }
  bool ok() const { return m_failure.empty(); }
  const std::string& failure() const { return m_failure; }
  double solved_until() const { return m_segments.empty() ? 0.0 : m_segments.back().end; }

private:
  const Segment& segment_at(double time) const;

  Oscillator m_o;
  double m_window_end = 0.0;
  std::vector<Segment> m_segments;
  std::string m_failure;
};

} // namespace rsi::coulomb
