#include "output_files.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <unsupported/Eigen/SparseExtra>

namespace rsi {
namespace {

std::string temporary_name(const std::string& path) {
  return path + ".tmp" + std::to_string(::getpid());
}

void commit(const std::string& temporary, const std::string& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw OutputError(path + ": cannot write (" + error.message() + ")");
  }
}

} // namespace

void make_output_directory(const std::string& dir, const std::string& option) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir))
    throw OutputError(option + " " + dir + ": cannot create the output directory (" +
                      (error ? error.message() : "not a directory") + ")");
}

void write_text_file(const std::string& path, const std::string& content) {
  const std::string temporary = temporary_name(path);
  {
    std::ofstream out(temporary, std::ios::binary);
    out << content;
    out.close();
    if (!out) {
      std::filesystem::remove(temporary);
      throw OutputError(path + ": cannot write");
    }
  }
  commit(temporary, path);
}

namespace {

void write_matrix_market(const std::string& path, const Eigen::SparseMatrix<double>& matrix,
                         int symmetry) {
  const std::string temporary = temporary_name(path);
  if (!Eigen::saveMarket(matrix, temporary, symmetry)) {
    std::filesystem::remove(temporary);
    throw OutputError(path + ": cannot write");
  }
  commit(temporary, path);
}

} // namespace

void write_symmetric_matrix_market(const std::string& path,
                                   const Eigen::SparseMatrix<double>& matrix) {
  write_matrix_market(path, matrix.triangularView<Eigen::Lower>(), Eigen::Symmetric);
}

void write_general_matrix_market(const std::string& path,
                                 const Eigen::SparseMatrix<double>& matrix) {
  write_matrix_market(path, matrix, 0);
}

} // namespace rsi
