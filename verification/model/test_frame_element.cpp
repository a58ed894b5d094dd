// V1: the straight Euler-Bernoulli frame element (reference/frame_element).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "frame_element.hpp"

namespace rsi {
namespace {

const BeamProperties steel_blade = beam_properties({210e9, 7800}, {0.03, 0.0021});
constexpr double eps = std::numeric_limits<double>::epsilon();

/// Rigid motions of a two-node frame element with nodes at (0,0) and
/// L(cos a, sin a): translation x, translation y, rotation about node 1.
Eigen::Matrix<double, 6, 3> rigid_modes(double length, double angle) {
  const double x2 = length * std::cos(angle);
  const double y2 = length * std::sin(angle);
  Eigen::Matrix<double, 6, 3> r;
  // clang-format off
  r << 1, 0, 0,
       0, 1, 0,
       0, 0, 1,
       1, 0, -y2,
       0, 1, x2,
       0, 0, 1;
  // clang-format on
  return r;
}

TEST(FrameElement, SymmetricPositiveSemiDefiniteRankThree) {
  for (double angle : {0.0, 0.3, -1.2, 2.5}) {
    const Matrix6d k = frame_stiffness(steel_blade, 0.022, angle);
    const Matrix6d m = frame_mass(steel_blade, 0.022, angle);
    // Symmetry is exact up to the round-off of R^T K R: a few eps of the largest entry.
    EXPECT_LE((k - k.transpose()).cwiseAbs().maxCoeff(), 16 * eps * k.cwiseAbs().maxCoeff());
    EXPECT_LE((m - m.transpose()).cwiseAbs().maxCoeff(), 16 * eps * m.cwiseAbs().maxCoeff());
    const Eigen::VectorXd lk = Eigen::SelfAdjointEigenSolver<Matrix6d>(k).eigenvalues();
    const Eigen::VectorXd lm = Eigen::SelfAdjointEigenSolver<Matrix6d>(m).eigenvalues();
    std::printf("angle %.2f: stiffness eigenvalues %.3e %.3e %.3e | %.3e %.3e %.3e; min mass "
                "eigenvalue %.3e\n",
                angle, lk(0), lk(1), lk(2), lk(3), lk(4), lk(5), lm(0));
    // Three rigid modes: three eigenvalues at round-off level (eps * ||K|| times a small count).
    for (int i = 0; i < 3; ++i)
      EXPECT_LE(std::abs(lk(i)), 64 * eps * lk(5));
    // Rank exactly 3: the smallest deformation eigenvalue stands clear of
    // that round-off level by many orders of magnitude (here ~1e7).
    EXPECT_GT(lk(3), 1e4 * 64 * eps * lk(5));
    // Consistent mass is positive definite.
    EXPECT_GT(lm(0), 0.0);
  }
}

TEST(FrameElement, RigidBodyModesStoreNoEnergyExactly) {
  for (double angle : {0.0, 0.7, -0.2}) {
    const double length = 0.05;
    const Matrix6d k = frame_stiffness(steel_blade, length, angle);
    const Eigen::Matrix<double, 6, 3> r = rigid_modes(length, angle);
    const double residual =
        (k * r).cwiseAbs().maxCoeff() / (k.cwiseAbs().maxCoeff() * r.cwiseAbs().maxCoeff());
    std::printf("angle %.2f: max |K r| / (max|K| max|r|) = %.3e\n", angle, residual);
    // K r = 0 exactly in exact arithmetic (linear axial + cubic bending hold
    // rigid motions): round-off only, a few eps per entry.
    EXPECT_LE(residual, 64 * eps);
  }
}

TEST(FrameElement, MassMatrixGivesTheElementMassForTranslations) {
  // A unit rigid translation has kinetic energy 1/2 rho A L: r^T M r = rho A L.
  const double length = 0.05;
  const Matrix6d m = frame_mass(steel_blade, length, 0.4);
  const Eigen::Matrix<double, 6, 3> r = rigid_modes(length, 0.4);
  const double expected = steel_blade.rhoA * length;
  for (int i = 0; i < 2; ++i) {
    const double mass = r.col(i).dot(m * r.col(i));
    std::printf("translation %d: r^T M r = %.15e, rho A L = %.15e\n", i, mass, expected);
    EXPECT_NEAR(mass, expected, 16 * eps * expected);
  }
}

} // namespace
} // namespace rsi
