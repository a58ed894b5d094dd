#pragma once
// Sparse matrices written one entry a line, "row col value" (1-based): the
// body of CalculiX's JOB.sti / JOB.mas and of a Matrix Market coordinate
// file. Parsed with std::from_chars (exact: the decimal text rounds to the
// nearest double, so a matrix written with 17 digits reads back bitwise),
// every failure named by file and line: a truncated or non-numeric line, an
// index out of range, NaN or Inf, an entry given twice, a mirrored pair that
// disagrees. A hand-written parser rather than Eigen's loadMarket, which
// reports none of these, and for the ccx files, which no library reads.

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/SparseCore>

namespace rsi {

struct CoordinateEntries {
  std::vector<int> row;       ///< 0-based
  std::vector<int> col;       ///< 0-based
  std::vector<double> value;
  std::vector<int> line;      ///< 1-based line of each entry in its file

  size_t size() const { return value.size(); }
};

/// The whole file as text; throws ImportError naming `path` if it cannot be read.
std::string read_whole_file(const std::string& path);

/// Parses `text` from byte `offset` (on line `first_line`) to its end: one
/// entry a line, blank lines skipped. Indices must lie in [1, n]. Throws
/// ImportError naming `path` and the line.
CoordinateEntries parse_coordinate_entries(std::string_view text, size_t offset, int first_line,
                                           int n, const std::string& path);

/// What an entry without its mirror (j, i) means.
enum class MirrorRule {
  /// The file stores one triangle of a symmetric matrix (or some entries in
  /// both, as ccx's files may): the missing mirror is the entry itself.
  one_triangle,
  /// The file stores the whole matrix (Matrix Market `general`): a missing
  /// mirror is a zero, and the pair (v, 0) must agree like any other.
  both_triangles
};

/// The n x n symmetric matrix of the entries, both triangles stored. A
/// mirrored pair must agree within 1e-12 of the largest entry (with
/// MirrorRule::both_triangles an entry without its mirror is paired with
/// 0). Throws ImportError naming `path` and the lines of an entry given
/// twice or of a pair that disagrees.
Eigen::SparseMatrix<double> symmetric_matrix(const CoordinateEntries& entries, int n,
                                             const std::string& path,
                                             MirrorRule rule = MirrorRule::one_triangle);

/// Every diagonal entry given and positive (a mass matrix); throws
/// ImportError naming `path` and the line of a non-positive one, or the
/// first row without a diagonal entry.
void check_positive_diagonal(const CoordinateEntries& entries, int n, const std::string& path);

/// The next line of `text` from `offset` (without its end of line), and
/// `offset` moved past it; false at the end.
bool next_line(std::string_view text, size_t& offset, std::string_view& line);

} // namespace rsi
