#include "coordinate_entries.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

#include "component.hpp"

namespace rsi {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

void skip_spaces(const char*& p, const char* end) {
  while (p < end && is_space(*p))
    ++p;
}

[[noreturn]] void fail_line(const std::string& path, int line, const std::string& what,
                            std::string_view text) {
  std::string shown(text.substr(0, 80));
  throw ImportError(path + ":" + std::to_string(line) + ": " + what + " (line: '" + shown + "')");
}

} // namespace

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImportError(path + ": cannot open (missing or unreadable)");
  // Appended piece by piece, not `stream << in.rdbuf()`: a string stream
  // that cannot grow stops with no error (stream_text.hpp), and a matrix
  // file cut short under a memory limit was then reported as a malformed
  // line of the file. std::string::append throws std::bad_alloc.
  std::string text;
  char piece[1 << 16];
  while (in.read(piece, sizeof piece) || in.gcount() > 0)
    text.append(piece, static_cast<size_t>(in.gcount()));
  if (in.bad()) throw ImportError(path + ": cannot read");
  return text;
}

bool next_line(std::string_view text, size_t& offset, std::string_view& line) {
  if (offset >= text.size()) return false;
  const size_t end = text.find('\n', offset);
  const size_t stop = end == std::string_view::npos ? text.size() : end;
  line = text.substr(offset, stop - offset);
  offset = end == std::string_view::npos ? text.size() : end + 1;
  return true;
}

CoordinateEntries parse_coordinate_entries(std::string_view text, size_t offset, int first_line,
                                           int n, const std::string& path) {
  CoordinateEntries e;
  const size_t estimate = (text.size() - std::min(offset, text.size())) / 24;
  e.row.reserve(estimate);
  e.col.reserve(estimate);
  e.value.reserve(estimate);
  e.line.reserve(estimate);
  std::string_view line;
  int number = first_line - 1;
  while (next_line(text, offset, line)) {
    ++number;
    const char* p = line.data();
    const char* end = p + line.size();
    skip_spaces(p, end);
    if (p == end) continue;
    long index[2];
    for (long& k : index) {
      skip_spaces(p, end);
      const auto [next, ec] = std::from_chars(p, end, k);
      if (ec != std::errc() || (next < end && !is_space(*next)))
        fail_line(path, number, "expected 'row col value' with integer row and col", line);
      p = next;
      if (k < 1 || k > n)
        fail_line(path, number,
                  "index " + std::to_string(k) + " outside [1, " + std::to_string(n) + "]", line);
    }
    skip_spaces(p, end);
    double v = 0.0;
    const auto [next, ec] = std::from_chars(p, end, v);
    if (ec == std::errc::result_out_of_range)
      fail_line(path, number, "value out of the range of a double", line);
    if (ec != std::errc() || (next < end && !is_space(*next)))
      fail_line(path, number, "expected a number as the third field", line);
    if (!std::isfinite(v)) fail_line(path, number, "value is not finite", line);
    p = next;
    skip_spaces(p, end);
    if (p != end) fail_line(path, number, "more than three fields", line);
    e.row.push_back(static_cast<int>(index[0] - 1));
    e.col.push_back(static_cast<int>(index[1] - 1));
    e.value.push_back(v);
    e.line.push_back(number);
  }
  return e;
}

void check_positive_diagonal(const CoordinateEntries& e, int n, const std::string& path) {
  std::vector<char> seen(n, 0);
  for (size_t k = 0; k < e.size(); ++k)
    if (e.row[k] == e.col[k]) {
      if (!(e.value[k] > 0.0)) {
        std::ostringstream why;
        why << path << ":" << e.line[k] << ": diagonal entry (" << e.row[k] + 1 << ", "
            << e.col[k] + 1 << ") = " << e.value[k] << ": the mass diagonal must be positive";
        throw ImportError(why.str());
      }
      seen[e.row[k]] = 1;
    }
  for (int i = 0; i < n; ++i)
    if (!seen[i])
      throw ImportError(path + ": no diagonal entry (" + std::to_string(i + 1) + ", " +
                        std::to_string(i + 1) + "): the mass diagonal must be positive");
}

Eigen::SparseMatrix<double> symmetric_matrix(const CoordinateEntries& e, int n,
                                             const std::string& path, MirrorRule rule) {
  const size_t m = e.size();
  // Group the entries by their position in the lower triangle.
  std::vector<size_t> order(m);
  std::iota(order.begin(), order.end(), size_t{0});
  auto key = [&](size_t k) {
    const long lo = std::min(e.row[k], e.col[k]);
    const long hi = std::max(e.row[k], e.col[k]);
    return lo * static_cast<long>(n) + hi;
  };
  std::vector<long> keys(m);
  for (size_t k = 0; k < m; ++k)
    keys[k] = key(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  double largest = 0.0;
  for (double v : e.value)
    largest = std::max(largest, std::abs(v));

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(2 * m);
  for (size_t g = 0; g < m;) {
    size_t h = g + 1;
    while (h < m && keys[order[h]] == keys[order[g]])
      ++h;
    const size_t a = order[g];
    const bool diagonal = e.row[a] == e.col[a];
    if (h - g > 2 || (h - g == 2 && (diagonal || e.row[a] == e.row[order[g + 1]]))) {
      const size_t b = order[g + 1];
      throw ImportError(path + ":" + std::to_string(e.line[b]) + ": entry (" +
                        std::to_string(e.row[b] + 1) + ", " + std::to_string(e.col[b] + 1) +
                        ") given again (first at line " + std::to_string(e.line[a]) + ")");
    }
    if (h - g == 2) {
      const size_t b = order[g + 1];
      if (std::abs(e.value[a] - e.value[b]) > 1e-12 * largest) {
        std::ostringstream why;
        why.precision(17);
        why << path << ":" << e.line[b] << ": not symmetric: (" << e.row[b] + 1 << ", "
            << e.col[b] + 1 << ") = " << e.value[b] << " but (" << e.row[a] + 1 << ", "
            << e.col[a] + 1 << ") = " << e.value[a] << " at line " << e.line[a]
            << "; they must agree within 1e-12 x the largest entry " << largest;
        throw ImportError(why.str());
      }
    }
    if (h - g == 1 && !diagonal && rule == MirrorRule::both_triangles &&
        std::abs(e.value[a]) > 1e-12 * largest) {
      std::ostringstream why;
      why.precision(17);
      why << path << ":" << e.line[a] << ": not symmetric: (" << e.row[a] + 1 << ", "
          << e.col[a] + 1 << ") = " << e.value[a] << " but (" << e.col[a] + 1 << ", "
          << e.row[a] + 1 << ") is not given (0); a general file stores both triangles, "
          << "which must agree within 1e-12 x the largest entry " << largest
          << " (for one triangle write 'symmetric' and the lower one)";
      throw ImportError(why.str());
    }
    triplets.emplace_back(e.row[a], e.col[a], e.value[a]);
    if (!diagonal) triplets.emplace_back(e.col[a], e.row[a], e.value[a]);
    g = h;
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

} // namespace rsi
