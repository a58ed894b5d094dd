// V5 (issue 26): the liner step solved directly where every touching contact
// slips (reduced/liner_slip_set.hpp), the start of the liner's Gauss-Seidel:
//   - PatchCompliantSolve::piece: the line it returns is the sum of the bars'
//     own laws (AbradableCells::bar) at depths across its piece;
//   - one decoupled contact against patch_compliant (the patch's root
//     search, written apart), on a fresh liner (the rigid stand-in path) and
//     on worn, hardened bars;
//   - random coupled sliding problems: the answer holds the patch law and
//     Coulomb's slip law within bounds derived from the slip set's
//     acceptance (coulomb_slip_set.hpp) and patch_compliant's rounding;
//   - declines (stick, a flat perfectly plastic piece) leave lambda as it
//     was; bad arguments.
//
// Units: mm, N, MPa. The cells: r 250, h 2, 8 x 4 cells over z in [0, 8]
// (area 392.7 mm2), E 1000, sigma_y 10, H 300: k = 1.96e5 N/mm, the fresh
// yield depth dy = 0.02 mm. W's normal entries about 1e-5 mm/N (a tip's
// static flexibility, k W_nn about 2), slips of 5-10 mm a step.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "abradable_cells.hpp"
#include "abradable_cells_fixture.hpp"
#include "liner_patch_cells.hpp"
#include "liner_slip_set.hpp"
#include "random_delassus.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
using VectorL = Eigen::Matrix<long double, Eigen::Dynamic, 1>;

AbradableCells cells_with(double hardening) {
  return AbradableCells(abradable_test_geometry(), abradable_test_material(hardening));
}

/// Bars worn by the given numbers of fresh yield depths, each hardened by
/// its wear.
std::vector<BarState> worn_bars(const AbradableCells& cells, std::vector<double> wear_in_dy) {
  const double fy0 = 10.0 * cells.area(), dy = fy0 / cells.stiffness();
  std::vector<BarState> from;
  for (double p : wear_in_dy)
    from.push_back(BarState{p * dy, fy0 + cells.hardening_stiffness() * p * dy});
  return from;
}

double bars_force(const AbradableCells& cells, const std::vector<BarState>& from, double d) {
  double g = 0.0;
  for (const BarState& s : from)
    g += cells.bar(s, d - s.wear).force;
  return g;
}

TEST(LinerPatchPiece, TheLineIsTheBarsSumOnItsPiece) {
  const AbradableCells cells = cells_with(300.0);
  const std::vector<BarState> from = worn_bars(cells, {0.0, 0.3, 1.0, 2.5, 6.0});
  const double k = cells.stiffness(), dy = 10.0 * cells.area() / k, p_max = 6.0 * dy;
  const double n = static_cast<double>(from.size());
  double fy_sum = 0.0;
  for (const BarState& s : from)
    fy_sum += s.yield_force;
  PatchCompliantSolve solve;
  double worst = 0.0;
  int pieces_seen = 0;
  double last_lower = std::nan("");
  for (int s = 0; s <= 1000; ++s) {
    const double d = -dy + 10.0 * dy * s / 1000.0;
    const LinearPiece p = solve.piece(cells, from, d);
    ASSERT_LE(p.lower, d);
    ASSERT_LT(d, p.upper);
    if (!(p.lower == last_lower)) ++pieces_seen, last_lower = p.lower;
    if (d < 0.0) { // below every bar (the least wear is 0)
      EXPECT_EQ(p.slope, 0.0);
      EXPECT_EQ(p.intercept, 0.0);
      EXPECT_EQ(p.lower, -std::numeric_limits<double>::infinity());
      EXPECT_EQ(p.upper, 0.0);
    }
    // Tolerance: the line and the bars' sum each add at most 2n terms of
    // size at most k (|d| + p_max) + F_Y (one rounding each, and one for each
    // bar's own few operations): 4 (n + 2) eps of that size.
    const double tolerance = 4.0 * (n + 2.0) * eps * (n * k * (std::abs(d) + p_max) + fy_sum);
    const double error = std::abs(p.slope * d + p.intercept - bars_force(cells, from, d));
    worst = std::max(worst, error / tolerance);
    EXPECT_LE(error, tolerance) << "depth " << d;
  }
  std::printf("piece against the bars' sum: %d pieces, worst error / tolerance %.3g\n", pieces_seen,
              worst);
  // Below every bar, then one a distinct breakpoint: the wears 0, 0.3, 1,
  // 2.5, 6 dy and the yield depths p + (1 + 0.3 p) dy = 1, 1.39, 2.3, 4.25,
  // 8.8 dy, the fresh bar's yield depth at the third bar's wear (both dy).
  EXPECT_EQ(pieces_seen, 10);
}

/// The absolute sum of the terms that form a piece's intercept b over the
/// bars touching at `lower` (k p_i elastic, k (F_Y,i + k_H p_i) / (k + k_H)
/// yielding): b's rounding is relative to it, not to |b| (they cancel).
double intercept_terms(const AbradableCells& cells, const std::vector<BarState>& bars,
                       double lower) {
  const double k = cells.stiffness(), kh = cells.hardening_stiffness();
  double sum = 0.0;
  for (const BarState& s : bars) {
    if (!(s.wear <= lower)) continue;
    sum += s.wear + s.yield_force / k <= lower ? k * (s.yield_force + kh * s.wear) / (k + kh)
                                               : k * s.wear;
  }
  return sum;
}

/// Contact c's law over `patches` (the test's stand-in for the liner's
/// placement).
LinerSlipSet::PieceAt pieces_of(const AbradableCells& cells,
                                std::vector<std::vector<BarState>>& patches,
                                std::vector<PatchCompliantSolve>& solves) {
  return [&](int c, double depth) { return solves[c].piece(cells, patches[c], depth); };
}

/// lambda_n against patch_compliant for one decoupled contact (W diagonal),
/// from the warm start lambda_n = warm; returns the slip-set solves.
int expect_decoupled(const AbradableCells& cells, const std::vector<BarState>& bars,
                     double depth_pred, double warm = 0.0) {
  const double wn = 1e-5, wt = 2e-5, mu = 0.15;
  Eigen::MatrixXd w = Eigen::Vector3d(wn, wt, wt).asDiagonal();
  Eigen::VectorXd predicted(3);
  predicted << -depth_pred, 3.0, -4.0;
  std::vector<std::vector<BarState>> patches{bars};
  std::vector<PatchCompliantSolve> solves(1);
  LinerSlipSet set(mu);
  Eigen::VectorXd lambda = Eigen::Vector3d(warm, 0.0, 0.0);
  const bool accepted = set.solve(w, predicted, pieces_of(cells, patches, solves), lambda);
  EXPECT_TRUE(accepted);
  if (!accepted) return 0;
  std::vector<BarResponse> responses;
  const double f = patch_compliant(cells, bars, depth_pred, wn, responses);
  // Tolerance: the slip set's closed-gap residual r <= (6 + 10) eps T'
  // (its header, k = 1), T' = |g~'| + |W' lambda|, moves lambda_n by
  // r / W'_nn; the piece's line forms g~' = g~ - b/a from n-term sums,
  // (n + 4) eps (|g~| + B / a) / W'_nn with B the absolute sum of b's terms
  // (intercept_terms); patch_compliant rounds 4 (n + 8) eps F
  // (test_abradable_cells, JointRootAgainstBisection).
  const double n = static_cast<double>(bars.size());
  PatchCompliantSolve probe;
  const LinearPiece p = probe.piece(cells, bars, depth_pred - wn * f);
  EXPECT_GT(p.slope, 0.0);
  if (!(p.slope > 0.0)) return 0;
  const double w_series = wn + 1.0 / p.slope;
  const double g_series = -depth_pred - p.intercept / p.slope;
  const double terms = std::abs(g_series) + w_series * lambda(0);
  const double tolerance =
      (16.0 * terms + (n + 4.0) * (depth_pred + intercept_terms(cells, bars, p.lower) / p.slope)) *
          eps / w_series +
      4.0 * (n + 8.0) * eps * f;
  std::printf("decoupled: lambda_n %.17g, patch_compliant %.17g, difference %.3g (tolerance %.3g), "
              "%d solves\n",
              lambda(0), f, std::abs(lambda(0) - f), tolerance, set.iterations());
  EXPECT_GT(f, 0.0);
  EXPECT_LE(std::abs(lambda(0) - f), tolerance);
  // Slip against s~: W_tt = wt I, so s = s~ - mu wt lambda_n e stays parallel
  // to s~ = (3, -4) and the exact direction is e = (0.6, -0.8). Bound:
  // 8 sqrt2 eps (the slip set's accepted direction move) + 4 sqrt2 eps (its
  // direction s/|s| against e: s's rounding and the normalisation's, 2 eps
  // an entry each) + sqrt2 eps (lambda_t's own rounding) = 18.4 eps of
  // mu lambda_n.
  const Eigen::Vector2d e(0.6, -0.8);
  EXPECT_LE((lambda.tail<2>() + mu * lambda(0) * e).norm(), 18.4 * eps * mu * lambda(0));
  return set.iterations();
}

TEST(LinerSlipSet, DecoupledContactIsThePatchCompliantSolve) {
  const AbradableCells cells = cells_with(300.0);
  const double dy = 10.0 * cells.area() / cells.stiffness();
  // Fresh bars (elastic, then yielding): the first piece is the bars' at
  // the predicted depth; past the yield depth the first line overshoots and
  // the pieces move.
  for (double depth : {0.5 * dy, 3.0 * dy, 20.0 * dy})
    expect_decoupled(cells, worn_bars(cells, {0.0, 0.0, 0.0, 0.0, 0.0}), depth);
  // Worn and hardened bars: some off, some elastic, some yielding.
  for (double depth : {0.7 * dy, 2.0 * dy, 8.0 * dy})
    expect_decoupled(cells, worn_bars(cells, {0.0, 0.3, 1.0, 2.5, 6.0}), depth);
  // The rigid stand-in: bars worn by 1 to 4 dy, a warm start that leaves
  // the tip at 0.5 dy (short of every bar); the slip set closes it on the
  // stand-in at the least wear (g~ + p_min = -1.5 dy), then the piece moves
  // onto the bars: at least two solves.
  const double wn = 1e-5;
  EXPECT_GE(
      expect_decoupled(cells, worn_bars(cells, {1.0, 1.5, 2.0, 3.0, 4.0}), 2.5 * dy, 2.0 * dy / wn),
      2);
}

/// W = B M^-1 B^T scaled to normal entries about 1e-5 mm/N
/// (random_delassus.hpp).
Eigen::MatrixXd random_w(int n, int rows, std::mt19937& rng) {
  return random_delassus(n, rows, 1e-5 / n, rng);
}

// Random coupled problems: 8 contacts, each over 5 bars worn by 0 to 3 yield
// depths; predicted depths from 1 dy short of the surface to 6 dy past it;
// slips of random direction, 5 to 10 mm. Every answer must hold, evaluated in
// long double (64-bit mantissa):
//   - lambda_n >= 0; the bar law: lambda_n,c = F_c, F_c = patch_compliant
//     from d~ = -(g_c - W_nn lambda_n,c) (the Gauss-Seidel's certificate,
//     liner_contact_solve.hpp). With the slip set's closed-gap residual
//     r_c <= (6k + 10) eps T'_c on W' = W + 1/a (its header), lambda_n,c -
//     F_c = a r_c / (1 + a W_nn) up to patch_compliant's 4 (n + 8) eps F,
//     and forming W' and g~' = g~ - b/a moves r_c by (n + 4) eps (|g~_c| +
//     B/a) (B the absolute sum of b's terms), so |lambda_n,c - F_c| <=
//     [(6k + 10) eps T'_c + (n + 4) eps (|g~_c| + B/a)] / W_nn
//     + 4 (n + 8) eps F + (m + 1) eps T_c / W_nn (g in long double rounded
//     to double);
//   - slipping: |lambda_t + mu lambda_n s/|s|| <= mu lambda_n (8 sqrt 2 eps
//     + 2 sqrt 2 (m + 1) eps T_s / |s|) (the slip set's direction bound, and
//     s's rounding);
//   - open: lambda_c = 0 and -g_c <= the least wear + (m + 1) eps T_c.
TEST(LinerSlipSet, RandomSlidingProblemsHoldTheLaw) {
  const AbradableCells cells = cells_with(300.0);
  const double k = cells.stiffness(), dy = 10.0 * cells.area() / k, mu = 0.15;
  const int nc = 8, m = 3 * nc, problems = 20;
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int accepted = 0, touching = 0, open = 0;
  double worst_law = 0.0, worst_slip = 0.0;
  for (int trial = 0; trial < problems; ++trial) {
    const Eigen::MatrixXd w = random_w(3 * nc + 6, m, rng);
    std::vector<std::vector<BarState>> patches;
    Eigen::VectorXd predicted(m);
    for (int c = 0; c < nc; ++c) {
      std::vector<double> wear;
      for (int i = 0; i < 5; ++i)
        wear.push_back(3.0 * unit(rng));
      patches.push_back(worn_bars(cells, wear));
      const double angle = 2.0 * M_PI * unit(rng), size = 5.0 * (1.0 + unit(rng));
      predicted.segment<3>(3 * c) << -dy * (7.0 * unit(rng) - 1.0), size * std::cos(angle),
          size * std::sin(angle);
    }
    std::vector<PatchCompliantSolve> solves(nc);
    LinerSlipSet set(mu);
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
    if (!set.solve(w, predicted, pieces_of(cells, patches, solves), lambda)) continue;
    ++accepted;
    int k_set = 0;
    for (int c = 0; c < nc; ++c)
      k_set += lambda(3 * c) > 0.0;
    const Eigen::MatrixX<long double> wl = w.cast<long double>();
    const VectorL y = predicted.cast<long double>() + wl * lambda.cast<long double>();
    for (int c = 0; c < nc; ++c) {
      const double ln = lambda(3 * c);
      const double wnn = w(3 * c, 3 * c);
      double row_terms = std::abs(predicted(3 * c)), slip_terms = 0.0;
      for (int j = 0; j < m; ++j) {
        row_terms += std::abs(w(3 * c, j) * lambda(j));
        slip_terms += std::abs(w(3 * c + 1, j) * lambda(j)) + std::abs(w(3 * c + 2, j) * lambda(j));
      }
      slip_terms += predicted.segment<2>(3 * c + 1).cwiseAbs().sum();
      const double g = static_cast<double>(y(3 * c));
      ASSERT_GE(ln, 0.0);
      if (ln == 0.0) {
        ++open;
        EXPECT_EQ(lambda.segment<2>(3 * c + 1).norm(), 0.0);
        double least = std::numeric_limits<double>::infinity();
        for (const BarState& s : patches[c])
          least = std::min(least, s.wear);
        EXPECT_LE(-g, least + (m + 1) * eps * row_terms) << "trial " << trial << " contact " << c;
        continue;
      }
      ++touching;
      std::vector<BarResponse> responses;
      const double f = patch_compliant(cells, patches[c], -(g - wnn * ln), wnn, responses);
      // The piece the answer lies on (at the least wear if -g rounds below it).
      double least = std::numeric_limits<double>::infinity();
      for (const BarState& s : patches[c])
        least = std::min(least, s.wear);
      PatchCompliantSolve probe;
      const LinearPiece p = probe.piece(cells, patches[c], std::max(-g, least));
      ASSERT_GT(p.slope, 0.0) << "trial " << trial << " contact " << c;
      const double b_terms = intercept_terms(cells, patches[c], p.lower) / p.slope;
      const double series_terms = row_terms + ln / p.slope + b_terms; // T'_c
      const double law_tolerance =
          (6.0 * k_set + 10.0) * eps * series_terms / wnn +
          (5.0 + 4.0) * eps * (std::abs(predicted(3 * c)) + b_terms) / wnn +
          4.0 * (5.0 + 8.0) * eps * std::max(f, ln) + (m + 1) * eps * row_terms / wnn;
      worst_law = std::max(worst_law, std::abs(ln - f) / law_tolerance);
      EXPECT_LE(std::abs(ln - f), law_tolerance) << "trial " << trial << " contact " << c;
      const Eigen::Vector2d s(static_cast<double>(y(3 * c + 1)), static_cast<double>(y(3 * c + 2)));
      const double slip_tolerance = mu * ln *
                                    (8.0 * std::sqrt(2.0) * eps +
                                     2.0 * std::sqrt(2.0) * (m + 1) * eps * slip_terms / s.norm());
      const double slip_error = (lambda.segment<2>(3 * c + 1) + mu * ln * s / s.norm()).norm();
      worst_slip = std::max(worst_slip, slip_error / slip_tolerance);
      EXPECT_LE(slip_error, slip_tolerance) << "trial " << trial << " contact " << c;
    }
  }
  std::printf("random liner problems: %d of %d accepted, %d touching and %d open contacts; worst "
              "law residual / tolerance %.3g, slip %.3g\n",
              accepted, problems, touching, open, worst_law, worst_slip);
  // Every contact slides 5-10 mm a step past forces whose slips are 1e-4 of
  // that: no stick, no reversal, so the slip set has no reason to decline.
  EXPECT_EQ(accepted, problems);
  EXPECT_GT(touching, 0);
  EXPECT_GT(open, 0);
}

TEST(LinerSlipSet, DeclinesStickAndAFlatPieceLeavingLambda) {
  const double wn = 1e-5, wt = 2e-5, mu = 0.15;
  const Eigen::MatrixXd w = Eigen::Vector3d(wn, wt, wt).asDiagonal();
  const Eigen::VectorXd warm = Eigen::Vector3d(12.5, -0.25, 0.5);
  {
    // No slip predicted: the contact sticks; the slip set declines.
    const AbradableCells cells = cells_with(300.0);
    std::vector<std::vector<BarState>> patches{worn_bars(cells, {0.0, 1.0})};
    std::vector<PatchCompliantSolve> solves(1);
    LinerSlipSet set(mu);
    Eigen::VectorXd lambda = warm;
    EXPECT_FALSE(
        set.solve(w, Eigen::Vector3d(-0.1, 0.0, 0.0), pieces_of(cells, patches, solves), lambda));
    EXPECT_EQ(lambda, warm);
  }
  {
    // H = 0 and every bar past its yield depth: a force independent of the
    // depth, no series spring.
    const AbradableCells cells = cells_with(0.0);
    std::vector<std::vector<BarState>> patches{worn_bars(cells, {0.0, 0.0})};
    std::vector<PatchCompliantSolve> solves(1);
    LinerSlipSet set(mu);
    Eigen::VectorXd lambda = warm;
    const double dy = 10.0 * cells.area() / cells.stiffness();
    EXPECT_FALSE(set.solve(w, Eigen::Vector3d(-50.0 * dy, 3.0, 4.0),
                           pieces_of(cells, patches, solves), lambda));
    EXPECT_EQ(lambda, warm);
  }
  {
    // H = 0, bars worn 0 and 3 dy, k W_nn = 0.5, predicted depth 3.2 dy: the
    // first line (both bars, the second elastic) lands at 2.8 dy, on the
    // flat piece of the first bar alone (the answer, F_Y, lies there): a
    // flat piece in the middle of the law is declined, not taken.
    const AbradableCells cells = cells_with(0.0);
    const double k = cells.stiffness(), dy = 10.0 * cells.area() / k;
    std::vector<std::vector<BarState>> patches{worn_bars(cells, {0.0, 3.0})};
    std::vector<PatchCompliantSolve> solves(1);
    LinerSlipSet set(mu);
    const Eigen::MatrixXd w_stiff = Eigen::Vector3d(0.5 / k, wt, wt).asDiagonal();
    Eigen::VectorXd lambda = warm;
    EXPECT_FALSE(set.solve(w_stiff, Eigen::Vector3d(-3.2 * dy, 3.0, 4.0),
                           pieces_of(cells, patches, solves), lambda));
    EXPECT_EQ(lambda, warm);
  }
}

TEST(LinerSlipSet, RefusesBadArguments) {
  EXPECT_THROW(LinerSlipSet(0.0), std::invalid_argument);
  EXPECT_THROW(LinerSlipSet(std::nan("")), std::invalid_argument);
  const AbradableCells cells = cells_with(300.0);
  std::vector<std::vector<BarState>> patches{worn_bars(cells, {0.0})};
  std::vector<PatchCompliantSolve> solves(1);
  LinerSlipSet set(0.15);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(set.solve(Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Zero(6),
                         pieces_of(cells, patches, solves), lambda),
               std::invalid_argument);
}

} // namespace
} // namespace rsi
