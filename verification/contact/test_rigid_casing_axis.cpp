// The rigid casing about any rotation axis (hardening, third round, class
// 1: component.rotation_axis was read and had no effect, both casing laws
// hard-coding z). The reference law (reference/contact/rigid_surface_contact)
// and the reduced one (reduced/rigid_casing), written independently, are
// checked each against the definitions of their headers:
//  - about z, the frames, radii and polar angles of the first round, bit for
//    bit (e_n = -(x, y, 0)/r, e_t1 = z, phi = atan2(y, x));
//  - turned by the cyclic permutation x -> y -> z -> x (the axis z becomes
//    x), the same frames permuted and the same radii and angles, bit for
//    bit (the reference direction e_1 turns with the model);
//  - about a general axis, the frame is orthonormal and right-handed, e_t1
//    is the axis, e_n points from the node to the axis, r is the node's
//    distance from the axis; and the model turned with its axis keeps its
//    radii and frames turned, to rounding (a few eps).
// And the two laws agree with each other to rounding on every node.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "rigid_casing.hpp"
#include "rigid_surface_contact.hpp"

namespace rsi {
namespace {

constexpr double eps = 2.220446049250313e-16;

const std::vector<Eigen::Vector3d>& positions() {
  static const std::vector<Eigen::Vector3d> x{
      {270.0, 3.0, -12.0}, {-150.0, 200.0, 7.5}, {0.5, -80.0, 1.0}, {-30.0, -40.0, -2.0}};
  return x;
}

std::vector<RigidSurfaceNode> nodes_at(const std::vector<Eigen::Vector3d>& x) {
  std::vector<RigidSurfaceNode> nodes;
  for (size_t c = 0; c < x.size(); ++c) {
    RigidSurfaceNode n;
    n.dofs = {static_cast<int>(3 * c), static_cast<int>(3 * c + 1), static_cast<int>(3 * c + 2)};
    n.position = x[c];
    nodes.push_back(n);
  }
  return nodes;
}

std::vector<std::array<int, 3>> slots(size_t n) {
  std::vector<std::array<int, 3>> s;
  for (size_t c = 0; c < n; ++c)
    s.push_back(
        {static_cast<int>(3 * c), static_cast<int>(3 * c + 1), static_cast<int>(3 * c + 2)});
  return s;
}

RigidSurfaceContact reference_law(const std::vector<Eigen::Vector3d>& x,
                                  const Eigen::Vector3d& axis) {
  return RigidSurfaceContact(nodes_at(x), ImposedGap::constant(0.1), 100.0, 0.1, 100.0, axis);
}

RigidCasing reduced_law(const std::vector<Eigen::Vector3d>& x, const Eigen::Vector3d& axis) {
  return RigidCasing(x, slots(x.size()), CasingGap{}, 100.0, 100.0, axis);
}

/// (x, y, z) -> (z, x, y): the cyclic turn taking z to x.
Eigen::Vector3d cyclic(const Eigen::Vector3d& v) {
  return {v(2), v(0), v(1)};
}

TEST(RigidCasingAxis, AboutZTheFirstRoundFramesBitForBit) {
  const RigidSurfaceContact ref = reference_law(positions(), Eigen::Vector3d::UnitZ());
  const RigidCasing red = reduced_law(positions(), Eigen::Vector3d::UnitZ());
  for (size_t c = 0; c < positions().size(); ++c) {
    const Eigen::Vector3d& x = positions()[c];
    const double r = std::hypot(x(0), x(1));
    const Eigen::Vector3d en(-x(0) / r, -x(1) / r, 0.0);
    const Eigen::Vector3d et2 = en.cross(Eigen::Vector3d::UnitZ());
    const ContactFrame& f = ref.frame(static_cast<int>(c));
    EXPECT_EQ(f.radius, r);
    EXPECT_EQ(f.angle, std::atan2(x(1), x(0)));
    EXPECT_EQ(f.normal, en);
    EXPECT_EQ(f.tangent1, Eigen::Vector3d::UnitZ());
    EXPECT_EQ(f.tangent2, et2);
    EXPECT_EQ(red.radius(static_cast<int>(c)), r);
    EXPECT_EQ(red.polar_angle(static_cast<int>(c)), std::atan2(x(1), x(0)));
    EXPECT_EQ(Eigen::Vector3d(red.frame(static_cast<int>(c)).row(0).transpose()), en);
    EXPECT_EQ(Eigen::Vector3d(red.frame(static_cast<int>(c)).row(1).transpose()),
              Eigen::Vector3d::UnitZ());
    EXPECT_EQ(Eigen::Vector3d(red.frame(static_cast<int>(c)).row(2).transpose()), et2);
    // +0, not -0, along the axis: a history written with %.17g stays the same bytes.
    EXPECT_FALSE(std::signbit(f.normal(2)));
    EXPECT_FALSE(std::signbit(red.frame(static_cast<int>(c))(0, 2)));
  }
}

TEST(RigidCasingAxis, CyclicTurnKeepsRadiiAnglesAndTurnsTheFrames) {
  std::vector<Eigen::Vector3d> turned;
  for (const Eigen::Vector3d& x : positions())
    turned.push_back(cyclic(x));
  const RigidSurfaceContact ref_z = reference_law(positions(), Eigen::Vector3d::UnitZ());
  const RigidSurfaceContact ref_x = reference_law(turned, Eigen::Vector3d::UnitX());
  const RigidCasing red_z = reduced_law(positions(), Eigen::Vector3d::UnitZ());
  const RigidCasing red_x = reduced_law(turned, Eigen::Vector3d::UnitX());
  for (int c = 0; c < static_cast<int>(positions().size()); ++c) {
    EXPECT_EQ(ref_x.frame(c).radius, ref_z.frame(c).radius) << c;
    EXPECT_EQ(ref_x.frame(c).angle, ref_z.frame(c).angle) << c;
    EXPECT_EQ(ref_x.frame(c).normal, cyclic(ref_z.frame(c).normal)) << c;
    EXPECT_EQ(ref_x.frame(c).tangent1, cyclic(ref_z.frame(c).tangent1)) << c;
    EXPECT_EQ(ref_x.frame(c).tangent2, cyclic(ref_z.frame(c).tangent2)) << c;
    EXPECT_EQ(ref_x.imposed_gap(c, 0.003), ref_z.imposed_gap(c, 0.003)) << c;
    EXPECT_EQ(red_x.radius(c), red_z.radius(c)) << c;
    EXPECT_EQ(red_x.polar_angle(c), red_z.polar_angle(c)) << c;
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(Eigen::Vector3d(red_x.frame(c).row(k).transpose()),
                cyclic(red_z.frame(c).row(k).transpose()))
          << c << " row " << k;
  }
}

TEST(RigidCasingAxis, GeneralAxisFramesFollowTheModel) {
  // The model turned by 0.7 rad about (1, 2, 3)/sqrt(14), its axis with it.
  const Eigen::Matrix3d q =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Eigen::Vector3d axis = q * Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> turned;
  for (const Eigen::Vector3d& x : positions())
    turned.push_back(q * x);
  const RigidSurfaceContact ref_z = reference_law(positions(), Eigen::Vector3d::UnitZ());
  const RigidSurfaceContact ref = reference_law(turned, axis);
  const RigidCasing red = reduced_law(turned, axis);
  double worst_turn = 0.0, worst_def = 0.0, worst_agree = 0.0;
  for (int c = 0; c < static_cast<int>(turned.size()); ++c) {
    const Eigen::Vector3d& x = turned[c];
    const Eigen::Vector3d radial = x - x.dot(axis) * axis; // from the axis to the node
    const ContactFrame& f = ref.frame(c);
    Eigen::Matrix3d frame;
    frame.row(0) = f.normal.transpose();
    frame.row(1) = f.tangent1.transpose();
    frame.row(2) = f.tangent2.transpose();
    const double scale = x.norm();
    // The definitions: orthonormal, right-handed, e_t1 = a, e_n = -radial / r, r = |radial|.
    worst_def = std::max(
        {worst_def, (frame * frame.transpose() - Eigen::Matrix3d::Identity()).norm(),
         std::abs(frame.determinant() - 1.0), (f.tangent1 - axis).norm(),
         (f.normal + radial / radial.norm()).norm(), std::abs(f.radius - radial.norm()) / scale});
    // The model turned: radius kept, frame turned (the polar angle's origin
    // moves with the choice of e_1, the frame does not depend on it).
    worst_turn = std::max({worst_turn, std::abs(f.radius - ref_z.frame(c).radius) / scale,
                           (f.normal - q * ref_z.frame(c).normal).norm(),
                           (f.tangent2 - q * ref_z.frame(c).tangent2).norm()});
    // The two laws, written apart, agree.
    worst_agree = std::max({worst_agree, (red.frame(c) - frame).norm(),
                            std::abs(red.radius(c) - f.radius) / scale,
                            std::abs(red.polar_angle(c) - f.angle)});
  }
  // Each quantity is a few roundings of unit-size numbers (a projection, a
  // hypot, a division, a cross product, the turn q applied in double): 32 eps.
  const double bound = 32.0 * eps;
  std::printf("general axis (%.6f, %.6f, %.6f): definitions %.2e, turned model %.2e, reference "
              "against reduced %.2e (bound %.2e)\n",
              axis(0), axis(1), axis(2), worst_def, worst_turn, worst_agree, bound);
  EXPECT_LE(worst_def, bound);
  EXPECT_LE(worst_turn, bound);
  EXPECT_LE(worst_agree, bound);
}

TEST(RigidCasingAxis, RefusesAZeroAxisAndANodeOnIt) {
  EXPECT_THROW(reference_law(positions(), Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(reduced_law(positions(), Eigen::Vector3d::Zero()), std::invalid_argument);
  const Eigen::Vector3d axis(0.0, 2.0, 0.0);
  const std::vector<Eigen::Vector3d> on_axis{{0.0, 5.0, 0.0}};
  EXPECT_THROW(reference_law(on_axis, axis), std::invalid_argument);
  EXPECT_THROW(reduced_law(on_axis, axis), std::invalid_argument);
}

// Rotation effects: each contact node's static radial growth closes its gap,
// g = g0(theta) - growth_c, in both laws (the oval's value at theta is the
// same expression in each, so the difference is the growth to round-off of
// one subtraction); a growth that is not finite, or of the wrong count, is
// refused.
TEST(RigidCasingGrowth, BothLawsCloseEachGapByItsGrowth) {
  const std::vector<Eigen::Vector3d>& x = positions();
  const std::vector<double> growth{0.073, 0.121, 0.0, -0.01};
  std::vector<RigidSurfaceNode> nodes = nodes_at(x);
  for (size_t c = 0; c < nodes.size(); ++c) nodes[c].growth = growth[c];
  const double omega = 1344.0;
  const RigidSurfaceContact reference(nodes, ImposedGap::oval(0.356, 0.15), omega, 0.1, omega);
  const RigidSurfaceContact reference_rest(nodes_at(x), ImposedGap::oval(0.356, 0.15), omega, 0.1,
                                           omega);
  const CasingGap oval = oval_casing_gap(0.356);
  const RigidCasing reduced(x, slots(x.size()), oval, omega, omega, Eigen::Vector3d::UnitZ(),
                            growth);
  const RigidCasing reduced_rest(x, slots(x.size()), oval, omega, omega);
  double worst = 0.0;
  for (int c = 0; c < static_cast<int>(x.size()); ++c)
    for (double t : {0.0, 1e-4, 7.3e-4, 2e-3}) {
      const double g_rest = reference_rest.imposed_gap(c, t);
      // |g| <= g_m: one rounding of the difference, eps (g_m + growth).
      const double bound = eps * (0.356 + std::abs(growth[c]));
      worst = std::max(worst, std::abs(reference.imposed_gap(c, t) - (g_rest - growth[c])));
      EXPECT_LE(std::abs(reference.imposed_gap(c, t) - (g_rest - growth[c])), bound);
      EXPECT_LE(std::abs(reduced.imposed_gap(c, t) - (reduced_rest.imposed_gap(c, t) - growth[c])),
                bound);
      // The two laws' oval gaps, written apart, agree to a few roundings of g_m.
      EXPECT_LE(std::abs(reduced.imposed_gap(c, t) - reference.imposed_gap(c, t)), 64 * eps);
    }
  std::printf("largest |g - (g_rest - growth)| %.2e\n", worst);
  nodes[1].growth = std::nan("");
  EXPECT_THROW(RigidSurfaceContact(nodes, ImposedGap::constant(0.1), omega, 0.1, omega),
               std::invalid_argument);
  EXPECT_THROW(RigidCasing(x, slots(x.size()), oval, omega, omega, Eigen::Vector3d::UnitZ(),
                           std::vector<double>{0.1}),
               std::invalid_argument);
  EXPECT_THROW(RigidCasing(x, slots(x.size()), oval, omega, omega, Eigen::Vector3d::UnitZ(),
                           std::vector<double>{0.1, INFINITY, 0.0, 0.0}),
               std::invalid_argument);
}

} // namespace
} // namespace rsi
