#pragma once
// The contact surface of a solid casing (issue 27 item 3, SPEC §9
// "Flexible casing in 3D"): the faces of its quadratic tetrahedra that an
// element surface of the deck lists (*SURFACE, TYPE=ELEMENT, "element,
// Sk"), each a 6-node triangle, and the point of it under a blade tip. The
// model side of the contact, which both solvers read (reduced/README.md:
// the casing's geometry and shape functions): the contact laws are theirs.
//
// A face of C3D10 (ccx's and Abaqus's numbering): S1 = corners 1 2 3, S2 =
// 1 4 2, S3 = 2 4 3, S4 = 3 4 1; as a 6-node triangle its corners a b c in
// that order, then the midside nodes of ab, bc, ca. With area coordinates
// L1 = 1 - xi - eta, L2 = xi, L3 = eta, the quadratic shape functions are
//   N_a = L1 (2 L1 - 1), N_b = L2 (2 L2 - 1), N_c = L3 (2 L3 - 1),
//   N_ab = 4 L1 L2,      N_bc = 4 L2 L3,      N_ca = 4 L3 L1,
// the face's points X(xi, eta) = sum N_i X_i and its displacement
// u(xi, eta) = sum N_i u_i (isoparametric: a quadratic field of the
// element is reproduced exactly on its face).
//
// The point under a tip: the tip at polar angle theta about the casing's
// axis z and at height z meets the surface where the ray from (0, 0, z)
// along e_r = (cos theta, sin theta, 0) crosses a face: X(xi, eta) =
// (rho cos theta, rho sin theta, z), three equations in (xi, eta, rho),
// solved by Newton from the corners' plane (one step when the midside nodes
// are the edges' midpoints, as gmsh's SecondOrderLinear mesh has them).
// The faces are found through a grid over (theta, z) of their bounding
// boxes.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "calculix_deck.hpp"

namespace rsi {

/// The local node indices (0-based, into C3D10's 10 nodes) of face S1 ..
/// S4 (face = 1 .. 4) as a 6-node triangle: corners a b c, midsides ab bc ca.
std::array<int, 6> c3d10_face_nodes(int face);

/// The six quadratic shape functions at (xi, eta), in the triangle's order.
std::array<double, 6> triangle6_shape_functions(double xi, double eta);
/// Their derivatives: [0] d/d xi, [1] d/d eta.
std::array<std::array<double, 6>, 2> triangle6_derivatives(double xi, double eta);

/// A face under a tip: which, where on it (xi, eta) and the distance rho
/// from the axis to the face along the tip's ray.
struct SurfacePoint {
  int face = -1;
  double xi = 0.0, eta = 0.0;
  double rho = 0.0;
};

class CasingSurface {
public:
  /// The faces of surface `name` of the deck (upper case), every one a face
  /// of a C3D10 element. Throws ImportError naming the surface when the deck
  /// has no such element surface, when it lists a face this reader does not
  /// take (an *ELSET, another element type, a face label above S4), or an
  /// element the deck does not define as C3D10, or none at all.
  CasingSurface(const CalculixDeck& deck, const std::string& name);

  int n_faces() const { return static_cast<int>(faces_.size()); }
  /// The deck's node ids of face f, in the triangle's order.
  const std::array<int, 6>& face_nodes(int f) const { return faces_[f]; }
  /// Their reference positions.
  const std::array<Eigen::Vector3d, 6>& face_positions(int f) const { return positions_[f]; }

  /// The face under polar angle theta [rad] and height z, or nullopt when
  /// the ray misses every face (past the surface's axial ends). On a shared
  /// edge either neighbour answers.
  std::optional<SurfacePoint> locate(double theta, double z) const;
  /// The same, trying face `hint` first (a tip's face of the step before:
  /// it moves by a fraction of a face a step; -1: no hint). Off the hint,
  /// or on a shared edge, another face may answer than locate(theta, z)'s.
  std::optional<SurfacePoint> locate(double theta, double z, int hint) const;

private:
  std::vector<std::array<int, 6>> faces_;
  std::vector<std::array<Eigen::Vector3d, 6>> positions_;
  // The grid over theta in [-pi, pi) and z in [z_min, z_max]: each cell's
  // faces, those whose bounding box (widened by a margin) meets it.
  int n_theta_ = 1, n_z_ = 1;
  double z_min_ = 0.0, z_max_ = 0.0;
  std::vector<std::vector<int>> cells_;
  std::optional<SurfacePoint> on_face(int f, double theta, double z) const;
};

} // namespace rsi
