#include "component.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace rsi {

std::string direction_kind(int direction) {
  static const char* const kinds[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  if (direction < 1 || direction > 6)
    throw ImportError("direction_kind: a dof direction must be 1 to 6, got " +
                      std::to_string(direction));
  return kinds[direction - 1];
}

std::vector<int> boundary_of_nodes(const std::vector<int>& node_ids, DofMap& dofs,
                                   const std::string& what) {
  std::unordered_map<int, std::vector<int>> dofs_of_node;
  for (int i = 0; i < static_cast<int>(dofs.size()); ++i)
    dofs_of_node[dofs[i].node].push_back(i);
  std::vector<int> boundary;
  for (size_t k = 0; k < node_ids.size(); ++k) {
    const auto found = dofs_of_node.find(node_ids[k]);
    if (found == dofs_of_node.end())
      throw ImportError(what + ": boundary node " + std::to_string(node_ids[k]) +
                        " has no degree of freedom in the model (not a node of it, or fully "
                        "constrained)");
    if (dofs[found->second.front()].boundary)
      throw ImportError(what + ": boundary node " + std::to_string(node_ids[k]) +
                        " is listed twice");
    for (int i : found->second) {
      dofs[i].boundary = true;
      boundary.push_back(i);
    }
  }
  return boundary;
}

std::vector<int> flagged_boundary(const DofMap& dofs) {
  std::vector<int> boundary;
  for (int i = 0; i < static_cast<int>(dofs.size()); ++i)
    if (dofs[i].boundary) boundary.push_back(i);
  return boundary;
}

namespace {

/// Largest |A_ij - A_ji| over the stored entries, and where.
struct Asymmetry {
  double largest = 0.0;
  int row = -1;
  int col = -1;
};

Asymmetry asymmetry(const Eigen::SparseMatrix<double>& a) {
  const Eigen::SparseMatrix<double> at = a.transpose();
  const Eigen::SparseMatrix<double> d = a - at;
  Asymmetry worst;
  for (int j = 0; j < d.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(d, j); it; ++it)
      if (!(std::abs(it.value()) <= worst.largest)) {
        worst.largest = std::abs(it.value());
        worst.row = static_cast<int>(it.row());
        worst.col = j;
      }
  return worst;
}

void check_matrix(const Eigen::SparseMatrix<double>& a, const std::string& name, int n,
                  const std::string& source) {
  if (a.rows() != n || a.cols() != n) {
    std::ostringstream m;
    m << source << ": " << name << " is " << a.rows() << " x " << a.cols() << ", the dof map has "
      << n << " dofs";
    throw ImportError(m.str());
  }
  double largest = 0.0;
  for (int j = 0; j < a.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it) {
      if (!std::isfinite(it.value())) {
        std::ostringstream m;
        m << source << ": " << name << "(" << it.row() + 1 << ", " << j + 1
          << ") is not finite (" << it.value() << ")";
        throw ImportError(m.str());
      }
      largest = std::max(largest, std::abs(it.value()));
    }
  const Asymmetry worst = asymmetry(a);
  if (worst.largest > 1e-12 * largest) {
    std::ostringstream m;
    m << source << ": " << name << " is not symmetric: |" << name << "(" << worst.row + 1 << ", "
      << worst.col + 1 << ") - " << name << "(" << worst.col + 1 << ", " << worst.row + 1
      << ")| = " << worst.largest << " > 1e-12 x the largest entry " << largest;
    throw ImportError(m.str());
  }
}

} // namespace

void check_component(const Component& c, const std::string& source) {
  const int n = c.n_dofs();
  if (n == 0) throw ImportError(source + ": the component has no degree of freedom");
  check_matrix(c.stiffness, "K", n, source);
  check_matrix(c.mass, "M", n, source);
  for (int i = 0; i < n; ++i)
    if (!(c.mass.coeff(i, i) > 0.0)) {
      std::ostringstream m;
      m << source << ": M(" << i + 1 << ", " << i + 1 << ") = " << c.mass.coeff(i, i)
        << " (dof " << i + 1 << ", node " << c.dofs[i].node << " " << c.dofs[i].kind
        << "): the mass diagonal must be positive";
      throw ImportError(m.str());
    }
  for (int b : c.boundary)
    if (b < 0 || b >= n)
      throw ImportError(source + ": boundary dof " + std::to_string(b) + " outside the model");
}

} // namespace rsi
