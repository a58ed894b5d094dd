#pragma once
// Output files of the CLI, each written whole: to a temporary file in the
// same directory, then renamed over the target (SPEC §5), so a reader never
// sees a half-written file.

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

namespace rsi {

/// An output that cannot be written (directory not creatable, disk full).
class OutputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The output directories a command creates, remembered so that a failed
/// command can remove those it left empty (no output on failure, SPEC §5).
class OutputDirectories {
public:
  /// Creates `dir` (and parents) and checks that a file can be created in it
  /// (a probe file, removed at once); throws OutputError naming `option` and
  /// the directory.
  void make(const std::string& dir, const std::string& option);
  /// Removes the directories `make` created that are still empty, deepest
  /// first (a directory holding a file stays). Never throws: it runs while
  /// a failed command unwinds.
  void remove_empty() noexcept;

private:
  std::vector<std::filesystem::path> m_created; ///< parents first
};

void write_text_file(const std::string& path, const std::string& content);

/// A text file written piece by piece (streamed output of a long run) and
/// still whole for a reader: the pieces go to a temporary file in the
/// target's directory, renamed over `path` by commit(); destroyed without a
/// commit (an exception during the run), the temporary file is removed and
/// `path` is left as it was. Throws OutputError when a piece cannot be
/// written (disk full).
class StreamedTextFile {
public:
  explicit StreamedTextFile(const std::string& path);
  ~StreamedTextFile();
  StreamedTextFile(const StreamedTextFile&) = delete;
  StreamedTextFile& operator=(const StreamedTextFile&) = delete;

  void append(const std::string& piece);
  /// Flushes, closes and renames the temporary file to `path`.
  void commit();

private:
  std::string m_path;
  std::string m_temporary;
  std::FILE* m_file = nullptr; ///< owned; null once committed
};

/// Matrix Market coordinate real symmetric (lower triangle), 17 significant digits.
void write_symmetric_matrix_market(const std::string& path,
                                   const Eigen::SparseMatrix<double>& matrix);

/// Matrix Market coordinate real general, 17 significant digits.
void write_general_matrix_market(const std::string& path,
                                 const Eigen::SparseMatrix<double>& matrix);

} // namespace rsi
