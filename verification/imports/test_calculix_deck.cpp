// CalculiX decks read as ccx 2.20 reads them (calculix_fields.hpp,
// calculix_deck.hpp): each reading below was checked by running ccx 2.20 on
// a one-element C3D8 deck holding the line, and reading back the node
// coordinates it wrote (.frd) or the set it printed (*NODE PRINT, NSET=);
// "ccx refuses" means ccx stopped with *ERROR, "ccx crashes" a signal.
// Also the rows of the nodes ccx creates (calculix_matrices.hpp), read from
// hand-written JOB files, and their export and import.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>
#include <unistd.h>

#include "calculix_deck.hpp"
#include "calculix_features.hpp"
#include "calculix_fields.hpp"
#include "calculix_matrices.hpp"
#include "matrix_market.hpp"

namespace {

namespace fs = std::filesystem;

struct ScratchDir {
  fs::path path;
  ScratchDir() {
    path = fs::temp_directory_path() / ("rsi-calculix-deck-" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p);
  out << text;
}

/// The deck `text` read from a scratch file.
rsi::CalculixDeck read(const std::string& text) {
  ScratchDir dir;
  write(dir.path / "deck.inp", text);
  return rsi::read_calculix_deck((dir.path / "deck.inp").string());
}

/// The message of reading `text`, or "" if it is read.
std::string refusal(const std::string& text) {
  try {
    read(text);
  } catch (const rsi::ImportError& e) {
    return e.what();
  }
  return "";
}

const std::string kNodes = "*NODE, NSET=NALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
                           "5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n8, 0, 1, 1\n20, 5, 5, 5\n";

std::vector<int> set_of(const std::string& nset_lines) {
  return read(kNodes + nset_lines).nsets.at("X");
}

TEST(CalculixFields, FortranRealsAsCcxReadsThem) {
  // Read by ccx 2.20 as these values (F20.0).
  EXPECT_EQ(rsi::fortran_real("1.5+2"), 150.0);
  EXPECT_EQ(rsi::fortran_real("1.5-2"), 0.015);
  EXPECT_EQ(rsi::fortran_real("1.5D2"), 150.0);
  EXPECT_EQ(rsi::fortran_real("1.5q2"), 150.0);
  EXPECT_EQ(rsi::fortran_real("+.5"), 0.5);
  EXPECT_EQ(rsi::fortran_real("1.E0"), 1.0);
  EXPECT_EQ(rsi::fortran_real("1.5E+002"), 150.0);
  EXPECT_EQ(rsi::fortran_real("."), 0.0);
  EXPECT_EQ(rsi::fortran_real("-"), 0.0);
  EXPECT_EQ(rsi::fortran_real("E5"), 0.0);
  EXPECT_EQ(rsi::fortran_real(""), 0.0);
  EXPECT_EQ(rsi::fortran_real("1.0000000000000000000"), 1.0) << "21 characters, the first 20 read";
  // Refused by ccx ("*ERROR reading *NODE").
  for (const char* bad : {"1.5E", "1E5.5", "1.5E2.", "1..5", "0X10", "1.5F2", "1.5E2E", "1_000"})
    EXPECT_FALSE(rsi::fortran_real(bad)) << bad;
  EXPECT_TRUE(std::isinf(*rsi::fortran_real("1E999")));
}

TEST(CalculixFields, FortranIntegersAndFields) {
  EXPECT_EQ(rsi::fortran_integer("+5"), 5);
  EXPECT_EQ(rsi::fortran_integer(""), 0);
  EXPECT_EQ(rsi::fortran_integer("2147483647"), 2147483647);
  EXPECT_FALSE(rsi::fortran_integer("9999999999")) << "ccx: *ERROR reading *NODE";
  EXPECT_FALSE(rsi::fortran_integer("5.0"));
  EXPECT_EQ(rsi::fortran_integer("12345678901"), 1234567890) << "I10 reads 10 characters";
  const rsi::CalculixLine line = rsi::calculix_line("*Include, Input = Mesh/A b.inp, x\r\ny");
  EXPECT_EQ(line.upper, "*INCLUDE,INPUT=Mesh/Ab.inp,X") << "file names keep their case";
  EXPECT_EQ(*rsi::calculix_fields("1,2,"), (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(*rsi::calculix_fields("1,2,,"), (std::vector<std::string>{"1", "2", ""}));
  EXPECT_EQ(rsi::calculix_fields("1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,,,")->size(), 16u);
  EXPECT_FALSE(rsi::calculix_fields("1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17"));
}

TEST(CalculixDeck, NodeLinesCcxAccepts) {
  // ccx 2.20 reads each of these (exit 0, coordinates in the .frd).
  const rsi::CalculixDeck deck =
      read("*NODE\n9\n10, 1, 2, 3, 4, 5\n11,, 2,\n1 2, 1 . 5, 2\n*Node , nset = Top\n 13, 1.5+2\n"
           "14,7,7,7\n14,8,8,8\n");
  ASSERT_EQ(deck.nodes.size(), 6u);
  EXPECT_EQ(deck.nodes[0].id, 9);
  EXPECT_EQ(deck.nodes[0].x, Eigen::Vector3d(0, 0, 0)) << "an id alone is at the origin";
  EXPECT_EQ(deck.nodes[1].x, Eigen::Vector3d(1, 2, 3)) << "fields after the fourth are ignored";
  EXPECT_EQ(deck.nodes[2].x, Eigen::Vector3d(0, 2, 0)) << "empty fields are 0";
  EXPECT_EQ(deck.nodes[3].id, 12) << "blanks are removed: '1 2' is 12";
  EXPECT_EQ(deck.nodes[3].x, Eigen::Vector3d(1.5, 2, 0));
  EXPECT_EQ(deck.nodes[4].x, Eigen::Vector3d(150, 0, 0));
  EXPECT_EQ(deck.nodes[5].x, Eigen::Vector3d(8, 8, 8));
  EXPECT_EQ(deck.nsets.at("TOP"), (std::vector<int>{13, 14, 14}));
  EXPECT_EQ(deck.largest_node_id, 14);
  // 14 defined twice: ccx keeps the last (its element then had a
  // nonpositive Jacobian at (5, 5, 5) when 8 was redefined so).
  const rsi::CalculixDeck twice = read("*NODE\n14,7,7,7\n*NODE\n14,8,8,8\n");
  ASSERT_EQ(twice.nodes.size(), 1u);
  EXPECT_EQ(twice.nodes[0].x, Eigen::Vector3d(8, 8, 8));
}

TEST(CalculixDeck, NodeLinesCcxRefusesOrMisreads) {
  // ccx crashes on node 0 (SIGABRT) and -3 (SIGSEGV), refuses 9999999999,
  // reads 00000000009 as node 0 and crashes, and reads a 22-character
  // coordinate's first 20 characters "1.2345678901234567e+" (refused).
  EXPECT_NE(refusal("*NODE\n0, 1, 2, 3\n").find("deck.inp:2: *NODE: node id 0"), std::string::npos);
  EXPECT_NE(refusal("*NODE\n-3, 1, 2, 3\n").find("node id -3"), std::string::npos);
  EXPECT_NE(refusal("*NODE\n9999999999, 1, 2, 3\n").find("the node id must be an integer"),
            std::string::npos);
  EXPECT_NE(refusal("*NODE\n00000000009, 1, 2, 3\n").find("has more than 10 characters"),
            std::string::npos);
  EXPECT_NE(refusal("*NODE\n9, 1.2345678901234567e+02, 1, 1\n")
                .find("has more than 20 characters: ccx reads only its first 20"),
            std::string::npos);
  EXPECT_NE(refusal("*NODE\n9, 1e999\n").find("must be finite"), std::string::npos);
  EXPECT_NE(refusal("*NODE\n9, 0x10\n").find("a coordinate must be a number, got '0X10'"),
            std::string::npos);
  EXPECT_NE(refusal("*NODE\n1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17\n").find("more than 16"),
            std::string::npos);
  EXPECT_NE(refusal("*NODE\n1, " + std::string(1400, '0') + "\n").find("ccx reads at most 1319"),
            std::string::npos);
}

TEST(CalculixDeck, NodeSetsAsCcxBuildsThem) {
  // Each set below is the one ccx 2.20 printed (*NODE PRINT, NSET=X).
  EXPECT_EQ(set_of("*NSET, NSET=X\n5, 6,\n7,\n"), (std::vector<int>{5, 6, 7}))
      << "trailing commas";
  EXPECT_EQ(set_of("*NSET, NSET=X\n5, 25\n"), (std::vector<int>{5}))
      << "an id above the largest node id (20) is dropped";
  EXPECT_EQ(read(kNodes + "*NSET, NSET=X\n5, 25\n").dropped_ids.at("X"), (std::vector<int>{25}))
      << "and kept aside: a boundary set losing it is refused";
  EXPECT_EQ(set_of("*NSET, NSET=X\n5, 15\n"), (std::vector<int>{5, 15}))
      << "an undefined id below it is kept";
  EXPECT_EQ(set_of("*NSET, NSET=A\n5, 6\n*NSET, NSET=X\nA, 7\n"), (std::vector<int>{5, 6, 7}));
  EXPECT_EQ(set_of("*NSET, NSET=X\n5\n*NSET, NSET=X\nX, 6\n"), (std::vector<int>{5, 6}))
      << "a set naming itself adds nothing; *NSET again appends";
  EXPECT_EQ(set_of("*NSET, NSET=X\nNALL\n"), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 20}));
  EXPECT_EQ(set_of("*NSET, NSET=12A\n5\n*NSET, NSET=X\n12A, 7\n"), (std::vector<int>{5, 7}));
  EXPECT_EQ(set_of("*NSET, NSET=X\n5, 5, 6\n"), (std::vector<int>{5, 5, 6}));
  EXPECT_EQ(set_of("*nset, nset=x\n5\n"), (std::vector<int>{5}));
  EXPECT_EQ(set_of("*NSET, NSET=X\n7\n*NODE, NSET=X\n30, 1, 1, 1\n"), (std::vector<int>{30, 7}))
      << "every *NODE block is read before any *NSET";
  EXPECT_EQ(set_of("*NSET, NSET=X, GENERATE\n5, 8\n"), (std::vector<int>{5, 6, 7, 8}));
  EXPECT_EQ(set_of("*NSET, NSET=X, GENERATE\n5, 20, 3\n"), (std::vector<int>{5, 8, 11, 14, 17, 20}));
  EXPECT_EQ(set_of("*NSET, NSET=X, GENERATE\n5, 8, 2,\n"), (std::vector<int>{5, 7}));
  EXPECT_EQ(set_of("*NSET, NSET=X, GENERATE\n5, 8, 2, 7\n"), (std::vector<int>{5, 7}));
  EXPECT_EQ(set_of("*NSET, NSET=X, GENERATE\n5, 5\n"), (std::vector<int>{5}));
  std::vector<int> to_largest;
  for (int id = 5; id <= 20; ++id)
    to_largest.push_back(id);
  EXPECT_EQ(set_of("*NSET, NSET=X, GENERATE\n5, 100\n"), to_largest)
      << "last clamped to the largest node id (ccx: replaced by nk)";
  EXPECT_EQ(set_of("*NSET, NSET=X, GENERATE\n5, 2147483647, 1\n"), to_largest);
}

TEST(CalculixDeck, GenerateNearTheIntegerLimitEnds) {
  // 2147483637 + 10 = 2147483647, + 10 overflows a 32-bit int: the loop
  // must end after the two ids (it looped forever in 32-bit arithmetic).
  const rsi::CalculixDeck deck =
      read("*NODE\n2147483637, 0, 0, 0\n2147483647, 1, 0, 0\n"
           "*NSET, NSET=X, GENERATE\n2147483637, 2147483647, 10\n"
           "*NSET, NSET=Y, GENERATE\n2147483600, 2147483647, 1000\n");
  EXPECT_EQ(deck.nsets.at("X"), (std::vector<int>{2147483637, 2147483647}));
  EXPECT_EQ(deck.nsets.at("Y"), (std::vector<int>{2147483600}));
  EXPECT_NE(refusal("*NODE\n2147483647, 0, 0, 0\n*NSET, NSET=X, GENERATE\n1, 2147483647\n")
                .find("2147483647 ids in one line, more than the 100000000 rsi holds"),
            std::string::npos);
}

TEST(CalculixDeck, NodeSetsCcxRefusesOrMisreads) {
  // ccx: "node set ZZZ has not been defined yet"; crashes (SIGFPE) on
  // "5,,6", on GENERATE step 0 and on a GENERATE line of one field;
  // refuses step -1 and a first value above the largest node id; reads
  // "8, 5" as {8}; reads a set named before its definition as empty.
  const auto refused = [](const std::string& nset, const std::string& fragment) {
    const std::string why = refusal(kNodes + nset);
    EXPECT_NE(why.find(fragment), std::string::npos) << nset << " gave: " << why;
  };
  refused("*NSET, NSET=X\nZZZ, 7\n", "node set ZZZ is not defined");
  refused("*NSET, NSET=X\n5,,6\n", "deck.inp:12: *NSET: an empty field between two commas");
  refused("*NSET, NSET=X, GENERATE\n5, 8, 0\n", "step = 0 must be at least 1");
  refused("*NSET, NSET=X, GENERATE\n5, 8, -1\n", "step = -1 must be at least 1");
  refused("*NSET, NSET=X, GENERATE\n5\n", "a line is 'first, last[, step]'");
  refused("*NSET, NSET=X, GENERATE\n50, 100\n", "first = 50 must lie in [1, 20]");
  refused("*NSET, NSET=X, GENERATE\n8, 5\n", "last = 5 is below first = 8");
  refused("*NSET, NSET=X\nB, 7\n*NSET, NSET=B\n5, 6\n",
          "*NSET X names the node set B before it is defined");
  refused("*NSET, NSET=X\n123456789012\n", "has more than 10 characters");
  refused("*NSET\n5\n", "*NSET without NSET=name");
  refused("*NSET, NSET=" + std::string(81, 'A') + "\n5\n", "more than 80 characters");
}

TEST(CalculixDeck, IncludesResolvedAsCcxResolvesThem) {
  // ccx opens every INPUT= relative to its working directory (the deck's
  // folder), however deep: mesh/all.inp's "mesh/nodes.inp" is
  // DIR/mesh/nodes.inp, not DIR/mesh/mesh/nodes.inp. Here a decoy
  // DIR/mesh/mesh/nodes.inp exists: the folder of the including file would
  // read it (the coordinates 9, 9, 9).
  ScratchDir dir;
  write(dir.path / "deck.inp", "*HEADING\n *STEP in a heading line\n** comment\n"
                               "*INCLUDE, INPUT=mesh/all.inp\n*NSET, NSET=TIP\n2\n"
                               "*STEP\n*NODE\n99, 9, 9, 9\n*END STEP\n");
  write(dir.path / "mesh" / "all.inp", "*INCLUDE, INPUT=mesh/nodes.inp\n"
                                       "*include,input=\"mesh/More.inp\"\n");
  write(dir.path / "mesh" / "nodes.inp", "*NODE, NSET=NALL\n1, 0, 0, 0\n2, 1, 0, 0\n");
  write(dir.path / "mesh" / "More.inp", "*NODE, NSET=NALL\n3, 2, 0, 0\n");
  write(dir.path / "mesh" / "mesh" / "nodes.inp", "*NODE, NSET=NALL\n1, 9, 9, 9\n2, 9, 9, 9\n");
  const rsi::CalculixDeck deck = rsi::read_calculix_deck((dir.path / "deck.inp").string());
  ASSERT_EQ(deck.nodes.size(), 3u) << "the *NODE inside *STEP is not model data";
  EXPECT_EQ(deck.nodes[1].x, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(deck.nsets.at("NALL"), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(deck.nsets.at("TIP"), (std::vector<int>{2}));
  EXPECT_NE(deck.model_text.find("3, 2, 0, 0"), std::string::npos) << "includes inlined";

  // The including file's folder holds the file, the deck's folder not.
  fs::remove_all(dir.path / "mesh" / "mesh");
  write(dir.path / "mesh" / "all.inp", "*INCLUDE, INPUT=nodes.inp\n");
  try {
    rsi::read_calculix_deck((dir.path / "deck.inp").string());
    ADD_FAILURE() << "read nodes.inp beside mesh/all.inp";
  } catch (const rsi::ImportError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("all.inp:1: *INCLUDE: the file '" + (dir.path / "nodes.inp").string() +
                        "' does not exist (ccx opens an included file relative to its working "
                        "directory"),
              std::string::npos)
        << what;
  }
  // Ten levels: ccx stops at nine ("include statements can not be
  // cascaded over more than 9 levels").
  for (int k = 0; k < 9; ++k)
    write(dir.path / ("level" + std::to_string(k) + ".inp"),
          "*INCLUDE, INPUT=level" + std::to_string(k + 1) + ".inp\n");
  write(dir.path / "level9.inp", "*NODE\n1, 0, 0, 0\n");
  write(dir.path / "deep.inp", "*INCLUDE, INPUT=level1.inp\n");
  EXPECT_NO_THROW(rsi::read_calculix_deck((dir.path / "deep.inp").string())) << "9 levels";
  write(dir.path / "deeper.inp", "*INCLUDE, INPUT=level0.inp\n");
  EXPECT_THROW(rsi::read_calculix_deck((dir.path / "deeper.inp").string()), rsi::ImportError);
}

TEST(CalculixDeck, KeywordsAndElementTypes) {
  const rsi::CalculixDeck deck =
      read("*NODE\n1\n*NODE PRINT, NSET=NALL\nU\n*ELEMENT, TYPE=C3D8I, ELSET=E\n"
           "1, 1, 1, 1, 1, 1, 1, 1, 1\n*Element, type=b31\n2, 1, 1\n*CONTACT PAIR, INTERACTION=I\n");
  ASSERT_EQ(deck.nodes.size(), 1u) << "*NODE PRINT is not a *NODE block";
  ASSERT_EQ(deck.element_types.size(), 2u);
  EXPECT_EQ(deck.element_types[0].name, "C3D8I");
  EXPECT_EQ(deck.element_types[1].name, "B31");
  EXPECT_NE(deck.element_types[1].where.find("deck.inp:7"), std::string::npos);
  ASSERT_EQ(deck.keywords.size(), 4u);
  EXPECT_EQ(deck.keywords[3].name, "CONTACTPAIR");
  try {
    rsi::check_calculix_features(deck);
    ADD_FAILURE() << "took a contact pair";
  } catch (const rsi::ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.inp:9: *CONTACT PAIR: contact is not linear"),
              std::string::npos)
        << e.what();
  }
  // Structural elements and linear constraints are taken; heat transfer,
  // dashpots and cyclic sectors are not (named with what to use instead).
  EXPECT_NO_THROW(rsi::check_calculix_features(
      read("*ELEMENT, TYPE=DCOUP3D\n*ELEMENT, TYPE=S8R\n*EQUATION\n*TIE, NAME=T\n*TRANSFORM\n")));
  const auto refused = [](const std::string& text, const std::string& fragment) {
    try {
      rsi::check_calculix_features(read(text));
      ADD_FAILURE() << text;
    } catch (const rsi::ImportError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  refused("*ELEMENT, TYPE=DC3D8\n", "element type DC3D8 (heat transfer): rsi takes structural");
  refused("*ELEMENT, TYPE=DASHPOTA\n", "element type DASHPOTA (dashpot)");
  refused("*ELEMENT, TYPE=GAPUNI\n", "element type GAPUNI (gap)");
  refused("*CYCLIC SYMMETRY MODEL, N=12\n", "*CYCLIC SYMMETRY MODEL: rsi takes the whole component");
  refused("*MATERIAL, NAME=M\n*DAMPING, STRUCTURAL=0.01\n", "*DAMPING: material damping");
}

TEST(CalculixMatrices, RowsOfNodesCcxCreates) {
  // A B31 beam of nodes 1-2 as ccx 2.20 writes it: its expanded nodes'
  // rows carry the beam node (1.1 twice), the C3D8I incompatible-mode
  // node 100 lies above the deck's largest id (2).
  ScratchDir dir;
  write(dir.path / "deck.inp", "*NODE, NSET=NALL\n1, 0, 0, 0\n2, 1, 0, 0\n");
  write(dir.path / "job.dof", "1.1\n1.1\n2.1\n100.1\n100.2\n");
  write(dir.path / "job.sti", "1 1 4\n2 2 4\n3 3 4\n4 4 4\n5 5 4\n1 3 -1\n");
  write(dir.path / "job.mas", "1 1 1\n2 2 1\n3 3 1\n4 4 1\n5 5 1\n");
  const rsi::CalculixDeck deck = rsi::read_calculix_deck((dir.path / "deck.inp").string());
  const rsi::Component c =
      rsi::read_calculix_component((dir.path / "job").string(), deck, {1}, "beam");
  EXPECT_EQ(c.boundary, (std::vector<int>{0, 1})) << "both rows of node 1";
  ASSERT_EQ(c.nodes.size(), 3u);
  EXPECT_FALSE(c.nodes[1].generated);
  EXPECT_TRUE(c.nodes[2].generated);
  EXPECT_EQ(c.nodes[2].id, 100);
  EXPECT_TRUE(std::isnan(c.nodes[2].x(0)));

  // A node below the largest id that the deck does not define: the JOB
  // files belong to another deck.
  write(dir.path / "other.dof", "1.1\n1.1\n3.1\n100.1\n100.2\n");
  write(dir.path / "other.sti", "1 1 4\n2 2 4\n3 3 4\n4 4 4\n5 5 4\n");
  write(dir.path / "other.mas", "1 1 1\n2 2 1\n3 3 1\n4 4 1\n5 5 1\n");
  write(dir.path / "deck3.inp", "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n4, 2, 0, 0\n");
  const rsi::CalculixDeck deck3 = rsi::read_calculix_deck((dir.path / "deck3.inp").string());
  try {
    rsi::read_calculix_component((dir.path / "other").string(), deck3, {1}, "beam");
    ADD_FAILURE() << "read node 3";
  } catch (const rsi::ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("node 3 has dofs but no *NODE line"), std::string::npos)
        << e.what();
  }
}

} // namespace
