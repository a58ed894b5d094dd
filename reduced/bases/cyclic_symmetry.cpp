#include "cyclic_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "reduced_basis.hpp"
#include "sector_assembly.hpp"

namespace rsi {

namespace {

using Key = std::array<long, 3>;

Key place_key(const Eigen::Vector3d& x, double q) {
  return {std::lround(x.x() / q), std::lround(x.y() / q), std::lround(x.z() / q)};
}

std::string node_name(const Component& c, int node) {
  return "node " + std::to_string(node) + " of the component '" + c.name + "'";
}

/// Triple index of each dof, -1 for none.
std::vector<int> triple_of_dofs(const CyclicSymmetry& s, int n_dofs) {
  std::vector<int> out(static_cast<size_t>(n_dofs), -1);
  for (size_t t = 0; t < s.triples.size(); ++t)
    for (int d : s.triples[t])
      out[static_cast<size_t>(d)] = static_cast<int>(t);
  return out;
}

/// turned applied k times.
std::vector<int> turned_by(const CyclicSymmetry& s, int k) {
  std::vector<int> out(s.triples.size());
  for (size_t t = 0; t < out.size(); ++t) {
    int image = static_cast<int>(t);
    for (int i = 0; i < k; ++i)
      image = s.turned[static_cast<size_t>(image)];
    out[t] = image;
  }
  return out;
}

} // namespace

CyclicSymmetry cyclic_symmetry(const Component& c, int sectors) {
  if (sectors < 2)
    throw ReductionError("cyclic bases: the sector count must be at least 2, got " +
                         std::to_string(sectors));
  CyclicSymmetry s;
  s.sectors = sectors;
  s.axis = c.rotation_axis.normalized();
  const std::map<int, std::array<int, 3>> by_node = node_translations(c.dofs);
  int with_dofs = 0;
  for (const DofInfo& d : c.dofs)
    with_dofs += d.kind == "ux" || d.kind == "uy" || d.kind == "uz";
  if (with_dofs != c.n_dofs())
    throw ReductionError("cyclic bases: the component '" + c.name +
                         "' has dofs other than ux, uy, uz (a solid model's only)");
  double size = 0.0;
  for (const ComponentNode& n : c.nodes)
    if (!n.generated) size = std::max(size, n.x.norm());
  // Places to 1e-6 of the model's size, as cyclic_images.hpp keys them; a
  // turned position is looked up in the 27 cells around its key, so one
  // rounded across a cell edge is found.
  const double q = 1e-6 * size;
  std::map<Key, int> triple_at;
  std::vector<Eigen::Vector3d> x;
  std::vector<int> node_of;
  for (const ComponentNode& n : c.nodes) {
    const auto t = by_node.find(n.id);
    if (t == by_node.end() || n.generated) continue;
    for (int d : t->second)
      if (d < 0)
        throw ReductionError("cyclic bases: " + node_name(c, n.id) +
                             " lacks one of ux, uy, uz (a node held in one direction only "
                             "is not held in that direction once turned)");
    if (!triple_at.emplace(place_key(n.x, q), static_cast<int>(s.triples.size())).second)
      throw ReductionError("cyclic bases: " + node_name(c, n.id) +
                           " lies where another node with dofs lies (within 1e-6 of the "
                           "model's size)");
    s.triples.push_back(t->second);
    x.push_back(n.x);
    node_of.push_back(n.id);
  }
  // Every dof in a triple: the turn then moves every row (turn_fields).
  if (3 * s.triples.size() != static_cast<size_t>(c.n_dofs()))
    throw ReductionError("cyclic bases: the component '" + c.name + "' has " +
                         std::to_string(c.n_dofs()) + " dofs, not the ux, uy, uz of its " +
                         std::to_string(s.triples.size()) + " nodes with dofs");
  const Eigen::Matrix3d r = turn_rotation(s, 1);
  s.turned.assign(s.triples.size(), -1);
  for (size_t t = 0; t < s.triples.size(); ++t) {
    const Eigen::Vector3d y = r * x[t];
    const Key key = place_key(y, q);
    for (long i = -1; i <= 1 && s.turned[t] < 0; ++i)
      for (long j = -1; j <= 1 && s.turned[t] < 0; ++j)
        for (long k = -1; k <= 1 && s.turned[t] < 0; ++k) {
          const auto found = triple_at.find({key[0] + i, key[1] + j, key[2] + k});
          if (found != triple_at.end() && (x[static_cast<size_t>(found->second)] - y).norm() <= q)
            s.turned[t] = found->second;
        }
    if (s.turned[t] < 0)
      throw ReductionError("cyclic bases: " + node_name(c, node_of[t]) + " turned by 2 pi / " +
                           std::to_string(sectors) + " about the rotation axis meets no node " +
                           "with dofs: the component is not " + std::to_string(sectors) +
                           "-fold cyclic");
  }
  const std::vector<int> round_trip = turned_by(s, sectors);
  for (size_t t = 0; t < round_trip.size(); ++t)
    if (round_trip[t] != static_cast<int>(t))
      throw ReductionError("cyclic bases: " + node_name(c, node_of[t]) +
                           " does not come back "
                           "after " +
                           std::to_string(sectors) + " turns");
  return s;
}

Eigen::Matrix3d turn_rotation(const CyclicSymmetry& s, int k) {
  return axis_rotation(s.axis, 2.0 * M_PI * k / s.sectors);
}

Eigen::MatrixXd turn_fields(const CyclicSymmetry& s, int k, const Eigen::MatrixXd& u) {
  const std::vector<int> image = turned_by(s, k);
  const Eigen::Matrix3d r = turn_rotation(s, k);
  Eigen::MatrixXd out(u.rows(), u.cols());
  for (size_t t = 0; t < s.triples.size(); ++t) {
    const std::array<int, 3>& from = s.triples[t];
    const std::array<int, 3>& to = s.triples[static_cast<size_t>(image[t])];
    for (int a = 0; a < 3; ++a)
      out.row(to[static_cast<size_t>(a)]) =
          r(a, 0) * u.row(from[0]) + r(a, 1) * u.row(from[1]) + r(a, 2) * u.row(from[2]);
  }
  return out;
}

Eigen::SparseMatrix<double> turn_matrix(const CyclicSymmetry& s, int k, int n_dofs) {
  const std::vector<int> image = turned_by(s, k);
  const Eigen::Matrix3d r = turn_rotation(s, k);
  std::vector<Eigen::Triplet<double>> entries;
  for (size_t t = 0; t < s.triples.size(); ++t)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (r(a, b) != 0.0)
          entries.emplace_back(s.triples[static_cast<size_t>(image[t])][static_cast<size_t>(a)],
                               s.triples[t][static_cast<size_t>(b)], r(a, b));
  Eigen::SparseMatrix<double> p(n_dofs, n_dofs);
  p.setFromTriplets(entries.begin(), entries.end());
  return p;
}

double relative_asymmetry(const CyclicSymmetry& s, const Eigen::SparseMatrix<double>& a) {
  const Eigen::SparseMatrix<double> p = turn_matrix(s, 1, static_cast<int>(a.rows()));
  const Eigen::SparseMatrix<double> turned = p.transpose() * a * p;
  const double scale = a.coeffs().cwiseAbs().maxCoeff();
  const Eigen::SparseMatrix<double> difference = turned - a;
  return difference.coeffs().cwiseAbs().maxCoeff() / scale;
}

std::vector<int> BoundaryOrbits::representative_positions() const {
  std::vector<int> out;
  for (const auto& turns_of_rep : position)
    for (int c = 0; c < 3; ++c)
      out.push_back(turns_of_rep[0][static_cast<size_t>(c)]);
  return out;
}

BoundaryOrbits boundary_orbits(const CyclicSymmetry& s, const Partition& p) {
  if (static_cast<size_t>(p.n()) != 3 * s.triples.size())
    throw std::invalid_argument("boundary_orbits: a partition of " + std::to_string(p.n()) +
                                " dofs for a turn of " + std::to_string(3 * s.triples.size()));
  const std::vector<int> triple = triple_of_dofs(s, p.n());
  std::vector<int> position_of_dof(static_cast<size_t>(p.n()), -1);
  for (int j = 0; j < p.n_boundary(); ++j)
    position_of_dof[static_cast<size_t>(p.boundary[static_cast<size_t>(j)])] = j;
  const int nb = p.n_boundary();
  BoundaryOrbits o;
  o.sectors = s.sectors;
  o.rep.assign(static_cast<size_t>(nb), -1);
  o.turns.assign(static_cast<size_t>(nb), -1);
  o.component.assign(static_cast<size_t>(nb), -1);
  for (int j = 0; j < nb; ++j) {
    if (o.rep[static_cast<size_t>(j)] >= 0) continue;
    const int dof = p.boundary[static_cast<size_t>(j)];
    const int first = triple[static_cast<size_t>(dof)];
    const int r = o.n_representatives();
    o.position.emplace_back(static_cast<size_t>(s.sectors));
    int t = first;
    for (int k = 0; k < s.sectors; ++k, t = s.turned[static_cast<size_t>(t)])
      for (int c = 0; c < 3; ++c) {
        const int at = position_of_dof[static_cast<size_t>(
            s.triples[static_cast<size_t>(t)][static_cast<size_t>(c)])];
        if (at < 0 || o.rep[static_cast<size_t>(at)] >= 0)
          throw ReductionError(
              "cyclic bases: boundary dof " + std::to_string(dof) +
              (at < 0 ? " turned " + std::to_string(k) +
                            " times lands on a node whose ux, uy, uz are not all boundary dofs"
                      : " comes back onto itself after " + std::to_string(k) +
                            " turns (a node on the axis)") +
              ": the boundary is not cyclic");
        o.rep[static_cast<size_t>(at)] = r;
        o.turns[static_cast<size_t>(at)] = k;
        o.component[static_cast<size_t>(at)] = c;
        o.position[static_cast<size_t>(r)][static_cast<size_t>(k)][static_cast<size_t>(c)] = at;
      }
  }
  return o;
}

} // namespace rsi
