#include "cyclic_images.hpp"

#include <cmath>
#include <complex>
#include <map>
#include <stdexcept>

#include <Eigen/Geometry>

#include "nodal_diameter.hpp"
#include "sector_assembly.hpp"

namespace rsi {

namespace {

/// Two unit vectors completing the axis to a right-handed frame.
std::pair<Eigen::Vector3d, Eigen::Vector3d> polar_frame(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d helper =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (helper - helper.dot(axis) * axis).normalized();
  return {e1, axis.cross(e1)};
}

} // namespace

CyclicImages cyclic_images(const Component& c, int sectors) {
  if (sectors < 2) throw std::invalid_argument("cyclic_images: sectors must be at least 2");
  CyclicImages out;
  out.sectors = sectors;
  out.axis = c.rotation_axis.normalized();
  const auto [e1, e2] = polar_frame(out.axis);
  const std::map<int, std::array<int, 3>> triples = node_translations(c.dofs);
  double size = 0.0;
  for (const ComponentNode& n : c.nodes)
    if (!n.generated) size = std::max(size, n.x.norm());
  const double q = 1e-6 * size;
  const double alpha = 2.0 * M_PI / sectors;
  // Place key -> the dofs of its image in each sector (-1: none yet).
  std::map<std::array<long, 3>, std::vector<std::array<int, 3>>> by_place;
  for (const ComponentNode& n : c.nodes) {
    const auto t = triples.find(n.id);
    if (n.generated || t == triples.end()) continue;
    if (t->second[0] < 0 || t->second[1] < 0 || t->second[2] < 0) continue;
    const double theta = std::atan2(n.x.dot(e2), n.x.dot(e1));
    const long bin = std::lround(theta / alpha);
    const int k = static_cast<int>(((bin % sectors) + sectors) % sectors);
    const Eigen::Vector3d x0 = axis_rotation(out.axis, -bin * alpha) * n.x;
    const std::array<long, 3> key{std::lround(x0.x() / q), std::lround(x0.y() / q),
                                  std::lround(x0.z() / q)};
    auto& images = by_place[key];
    if (images.empty()) images.assign(static_cast<size_t>(sectors), {-1, -1, -1});
    images[static_cast<size_t>(k)] = t->second;
  }
  for (auto& [key, images] : by_place) {
    bool whole = true;
    for (const auto& dofs : images)
      whole = whole && dofs[0] >= 0;
    if (whole) out.places.push_back(std::move(images));
  }
  if (out.places.empty())
    throw ImportError("the component '" + c.name + "' has no node with an image in each of " +
                      std::to_string(sectors) + " sectors about its axis: not " +
                      std::to_string(sectors) + "-fold cyclic");
  return out;
}

Eigen::VectorXd sector_blocks(const CyclicImages& images,
                              const Eigen::Ref<const Eigen::VectorXd>& mode) {
  const int n = images.sectors;
  const int block = 3 * static_cast<int>(images.places.size());
  Eigen::VectorXd out(static_cast<Eigen::Index>(n) * block);
  for (int k = 0; k < n; ++k) {
    const Eigen::Matrix3d back = axis_rotation(images.axis, -2.0 * M_PI * k / n);
    for (size_t p = 0; p < images.places.size(); ++p) {
      const std::array<int, 3>& d = images.places[p][static_cast<size_t>(k)];
      const Eigen::Vector3d u(mode(d[0]), mode(d[1]), mode(d[2]));
      out.segment<3>(static_cast<Eigen::Index>(k) * block + 3 * static_cast<Eigen::Index>(p)) =
          back * u;
    }
  }
  return out;
}

int cyclic_nodal_diameter(const CyclicImages& images,
                          const Eigen::Ref<const Eigen::VectorXd>& mode) {
  return nodal_diameter(sector_blocks(images, mode), images.sectors,
                        3 * static_cast<int>(images.places.size()));
}

int circumferential_harmonic(const Component& c, const Eigen::Ref<const Eigen::VectorXd>& mode,
                             int h_max) {
  const Eigen::Vector3d axis = c.rotation_axis.normalized();
  const auto [e1, e2] = polar_frame(axis);
  const std::map<int, std::array<int, 3>> triples = node_translations(c.dofs);
  std::vector<std::complex<double>> sum(static_cast<size_t>(h_max) + 1, 0.0);
  for (const ComponentNode& n : c.nodes) {
    const auto t = triples.find(n.id);
    if (n.generated || t == triples.end()) continue;
    const auto& d = t->second;
    if (d[0] < 0 || d[1] < 0 || d[2] < 0) continue;
    const Eigen::Vector3d r = n.x - n.x.dot(axis) * axis;
    if (!(r.norm() > 0.0)) continue;
    const double theta = std::atan2(n.x.dot(e2), n.x.dot(e1));
    const double u_r = r.normalized().dot(Eigen::Vector3d(mode(d[0]), mode(d[1]), mode(d[2])));
    for (int h = 0; h <= h_max; ++h)
      sum[static_cast<size_t>(h)] += u_r * std::polar(1.0, -h * theta);
  }
  int best = 0;
  for (int h = 1; h <= h_max; ++h)
    if (std::norm(sum[static_cast<size_t>(h)]) > std::norm(sum[static_cast<size_t>(best)]))
      best = h;
  return best;
}

} // namespace rsi
