// The parametric K(Omega) of rotation_fit.hpp on the gmsh blade, fitted at
// 200, 400, 800, 1200, 1600, 2000 rad/s (2 deflection shapes: the fit the
// study in reports/rotation-fit measured), against ccx run in the test.
//
// 1. At the fit speeds the model is ccx's K and deflection, to the p x p
//    solve's rounding: cond(F) eps times the entries' scale.
// 2. At speeds outside the fit (600, 1000, 1400 rad/s) the lowest
//    eigenvalues of (K(Omega), M) against ccx's own prestressed Lanczos at
//    those speeds, and the tip's radial growth against ccx's static
//    deflection there. The tolerance is the fit's truncation estimated
//    from the fit's own data (not from ccx at the test speed), as an
//    embedded pair estimates a step's error: the model interpolates ccx's K
//    at the 7 nodes 0 and the fit speeds through a(s), and between nodes
//    errs by its interpolation error; the same model with a coarser spline
//    (one neighbouring fit node left out, the matrices kept: twice the
//    local h, 16 times the O(h^4) error) differs from it by about 15 times
//    its error. The larger of the two neighbours' differences, plus ccx's
//    7 printed digits, is asserted: on each lambda_i, and on the tip's
//    growth as its largest over the 16 contact nodes (an estimate of a
//    norm, not of each node's error).
// 3. Omega = 0 is the model at rest bit for bit; beyond the highest fit
//    speed the model refuses (CaseError).
//
// Skipped (GTEST_SKIP, reason printed) when ccx or gmsh is not on PATH.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "calculix_run.hpp"
#include "case_file.hpp"
#include "child_process.hpp"
#include "component_case.hpp"
#include "gmsh_blade_fit.hpp"
#include "modal_analysis.hpp"
#include "rotation_fit.hpp"

namespace {

const std::vector<double>& fit_speeds = rsi::testing::blade_fit_speeds();
constexpr double eps = 2.220446049250313e-16;
/// ccx prints omega^2 and the displacements to 7 significant digits.
constexpr double ccx_digits = 5e-7;

class RotationFitBlade : public rsi::testing::GmshBladeFit {};

double largest(const Eigen::SparseMatrix<double>& a) {
  double m = 0.0;
  for (int k = 0; k < a.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it)
      m = std::max(m, std::abs(it.value()));
  return m;
}

/// Node ids of the component's boundary (the tip's contact nodes).
std::vector<int> boundary_nodes(const rsi::Component& component) {
  std::vector<int> nodes;
  for (int i : component.boundary)
    if (nodes.empty() || nodes.back() != component.dofs[static_cast<size_t>(i)].node)
      nodes.push_back(component.dofs[static_cast<size_t>(i)].node);
  return nodes;
}

/// The fit with fit speed `drop` left out of the spline's nodes (the
/// matrices stay): a coarser spline.
rsi::RotationFit without_node(const rsi::RotationFit& f, size_t drop) {
  rsi::RotationFit coarser = f;
  coarser.fit_speeds.erase(coarser.fit_speeds.begin() + static_cast<long>(drop));
  const Eigen::Index n = f.node_deflections.rows(), cols = f.node_deflections.cols();
  coarser.node_deflections.resize(n, cols - 1);
  Eigen::Index k = 0;
  for (Eigen::Index j = 0; j < cols; ++j)
    if (j != static_cast<Eigen::Index>(drop) + 1) coarser.node_deflections.col(k++) = f.node_deflections.col(j);
  return coarser;
}

TEST_F(RotationFitBlade, ReproducesCcxAtTheFitSpeeds) {
  std::printf("feature matrix cond_2 = %.3e, rank %d of 6\n", fit.feature_condition, fit.feature_rank);
  // The blade deflects nonlinearly in s (it stiffens): all 6 features count.
  EXPECT_EQ(fit.feature_rank, 6);
  for (size_t j = 0; j < fit_speeds.size(); ++j) {
    const rsi::RotatingComponent ccx = rsi::rotating_component(c, options, fit_speeds[j]);
    const rsi::RotatingComponent model = rsi::rotating_component_at(fit, fit_speeds[j]);
    const double k_error = largest(model.component.stiffness - ccx.component.stiffness) /
                           largest(ccx.component.stiffness);
    const double u_error = (model.deflection - ccx.deflection).cwiseAbs().maxCoeff() /
                           ccx.deflection.cwiseAbs().maxCoeff();
    std::printf("%6.0f rad/s: max |K_model - K_ccx| / max |K_ccx| = %.2e, deflection %.2e\n",
                fit_speeds[j], k_error, u_error);
    // C = F^-1 D by LU: forward error <= cond(F) eps per term (Higham, LU
    // with pivoting), 6 terms summed, each |C_q f_q| <= |K_ccx| times
    // cond(F): 100 cond(F) eps covers the growth and the sums.
    EXPECT_LT(k_error, 100.0 * fit.feature_condition * eps);
    // The spline interpolates its nodes: exact at the interior nodes, one
    // cubic's evaluation (4 roundings) at the last.
    EXPECT_LT(u_error, 16.0 * eps);
  }
}

TEST_F(RotationFitBlade, FrequenciesAndTipGrowthBetweenFitSpeedsAgainstCcx) {
  const int count = 5;
  const std::vector<int> tip = boundary_nodes(fit.rest);
  const rsi::Modes rest_modes = rsi::lowest_modes(fit.rest.stiffness, fit.rest.mass, count);
  for (double speed : {600.0, 1000.0, 1400.0}) {
    const rsi::RotatingComponent model = rsi::rotating_component_at(fit, speed);
    const rsi::Modes modes = rsi::lowest_modes(model.component.stiffness, model.component.mass, count);
    rsi::CentrifugalLoad load;
    load.omega = speed;
    const std::vector<double> ccx_lambda = rsi::calculix_prestressed_eigenvalues(
        rsi::component_deck(c, options).deck, load, count, options.ccx_cache);
    const rsi::RotatingComponent ccx = rsi::rotating_component(c, options, speed);

    // The spline without each neighbouring fit node (the matrices stay).
    std::vector<rsi::Modes> coarser_modes;
    std::vector<Eigen::VectorXd> coarser_deflections;
    for (size_t j = 0; j + 1 < fit_speeds.size(); ++j) {
      const bool neighbour = (fit_speeds[j] < speed && fit_speeds[j + 1] > speed) ||
                             (fit_speeds[j] > speed && (j == 0 || fit_speeds[j - 1] < speed));
      if (!neighbour) continue;
      rsi::RotationFit coarser = without_node(fit, j);
      const rsi::RotatingComponent at = rsi::rotating_component_at(coarser, speed);
      coarser_modes.push_back(rsi::lowest_modes(at.component.stiffness, at.component.mass, count));
      coarser_deflections.push_back(at.deflection);
    }
    for (int i = 0; i < count; ++i) {
      const double lambda = modes.omega_squared(i);
      double tolerance = ccx_digits;
      for (const rsi::Modes& m : coarser_modes)
        tolerance = std::max(tolerance, std::abs(m.omega_squared(i) / lambda - 1.0) + ccx_digits);
      const double error = std::abs(lambda / ccx_lambda[static_cast<size_t>(i)] - 1.0);
      std::printf("%6.0f rad/s mode %d: f = %.3f Hz (%.3f at rest), |lambda/lambda_ccx - 1| = %.2e, "
                  "tolerance (coarser splines) %.2e\n",
                  speed, i + 1, modes.frequency_hz(i), rest_modes.frequency_hz(i), error, tolerance);
      EXPECT_LT(error, tolerance) << "mode " << i + 1 << " at " << speed << " rad/s";
    }
    double worst_growth = 0.0, growth_tolerance = 0.0;
    for (int node : tip) {
      const double g = rsi::radial_growth(fit.rest, model.deflection, node);
      const double g_ccx = rsi::radial_growth(fit.rest, ccx.deflection, node);
      worst_growth = std::max(worst_growth, std::abs(g - g_ccx));
      for (const Eigen::VectorXd& u : coarser_deflections)
        growth_tolerance = std::max(growth_tolerance, std::abs(g - rsi::radial_growth(fit.rest, u, node)) +
                                                          ccx_digits * std::abs(g_ccx));
    }
    EXPECT_LT(worst_growth, growth_tolerance) << "the tip's growth at " << speed << " rad/s";
    std::printf("%6.0f rad/s: tip growth, largest |g_model - g_ccx| = %.3e mm over %zu nodes "
                "(largest tolerance %.3e mm)\n",
                speed, worst_growth, tip.size(), growth_tolerance);
  }
}

TEST_F(RotationFitBlade, AtRestBitForBitAndNoExtrapolation) {
  const rsi::RotatingComponent still = rsi::rotating_component_at(fit, 0.0);
  EXPECT_EQ(still.component.stiffness.nonZeros(), fit.rest.stiffness.nonZeros());
  EXPECT_EQ(largest(still.component.stiffness - fit.rest.stiffness), 0.0);
  EXPECT_EQ(still.deflection.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(rsi::rotating_component_at(fit, 2000.5), rsi::CaseError);
  EXPECT_NO_THROW(rsi::rotating_component_at(fit, -2000.0));
}

} // namespace
