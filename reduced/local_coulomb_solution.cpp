#include "local_coulomb_solution.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct Candidates {
  std::array<LocalCoulombSolution, 12> item;
  int n = 0;
  void add(const LocalCoulombSolution& s) {
    if (n < static_cast<int>(item.size())) item[n++] = s;
  }
};

/// f(th) = e x (b + A e), e = (cos th, sin th), and its derivative.
double slip_function(const Eigen::Vector2d& b, const Eigen::Matrix2d& a, double th, double* df) {
  const Eigen::Vector2d e(std::cos(th), std::sin(th));
  const Eigen::Vector2d de(-e(1), e(0));
  const Eigen::Vector2d h = b + a * e;
  const Eigen::Vector2d ade = a * de;
  if (df) *df = (de(0) * h(1) - de(1) * h(0)) + (e(0) * ade(1) - e(1) * ade(0));
  return e(0) * h(1) - e(1) * h(0);
}

/// Newton's method on f from th (steps capped at pi/8), at most 30 steps;
/// `converged` (if given) tells whether the last step fell to round-off.
double polish(const Eigen::Vector2d& b, const Eigen::Matrix2d& a, double th, bool* converged) {
  if (converged) *converged = false;
  for (int it = 0; it < 30; ++it) {
    double df = 0.0;
    const double f = slip_function(b, a, th, &df);
    if (f == 0.0) {
      if (converged) *converged = true;
      break;
    }
    if (df == 0.0) break;
    const double step = std::max(-M_PI / 8.0, std::min(M_PI / 8.0, f / df));
    th -= step;
    if (std::abs(step) <= 2.0 * eps * (1.0 + std::abs(th))) {
      if (converged) *converged = true;
      break;
    }
  }
  return th;
}

/// The slip candidate of direction e (unit, R^d) if its denominator is
/// positive.
void add_slip(const Eigen::Matrix3d& w, const Eigen::Vector3d& r, int d, double mu,
              const Eigen::Vector2d& e, Candidates& out) {
  const double rho = -r(0);
  double wnt_e = 0.0;
  for (int i = 0; i < d; ++i)
    wnt_e += w(0, 1 + i) * e(i);
  const double den = w(0, 0) - mu * wnt_e;
  if (!(den > 0.0)) return;
  LocalCoulombSolution c;
  c.state = ReducedContactState::slip;
  c.lambda(0) = rho / den;
  for (int i = 0; i < d; ++i)
    c.lambda(1 + i) = -mu * c.lambda(0) * e(i);
  // s = r_t + w_tn lambda_n + W_tt lambda_t, and the size of its terms.
  Eigen::Vector2d s = Eigen::Vector2d::Zero();
  double size = 0.0;
  for (int i = 0; i < d; ++i) {
    s(i) = r(1 + i) + w(1 + i, 0) * c.lambda(0);
    double terms = std::abs(r(1 + i)) + std::abs(w(1 + i, 0) * c.lambda(0));
    for (int j = 0; j < d; ++j) {
      s(i) += w(1 + i, 1 + j) * c.lambda(1 + j);
      terms += std::abs(w(1 + i, 1 + j) * c.lambda(1 + j));
    }
    size = std::max(size, terms);
  }
  // s must be sigma e, sigma >= 0: its part across e and its part against e.
  double along = 0.0;
  for (int i = 0; i < d; ++i)
    along += s(i) * e(i);
  const double across = (s.head(d) - along * e.head(d)).norm();
  const double off = across + std::max(-along, 0.0);
  c.violation = off == 0.0 ? 0.0 : off / size;
  out.add(c);
}

/// The slip candidates of d = 2: roots of f (header).
void add_slip_3d(const Eigen::Matrix3d& w, const Eigen::Vector3d& r, double mu,
                 const Eigen::Vector3d& current, Candidates& out) {
  const double rho = -r(0);
  const Eigen::Vector2d rt = r.segment<2>(1);
  const Eigen::Vector2d b = w(0, 0) * rt + rho * w.block<2, 1>(1, 0);
  const Eigen::Matrix2d a = -mu * (rt * w.block<1, 2>(0, 1) + rho * w.block<2, 2>(1, 1));
  // Warm path: Newton from the current slip direction e = -lambda_t/|lambda_t|.
  // A converged root with s along e (s . e >= 0, violation at round-off) is
  // an exact slip solution, the one continuous with the sweeps; otherwise
  // the quartic below gives them all.
  if (current(1) != 0.0 || current(2) != 0.0) {
    bool converged = false;
    const double th = polish(b, a, std::atan2(-current(2), -current(1)), &converged);
    if (converged) {
      Candidates warm;
      add_slip(w, r, 2, mu, Eigen::Vector2d(std::cos(th), std::sin(th)), warm);
      if (warm.n == 1 && warm.item[0].violation <= 64.0 * eps) {
        out.add(warm.item[0]);
        return;
      }
    }
  }
  // The turn th0 = k pi/4 with the largest |f(th0 + pi)|.
  int best = 0;
  double best_f = -1.0;
  for (int k = 0; k < 8; ++k) {
    const double f = std::abs(slip_function(b, a, M_PI / 4.0 * k + M_PI, nullptr));
    if (f > best_f) best_f = f, best = k;
  }
  if (best_f == 0.0) return; // f == 0: b = 0, A = alpha I, no slip with kappa > 0 for W_tt > 0
  const double th0 = M_PI / 4.0 * best;
  Eigen::Matrix2d rot;
  rot << std::cos(th0), -std::sin(th0), std::sin(th0), std::cos(th0);
  const Eigen::Vector2d bp = rot.transpose() * b;
  const Eigen::Matrix2d ap = rot.transpose() * a * rot;
  const double p4 = ap(1, 0) - bp(1);
  const double p3 = -2.0 * (bp(0) + ap(1, 1) - ap(0, 0));
  const double p2 = -2.0 * (ap(1, 0) + 2.0 * ap(0, 1));
  const double p1 = 2.0 * (ap(1, 1) - ap(0, 0) - bp(0));
  const double p0 = bp(1) + ap(1, 0);
  Eigen::Matrix4d companion = Eigen::Matrix4d::Zero();
  companion(1, 0) = companion(2, 1) = companion(3, 2) = 1.0;
  companion(0, 3) = -p0 / p4;
  companion(1, 3) = -p1 / p4;
  companion(2, 3) = -p2 / p4;
  companion(3, 3) = -p3 / p4;
  Eigen::EigenSolver<Eigen::Matrix4d> roots(companion, false);
  std::array<double, 8> seeds{};
  int n_seeds = 0;
  if (roots.info() == Eigen::Success) {
    for (int i = 0; i < 4; ++i)
      seeds[n_seeds++] = th0 + 2.0 * std::atan(roots.eigenvalues()(i).real());
  } else { // never seen for a 4 x 4; the 8 turns as Newton seeds instead
    for (int k = 0; k < 8; ++k)
      seeds[n_seeds++] = M_PI / 4.0 * k;
  }
  for (int i = 0; i < n_seeds; ++i) {
    const double th = polish(b, a, seeds[i], nullptr);
    add_slip(w, r, 2, mu, Eigen::Vector2d(std::cos(th), std::sin(th)), out);
  }
}

} // namespace

LocalCoulombSolution local_coulomb_solution(const Eigen::Matrix3d& w,
                                            const Eigen::PartialPivLU<CoulombBlockMatrix>& w_lu,
                                            const Eigen::Vector3d& r, int d, double mu,
                                            const Eigen::Vector3d& current) {
  assert((d == 1 || d == 2) && mu >= 0.0);
  LocalCoulombSolution open; // lambda = 0
  if (r(0) >= 0.0) return open;
  assert(w(0, 0) > 0.0);
  if (mu == 0.0) {
    LocalCoulombSolution closed;
    closed.state = ReducedContactState::slip;
    closed.lambda(0) = -r(0) / w(0, 0);
    return closed;
  }
  // Stick when its multiplier lies in the cone (exactly as computed, so the
  // certificate's cone violation of a stick contact is 0 up to the same
  // arithmetic).
  LocalCoulombSolution stick;
  stick.state = ReducedContactState::stick;
  const int m = 1 + d;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> rhs(m);
  for (int i = 0; i < m; ++i)
    rhs(i) = -r(i);
  const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> x = w_lu.solve(rhs);
  for (int i = 0; i < m; ++i)
    stick.lambda(i) = x(i);
  const double cone = std::hypot(stick.lambda(1), stick.lambda(2)) - mu * stick.lambda(0);
  const double stick_size = stick.lambda.cwiseAbs().maxCoeff();
  const double stick_off = std::max({-stick.lambda(0), cone, 0.0});
  stick.violation = stick_off == 0.0 ? 0.0 : stick_off / stick_size;
  if (stick.lambda(0) >= 0.0 && cone <= 0.0) return stick;
  // Otherwise slip: the candidate of least violation, the nearest to
  // `current` between those within round-off of it.
  Candidates cand;
  if (d == 1) {
    add_slip(w, r, 1, mu, Eigen::Vector2d(1.0, 0.0), cand);
    add_slip(w, r, 1, mu, Eigen::Vector2d(-1.0, 0.0), cand);
  } else {
    add_slip_3d(w, r, mu, current, cand);
  }
  if (cand.n == 0)
    return stick; // no slip direction with a positive denominator: the caller reports it
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < cand.n; ++i)
    least = std::min(least, cand.item[i].violation);
  const double window = least + 64.0 * eps;
  int chosen = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < cand.n; ++i) {
    if (!(cand.item[i].violation <= window)) continue;
    const double distance = (cand.item[i].lambda - current).cwiseAbs().maxCoeff();
    if (distance < nearest) nearest = distance, chosen = i;
  }
  return cand.item[chosen];
}

} // namespace rsi
