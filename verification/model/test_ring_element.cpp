// V1: the curved Hermite ring element (reference/ring_element).

#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "ring_element.hpp"

namespace rsi {
namespace {

const BeamProperties casing_section = beam_properties({210e9, 7800}, {0.03, 0.01});
constexpr double radius = 0.501;
constexpr double eps = std::numeric_limits<double>::epsilon();

/// Nodal values (u, u_s, v, v_s) at both ends of an element spanning
/// [1, 1 + dtheta] rad of the rigid translation of unit length along x:
/// u = cos(theta), v = -sin(theta), s = R theta. (Away from theta = 0, where
/// sin vanishes and would hide the leading error of v.)
Eigen::Matrix<double, 8, 1> translation_x(double dtheta) {
  Eigen::Matrix<double, 8, 1> r;
  for (int node = 0; node < 2; ++node) {
    const double t = 1.0 + node * dtheta;
    r.segment<4>(4 * node) << std::cos(t), -std::sin(t) / radius, -std::sin(t),
        -std::cos(t) / radius;
  }
  return r;
}

/// Rigid rotation by a unit angle: u = 0, v = R (theta = v/R - u_s = 1).
Eigen::Matrix<double, 8, 1> rotation() {
  Eigen::Matrix<double, 8, 1> r;
  r << 0, 0, radius, 0, 0, 0, radius, 0;
  return r;
}

TEST(RingElement, SymmetricPositiveSemiDefinite) {
  for (int n : {8, 40, 200}) {
    const double arc = 2 * M_PI * radius / n;
    const Matrix8d k = ring_stiffness(casing_section, radius, arc);
    const Matrix8d m = ring_mass(casing_section, arc);
    // Each entry is a sum of Gauss-point terms w (B^T B)_ab, symmetric up to
    // the rounding of the (possibly fused) products: a few eps of the largest entry.
    EXPECT_LE((k - k.transpose()).cwiseAbs().maxCoeff(), 8 * eps * k.cwiseAbs().maxCoeff());
    EXPECT_LE((m - m.transpose()).cwiseAbs().maxCoeff(), 8 * eps * m.cwiseAbs().maxCoeff());
    const Eigen::VectorXd lk = Eigen::SelfAdjointEigenSolver<Matrix8d>(k).eigenvalues();
    const Eigen::VectorXd lm = Eigen::SelfAdjointEigenSolver<Matrix8d>(m).eigenvalues();
    std::printf(
        "n = %d: stiffness eigenvalues %.3e %.3e %.3e %.3e ... %.3e; min mass eigenvalue %.3e\n", n,
        lk(0), lk(1), lk(2), lk(3), lk(7), lm(0));
    // Semi-definite: no eigenvalue below round-off of the largest (64 eps ||K||).
    EXPECT_GE(lk(0), -64 * eps * lk(7));
    EXPECT_GT(lm(0), 0.0);
  }
}

TEST(RingElement, RigidRotationExact) {
  const double arc = 2 * M_PI * radius / 40;
  const Matrix8d k = ring_stiffness(casing_section, radius, arc);
  const Eigen::Matrix<double, 8, 1> r = rotation();
  const double residual = (k * r).norm() / (k.norm() * r.norm());
  std::printf("rigid rotation: |K r| / (|K| |r|) = %.3e\n", residual);
  // v = const, u = 0 gives eps = 0 and kappa = 0 pointwise: K r = 0 up to round-off.
  EXPECT_LE(residual, 64 * eps);
}

/// Rayleigh quotient r^T K r / r^T M r of the interpolated unit translation
/// on one element of n around the ring, and its round-off level
/// 16 eps |r|^T |K| |r| / r^T M r (the cancellation in r^T K r).
std::pair<double, double> translation_quotient(const BeamProperties& p, int n) {
  const double dtheta = 2 * M_PI / n;
  const double arc = radius * dtheta;
  const Eigen::Matrix<double, 8, 1> r = translation_x(dtheta);
  const Matrix8d k = ring_stiffness(p, radius, arc);
  const double mass = r.dot(ring_mass(p, arc) * r);
  return {r.dot(k * r) / mass, 16 * eps * r.cwiseAbs().dot(k.cwiseAbs() * r.cwiseAbs()) / mass};
}

/// Observed convergence rate of the spurious energy of a rigid translation
/// over successive halvings of the element from n = 20, using only meshes
/// where the quotient stands 100 times above its round-off bound (round-off
/// then moves a rate by at most log2(1.01/0.99) = 0.03).
void check_translation_rate(const std::string& name, const BeamProperties& p,
                            double expected_rate) {
  std::vector<double> quotient;
  for (int n = 20; n <= 640; n *= 2) {
    const auto [q, noise] = translation_quotient(p, n);
    std::printf("%s, n = %4d: spurious omega^2 %.4e (round-off bound %.1e)\n", name.c_str(), n, q,
                noise);
    if (q < 100 * noise) break;
    quotient.push_back(q);
  }
  ASSERT_GE(quotient.size(), 2u) << "need a rate above round-off";
  for (size_t i = 0; i + 1 < quotient.size(); ++i) {
    const double rate = std::log2(quotient[i] / quotient[i + 1]);
    std::printf("%s: observed rate %.3f (asymptotic %.0f)\n", name.c_str(), rate, expected_rate);
    // kappa's error mixes u_ss (O(h^2)) and v_s/R (O(h^3)): the rate approaches
    // its limit with a deviation O(dtheta), from below. A 50-digit computation
    // of the same quotient (verification/model/ring_translation_rates.py) gives
    // bending 3.54 (n 20->40), 3.80, 3.91, 3.95 and membrane 6.11, 6.06,
    // 6.03: within 0.5 below and 0.2 above the limit from n = 20 on.
    EXPECT_GE(rate, expected_rate - 0.5);
    EXPECT_LE(rate, expected_rate + 0.2);
  }
}

TEST(RingElement, RigidTranslationEnergyConverges) {
  // Cubic Hermite interpolation of u = cos, v = -sin: u_ss is wrong by
  // O(h^2), v_s by O(h^3), u by O(h^4). Hence kappa = u_ss - v_s/R = O(h^2)
  // and the bending quotient EI int kappa^2 / rhoA int (u^2+v^2) = O(h^4);
  // eps = v_s + u/R = O(h^3) and the membrane quotient is O(h^6). Each part
  // is measured alone (the other stiffness set to zero), since their sum
  // changes from membrane- to bending-dominated at h ~ sqrt(EI/EA).
  BeamProperties bending = casing_section;
  bending.EA = 0.0;
  BeamProperties membrane = casing_section;
  membrane.EI = 0.0;
  check_translation_rate("bending", bending, 4.0);
  check_translation_rate("membrane", membrane, 6.0);
  // At 40 elements (the casing) the spurious translation frequency is far
  // below the casing's lowest mode (5 Hz).
  const double f40 = std::sqrt(translation_quotient(casing_section, 40).first) / (2 * M_PI);
  std::printf("spurious translation frequency of one element at n = 40: %.3e Hz\n", f40);
  EXPECT_LT(f40, 0.05);
}

TEST(RingElement, MassOfUniformMotionIsElementMass) {
  // r^T M r for the rigid rotation r (|velocity| = R everywhere) equals rho A l R^2.
  const double arc = 2 * M_PI * radius / 40;
  const Eigen::Matrix<double, 8, 1> r = rotation();
  const double mass = r.dot(ring_mass(casing_section, arc) * r);
  const double expected = casing_section.rhoA * arc * radius * radius;
  std::printf("r^T M r = %.15e, rho A l R^2 = %.15e\n", mass, expected);
  // Gauss-Legendre with 4 points is exact for the degree-6 integrand: round-off only.
  EXPECT_NEAR(mass, expected, 64 * eps * expected);
}

} // namespace
} // namespace rsi
