// Rotation effects (SPEC §9): ccx's prestressed K(Omega) and static
// centrifugal deflection, read by rotating_component.
//
// 1. A straight bar along the radius, r in [r0, R], clamped axially at r0
//    and spinning about z: the tip's radial growth against the closed form
//    of a uniaxial bar under the body force rho Omega^2 r,
//      sigma(r) = rho Omega^2 (R^2 - r^2) / 2,
//      u(R) = rho Omega^2 / E * [R^2 (R - r0) / 2 - (R^3 - r0^3) / 6].
//    A check of what rsi hands ccx (Omega^2, the axis, the sections'
//    element sets) and of the deflection it reads back.
// 2. The gmsh blade at 1344 rad/s: the lowest eigenvalues of the stored
//    prestressed pair (rsi's own eigensolver) against ccx's own perturbed
//    eigenvalues at that speed (its Lanczos in the perturbation step): the
//    stored pair is the rotating blade.
// 3. Omega = 0 is the component load_component builds, bit for bit, with
//    no ccx run of the prestressed kind.
//
// Skipped (GTEST_SKIP, reason printed) when ccx or gmsh is not on PATH.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "calculix_deck.hpp"
#include "calculix_run.hpp"
#include "case_file.hpp"
#include "child_process.hpp"
#include "component_case.hpp"
#include "gmsh_blade_fit.hpp"
#include "modal_analysis.hpp"
#include "rotating_component.hpp"

namespace {

namespace fs = std::filesystem;

#define SKIP_WITHOUT(...)                                                                          \
  do {                                                                                             \
    const std::string why_ = rsi::testing::missing_programs({__VA_ARGS__});                                               \
    if (!why_.empty()) {                                                                           \
      std::printf("skipped: %s not on PATH\n", why_.c_str());                                      \
      GTEST_SKIP() << why_ << " not on PATH";                                                      \
    }                                                                                              \
  } while (0)

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rsi-rotation-" + name + "-" +
                                                    std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct Bar {
  double r0 = 100.0, length = 100.0, side = 4.0; // mm
  int n_axial = 20;                              // C3D8 elements along the bar
  double young = 210000.0, poisson = 0.3, density = 7.85e-9; // N/mm^2, t/mm^3
};

/// Node (i along the bar, j along y, k along z): 9 a cross-section.
int bar_node(int i, int j, int k) { return 1 + i * 9 + j * 3 + k; }

/// A C3D8 bar of 2 x 2 elements in its section, along x from r0. Root face:
/// u_x = 0; its centre node u_y = u_z = 0, and the node at (y = side/2,
/// z = 0) u_z = 0 (the rigid modes, without stopping the Poisson
/// contraction: a uniaxial stress state).
std::string write_bar_deck(const Bar& b, const fs::path& dir) {
  std::ofstream out(dir / "bar.inp");
  out << "*NODE, NSET=NALL\n";
  for (int i = 0; i <= b.n_axial; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        char line[160];
        std::snprintf(line, sizeof line, "%d, %.17g, %.17g, %.17g\n", bar_node(i, j, k),
                      b.r0 + b.length * i / b.n_axial, (j - 1) * b.side / 2, (k - 1) * b.side / 2);
        out << line;
      }
  out << "*ELEMENT, TYPE=C3D8, ELSET=BAR\n";
  int id = 1;
  for (int i = 0; i < b.n_axial; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        const auto n = [&](int di, int dj, int dk) { return bar_node(i + di, j + dj, k + dk); };
        // C3D8: bottom face counter-clockwise seen from the top, then the top face.
        out << id++ << ", " << n(0, 0, 0) << ", " << n(0, 1, 0) << ", " << n(0, 1, 1) << ", "
            << n(0, 0, 1) << ", " << n(1, 0, 0) << ", " << n(1, 1, 0) << ", " << n(1, 1, 1)
            << ", " << n(1, 0, 1) << "\n";
      }
  out << "*BOUNDARY\n";
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) out << bar_node(0, j, k) << ", 1, 1\n";
  out << bar_node(0, 1, 1) << ", 2, 3\n" << bar_node(0, 2, 1) << ", 3, 3\n";
  out << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << b.young << ", " << b.poisson << "\n*DENSITY\n"
      << b.density << "\n*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n";
  return (dir / "bar.inp").string();
}

TEST(RotatingBar, TipGrowthMatchesTheUniaxialClosedForm) {
  SKIP_WITHOUT("ccx");
  const Bar b;
  const fs::path dir = scratch("bar");
  const rsi::CalculixDeck deck = rsi::read_calculix_deck(write_bar_deck(b, dir));
  rsi::CentrifugalLoad load;
  load.omega = 300.0;
  const std::string job =
      rsi::calculix_prestressed_matrices(deck, load, (dir / "cache").string());
  const auto u = rsi::read_calculix_displacements(job + ".dat");
  const double R = b.r0 + b.length;
  const double exact = b.density * load.omega * load.omega / b.young *
                       (R * R * (R - b.r0) / 2 - (R * R * R - b.r0 * b.r0 * b.r0) / 6);
  const double tip = u.at(bar_node(b.n_axial, 1, 1)).x();
  const double error = std::abs(tip / exact - 1.0);
  std::printf("bar r0 = %g, R = %g mm at %g rad/s: tip growth %.7e mm (ccx), %.7e (closed "
              "form), relative difference %.2e\n",
              b.r0, R, load.omega, tip, exact, error);
  // Linear elements give the 1D bar's exact nodal values (the load rho
  // Omega^2 r is integrated exactly by 2x2x2 Gauss points); what remains:
  // the geometric nonlinearity, strain rho Omega^2 R^2 / E = 6e-6 relative,
  // the load at the deflected radius, u/r = 4e-6, the lateral body force
  // rho Omega^2 y through Poisson, nu (side/2R)^2 = 3e-5, and ccx's 7
  // printed digits, 5e-7: 4e-5 in all, asserted at 1e-4.
  EXPECT_LT(error, 1e-4);
  fs::remove_all(dir);
}

const std::string blade_case = RSI_SOURCE_DIR "/data/cases/blade3d.json";

rsi::ComponentCase blade() {
  return rsi::parse_component_case(rsi::read_case_document(blade_case), blade_case);
}

TEST(RotatingBlade, StoredPairHasCcxsPerturbedFrequencies) {
  SKIP_WITHOUT("ccx", "gmsh");
  const fs::path dir = scratch("blade");
  rsi::ComponentLoadOptions options;
  options.ccx_cache = (dir / "cache").string();
  const rsi::ComponentCase c = blade();
  const double speed = 1344.0;
  const rsi::RotatingComponent rotating = rsi::rotating_component(c, options, speed);
  const int count = 10;
  const rsi::Modes modes = rsi::lowest_modes(rotating.component.stiffness, rotating.component.mass, count);
  rsi::CentrifugalLoad load;
  load.omega = speed;
  const std::vector<double> ccx = rsi::calculix_prestressed_eigenvalues(
      rsi::component_deck(c, options).deck, load, count, options.ccx_cache);
  const rsi::Component rest = rsi::load_component(c, options);
  const rsi::Modes rest_modes = rsi::lowest_modes(rest.stiffness, rest.mass, 1);
  double worst = 0.0;
  for (int i = 0; i < count; ++i)
    worst = std::max(worst, std::abs(modes.omega_squared(i) / ccx[i] - 1.0));
  std::printf("gmsh blade at %g rad/s: f1 = %.4f Hz (at rest %.4f Hz), f%d = %.4f Hz; largest "
              "relative difference of omega^2 from ccx's perturbed Lanczos %.2e\n",
              speed, modes.frequency_hz(0), rest_modes.frequency_hz(0), count,
              modes.frequency_hz(count - 1), worst);
  // ccx prints omega^2 to 7 significant digits (5e-7 relative); the stored
  // matrices carry 14 (5e-14): 1e-6 leaves the rest to the two eigensolvers.
  EXPECT_LT(worst, 1e-6);
  fs::remove_all(dir);
}

TEST(RotatingBlade, AtRestIsTheLoadedComponentBitForBit) {
  SKIP_WITHOUT("ccx", "gmsh");
  const fs::path dir = scratch("rest");
  rsi::ComponentLoadOptions options;
  options.ccx_cache = (dir / "cache").string();
  const rsi::ComponentCase c = blade();
  const rsi::Component rest = rsi::load_component(c, options);
  const rsi::RotatingComponent still = rsi::rotating_component(c, options, 0.0);
  EXPECT_EQ(still.component.stiffness.nonZeros(), rest.stiffness.nonZeros());
  EXPECT_EQ(Eigen::MatrixXd(still.component.stiffness - rest.stiffness).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(Eigen::MatrixXd(still.component.mass - rest.mass).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(still.deflection.cwiseAbs().maxCoeff(), 0.0);
  int prestressed = 0;
  for (const auto& entry : fs::directory_iterator(options.ccx_cache))
    prestressed += entry.path().filename().string().find("prestressed") != std::string::npos;
  EXPECT_EQ(prestressed, 0) << "Omega = 0 ran ccx's prestressed step";
  fs::remove_all(dir);
}

} // namespace
