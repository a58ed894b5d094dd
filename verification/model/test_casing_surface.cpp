// The contact surface of a solid casing (reference/model/casing_surface.hpp,
// issue 27 item 3), on decks written here (no gmsh or ccx needed): one
// quadratic tetrahedron whose face S1 lies on a cylinder of radius 100 mm
// about z, its midside nodes on the chords (flat face, as gmsh's
// SecondOrderLinear mesh) or moved onto the cylinder (a curved face).
//
// - The shape functions: N_i(node j) = delta_ij at the six nodes, sum 1
//   everywhere, and a quadratic polynomial reproduced exactly (to round-off,
//   1e-13 of its size: a 6-term sum of O(1) numbers).
// - locate: the point found lies on the tip's ray, X(xi, eta) = (rho cos
//   theta, rho sin theta, z), to 1e-12 mm (Newton's convergence; 1e-12 is
//   1e-14 of the 100 mm radius times a safety of 100), inside the face, and
//   rho = 100 exactly at a corner; a ray past the face's ends is not found.
// - The deck reader's element surfaces and the refusals, each naming the
//   surface or the line.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "calculix_deck.hpp"
#include "casing_surface.hpp"
#include "component.hpp"

namespace rsi {
namespace {

constexpr double R = 100.0;

Eigen::Vector3d on_cylinder(double theta, double z, double r = R) {
  return {r * std::cos(theta), r * std::sin(theta), z};
}

/// One C3D10: corners 1-3 on the cylinder, 4 outside; the face S1's
/// midside nodes at the chords' midpoints, or on the cylinder (`curved`).
std::string tetrahedron_deck(bool curved, const std::string& surface_lines) {
  const Eigen::Vector3d c1 = on_cylinder(-0.1, 0.0), c2 = on_cylinder(0.1, 0.0),
                        c3 = on_cylinder(0.0, 10.0), c4 = on_cylinder(0.0, 3.0, 110.0);
  const auto mid = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool onto) {
    Eigen::Vector3d m = (a + b) / 2.0;
    if (onto) m.head<2>() *= R / m.head<2>().norm();
    return m;
  };
  const Eigen::Vector3d x[10] = {c1,
                                 c2,
                                 c3,
                                 c4,
                                 mid(c1, c2, curved),
                                 mid(c2, c3, curved),
                                 mid(c3, c1, curved),
                                 mid(c1, c4, false),
                                 mid(c2, c4, false),
                                 mid(c3, c4, false)};
  std::string deck = "*NODE, NSET=NALL\n";
  char line[200];
  for (int i = 0; i < 10; ++i) {
    std::snprintf(line, sizeof line, "%d, %.17g, %.17g, %.17g\n", i + 1, x[i].x(), x[i].y(),
                  x[i].z());
    deck += line;
  }
  // The element on two lines (ccx reads on until the 10 nodes).
  deck += "*ELEMENT, TYPE=C3D10, ELSET=EALL\n7, 1, 2, 3, 4, 5,\n6, 7, 8, 9, 10\n";
  return deck + surface_lines;
}

CalculixDeck read_deck(const std::string& text) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("rsi_casing_surface_" + std::to_string(::getpid()) + ".inp");
  std::ofstream(path) << text;
  CalculixDeck deck = read_calculix_deck(path.string());
  std::filesystem::remove(path);
  return deck;
}

TEST(CasingSurface, ShapeFunctions) {
  const double at[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  for (int j = 0; j < 6; ++j) {
    const std::array<double, 6> n = triangle6_shape_functions(at[j][0], at[j][1]);
    for (int i = 0; i < 6; ++i)
      EXPECT_EQ(n[i], i == j ? 1.0 : 0.0) << "N_" << i << " at node " << j;
  }
  // p(xi, eta) = 1 + 2 xi - 3 eta + 5 xi^2 - 7 xi eta + 11 eta^2 from its
  // nodal values.
  const auto p = [](double xi, double eta) {
    return 1.0 + 2.0 * xi - 3.0 * eta + 5.0 * xi * xi - 7.0 * xi * eta + 11.0 * eta * eta;
  };
  for (const double xi : {0.0, 0.13, 0.4, 0.77})
    for (const double eta : {0.0, 0.21, 0.5}) {
      if (xi + eta > 1.0) continue;
      const std::array<double, 6> n = triangle6_shape_functions(xi, eta);
      double sum = 0.0, value = 0.0;
      for (int i = 0; i < 6; ++i) {
        sum += n[i];
        value += n[i] * p(at[i][0], at[i][1]);
      }
      EXPECT_NEAR(sum, 1.0, 1e-15);
      EXPECT_NEAR(value, p(xi, eta), 1e-13 * 20.0) << xi << ", " << eta;
    }
}

// The derivatives against central differences of the shape functions:
// exact for quadratics, so the difference quotient's error is rounding,
// eps / h = 2e-10 at h = 1e-6 (1e-9 asserted).
TEST(CasingSurface, ShapeFunctionDerivatives) {
  const double h = 1e-6;
  for (const double xi : {0.1, 0.3, 0.6})
    for (const double eta : {0.05, 0.25}) {
      const std::array<std::array<double, 6>, 2> d = triangle6_derivatives(xi, eta);
      const std::array<double, 6> xp = triangle6_shape_functions(xi + h, eta),
                                  xm = triangle6_shape_functions(xi - h, eta),
                                  ep = triangle6_shape_functions(xi, eta + h),
                                  em = triangle6_shape_functions(xi, eta - h);
      for (int i = 0; i < 6; ++i) {
        EXPECT_NEAR(d[0][i], (xp[i] - xm[i]) / (2.0 * h), 1e-9) << "dN_" << i << "/dxi";
        EXPECT_NEAR(d[1][i], (ep[i] - em[i]) / (2.0 * h), 1e-9) << "dN_" << i << "/deta";
      }
    }
}

// Each face S1 .. S4 of C3D10 (ccx's convention: S1 = 1 2 3, S2 = 1 4 2,
// S3 = 2 4 3, S4 = 3 4 1) as a 6-node triangle: its corners those, and each
// midside node the midpoint of its two corners (the deck's midside nodes
// are the edges' midpoints, written in 17 digits: to 1e-13 mm).
TEST(CasingSurface, TheFourFacesOfATetrahedron) {
  const CalculixDeck deck = read_deck(tetrahedron_deck(
      false, "*SURFACE, NAME=ALL, TYPE=ELEMENT\n7, S1\n7, S2\n7, S3\n7, S4\n"));
  const CasingSurface surface(deck, "ALL");
  ASSERT_EQ(surface.n_faces(), 4);
  const std::array<std::array<int, 3>, 4> corners = {{{1, 2, 3}, {1, 4, 2}, {2, 4, 3}, {3, 4, 1}}};
  for (int f = 0; f < 4; ++f) {
    const std::array<int, 6>& ids = surface.face_nodes(f);
    const std::array<Eigen::Vector3d, 6>& x = surface.face_positions(f);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(ids[i], corners[f][i]) << "face S" << f + 1 << " corner " << i;
      EXPECT_LE((x[3 + i] - (x[i] + x[(i + 1) % 3]) / 2.0).norm(), 1e-13)
          << "face S" << f + 1 << " midside " << i;
    }
  }
}

TEST(CasingSurface, LocateOnFlatAndCurvedFaces) {
  for (const bool curved : {false, true}) {
    const CalculixDeck deck =
        read_deck(tetrahedron_deck(curved, "*SURFACE, NAME=Inner, TYPE=ELEMENT\n7, S1\n"));
    ASSERT_EQ(deck.tetrahedra.size(), 1u);
    const CasingSurface surface(deck, "INNER");
    ASSERT_EQ(surface.n_faces(), 1);
    EXPECT_EQ(surface.face_nodes(0), (std::array<int, 6>{1, 2, 3, 5, 6, 7}));
    for (const double theta : {-0.09, -0.03, 0.0, 0.02, 0.06})
      for (const double z : {0.0, 0.5, 2.0, 4.0}) {
        const std::optional<SurfacePoint> p = surface.locate(theta, z);
        const bool inside = std::abs(theta) <= 0.1 * (1.0 - z / 10.0) - 1e-3;
        if (!inside) continue; // near the slanted edges: either answer is right
        ASSERT_TRUE(p) << "curved " << curved << ": theta " << theta << ", z " << z;
        const std::array<double, 6> n = triangle6_shape_functions(p->xi, p->eta);
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for (int i = 0; i < 6; ++i)
          x += n[i] * surface.face_positions(0)[i];
        EXPECT_LE((x - on_cylinder(theta, z, p->rho)).norm(), 1e-12)
            << "curved " << curved << ": theta " << theta << ", z " << z;
        EXPECT_LE(p->rho, R * (1.0 + 1e-15));
        // No nearer the axis than the chord of the widest edge (half-angle 0.1).
        EXPECT_GE(p->rho, R * std::cos(0.1) * (1.0 - 1e-15));
        if (curved && z == 0.0) {
          // On the edge 1-2 of the curved face the midside node lies on the
          // cylinder: rho is the quadratic through three points of r = R,
          // within the arc's sagitta of the 0.1 rad half-edges.
          EXPECT_NEAR(p->rho, R, R * (1.0 - std::cos(0.05)));
        }
      }
    // The corner 3: rho = R exactly (its position is on the cylinder).
    const std::optional<SurfacePoint> corner = surface.locate(0.0, 10.0);
    ASSERT_TRUE(corner);
    EXPECT_NEAR(corner->rho, R, 1e-12);
    EXPECT_FALSE(surface.locate(0.0, 10.5)) << "past the face's axial end";
    EXPECT_FALSE(surface.locate(0.5, 2.0)) << "beside the face";
    EXPECT_FALSE(surface.locate(M_PI, 2.0)) << "the opposite side of the axis";
  }
}

// The hinted search (the reduced solver's: a tip's face of the step before
// tried first) finds what the grid finds, falls back to it when the hint
// misses, and ignores a hint that is no face.
TEST(CasingSurface, HintedSearchFindsTheSamePoint) {
  const CalculixDeck deck =
      read_deck(tetrahedron_deck(true, "*SURFACE, NAME=Inner, TYPE=ELEMENT\n7, S1\n"));
  const CasingSurface surface(deck, "INNER");
  for (const int hint : {0, -1, 1, 7}) {
    const std::optional<SurfacePoint> a = surface.locate(0.02, 2.0);
    const std::optional<SurfacePoint> b = surface.locate(0.02, 2.0, hint);
    ASSERT_TRUE(a && b) << "hint " << hint;
    EXPECT_EQ(b->face, a->face);
    EXPECT_EQ(b->rho, a->rho) << "hint " << hint;
    EXPECT_EQ(b->xi, a->xi);
    EXPECT_EQ(b->eta, a->eta);
    EXPECT_FALSE(surface.locate(0.5, 2.0, hint)) << "beside the face, hint " << hint;
    EXPECT_FALSE(surface.locate(0.0, 10.5, hint)) << "past the axial end, hint " << hint;
  }
}

TEST(CasingSurface, RefusalsNameTheSurface) {
  const auto refused = [](const std::string& surface_lines, const std::string& name,
                          const std::string& words) {
    const CalculixDeck deck = read_deck(tetrahedron_deck(false, surface_lines));
    try {
      CasingSurface surface(deck, name);
      ADD_FAILURE() << surface_lines << ": accepted";
    } catch (const ImportError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("NAME=" + name), std::string::npos) << e.what();
    }
  };
  refused("", "INNER", "defines no element surface");
  refused("*SURFACE, NAME=INNER, TYPE=ELEMENT\nEALL, S1\n", "INNER", "does not read");
  refused("*SURFACE, NAME=INNER\n7, SPOS\n", "INNER", "does not read");
  refused("*SURFACE, NAME=INNER, TYPE=ELEMENT\n8, S1\n", "INNER",
          "element 8 is not a C3D10 element");
  refused("*SURFACE, NAME=INNER, TYPE=ELEMENT\n7, S5\n", "INNER", "has no face S5");
  // A node surface is not an element surface.
  refused("*SURFACE, NAME=INNER, TYPE=NODE\nNALL\n", "INNER", "defines no element surface");
}

} // namespace
} // namespace rsi
