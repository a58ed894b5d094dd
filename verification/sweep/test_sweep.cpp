// rsi sweep's numerics (issue 15): the Hann spectrum against a direct
// transform and exact tones, the per-run indicators on rows whose answers
// are known, the rank schedule against the optimum, and the interaction
// lines against ring theory and the calibration of the blade family.

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>

#include <gtest/gtest.h>

#include "case_file.hpp"
#include "interaction_lines.hpp"
#include "response_spectrum.hpp"
#include "sweep_indicators.hpp"
#include "sweep_schedule.hpp"

namespace rsi {
namespace {

std::vector<double> tones(int n, double dt, const std::vector<std::pair<double, double>>& f_a) {
  std::vector<double> x(static_cast<size_t>(n), 0.25); // a mean, removed by the spectrum
  for (int i = 0; i < n; ++i)
    for (const auto& [f, a] : f_a)
      x[static_cast<size_t>(i)] += a * std::cos(2.0 * M_PI * f * i * dt + 0.3);
  return x;
}

TEST(ResponseSpectrum, PaddedHannSpectrumIsTheDirectTransform) {
  // Independent: the windowed, padded DFT summed term by term (O(n N)).
  const int n = 100, padding = 8, big_n = n * padding;
  const std::vector<double> x = tones(n, 1e-3, {{37.0, 1.0}, {121.3, 0.4}});
  const std::vector<double> a = hann_amplitude_spectrum(x, padding);
  ASSERT_EQ(a.size(), static_cast<size_t>(big_n / 2 + 1));
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double window_sum = 0.0;
  for (int i = 0; i < n; ++i)
    window_sum += 0.5 * (1.0 - std::cos(2.0 * M_PI * i / n));
  double worst = 0.0;
  for (int m = 0; m <= big_n / 2; m += 7) {
    std::complex<double> sum = 0.0;
    for (int i = 0; i < n; ++i)
      sum += 0.5 * (1.0 - std::cos(2.0 * M_PI * i / n)) * (x[static_cast<size_t>(i)] - mean) *
             std::polar(1.0, -2.0 * M_PI * m * i / big_n);
    worst = std::max(worst, std::abs(2.0 * std::abs(sum) / window_sum - a[static_cast<size_t>(m)]));
  }
  // Both sums carry round-off of order n eps times the largest amplitude (1).
  EXPECT_LE(worst, 1e3 * 1e-16 * n);
}

TEST(ResponseSpectrum, TonesOnBinsAreExact) {
  // f on an unpadded bin k / (n dt): the periodic Hann transform vanishes at
  // every other unpadded bin, so each tone reads its own amplitude exactly.
  const int n = 400;
  const double dt = 2.5e-5, bin = 1.0 / (n * dt); // 100 Hz
  const std::vector<SpectralPeak> p =
      dominant_frequencies(tones(n, dt, {{7 * bin, 1e-3}, {30 * bin, 3e-3}, {55 * bin, 5e-4}}), dt, 3);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[0].frequency_hz, 30 * bin, 1e-9 * bin);
  EXPECT_NEAR(p[1].frequency_hz, 7 * bin, 1e-9 * bin);
  EXPECT_NEAR(p[2].frequency_hz, 55 * bin, 1e-9 * bin);
  // FFT round-off: n log n eps of the largest amplitude.
  EXPECT_NEAR(p[0].amplitude, 3e-3, 1e-12);
  EXPECT_NEAR(p[1].amplitude, 1e-3, 1e-12);
  EXPECT_NEAR(p[2].amplitude, 5e-4, 1e-12);
}

TEST(ResponseSpectrum, ToneOffTheBinsWithinThePaddedResolution) {
  // An isolated tone anywhere between bins: located to half a padded bin,
  // 1/(16 n dt), plus the leakage of its image (far from 0 here), and its
  // amplitude within the Hann main lobe's loss over 1/16 bin (< 0.6 %).
  const int n = 320;
  const double dt = 2.5e-5, bin = 1.0 / (n * dt);
  for (double offset : {0.0, 0.13, 0.37, 0.5, 0.71, 0.93}) {
    const double f = (20.0 + offset) * bin;
    const std::vector<SpectralPeak> p = dominant_frequencies(tones(n, dt, {{f, 2e-3}}), dt, 1);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_LE(std::abs(p[0].frequency_hz - f), bin / 16.0 + 0.01 * bin) << "offset " << offset;
    EXPECT_NEAR(p[0].amplitude, 2e-3, 0.006 * 2e-3) << "offset " << offset;
  }
}

TEST(ResponseSpectrum, BadInputIsRefused) {
  EXPECT_THROW(dominant_frequencies({1.0, 2.0, 3.0}, 1e-3, 3), std::invalid_argument);
  EXPECT_THROW(dominant_frequencies({1.0, 2.0, 3.0, 4.0}, 0.0, 3), std::invalid_argument);
  EXPECT_THROW(dominant_frequencies({1.0, NAN, 3.0, 4.0}, 1e-3, 3), std::invalid_argument);
}

TEST(SweepIndicators, KnownRowsGiveKnownIndicators) {
  // Two blades, rows every 1 ms, transient 2 ms: rows at t = 0, 1 (skipped),
  // 2, 3, 4, 5 ms read. Values chosen so every answer is a plain number.
  SweepIndicatorAccumulator acc(2e-3, 1e-3);
  Eigen::VectorXd gap = Eigen::VectorXd::Zero(2);
  for (int i = 0; i < 6; ++i) {
    const double t = i * 1e-3;
    Eigen::VectorXd lambda(2), tips(4);
    lambda << (i == 3 ? 50.0 : 0.0), (i >= 4 ? 20.0 * i : 0.0);
    tips << (i < 2 ? 9.0 : 1e-3 * i), (i < 2 ? 9.0 : -2e-3 * i), -0.5e-3 * i, 0.1e-3;
    const HistoryRow row{t, gap, lambda, 1.0 + i, 0.0, 0.0, 0.0, nullptr, &tips};
    acc.add(row);
  }
  const SweepIndicators s = acc.finish();
  EXPECT_EQ(s.rows, 4);
  EXPECT_DOUBLE_EQ(s.max_tip_radial, 5e-3);       // blade 1 at 5 ms (the 9 m before 2 ms skipped)
  EXPECT_DOUBLE_EQ(s.max_tip_tangential, 10e-3);  // |v_1| at 5 ms
  EXPECT_DOUBLE_EQ(s.max_contact_force, 100.0);   // blade 2 at 5 ms
  EXPECT_DOUBLE_EQ(s.contact_fraction, 3.0 / 8.0); // (3 ms, b1), (4, b2), (5, b2) of 8 pairs
  EXPECT_DOUBLE_EQ(s.energy_ratio, 6.0 / 3.0);    // E(5 ms) / E(2 ms)
  EXPECT_EQ(s.peaks.size(), 1u);                  // 4 samples of a ramp: one local maximum
}

TEST(SweepIndicators, RowsWithoutTipsAreRefused) {
  SweepIndicatorAccumulator acc(0.0, 1e-3);
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(2);
  const HistoryRow row{0.0, v, v, 1.0, 0.0, 0.0, 0.0, nullptr, nullptr};
  EXPECT_THROW(acc.add(row), std::invalid_argument);
}

/// The best makespan over every assignment (small instances only).
double optimal_makespan(const std::vector<double>& cost, int ranks) {
  std::vector<int> a(cost.size(), 0);
  double best = 1e300;
  for (;;) {
    std::vector<double> load(static_cast<size_t>(ranks), 0.0);
    for (size_t i = 0; i < cost.size(); ++i)
      load[static_cast<size_t>(a[i])] += cost[i];
    best = std::min(best, *std::max_element(load.begin(), load.end()));
    size_t i = 0;
    while (i < a.size() && ++a[i] == ranks)
      a[i++] = 0;
    if (i == a.size()) break;
  }
  return best;
}

TEST(SweepSchedule, WithinGrahamsBoundOfTheOptimum) {
  // Graham (1969): LPT's makespan <= (4/3 - 1/(3 m)) of the optimum.
  const std::vector<std::vector<double>> cases{
      {5, 5, 4, 4, 3, 3, 3}, {9, 1, 1, 1, 1, 1, 1, 1, 1}, {7, 6, 5, 4, 3, 2, 1}, {2, 2, 2, 3, 3}};
  for (const std::vector<double>& cost : cases)
    for (int ranks : {2, 3}) {
      const std::vector<int> owner = balance_tasks(cost, ranks);
      std::vector<double> load(static_cast<size_t>(ranks), 0.0);
      for (size_t i = 0; i < cost.size(); ++i) {
        ASSERT_GE(owner[i], 0);
        ASSERT_LT(owner[i], ranks);
        load[static_cast<size_t>(owner[i])] += cost[i];
      }
      const double makespan = *std::max_element(load.begin(), load.end());
      EXPECT_LE(makespan, (4.0 / 3.0 - 1.0 / (3.0 * ranks)) * optimal_makespan(cost, ranks) + 1e-12);
    }
}

TEST(SweepSchedule, EqualCostsGoRoundTheRanks) {
  // 200 speeds x (full, cb): each rank gets half the full runs and half the cb runs.
  std::vector<double> cost;
  for (int s = 0; s < 200; ++s) {
    cost.push_back(50.0);
    cost.push_back(2.0);
  }
  const std::vector<int> owner = balance_tasks(cost, 2);
  int full0 = 0, cb0 = 0;
  for (size_t i = 0; i < cost.size(); ++i)
    (i % 2 == 0 ? full0 : cb0) += owner[i] == 0;
  EXPECT_EQ(full0, 100);
  EXPECT_EQ(cb0, 100);
  EXPECT_EQ(balance_tasks(cost, 1), std::vector<int>(cost.size(), 0));
  EXPECT_THROW(balance_tasks(cost, 0), std::invalid_argument);
}

TEST(InteractionLines, RingTheoryAndTheCalibratedFamily) {
  const Case c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  const std::vector<InteractionLine> lines = interaction_lines(c, 2, 40);
  ASSERT_FALSE(lines.empty());
  // Free thin ring (inextensional): omega_n = sqrt(EI / (rho A R^4)) n (n^2 - 1) / sqrt(n^2 + 1),
  // a pair for n >= 2 after 3 rigid modes. Clamping 4 dofs at one node:
  // lambda_k(free) <= lambda_k(clamped) <= lambda_{k+4}(free) (interlacing,
  // 4 constraints). Theory and the 40-element model differ by O((h/R)^2)
  // and the discretisation: 1 % for n <= 6 (at least 6.7 elements a wave).
  const double h = c.casing.section.thickness, radius = c.casing.radius;
  const double scale = std::sqrt(c.material.young_modulus * h * h / 12.0 / c.material.density) /
                       (radius * radius) / (2.0 * M_PI);
  std::vector<double> free{0.0, 0.0, 0.0};
  for (int n = 2; n <= 12; ++n)
    free.insert(free.end(), 2, scale * n * (n * n - 1) / std::sqrt(n * n + 1.0));
  int checked = 0;
  for (const InteractionLine& l : lines) {
    EXPECT_NEAR(l.speed_rad_s * l.nodal_diameter / (2.0 * M_PI), l.blade_hz + l.casing_hz,
                1e-12 * (l.blade_hz + l.casing_hz));
    // Campbell crossing: seen from the rotating frame the casing mode sits
    // at |f_c - n Omega / 2 pi|, which meets the blade family at Omega_int.
    EXPECT_NEAR(std::abs(l.casing_hz - l.nodal_diameter * l.speed_rad_s / (2.0 * M_PI)),
                l.blade_hz, 1e-9 * l.blade_hz);
    if (l.family == 1) { // the calibration: first family 43.988-44.001 Hz (README)
      EXPECT_GE(l.blade_hz, 43.98);
      EXPECT_LE(l.blade_hz, 44.01);
    }
    const size_t k = static_cast<size_t>(l.casing_mode - 1);
    if (l.nodal_diameter <= 6 && k + 4 < free.size()) {
      EXPECT_GE(l.casing_hz, free[k] * (1.0 - 0.01)) << "casing mode " << l.casing_mode;
      EXPECT_LE(l.casing_hz, free[k + 4] * (1.0 + 0.01)) << "casing mode " << l.casing_mode;
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
}

// interaction_lines.hpp, aliased lines: 6 blades, a casing mode of n lobes
// meets the disk's k = |n - 6m| diameters. At the tips theta_j = 2 pi j / 6
// + Omega t the casing wave cos(n theta - omega_c t) is
// cos(2 pi n j / 6 + (n Omega - omega_c) t): the pattern cos(2 pi k j / 6)
// or its mirror (exact: n j and +-k j differ by a multiple of 6 j), and the
// blades' family frequency is n Omega_int / 2 pi - f_c (to 1e-12: the
// speed's rounding). Without `aliased` only n <= N/2 = 3.
TEST(InteractionLines, AliasedLobesMeetTheirDiameterAtTheTips) {
  std::vector<ClassifiedMode> disk;
  for (int k = 0; k <= 3; ++k) // one family, pairs but at 0 and N/2
    for (int copy = 0; copy < (k == 0 || k == 3 ? 1 : 2); ++copy)
      disk.push_back({290.0 + k, k});
  for (int k = 0; k <= 3; ++k)
    for (int copy = 0; copy < (k == 0 || k == 3 ? 1 : 2); ++copy)
      disk.push_back({1400.0 + k, k});
  std::sort(disk.begin(), disk.end(),
            [](const ClassifiedMode& a, const ClassifiedMode& b) { return a.frequency_hz < b.frequency_hz; });
  const std::vector<ClassifiedMode> casing{{2482.0, 6}, {2496.0, 7}, {2538.0, 5}, {2657.0, 4},
                                           {2801.0, 3}, {2990.0, 2}, {3146.0, 1}, {3241.0, 0},
                                           {3400.0, 9}, {3500.0, 12}};
  const std::vector<InteractionLine> plain = interaction_lines(disk, 6, casing, 1);
  const std::vector<InteractionLine> all = interaction_lines(disk, 6, casing, 1, true);
  ASSERT_EQ(plain.size(), 3u); // n = 1, 2, 3
  for (const InteractionLine& l : plain)
    EXPECT_EQ(l.casing_lobes, l.nodal_diameter);
  ASSERT_EQ(all.size(), 9u); // n = 1 .. 7, 9, 12 (n = 0 never)
  int previous = 0;
  for (const InteractionLine& l : all) {
    const int n = l.casing_lobes, k = l.nodal_diameter;
    EXPECT_GT(n, previous); // ordered by lobes
    previous = n;
    EXPECT_EQ(k, aliased_nodal_diameter(n, 6));
    for (int j = 0; j < 6; ++j) // the pattern at the tips: k's, exactly (integer phases)
      EXPECT_TRUE((n * j - k * j) % 6 == 0 || (n * j + k * j) % 6 == 0) << "n " << n << " j " << j;
    EXPECT_EQ(l.blade_hz, 290.0 + k);
    EXPECT_NEAR(n * l.speed_rad_s / (2.0 * M_PI) - l.casing_hz, l.blade_hz, 1e-12 * l.casing_hz);
  }
  EXPECT_EQ(all[3].casing_lobes, 4);
  EXPECT_EQ(all[3].nodal_diameter, 2);
  EXPECT_EQ(all[5].casing_lobes, 6);
  EXPECT_EQ(all[5].nodal_diameter, 0);
  EXPECT_EQ(all[8].casing_lobes, 12);
  EXPECT_EQ(all[8].nodal_diameter, 0);
}

} // namespace
} // namespace rsi
