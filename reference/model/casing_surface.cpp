#include "casing_surface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include <Eigen/LU>

#include "component.hpp"

namespace rsi {
namespace {

/// theta in [-pi, pi).
double wrapped(double theta) {
  const double t = std::remainder(theta, 2.0 * M_PI);
  return t >= M_PI ? t - 2.0 * M_PI : t;
}

} // namespace

std::array<int, 6> c3d10_face_nodes(int face) {
  // Corners (0-based) 0 1 2 3; midsides 4 = 0-1, 5 = 1-2, 6 = 2-0, 7 = 0-3,
  // 8 = 1-3, 9 = 2-3.
  switch (face) {
  case 1:
    return {0, 1, 2, 4, 5, 6};
  case 2:
    return {0, 3, 1, 7, 8, 4};
  case 3:
    return {1, 3, 2, 8, 9, 5};
  case 4:
    return {2, 3, 0, 9, 7, 6};
  default:
    throw std::invalid_argument("c3d10_face_nodes: face must be 1 .. 4, got " +
                                std::to_string(face));
  }
}

std::array<std::array<double, 6>, 2> triangle6_derivatives(double xi, double eta) {
  const double l1 = 1.0 - xi - eta, l2 = xi, l3 = eta;
  return {{{-(4.0 * l1 - 1.0), 4.0 * l2 - 1.0, 0.0, 4.0 * (l1 - l2), 4.0 * l3, -4.0 * l3},
           {-(4.0 * l1 - 1.0), 0.0, 4.0 * l3 - 1.0, -4.0 * l2, 4.0 * l2, 4.0 * (l1 - l3)}}};
}

std::array<double, 6> triangle6_shape_functions(double xi, double eta) {
  const double l1 = 1.0 - xi - eta, l2 = xi, l3 = eta;
  return {l1 * (2.0 * l1 - 1.0), l2 * (2.0 * l2 - 1.0), l3 * (2.0 * l3 - 1.0),
          4.0 * l1 * l2,         4.0 * l2 * l3,         4.0 * l3 * l1};
}

CasingSurface::CasingSurface(const CalculixDeck& deck, const std::string& name) {
  const std::string what = deck.path + ": *SURFACE, NAME=" + name + ": ";
  const auto listed = deck.element_surfaces.find(name);
  if (listed == deck.element_surfaces.end())
    throw ImportError(what + "the deck defines no element surface (TYPE=ELEMENT) of that name");
  const auto not_read = deck.surfaces_not_read.find(name);
  if (not_read != deck.surfaces_not_read.end())
    throw ImportError(not_read->second + ": *SURFACE, NAME=" + name +
                      ": a line rsi's contact surface does not read (an *ELSET, a shell's or "
                      "an edge's label); list its faces as 'element id, S1 .. S4' of C3D10 "
                      "elements");
  if (listed->second.empty()) throw ImportError(what + "lists no face");
  std::unordered_map<int, const DeckTetrahedron*> tetrahedra;
  for (const DeckTetrahedron& t : deck.tetrahedra)
    tetrahedra[t.id] = &t;
  std::unordered_map<int, Eigen::Vector3d> at;
  for (const ComponentNode& node : deck.nodes)
    at[node.id] = node.x;
  for (const DeckElementFace& f : listed->second) {
    const auto t = tetrahedra.find(f.element);
    if (t == tetrahedra.end())
      throw ImportError(what + "element " + std::to_string(f.element) +
                        " is not a C3D10 element of the deck (rsi's contact surfaces are faces "
                        "of quadratic tetrahedra)");
    if (f.face > 4)
      throw ImportError(what + "element " + std::to_string(f.element) + " has no face S" +
                        std::to_string(f.face) + " (a tetrahedron's are S1 .. S4)");
    std::array<int, 6> ids{};
    std::array<Eigen::Vector3d, 6> x;
    const std::array<int, 6> local = c3d10_face_nodes(f.face);
    for (int i = 0; i < 6; ++i) {
      ids[i] = t->second->nodes[static_cast<size_t>(local[i])];
      const auto p = at.find(ids[i]);
      if (p == at.end())
        throw ImportError(what + "element " + std::to_string(f.element) + " names node " +
                          std::to_string(ids[i]) + ", which the deck does not define");
      x[i] = p->second;
    }
    faces_.push_back(ids);
    positions_.push_back(x);
  }

  // The grid: each face's (theta, z) box, theta unwrapped about its first
  // corner; cells about the size of the mean box.
  struct Box {
    double t0, t1, z0, z1;
  };
  std::vector<Box> boxes;
  double sum_t = 0.0, sum_z = 0.0;
  z_min_ = 1e300;
  z_max_ = -1e300;
  for (const std::array<Eigen::Vector3d, 6>& x : positions_) {
    const double base = std::atan2(x[0].y(), x[0].x());
    Box b{0.0, 0.0, x[0].z(), x[0].z()};
    for (const Eigen::Vector3d& p : x) {
      const double d = std::remainder(std::atan2(p.y(), p.x()) - base, 2.0 * M_PI);
      b.t0 = std::min(b.t0, d);
      b.t1 = std::max(b.t1, d);
      b.z0 = std::min(b.z0, p.z());
      b.z1 = std::max(b.z1, p.z());
    }
    b.t0 += base;
    b.t1 += base;
    sum_t += b.t1 - b.t0;
    sum_z += b.z1 - b.z0;
    z_min_ = std::min(z_min_, b.z0);
    z_max_ = std::max(z_max_, b.z1);
    boxes.push_back(b);
  }
  const double n = static_cast<double>(boxes.size());
  n_theta_ = std::clamp(static_cast<int>(2.0 * M_PI / std::max(sum_t / n, 1e-9)), 1, 100000);
  n_z_ = std::clamp(static_cast<int>((z_max_ - z_min_) / std::max(sum_z / n, 1e-300)), 1, 100000);
  cells_.assign(static_cast<size_t>(n_theta_) * static_cast<size_t>(n_z_), {});
  const double dt = 2.0 * M_PI / n_theta_, dz = (z_max_ - z_min_) / n_z_;
  for (size_t f = 0; f < boxes.size(); ++f) {
    const Box& b = boxes[f];
    // A margin of a tenth of a cell: a point on a box's edge finds the face.
    const int i0 = static_cast<int>(std::floor((b.t0 + M_PI) / dt - 0.1));
    const int i1 = static_cast<int>(std::floor((b.t1 + M_PI) / dt + 0.1));
    const int j0 = std::max(0, static_cast<int>(std::floor((b.z0 - z_min_) / dz - 0.1)));
    const int j1 = std::min(n_z_ - 1, static_cast<int>(std::floor((b.z1 - z_min_) / dz + 0.1)));
    for (int i = i0; i <= i1 && i < i0 + n_theta_; ++i)
      for (int j = j0; j <= j1; ++j)
        cells_[static_cast<size_t>(((i % n_theta_) + n_theta_) % n_theta_) * n_z_ + j].push_back(
            static_cast<int>(f));
  }
}

std::optional<SurfacePoint> CasingSurface::on_face(int f, double theta, double z) const {
  const std::array<Eigen::Vector3d, 6>& x = positions_[static_cast<size_t>(f)];
  const Eigen::Vector3d er(std::cos(theta), std::sin(theta), 0.0);
  const Eigen::Vector3d target(0.0, 0.0, z);
  // The corners' plane first, then Newton on the quadratic map.
  Eigen::Matrix3d j;
  j << x[1] - x[0], x[2] - x[0], -er;
  Eigen::FullPivLU<Eigen::Matrix3d> lu(j);
  if (!lu.isInvertible()) return std::nullopt; // the ray along the face's plane
  Eigen::Vector3d s = lu.solve(target - x[0]); // (xi, eta, rho)
  for (int iteration = 0; iteration < 8; ++iteration) {
    const std::array<double, 6> n = triangle6_shape_functions(s(0), s(1));
    const std::array<std::array<double, 6>, 2> d = triangle6_derivatives(s(0), s(1));
    Eigen::Vector3d r = -s(2) * er - target, dxi = Eigen::Vector3d::Zero(),
                    deta = Eigen::Vector3d::Zero();
    for (int i = 0; i < 6; ++i) {
      r += n[i] * x[i];
      dxi += d[0][i] * x[i];
      deta += d[1][i] * x[i];
    }
    j << dxi, deta, -er;
    lu.compute(j);
    if (!lu.isInvertible()) return std::nullopt;
    const Eigen::Vector3d step = lu.solve(r);
    s -= step;
    // xi, eta are dimensionless, rho a length: each to round-off.
    if (std::abs(step(0)) + std::abs(step(1)) <= 1e-15 &&
        std::abs(step(2)) <= 1e-15 * std::abs(s(2)))
      break;
  }
  // Accepted only where Newton converged: X(xi, eta) on the ray to the
  // rounding of the face's coordinates (a few eps of their size; 1e-12 of it).
  {
    const std::array<double, 6> n = triangle6_shape_functions(s(0), s(1));
    Eigen::Vector3d r = -s(2) * er - target;
    double size = 0.0;
    for (int i = 0; i < 6; ++i) {
      r += n[i] * x[i];
      size = std::max(size, x[i].norm());
    }
    if (!(r.norm() <= 1e-12 * size)) return std::nullopt;
  }
  constexpr double edge = 1e-12; // a point on an edge belongs to both faces
  if (!(s(0) >= -edge && s(1) >= -edge && s(0) + s(1) <= 1.0 + edge && s(2) > 0.0))
    return std::nullopt;
  return SurfacePoint{f, s(0), s(1), s(2)};
}

std::optional<SurfacePoint> CasingSurface::locate(double theta, double z, int hint) const {
  if (hint >= 0 && hint < n_faces()) {
    const double tol = 1e-9 * (z_max_ - z_min_);
    if (z >= z_min_ - tol && z <= z_max_ + tol)
      if (std::optional<SurfacePoint> p = on_face(hint, wrapped(theta), z)) return p;
  }
  return locate(theta, z);
}

std::optional<SurfacePoint> CasingSurface::locate(double theta, double z) const {
  const double tol = 1e-9 * (z_max_ - z_min_);
  if (!(z >= z_min_ - tol && z <= z_max_ + tol)) return std::nullopt;
  const double t = wrapped(theta);
  const int i = std::clamp(static_cast<int>(std::floor((t + M_PI) / (2.0 * M_PI) * n_theta_)), 0,
                           n_theta_ - 1);
  const int j = std::clamp(
      static_cast<int>(std::floor((z - z_min_) / std::max(z_max_ - z_min_, 1e-300) * n_z_)), 0,
      n_z_ - 1);
  for (const int f : cells_[static_cast<size_t>(i) * n_z_ + j])
    if (const std::optional<SurfacePoint> p = on_face(f, t, z)) return p;
  return std::nullopt;
}

} // namespace rsi
