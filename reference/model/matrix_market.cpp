#include "matrix_market.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "coordinate_entries.hpp"

namespace rsi {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw ImportError(path + ":" + std::to_string(line) + ": " + what);
}

std::vector<std::string> split_csv(std::string_view line) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    std::string_view f = line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                           : comma - start);
    while (!f.empty() && (f.back() == '\r' || f.back() == ' '))
      f.remove_suffix(1);
    while (!f.empty() && f.front() == ' ')
      f.remove_prefix(1);
    fields.emplace_back(f);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

template <typename T>
T parse_field(const std::string& field, const std::string& path, int line,
              const std::string& what) {
  T value{};
  const auto [p, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || p != field.data() + field.size())
    fail(path, line, what + " must be a number, got '" + field + "'");
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) fail(path, line, what + " is not finite");
  return value;
}

/// The data lines of a CSV file with the given header, numbered.
std::vector<std::pair<int, std::vector<std::string>>>
csv_rows(const std::string& path, const std::string& header, size_t n_fields) {
  const std::string text = read_whole_file(path);
  size_t offset = 0;
  std::string_view line;
  int number = 0;
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  bool header_seen = false;
  while (next_line(text, offset, line)) {
    ++number;
    if (line.empty() || line == "\r") continue;
    if (!header_seen) {
      std::string h(line);
      if (!h.empty() && h.back() == '\r') h.pop_back();
      if (h != header) fail(path, number, "header must be '" + header + "', got '" + h + "'");
      header_seen = true;
      continue;
    }
    std::vector<std::string> fields = split_csv(line);
    if (fields.size() != n_fields)
      fail(path, number,
           "expected " + std::to_string(n_fields) + " fields (" + header + "), got " +
               std::to_string(fields.size()));
    rows.emplace_back(number, std::move(fields));
  }
  if (!header_seen) throw ImportError(path + ": empty file (header '" + header + "' expected)");
  return rows;
}

DofMap read_dofs_csv(const std::string& path) {
  DofMap dofs;
  for (const auto& [line, f] : csv_rows(path, "index,node,kind,boundary", 4)) {
    const long index = parse_field<long>(f[0], path, line, "index");
    if (index != static_cast<long>(dofs.size()))
      fail(path, line, "index must be " + std::to_string(dofs.size()) + " (rows in order), got " +
                           f[0]);
    if (f[2].empty()) fail(path, line, "kind is empty");
    if (f[3] != "0" && f[3] != "1") fail(path, line, "boundary must be 0 or 1, got '" + f[3] + "'");
    dofs.push_back({parse_field<int>(f[1], path, line, "node"), f[2], f[3] == "1"});
  }
  if (dofs.empty()) throw ImportError(path + ": no dof listed");
  return dofs;
}

std::vector<ComponentNode> read_nodes_csv(const std::string& path) {
  std::vector<ComponentNode> nodes;
  for (const auto& [line, f] : csv_rows(path, "node,x,y,z", 4)) {
    ComponentNode node;
    node.id = parse_field<int>(f[0], path, line, "node");
    if (f[1].empty() && f[2].empty() && f[3].empty()) {
      // A generated node (ccx's incompatible modes, knots): no position.
      node.x.setConstant(std::numeric_limits<double>::quiet_NaN());
      node.generated = true;
    } else {
      for (int k = 0; k < 3; ++k)
        node.x(k) = parse_field<double>(f[k + 1], path, line, "coordinate");
    }
    if (!nodes.empty() && node.id <= nodes.back().id)
      fail(path, line, "node ids must be ascending and unique");
    nodes.push_back(node);
  }
  return nodes;
}

} // namespace

Eigen::SparseMatrix<double>
read_symmetric_matrix_market(const std::string& path, bool positive_diagonal, long expected_rows) {
  const std::string text = read_whole_file(path);
  size_t offset = 0;
  std::string_view line;
  int number = 0;
  if (!next_line(text, offset, line)) throw ImportError(path + ": empty file");
  ++number;
  std::istringstream banner{std::string(line)};
  std::string word[5];
  banner >> word[0] >> word[1] >> word[2] >> word[3] >> word[4];
  if (word[0] != "%%MatrixMarket" || lower(word[1]) != "matrix" ||
      lower(word[2]) != "coordinate" || lower(word[3]) != "real" ||
      (lower(word[4]) != "symmetric" && lower(word[4]) != "general"))
    fail(path, 1,
         "expected the banner '%%MatrixMarket matrix coordinate real symmetric' (or general), "
         "got '" + std::string(line.substr(0, 80)) + "'");
  const bool symmetric = lower(word[4]) == "symmetric";
  long rows = 0, cols = 0, entries = 0;
  while (next_line(text, offset, line)) {
    ++number;
    if (line.empty() || line[0] == '%') continue;
    std::istringstream size{std::string(line)};
    std::string rest;
    if (!(size >> rows >> cols >> entries) || (size >> rest) || rows < 1 || rows != cols ||
        entries < 1 || rows > 2000000000L)
      fail(path, number,
           "size line must be 'n n entries' for a square matrix (n >= 1), got '" +
               std::string(line.substr(0, 80)) + "'");
    break;
  }
  if (rows == 0) throw ImportError(path + ": no size line");
  // The declared size and count are only words of the file: they are
  // checked against what the folder and the file hold before anything is
  // sized by them (a size line of 2e9 rows once allocated 23 GB).
  if (expected_rows >= 0 && rows != expected_rows)
    throw ImportError(path + ": " + std::to_string(rows) + " rows, but dofs.csv lists " +
                      std::to_string(expected_rows) + " dofs");
  // 64-bit: rows <= 2e9, so rows (rows + 1) < 4.1e18 < 2^63.
  const long most = symmetric ? rows * (rows + 1) / 2 : rows * rows;
  if (entries > most)
    fail(path, number,
         "the size line announces " + std::to_string(entries) + " entries, more than the " +
             std::to_string(most) + " a " + (symmetric ? "symmetric (lower triangle) " : "") +
             std::to_string(rows) + " x " + std::to_string(rows) + " matrix holds");
  long present = 0;
  for (size_t at = offset; next_line(text, at, line);)
    if (line.find_first_not_of(" \t\r") != std::string_view::npos) ++present;
  if (present != entries)
    throw ImportError(path + ": the size line announces " + std::to_string(entries) +
                      " entries, the file holds " + std::to_string(present) +
                      (present < entries ? " (truncated?)" : ""));
  const int n = static_cast<int>(rows);
  const CoordinateEntries e = parse_coordinate_entries(text, offset, number + 1, n, path);
  if (static_cast<long>(e.size()) != entries)
    throw ImportError(path + ": the size line announces " + std::to_string(entries) +
                      " entries, the file holds " + std::to_string(e.size()) +
                      (static_cast<long>(e.size()) < entries ? " (truncated?)" : ""));
  if (symmetric)
    for (size_t k = 0; k < e.size(); ++k)
      if (e.row[k] < e.col[k])
        fail(path, e.line[k],
             "a symmetric Matrix Market file stores the lower triangle (row >= col)");
  if (positive_diagonal) check_positive_diagonal(e, n, path);
  // A general file is a whole matrix: an entry without its mirror stands
  // beside a zero, and the pair is checked like any other.
  return symmetric_matrix(e, n, path,
                          symmetric ? MirrorRule::one_triangle : MirrorRule::both_triangles);
}

Component read_matrix_market_component(const std::string& folder, const std::string& name,
                                       const std::vector<int>* boundary_nodes) {
  Component c;
  c.name = name;
  c.dofs = read_dofs_csv(folder + "/dofs.csv");
  c.stiffness = read_symmetric_matrix_market(folder + "/K.mtx", false, c.n_dofs());
  c.mass = read_symmetric_matrix_market(folder + "/M.mtx", true, c.n_dofs());
  for (const auto& [matrix, file] : {std::pair{&c.stiffness, "K.mtx"}, {&c.mass, "M.mtx"}})
    if (matrix->rows() != c.n_dofs())
      throw ImportError(folder + "/" + file + ": " + std::to_string(matrix->rows()) +
                        " rows, but dofs.csv lists " + std::to_string(c.n_dofs()) + " dofs");
  c.nodes = read_nodes_csv(folder + "/nodes.csv");
  for (const DofInfo& d : c.dofs)
    if (const auto at = std::lower_bound(
            c.nodes.begin(), c.nodes.end(), d.node,
            [](const ComponentNode& a, int id) { return a.id < id; });
        at == c.nodes.end() || at->id != d.node)
      throw ImportError(folder + "/dofs.csv: node " + std::to_string(d.node) +
                        " has dofs but no line in nodes.csv");
  if (boundary_nodes) {
    for (DofInfo& d : c.dofs)
      d.boundary = false;
    c.boundary = boundary_of_nodes(*boundary_nodes, c.dofs, folder + " (boundary node set)");
  } else {
    c.boundary = flagged_boundary(c.dofs);
  }
  for (int b : c.boundary) {
    const auto at = std::lower_bound(c.nodes.begin(), c.nodes.end(), c.dofs[b].node,
                                     [](const ComponentNode& a, int id) { return a.id < id; });
    if (at->generated)
      throw ImportError(folder + ": boundary node " + std::to_string(at->id) +
                        " is a generated node (empty coordinates in nodes.csv): it cannot be on "
                        "the boundary");
  }
  check_component(c, folder);
  return c;
}

} // namespace rsi
