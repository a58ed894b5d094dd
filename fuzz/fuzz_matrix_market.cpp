// libFuzzer target for the Matrix Market reader: the bytes of an input are
// the text of a K.mtx, written to a file of this process's own folder and
// read by read_symmetric_matrix_market (reference/model/matrix_market.hpp)
// twice, as a stiffness (any diagonal) and as a mass (positive diagonal) of
// a component of 6 dofs, the way read_matrix_market_component reads K.mtx
// and M.mtx.
//
// The contract under test (matrix_market.hpp): every text is either read,
// and then the matrix is square, symmetric bit for bit (both triangles
// stored from one entry or equal pairs) and finite, a mass with a positive
// diagonal; or refused with ImportError whose message names the file. Any
// other exception, an anonymous message or an accepted matrix outside that
// contract calls abort(), so libFuzzer records a crash; ASan and UBSan turn
// memory errors and undefined behaviour into crashes too. libFuzzer's
// -malloc_limit_mb (default: its -rss_limit_mb, 2048 MB) makes an
// allocation sized by a declared count rather than by the file's lines a
// crash as well.
//
// Run: fuzz/run-fuzz.sh SECONDS fuzz_matrix_market (see fuzz/README.md).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>

#include <unistd.h>

#include "component.hpp"
#include "matrix_market.hpp"

namespace {

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_matrix_market: %s\n", what.c_str());
  std::abort();
}

void check_accepted(const Eigen::SparseMatrix<double>& a, bool mass, long expected_rows) {
  if (a.rows() != a.cols()) fail("accepted matrix is not square");
  if (expected_rows >= 0 && a.rows() != expected_rows) fail("accepted size differs from expected_rows");
  const Eigen::SparseMatrix<double> t = a.transpose();
  for (int k = 0; k < a.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it)
      if (!std::isfinite(it.value())) fail("accepted matrix holds a non-finite entry");
  if ((a - t).norm() != 0.0) fail("accepted matrix is not symmetric bit for bit");
  if (mass)
    for (int i = 0; i < a.rows(); ++i)
      if (!(a.coeff(i, i) > 0.0)) fail("accepted mass has a diagonal entry that is not positive");
}

void read_as(const std::string& path, bool mass, long expected_rows) {
  try {
    check_accepted(rsi::read_symmetric_matrix_market(path, mass, expected_rows), mass,
                   expected_rows);
  } catch (const rsi::ImportError& e) {
    const std::string message = e.what();
    if (message.rfind(path, 0) != 0) fail("ImportError not naming the file: " + message);
  } catch (const std::exception& e) {
    fail(std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("rsi-fuzz-mm-" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const std::string path = (folder / "K.mtx").string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  // As read_matrix_market_component reads them: the size a dofs.csv of 6
  // rows asks for, checked on the size line. (expected_rows = -1, any size,
  // is for tests: rsi never calls it so; a size line of 2e9 rows then sizes
  // an 8 GB index, as the header says: the seed huge-size-line.mtx.)
  read_as(path, false, 6);
  read_as(path, true, 6);
  return 0;
}
