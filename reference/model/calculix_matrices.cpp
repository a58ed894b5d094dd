#include "calculix_matrices.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <set>

#include "coordinate_entries.hpp"

namespace rsi {

DofMap read_calculix_dofs(const std::string& path) {
  const std::string text = read_whole_file(path);
  DofMap dofs;
  size_t offset = 0;
  std::string_view line;
  int number = 0;
  while (next_line(text, offset, line)) {
    ++number;
    const char* p = line.data();
    const char* end = p + line.size();
    while (p < end && (*p == ' ' || *p == '\t'))
      ++p;
    while (end > p && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\r'))
      --end;
    if (p == end) continue;
    int node = 0;
    int direction = 0;
    auto [q, ec] = std::from_chars(p, end, node);
    bool ok = ec == std::errc() && q < end && *q == '.';
    if (ok) {
      auto [r, ec2] = std::from_chars(q + 1, end, direction);
      ok = ec2 == std::errc() && r == end && direction >= 1 && direction <= 6 && node >= 1;
    }
    if (!ok)
      throw ImportError(path + ":" + std::to_string(number) +
                        ": expected 'node.direction' (node >= 1, direction 1 to 6), got '" +
                        std::string(line.substr(0, 80)) + "'");
    dofs.push_back({node, direction_kind(direction), false});
  }
  if (dofs.empty()) throw ImportError(path + ": no dof listed (empty file)");
  return dofs;
}

namespace {

int node_id(int id) {
  return id;
}
int node_id(const ComponentNode& node) {
  return node.id;
}

Eigen::SparseMatrix<double> read_matrix(const std::string& path, int n, bool mass) {
  const std::string text = read_whole_file(path);
  const CoordinateEntries entries = parse_coordinate_entries(text, 0, 1, n, path);
  if (entries.size() == 0) throw ImportError(path + ": no entry (empty file)");
  int largest = 0;
  for (size_t k = 0; k < entries.size(); ++k)
    largest = std::max({largest, entries.row[k], entries.col[k]});
  if (largest + 1 != n)
    throw ImportError(path + ": the largest row index is " + std::to_string(largest + 1) +
                      " but the .dof file lists " + std::to_string(n) +
                      " dofs: the matrix and the dof file do not belong together");
  if (mass) check_positive_diagonal(entries, n, path);
  return symmetric_matrix(entries, n, path);
}

} // namespace

Component read_calculix_component(const std::string& prefix, const CalculixDeck& deck,
                                  const std::vector<int>& boundary_nodes,
                                  const std::string& name) {
  Component c;
  c.name = name;
  c.dofs = read_calculix_dofs(prefix + ".dof");
  const int n = c.n_dofs();
  c.stiffness = read_matrix(prefix + ".sti", n, false);
  c.mass = read_matrix(prefix + ".mas", n, true);
  // A row's node is a node of the deck, or one ccx created above the
  // deck's largest id (nk): the incompatible modes of C3D8I elements, the
  // rotations of beam and shell knots. The nodes ccx creates when it
  // expands beams, shells and plane elements are written with the deck
  // node they expand (ccx's gennactdofinv.f), so every row of those
  // carries its user node.
  std::set<int> used;
  for (const DofInfo& d : c.dofs)
    used.insert(d.node);
  for (const ComponentNode& node : deck.nodes)
    if (used.count(node.id)) c.nodes.push_back(node);
  for (int id : used) {
    if (id > deck.largest_node_id) {
      ComponentNode created;
      created.id = id;
      created.x.setConstant(std::numeric_limits<double>::quiet_NaN());
      created.generated = true;
      c.nodes.push_back(created);
    } else if (!std::binary_search(deck.nodes.begin(), deck.nodes.end(), id,
                                   [](const auto& a, const auto& b) {
                                     return node_id(a) < node_id(b);
                                   })) {
      throw ImportError(prefix + ".dof: node " + std::to_string(id) +
                        " has dofs but no *NODE line in " + deck.path +
                        " (below its largest node id " + std::to_string(deck.largest_node_id) +
                        ", so not a node ccx created): the matrices do not belong to this deck");
    }
  }
  c.boundary = boundary_of_nodes(boundary_nodes, c.dofs, deck.path + " (boundary node set)");
  check_component(c, prefix + ".{sti,mas}");
  return c;
}

} // namespace rsi
