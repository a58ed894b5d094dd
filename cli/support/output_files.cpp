#include "output_files.hpp"

#include <cassert>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <vector>


namespace rsi {
namespace {

std::string temporary_name(const std::string& path) {
  return path + ".tmp" + std::to_string(::getpid());
}

/// ": cannot write (why); what to change", for the errno `error` of the
/// failed call (0: unknown). The temporary file is not named: it is removed.
std::string cannot_write(int error) {
  return std::string(": cannot write (") + (error != 0 ? std::strerror(error) : "write failed") +
         "); free space on its disk, raise the file-size limit (ulimit -f) or choose another "
         "--out";
}

void commit(const std::string& temporary, const std::string& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    const int why = error.value();
    std::filesystem::remove(temporary, error);
    throw OutputError(path + cannot_write(why));
  }
}

} // namespace

void OutputDirectories::make(const std::string& dir, const std::string& option) {
  const std::string allowed = "; --out must name a directory that can be created and written";
  if (dir.empty()) throw OutputError(option + ": empty path" + allowed);
  // The directories about to be created, parents first.
  std::vector<std::filesystem::path> missing;
  std::error_code error;
  for (std::filesystem::path p = std::filesystem::absolute(dir, error).lexically_normal();
       !p.empty() && !std::filesystem::exists(p, error); p = p.parent_path()) {
    missing.insert(missing.begin(), p);
    if (p == p.parent_path()) break;
  }
  std::filesystem::create_directories(dir, error);
  for (const std::filesystem::path& p : missing)
    if (std::filesystem::is_directory(p)) m_created.push_back(p);
  if (error || !std::filesystem::is_directory(dir))
    throw OutputError(option + " " + dir + ": cannot create the output directory (" +
                      (error ? error.message() : "not a directory") + ")" + allowed);
  // Permissions alone do not tell (root, read-only mounts): try a file.
  const std::string probe = dir + "/.rsi-probe" + std::to_string(::getpid());
  const bool writable = static_cast<bool>(std::ofstream(probe, std::ios::binary));
  std::filesystem::remove(probe, error);
  if (!writable)
    throw OutputError(option + " " + dir + ": cannot create a file in the output directory" +
                      allowed);
}

void OutputDirectories::remove_empty() noexcept {
  for (auto p = m_created.rbegin(); p != m_created.rend(); ++p) {
    try { // is_empty opens the directory, which allocates
      std::error_code error;
      if (std::filesystem::is_empty(*p, error)) std::filesystem::remove(*p, error);
    } catch (...) { // out of memory: the directory stays, empty
    }
  }
  m_created.clear();
}

void write_text_file(const std::string& path, const std::string& content) {
  const std::string temporary = temporary_name(path);
  {
    std::ofstream out(temporary, std::ios::binary);
    errno = 0;
    out << content;
    out.close();
    if (!out) {
      const int why = errno;
      std::filesystem::remove(temporary);
      throw OutputError(path + cannot_write(why));
    }
  }
  commit(temporary, path);
}

StreamedTextFile::StreamedTextFile(const std::string& path)
    : m_path(path)
    , m_temporary(temporary_name(path))
    , m_file(std::fopen(m_temporary.c_str(), "wb")) {
  if (!m_file) throw OutputError(path + cannot_write(errno));
}

StreamedTextFile::~StreamedTextFile() {
  if (!m_file) return;
  std::fclose(m_file);
  std::error_code error;
  std::filesystem::remove(m_temporary, error);
}

void StreamedTextFile::append(const std::string& piece) {
  assert(m_file && "StreamedTextFile::append after commit");
  if (std::fwrite(piece.data(), 1, piece.size(), m_file) != piece.size())
    throw OutputError(m_path + cannot_write(errno));
}

void StreamedTextFile::commit() {
  assert(m_file && "StreamedTextFile::commit twice");
  std::FILE* file = m_file;
  m_file = nullptr;
  if (std::fclose(file) != 0) {
    const int why = errno;
    std::error_code error;
    std::filesystem::remove(m_temporary, error);
    throw OutputError(m_path + cannot_write(why));
  }
  rsi::commit(m_temporary, m_path);
}

namespace {

/// The bytes Eigen::saveMarket writes (its header, then "row col value" a
/// line, column by column, values as std::scientific with 17 digits), but
/// through StreamedTextFile: saveMarket never checks its stream, so a full
/// disk or the file-size limit left a truncated file renamed into place
/// with success (issue 13). Every write and the close are checked here.
void write_matrix_market(const std::string& path, const Eigen::SparseMatrix<double>& matrix,
                         bool symmetric) {
  StreamedTextFile file(path);
  std::string text = symmetric ? "%%MatrixMarket matrix coordinate  real symmetric\n"
                               : "%%MatrixMarket matrix coordinate  real general\n";
  text += std::to_string(matrix.rows()) + " " + std::to_string(matrix.cols()) + " " +
          std::to_string(matrix.nonZeros()) + "\n";
  constexpr std::size_t chunk = 1 << 20;
  char line[96];
  for (Eigen::Index j = 0; j < matrix.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, j); it; ++it) {
      const int length = std::snprintf(line, sizeof line, "%lld %lld %.17e\n",
                                       static_cast<long long>(it.row() + 1),
                                       static_cast<long long>(it.col() + 1), it.value());
      text.append(line, static_cast<std::size_t>(length));
      if (text.size() >= chunk) {
        file.append(text);
        text.clear();
      }
    }
  file.append(text);
  file.commit();
}

} // namespace

void write_symmetric_matrix_market(const std::string& path,
                                   const Eigen::SparseMatrix<double>& matrix) {
  write_matrix_market(path, matrix.triangularView<Eigen::Lower>(), true);
}

void write_general_matrix_market(const std::string& path,
                                 const Eigen::SparseMatrix<double>& matrix) {
  write_matrix_market(path, matrix, false);
}

} // namespace rsi
