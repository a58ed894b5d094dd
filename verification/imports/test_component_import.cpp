// Components from files (issue 11): the paper's bladed disk exported and read
// back bitwise; a CalculiX deck with *INCLUDE, *NSET (list and GENERATE) and
// ccx's JOB files read into K, M, dofs, nodes and boundary as written.

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "calculix_deck.hpp"
#include "calculix_matrices.hpp"
#include "case_file.hpp"
#include "matrix_market.hpp"
#include "modal_analysis.hpp"
#include "output_files.hpp"
#include "paper_components.hpp"

namespace {

namespace fs = std::filesystem;

struct ScratchDir {
  fs::path path;
  ScratchDir() {
    path = fs::temp_directory_path() / ("rsi-import-" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

void write(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
}

/// Entries where a and b differ bitwise (same pattern required).
long bitwise_differences(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return -1;
  const Eigen::SparseMatrix<double> d = a - b;
  long count = 0;
  for (int j = 0; j < d.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(d, j); it; ++it)
      if (it.value() != 0.0) ++count;
  return count;
}

TEST(ComponentImport, BladedDiskExportThenImportIsBitwiseEqual) {
  const rsi::Case c = rsi::load_case(RSI_SOURCE_DIR "/data/cases/batailly2007.json");
  const rsi::Component original = rsi::bladed_disk_component(rsi::assemble_bladed_disk(c));
  ScratchDir dir;
  rsi::write_symmetric_matrix_market((dir.path / "K.mtx").string(), original.stiffness);
  rsi::write_symmetric_matrix_market((dir.path / "M.mtx").string(), original.mass);
  std::string dofs = "index,node,kind,boundary\n";
  for (int i = 0; i < original.n_dofs(); ++i)
    dofs += std::to_string(i) + "," + std::to_string(original.dofs[i].node) + "," +
            original.dofs[i].kind + "," + (original.dofs[i].boundary ? "1" : "0") + "\n";
  write(dir.path / "dofs.csv", dofs);
  std::string nodes = "node,x,y,z\n";
  char line[160];
  for (const rsi::ComponentNode& n : original.nodes) {
    std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g\n", n.id, n.x(0), n.x(1), n.x(2));
    nodes += line;
  }
  write(dir.path / "nodes.csv", nodes);

  const rsi::Component back =
      rsi::read_matrix_market_component(dir.path.string(), "bladed-disk", nullptr);
  // The exported file holds one triangle: a bitwise round trip needs the
  // assembled K and M to be exactly symmetric (K(i,j) and K(j,i) the same
  // sums in the same order), and 17 digits to name every double.
  const long k_diff = bitwise_differences(original.stiffness, back.stiffness);
  const long m_diff = bitwise_differences(original.mass, back.mass);
  std::printf("entries differing bitwise: K %ld of %ld, M %ld of %ld\n", k_diff,
              static_cast<long>(original.stiffness.nonZeros()), m_diff,
              static_cast<long>(original.mass.nonZeros()));
  EXPECT_EQ(k_diff, 0);
  EXPECT_EQ(m_diff, 0);
  EXPECT_EQ(back.boundary, original.boundary);
  ASSERT_EQ(back.nodes.size(), original.nodes.size());
  for (size_t k = 0; k < back.nodes.size(); ++k)
    EXPECT_EQ(back.nodes[k].x, original.nodes[k].x) << "node " << back.nodes[k].id;

  // Same matrices, same solver: the same modes to the last bit.
  const rsi::Modes a = rsi::lowest_modes(original.stiffness, original.mass, 60);
  const rsi::Modes b = rsi::lowest_modes(back.stiffness, back.mass, 60);
  const double largest = (a.omega_squared - b.omega_squared).cwiseAbs().maxCoeff();
  std::printf("60 modes: largest |omega^2 difference| = %.3e\n", largest);
  EXPECT_EQ(largest, 0.0);
}

TEST(ComponentImport, CalculixDeckAndJobFiles) {
  ScratchDir dir;
  fs::create_directories(dir.path / "mesh");
  write(dir.path / "mesh" / "nodes.msh", "*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 1.5, -2., 0.25\n"
                                        "3, 3.0, 0.0\n");
  write(dir.path / "deck.inp", "*HEADING\n** a comment\n*include, input=mesh/nodes.msh\n"
                               "*NSET, NSET=tip\n3, 2,\n*Nset, nset=ROW, generate\n1, 3, 2\n"
                               "*STEP\n*NODE\n9, 9., 9., 9.\n*END STEP\n");
  const rsi::CalculixDeck deck = rsi::read_calculix_deck((dir.path / "deck.inp").string());
  ASSERT_EQ(deck.nodes.size(), 3u) << "the *NODE inside *STEP is not model data";
  EXPECT_EQ(deck.nodes[1].x, Eigen::Vector3d(1.5, -2.0, 0.25));
  EXPECT_EQ(deck.nodes[2].x, Eigen::Vector3d(3.0, 0.0, 0.0)) << "a missing z is 0";
  EXPECT_EQ(deck.nsets.at("TIP"), (std::vector<int>{3, 2}));
  EXPECT_EQ(deck.nsets.at("ROW"), (std::vector<int>{1, 3}));
  EXPECT_EQ(deck.nsets.at("NALL"), (std::vector<int>{1, 2, 3}));

  // Nodes 2 and 3, two dofs each (node 1 clamped): upper triangle as ccx writes it.
  write(dir.path / "job.dof", "2.1\n2.2\n3.1\n3.3\n");
  write(dir.path / "job.sti", "1 1  4.0e+00\n1 3 -1.0e+00\n2 2  5.0e+00\n3 3  6.0e+00\n"
                              "3 4  0.5e+00\n4 4  7.0e+00\n");
  write(dir.path / "job.mas", "1 1 1.0\n2 2 2.0\n3 3 3.0\n4 4 4.0\n");
  const rsi::Component c =
      rsi::read_calculix_component((dir.path / "job").string(), deck, {3}, "tiny");
  Eigen::Matrix4d k_expected;
  k_expected << 4, 0, -1, 0, 0, 5, 0, 0, -1, 0, 6, 0.5, 0, 0, 0.5, 7;
  EXPECT_EQ(Eigen::Matrix4d(c.stiffness), k_expected);
  EXPECT_EQ(Eigen::Vector4d(Eigen::MatrixXd(c.mass).diagonal()), Eigen::Vector4d(1, 2, 3, 4));
  EXPECT_EQ(c.boundary, (std::vector<int>{2, 3}));
  EXPECT_EQ(c.dofs[3].kind, "uz");
  EXPECT_EQ(c.dofs[3].node, 3);
  ASSERT_EQ(c.nodes.size(), 2u) << "only the nodes that carry dofs";
  EXPECT_EQ(c.nodes[0].id, 2);
}

// Matrix Market `general` (hardening, third round, class 1): a general file
// is the whole matrix, so an entry whose mirror is missing stands beside a
// zero and the pair must agree within 1e-12 of the largest entry (the lower
// triangle alone was mirrored and used as symmetric).
TEST(MatrixMarketImport, GeneralFileMustHoldBothTriangles) {
  ScratchDir dir;
  const fs::path one = dir.path / "one.mtx";
  const fs::path both = dir.path / "both.mtx";
  const fs::path lower = dir.path / "lower.mtx";
  const fs::path tiny = dir.path / "tiny.mtx";
  write(one, "%%MatrixMarket matrix coordinate real general\n3 3 4\n1 1 4\n2 1 -1\n2 2 4\n3 3 4\n");
  write(both, "%%MatrixMarket matrix coordinate real general\n3 3 5\n1 1 4\n2 1 -1\n1 2 -1\n2 2 "
              "4\n3 3 4\n");
  write(lower,
        "%%MatrixMarket matrix coordinate real symmetric\n3 3 4\n1 1 4\n2 1 -1\n2 2 4\n3 3 4\n");
  // An unmirrored entry of 3e-12 x the largest (4) is within the tolerance: kept, mirrored.
  write(tiny,
        "%%MatrixMarket matrix coordinate real general\n3 3 4\n1 1 4\n3 1 3e-12\n2 2 4\n3 3 4\n");
  std::string message;
  try {
    rsi::read_symmetric_matrix_market(one.string(), false);
  } catch (const rsi::ImportError& e) {
    message = e.what();
  }
  std::printf("general, one triangle -> %s\n", message.c_str());
  EXPECT_NE(message.find("one.mtx:4: not symmetric: (2, 1) = -1 but (1, 2) is not given (0)"),
            std::string::npos)
      << message;
  const Eigen::SparseMatrix<double> a = rsi::read_symmetric_matrix_market(both.string(), false);
  const Eigen::SparseMatrix<double> b = rsi::read_symmetric_matrix_market(lower.string(), false);
  // The general file with both triangles and the symmetric one with the
  // lower: the same matrix, bit for bit (the same decimal text, from_chars).
  EXPECT_EQ(bitwise_differences(a, b), 0);
  const Eigen::SparseMatrix<double> c = rsi::read_symmetric_matrix_market(tiny.string(), false);
  EXPECT_EQ(c.coeff(0, 2), 3e-12);
  EXPECT_EQ(c.coeff(2, 0), 3e-12);
}

// The size line is checked before anything is sized by it (class 2): a
// declared 2e9 rows against the dofs expected, an entry count beyond what
// the size holds or what the file has, each refused at once (a size line
// of 2e9 rows took minutes and 23 GB before the mismatch was reported).
TEST(MatrixMarketImport, DeclaredSizeCheckedBeforeAllocation) {
  ScratchDir dir;
  const fs::path rows = dir.path / "rows.mtx";
  const fs::path count = dir.path / "count.mtx";
  const fs::path more = dir.path / "more.mtx";
  write(rows, "%%MatrixMarket matrix coordinate real symmetric\n2000000000 2000000000 1\n1 1 4\n");
  write(count, "%%MatrixMarket matrix coordinate real symmetric\n3 3 7\n1 1 4\n");
  write(more, "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 4\n2 2 4\n3 3 4\n");
  const auto message_of = [](const fs::path& p, long expected) {
    try {
      rsi::read_symmetric_matrix_market(p.string(), false, expected);
    } catch (const rsi::ImportError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string m1 = message_of(rows, 6);
  const std::string m2 = message_of(count, 3);
  const std::string m3 = message_of(more, 3);
  std::printf("2e9 rows -> %s\n7 entries in 3 x 3 -> %s\n3 lines, 2 declared -> %s\n", m1.c_str(),
              m2.c_str(), m3.c_str());
  EXPECT_NE(m1.find("rows.mtx: 2000000000 rows, but dofs.csv lists 6 dofs"), std::string::npos)
      << m1;
  EXPECT_NE(m2.find("count.mtx:2: the size line announces 7 entries, more than the 6 a symmetric "
                    "(lower triangle) 3 x 3 matrix holds"),
            std::string::npos)
      << m2;
  EXPECT_NE(m3.find("more.mtx: the size line announces 2 entries, the file holds 3"),
            std::string::npos)
      << m3;
}

} // namespace
