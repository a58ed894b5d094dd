// The engine-order crossings of a Campbell diagram (sweep/campbell_crossings):
// against the roots of f(Omega) = k Omega / 2 pi solved by hand.

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "campbell_crossings.hpp"

namespace {

std::vector<double> grid(double from, double to, int count) {
  std::vector<double> speeds;
  for (int i = 0; i < count; ++i) speeds.push_back(from + (to - from) * i / (count - 1));
  return speeds;
}

TEST(CampbellCrossings, LinearFrequenciesGiveTheExactRoots) {
  // f(Omega) = a + b Omega crosses k Omega / 2 pi at Omega = a / (k / 2 pi - b).
  const double a = 300.0, b = 0.05;
  const std::vector<double> speeds = grid(0.0, 2000.0, 21);
  Eigen::MatrixXd hz(speeds.size(), 1);
  for (size_t s = 0; s < speeds.size(); ++s) hz(s, 0) = a + b * speeds[s];
  const std::vector<rsi::CampbellCrossing> found = rsi::campbell_crossings(speeds, hz, 10);
  int expected_count = 0;
  double worst = 0.0;
  for (int k = 1; k <= 10; ++k) {
    const double root = a / (k / (2.0 * M_PI) - b);
    if (root < 0.0 || root > 2000.0) continue;
    ++expected_count;
    bool seen = false;
    for (const rsi::CampbellCrossing& c : found)
      if (c.engine_order == k) {
        seen = true;
        worst = std::max(worst, std::abs(c.speed_rad_s - root) / root);
        EXPECT_EQ(c.mode, 1);
        EXPECT_DOUBLE_EQ(c.frequency_hz, k * c.speed_rad_s / (2.0 * M_PI));
      }
    EXPECT_TRUE(seen) << "engine order " << k << " crosses at " << root << " rad/s";
  }
  std::printf("%zu crossings found, %d expected; largest relative error %.2e\n", found.size(),
              expected_count, worst);
  EXPECT_EQ(static_cast<int>(found.size()), expected_count);
  // Linear interpolation of a linear d(Omega) is exact: a few roundings.
  EXPECT_LT(worst, 1e-13);
}

TEST(CampbellCrossings, CurvedFrequencyWithinTheChordBound) {
  // f(Omega) = sqrt(f0^2 + c Omega^2) (a stiffening blade, Southwell's form):
  // the crossing of engine order k is Omega* = f0 / sqrt((k/2pi)^2 - c).
  const double f0 = 300.0, c = 0.04;
  const std::vector<double> speeds = grid(0.0, 3000.0, 31);
  const double step = speeds[1] - speeds[0];
  Eigen::MatrixXd hz(speeds.size(), 1);
  for (size_t s = 0; s < speeds.size(); ++s) hz(s, 0) = std::sqrt(f0 * f0 + c * speeds[s] * speeds[s]);
  for (const rsi::CampbellCrossing& x : rsi::campbell_crossings(speeds, hz, 10)) {
    const int k = x.engine_order;
    const double root = f0 / std::sqrt(std::pow(k / (2.0 * M_PI), 2) - c);
    // Chord error of f over one interval, (h^2 / 8) max |f''| with
    // f'' = c f0^2 / f^3 <= c / f0, over the slope gap |f' - k/2pi| >=
    // k/2pi - sqrt(c) (f' < sqrt(c)).
    const double bound = step * step / 8.0 * (c / f0) / (k / (2.0 * M_PI) - std::sqrt(c));
    std::printf("order %2d: %.6f rad/s, exact %.6f, error %.2e <= bound %.2e\n", k,
                x.speed_rad_s, root, std::abs(x.speed_rad_s - root), bound);
    EXPECT_LE(std::abs(x.speed_rad_s - root), bound);
  }
}

TEST(CampbellCrossings, RefusesTooFewOrUnsortedSpeeds) {
  Eigen::MatrixXd hz = Eigen::MatrixXd::Constant(2, 1, 100.0);
  EXPECT_THROW(rsi::campbell_crossings({0.0}, hz.topRows(1), 10), std::invalid_argument);
  EXPECT_THROW(rsi::campbell_crossings({10.0, 5.0}, hz, 10), std::invalid_argument);
  EXPECT_THROW(rsi::campbell_crossings({0.0, 5.0, 10.0}, hz, 10), std::invalid_argument);
}

} // namespace
