// V2 frequencies (SPEC §4): a straight clamped-free beam of n frame elements
// (reference/frame_element, assembled with reference/assembler, solved with
// reference/modal_analysis) against the exact Euler-Bernoulli cantilever and
// the exact fixed-free bar.
//
// Exact bending: omega_k^2 = beta_k^4 EI / (rho A L^4), cos(beta) cosh(beta) = -1
// (Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1).
// Exact axial: omega_k = (2k - 1) pi c / (2L), c = sqrt(E / rho).
//
// Expected rates. Bending: cubic Hermite (p = 3) for a fourth-order problem
// (m = 2) with consistent mass: eigenvalue error O(h^{2(p+1-m)}) = O(h^4)
// (Strang & Fix, An Analysis of the Finite Element Method, ch. 6). Axial:
// linear elements (p = 1, m = 1): O(h^2). The FE space is conforming, so
// every discrete eigenvalue lies above the exact one (min-max).
//
// Round-off. dsygvd solves C = L^-1 K L^-T, so each computed eigenvalue
// carries an absolute error of about eps ||C|| = eps omega_max^2, i.e. a
// relative floor eps omega_max^2 / omega_k^2. The frame model's axial
// stiffness makes omega_max^2 large (1e14 at n = 64), so for the lowest
// bending mode that floor reaches 1e-6 at n = 64, above the discretization
// error. Each mode is therefore measured on the three meshes starting at
// the first one with beta_k h <= 1 (about six elements per wavelength, the
// asymptotic range), and the test checks that each error used lies at
// least 100 x above the floor, so round-off moves an observed rate by at
// most log2(1.01 / 0.99) = 0.03.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "assembler.hpp"
#include "beam_properties.hpp"
#include "frame_element.hpp"
#include "modal_analysis.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
const Material steel{210e9, 7800};
// Width (out of plane) x thickness (in plane): L / thickness = 100.
const Section slender{0.03, 0.002};
constexpr double length = 0.2;
const BeamProperties beam = beam_properties(steel, slender);
const std::vector<int> meshes = {2, 4, 8, 16, 32, 64};
constexpr int n_modes = 5;

/// beta_k (= beta_k L, dimensionless), the k-th positive root (k = 1, 2, ...) of cos(beta)
/// cosh(beta) = -1, written cos(beta) + 1 / cosh(beta) = 0 (same roots, bounded values), by GSL
/// Brent on [(2k - 1) pi / 2 - 0.5, (2k - 1) pi / 2 + 0.5].
double cantilever_root(int k) {
  gsl_function f;
  f.function = [](double beta, void*) { return std::cos(beta) + 1.0 / std::cosh(beta); };
  f.params = nullptr;
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  const double centre = (2 * k - 1) * M_PI / 2;
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  int status = gsl_root_fsolver_set(solver.get(), &f, centre - 0.5, centre + 0.5);
  for (int iter = 0; status == GSL_SUCCESS && iter < 200; ++iter) {
    status = gsl_root_fsolver_iterate(solver.get());
    if (status != GSL_SUCCESS) break;
    const double lo = gsl_root_fsolver_x_lower(solver.get());
    const double hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 0.0, 4 * eps) == GSL_SUCCESS) break;
  }
  gsl_set_error_handler(previous);
  if (status != GSL_SUCCESS)
    throw std::runtime_error("cantilever_root: GSL Brent failed for k = " + std::to_string(k) +
                             " (" + gsl_strerror(status) + ")");
  return gsl_root_fsolver_root(solver.get());
}

double exact_bending_omega2(int k) {
  const double beta = cantilever_root(k);
  return std::pow(beta, 4) * beam.EI / (beam.rhoA * std::pow(length, 4));
}

double exact_axial_omega2(int k) {
  const double omega =
      (2 * k - 1) * M_PI * std::sqrt(steel.young_modulus / steel.density) / (2 * length);
  return omega * omega;
}

/// The spectrum of the clamped-free beam of n elements along x, sorted into
/// bending and axial modes by the share of the modal mass in the transverse
/// dofs (u_y, theta), not by position in the spectrum.
struct CantileverSpectrum {
  std::vector<double> bending; ///< omega^2 ascending [rad^2/s^2]
  std::vector<double> axial;
  double omega_max2 = 0.0;
  double worst_mixing = 0.0; ///< max over modes of min(transverse share, axial share)
};

CantileverSpectrum cantilever_spectrum(int n) {
  // Node 0 clamped; node i >= 1 owns dofs 3(i-1) + (0: u_x, 1: u_y, 2: theta).
  Assembler assembler(3 * n);
  const double h = length / n;
  for (int e = 0; e < n; ++e) {
    std::vector<DofCombination> map;
    for (int node : {e, e + 1})
      for (int d = 0; d < 3; ++d)
        map.push_back(node == 0 ? DofCombination{} : DofCombination{{3 * (node - 1) + d, 1.0}});
    assembler.add(frame_stiffness(beam, h, 0.0), frame_mass(beam, h, 0.0), map);
  }
  const Eigen::SparseMatrix<double> k = assembler.stiffness();
  const Eigen::SparseMatrix<double> m = assembler.mass();
  const Modes modes = lowest_modes(k, m, 3 * n);
  CantileverSpectrum s;
  s.omega_max2 = modes.omega_max * modes.omega_max;
  for (int i = 0; i < modes.n_modes(); ++i) {
    Eigen::VectorXd transverse = modes.shapes.col(i);
    for (int j = 0; j < 3 * n; j += 3)
      transverse(j) = 0.0;
    // Shapes are mass-normalised and M has no axial-transverse coupling, so
    // the transverse share and the axial share add up to 1.
    const double share = transverse.dot(m * transverse);
    s.worst_mixing = std::max(s.worst_mixing, std::min(share, 1.0 - share));
    (share > 0.5 ? s.bending : s.axial).push_back(modes.omega_squared(i));
  }
  return s;
}

/// Index in `meshes` of the coarsest mesh with wavenumber * h <= 1.
size_t first_resolved_mesh(double wavenumber) {
  for (size_t i = 0; i < meshes.size(); ++i)
    if (wavenumber * length / meshes[i] <= 1.0) return i;
  return meshes.size();
}

std::vector<CantileverSpectrum> all_spectra() {
  std::vector<CantileverSpectrum> spectra;
  for (int n : meshes)
    spectra.push_back(cantilever_spectrum(n));
  return spectra;
}

TEST(Cantilever, FrequencyEquationRoots) {
  // Blevins, table 8-1 (clamped-free), 9 significant digits.
  const double table[n_modes] = {1.87510407, 4.69409113, 7.85475744, 10.9955407, 14.1371684};
  for (int k = 1; k <= n_modes; ++k) {
    const double beta = cantilever_root(k);
    const double residual = std::cos(beta) * std::cosh(beta) + 1.0;
    std::printf("beta_%d = %.15f (table %.9f), cos cosh + 1 = %.2e\n", k, beta, table[k - 1],
                residual);
    // The table is rounded to 9 significant digits: |difference| <= half a unit in the last digit.
    EXPECT_NEAR(beta, table[k - 1], 0.5e-8 * std::pow(10.0, std::floor(std::log10(beta))));
    // |d(cos cosh)/d beta| <= 2 cosh(beta): a root to 4 eps leaves <= 8 eps beta cosh(beta).
    EXPECT_LE(std::abs(residual), 8 * eps * beta * std::cosh(beta));
  }
}

TEST(Cantilever, ModesSplitIntoBendingAndAxial) {
  for (int n : meshes) {
    const CantileverSpectrum s = cantilever_spectrum(n);
    std::printf("n = %2d: %zu bending, %zu axial modes, worst mixing %.2e\n", n, s.bending.size(),
                s.axial.size(), s.worst_mixing);
    // Dimension count: 2 transverse dofs (u_y, theta) and 1 axial dof per free node.
    EXPECT_EQ(s.bending.size(), static_cast<size_t>(2 * n));
    EXPECT_EQ(s.axial.size(), static_cast<size_t>(n));
    // Angle 0: cos = 1, sin = 0 exactly, K and M decouple; mixing is round-off (1e-15 seen).
    EXPECT_LE(s.worst_mixing, 1e-9);
  }
}

TEST(Cantilever, BendingFrequenciesConvergeAtFourthOrder) {
  const std::vector<CantileverSpectrum> spectra = all_spectra();
  std::printf("relative eigenvalue error e = omega_h^2 / omega^2 - 1 of the bending modes; "
              "floor = eps omega_max^2 / omega^2 (round-off of dsygvd)\n");
  for (int k = 1; k <= n_modes; ++k) {
    const double beta = cantilever_root(k);
    const double exact = exact_bending_omega2(k);
    const size_t first = first_resolved_mesh(beta / length);
    ASSERT_LE(first + 2, meshes.size() - 1) << "mode " << k << " needs finer meshes";
    std::printf("mode %d: f = %.6f Hz, beta = %.6f\n", k, std::sqrt(exact) / (2 * M_PI), beta);
    std::vector<double> errors;
    for (size_t i = 0; i < meshes.size(); ++i) {
      const CantileverSpectrum& s = spectra[i];
      if (static_cast<int>(s.bending.size()) < k) continue;
      const double e = s.bending[k - 1] / exact - 1.0;
      const double floor = eps * s.omega_max2 / exact;
      const bool used = i >= first && i <= first + 2;
      const double beta_h = beta / meshes[i]; // beta is beta_k L, dimensionless
      std::printf("  n = %2d: beta h = %.3f, f_h = %.6f Hz, e = %.4e, floor = %.1e, e / (beta h)^4 "
                  "= %.4e%s\n",
                  meshes[i], beta_h, std::sqrt(s.bending[k - 1]) / (2 * M_PI), e, floor,
                  e / std::pow(beta_h, 4), used ? "  [used]" : "");
      if (!used) continue;
      // Round-off guard (see the file header): the error must stand 100 x above the dsygvd floor.
      EXPECT_GE(e, 100 * floor) << "mode " << k << ", n = " << meshes[i];
      errors.push_back(e);
    }
    ASSERT_EQ(errors.size(), 3u);
    for (size_t j = 0; j + 1 < errors.size(); ++j) {
      const double rate = std::log2(errors[j] / errors[j + 1]);
      std::printf("  observed rate n = %d -> %d: %.3f\n", meshes[first + j], meshes[first + j + 1],
                  rate);
      // Strang-Fix h^4; 0.25: O((beta h)^2) next term, |coef| <= 0.2 (0.11 seen), at beta h <= 1.
      EXPECT_GE(rate, 4.0 - 0.25) << "mode " << k;
      EXPECT_LE(rate, 4.0 + 0.25) << "mode " << k;
    }
    const double bound = errors[0] * std::pow(4.0, -(4.0 - 0.25));
    std::printf("  finest error %.4e <= coarsest error x 4^-(4 - 0.25) = %.4e\n", errors[2], bound);
    // Rate 4 - 0.25 (above) over two halvings applied to the coarsest error of the three.
    EXPECT_LE(errors[2], bound) << "mode " << k;
  }
}

TEST(Cantilever, AxialFrequenciesMatchDiscreteBarAndConvergeAtSecondOrder) {
  const std::vector<CantileverSpectrum> spectra = all_spectra();
  const double c = std::sqrt(steel.young_modulus / steel.density);
  std::printf("relative eigenvalue error e = omega_h^2 / omega^2 - 1 of the axial modes\n");
  for (int k = 1; k <= n_modes; ++k) {
    const double wavenumber = (2 * k - 1) * M_PI / (2 * length);
    const double exact = exact_axial_omega2(k);
    const size_t first = first_resolved_mesh(wavenumber);
    ASSERT_LE(first + 2, meshes.size() - 1) << "mode " << k << " needs finer meshes";
    std::printf("mode %d: f = %.3f Hz\n", k, std::sqrt(exact) / (2 * M_PI));
    std::vector<double> errors;
    for (size_t i = 0; i < meshes.size(); ++i) {
      const CantileverSpectrum& s = spectra[i];
      if (static_cast<int>(s.axial.size()) < k) continue;
      // The sampled sin(kx) is an exact discrete eigenvector of the uniform fixed-free bar with
      // consistent mass (the free-end row is the symmetric extension about x = L, valid because
      // kL = (2k - 1) pi / 2); its eigenvalue is 6 (c/h)^2 (1 - cos kh) / (2 + cos kh).
      const double h = length / meshes[i];
      const double half = std::sin(wavenumber * h / 2);
      const double discrete = 12 * c * c / (h * h) * half * half / (2 + std::cos(wavenumber * h));
      const double deviation = std::abs(s.axial[k - 1] / discrete - 1.0);
      const double floor = eps * s.omega_max2 / exact;
      const double e = s.axial[k - 1] / exact - 1.0;
      const bool used = i >= first && i <= first + 2;
      std::printf(
          "  n = %2d: kh = %.3f, e = %.4e, |FE / discrete formula - 1| = %.2e, floor = %.1e%s\n",
          meshes[i], wavenumber * h, e, deviation, floor, used ? "  [used]" : "");
      // Closed-form discrete eigenvalue: dsygvd error eps omega_max^2, x4 for LAPACK's p(n).
      EXPECT_LE(deviation, 4 * floor) << "mode " << k << ", n = " << meshes[i];
      if (!used) continue;
      // Round-off guard: the error must stand 100 x above the dsygvd floor.
      EXPECT_GE(e, 100 * floor) << "mode " << k << ", n = " << meshes[i];
      errors.push_back(e);
    }
    ASSERT_EQ(errors.size(), 3u);
    for (size_t j = 0; j + 1 < errors.size(); ++j) {
      const double rate = std::log2(errors[j] / errors[j + 1]);
      std::printf("  observed rate n = %d -> %d: %.3f\n", meshes[first + j], meshes[first + j + 1],
                  rate);
      // Formula above: e = (kh)^2/12 (1 + (kh)^2/30 + ..), kh <= 1: |rate - 2| <= 0.036 (+
      // round-off).
      EXPECT_NEAR(rate, 2.0, 0.05) << "mode " << k;
    }
    const double bound = errors[0] * std::pow(4.0, -(2.0 - 0.05));
    std::printf("  finest error %.4e <= coarsest error x 4^-(2 - 0.05) = %.4e\n", errors[2], bound);
    // Rate 2 - 0.05 (above) over two halvings applied to the coarsest error of the three.
    EXPECT_LE(errors[2], bound) << "mode " << k;
  }
}

} // namespace
} // namespace rsi
