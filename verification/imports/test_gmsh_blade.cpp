// The project's own 3D blade (reference/model/gmsh_blade): gmsh meshes it,
// ccx (CalculiX 2.20) turns the deck into frequencies and matrices.
//
// 1. Spec validation: each field out of range is rejected, naming the field.
// 2. The coarse deck (the CI default) against an independent reading of it:
//    C3D10 node order (midside nodes at the Abaqus edge midpoints), ROOT =
//    every node of the clamped face, TIP = the 16 camber-line stations,
//    mesh volume against the exact volume of the geometry.
// 3. The error channel: gmsh missing, gmsh failing, gmsh writing no mesh.
// 4. ccx's Lanczos frequencies (JOB.dat, "E I G E N V A L U E   O U T P U T")
//    of the first five modes at element sizes h, h/2, h/4 (h = 10 mm, the
//    default) and the observed order p = log2((f1 - f2) / (f2 - f3)).
//    Expected rates: for conforming quadratic elements the eigenvalue error
//    is the square of the energy error (Strang & Fix, An Analysis of the
//    Finite Element Method, ch. 6), O(h^4) for a smooth solution. Here the
//    blade meets the root block's top face along a re-entrant 270 deg edge
//    (no fillet), where the stresses of a bending mode are singular like
//    r^(lambda - 1), lambda = 0.5445 (Williams, J. Appl. Mech. 19, 1952,
//    symmetric loading of a 270 deg wedge): the energy error is O(h^lambda)
//    and the eigenvalue (and frequency) error O(h^(2 lambda)) = O(h^1.09)
//    asymptotically under uniform refinement. At these sizes (h >= 2.5 mm
//    for a 3 mm plate) the thickness is crossed by one or two elements, so
//    the meshes are pre-asymptotic: the observed orders are printed, and the
//    test asserts that the frequencies decrease (upper bounds under
//    refinement, min-max) with contracting differences, p > 0.5.
// 5. The first (bending) frequency against the Euler-Bernoulli cantilever
//    f1 = beta1^2 / (2 pi) sqrt(E I / (rho A L^4)), beta1 = 1.8751 (Blevins,
//    Formulas for Natural Frequency and Mode Shape, table 8-1), L = span,
//    for a flat untwisted plate (I = chord t^3 / 12) and for the cambered
//    section (I about the chord-wise principal axis of the annular sector),
//    with the camber and twist effects measured by FE on the same mesh size.
// 6. *FREQUENCY, SOLVER=MATRIXSTORAGE: .sti/.mas/.dof of the coarse deck,
//    rows = 3 (nodes - ROOT nodes), and the lowest modes of those matrices
//    by rsi's own Lanczos (Spectra) against ccx's Lanczos frequencies.
//
// Skipped (GTEST_SKIP, reason printed) when gmsh or ccx is not on PATH.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include "child_process.hpp"
#include "gmsh_blade.hpp"
#include "modal_analysis.hpp"

namespace rsi {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A fresh directory for one test, removed when the test passes.
class WorkDir {
public:
  explicit WorkDir(const std::string& name)
      : m_path((fs::temp_directory_path() /
                ("rsi_gmsh_blade_" + name + "_" + std::to_string(getpid())))
                   .string()) {
    fs::remove_all(m_path);
    fs::create_directories(m_path);
  }
  ~WorkDir() {
    std::error_code ec;
    if (!::testing::Test::HasFailure()) fs::remove_all(m_path, ec);
  }
  const std::string& path() const { return m_path; }

private:
  std::string m_path;
};

/// The deck as this test reads it, independently of gmsh_blade.cpp.
struct Deck {
  std::map<long, Eigen::Vector3d> nodes;
  std::vector<std::array<long, 11>> elements;
  std::map<std::string, std::vector<long>> node_sets;
  std::vector<std::string> keywords;
};

Deck read_deck(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  Deck deck;
  std::string line, block, set_name;
  while (std::getline(in, line)) {
    if (line.empty() || line.rfind("**", 0) == 0) continue;
    if (line[0] == '*') {
      std::string key = line;
      for (char& c : key)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      deck.keywords.push_back(key);
      block = key.substr(0, key.find(','));
      if (block == "*NSET") {
        set_name = key.substr(key.find("NSET=") + 5);
        deck.node_sets[set_name];
      }
      continue;
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    if (block == "*NODE") {
      long id = 0;
      Eigen::Vector3d x;
      fields >> id >> x.x() >> x.y() >> x.z();
      deck.nodes[id] = x;
    } else if (block == "*ELEMENT") {
      std::array<long, 11> e{};
      for (long& v : e)
        fields >> v;
      EXPECT_FALSE(fields.fail()) << "element line: " << line;
      deck.elements.push_back(e);
    } else if (block == "*NSET") {
      long id = 0;
      while (fields >> id)
        deck.node_sets[set_name].push_back(id);
    }
  }
  return deck;
}

/// Frequencies [Hz] of the first "E I G E N V A L U E   O U T P U T" table of a ccx .dat file.
std::vector<double> read_ccx_frequencies(const std::string& dat_path) {
  std::ifstream in(dat_path);
  std::string line;
  bool in_table = false;
  std::vector<double> hz;
  while (std::getline(in, line)) {
    if (!in_table) {
      in_table = line.find("E I G E N V A L U E   O U T P U T") != std::string::npos;
      continue;
    }
    std::istringstream fields(line);
    int mode = 0;
    double eigenvalue = 0, rad = 0, cycles = 0, imaginary = 0;
    if (fields >> mode >> eigenvalue >> rad >> cycles >> imaginary) {
      EXPECT_EQ(mode, static_cast<int>(hz.size()) + 1) << line;
      hz.push_back(cycles);
    } else if (!hz.empty()) {
      break;
    }
  }
  return hz;
}

bool tools_present(const std::vector<std::string>& programs, std::string& missing) {
  for (const std::string& p : programs)
    if (!executable_on_path(p)) missing += (missing.empty() ? "" : ", ") + p;
  return missing.empty();
}

#define SKIP_WITHOUT(...)                                                                          \
  do {                                                                                             \
    std::string missing_;                                                                          \
    if (!tools_present({__VA_ARGS__}, missing_)) {                                                 \
      std::printf("skipped: %s not on PATH\n", missing_.c_str());                                  \
      GTEST_SKIP() << missing_ << " not on PATH";                                                  \
    }                                                                                              \
  } while (0)

/// Writes DIR/JOB.inp = the deck followed by `steps`, runs `ccx -i JOB` in
/// DIR; the wall time [s]. Fails the test when ccx fails.
double run_ccx(const std::string& deck_path, const std::string& dir, const std::string& job,
               const std::string& steps) {
  {
    std::ifstream in(deck_path);
    std::ofstream out(dir + "/" + job + ".inp");
    out << in.rdbuf() << steps;
  }
  const Clock::time_point start = Clock::now();
  const ChildResult r = run_child({"ccx", "-i", job}, dir, dir + "/" + job + ".log");
  const double wall = seconds_since(start);
  EXPECT_TRUE(r.succeeded()) << "ccx -i " << job << " in " << dir << ": " << r.error << "\n"
                             << r.output;
  EXPECT_EQ(r.output.find("*ERROR"), std::string::npos) << r.output;
  return wall;
}

const std::string lanczos_step = "*STEP\n*FREQUENCY\n10\n*END STEP\n";
const std::string matrix_step = "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n";

/// One blade model through gmsh and ccx's Lanczos step.
struct ModelRun {
  double element_size = 0;
  long n_nodes = 0;
  long n_elements = 0;
  long n_root = 0;
  long n_dofs() const { return 3 * (n_nodes - n_root); }
  double gmsh_seconds = 0;
  double ccx_seconds = 0;
  std::vector<double> hz;
};

ModelRun run_model(const GmshBladeSpec& spec, const std::string& dir) {
  ModelRun run;
  run.element_size = spec.element_size;
  const Clock::time_point start = Clock::now();
  const std::string deck_path = write_gmsh_blade_deck(spec, dir);
  run.gmsh_seconds = seconds_since(start);
  const Deck deck = read_deck(deck_path);
  run.n_nodes = static_cast<long>(deck.nodes.size());
  run.n_elements = static_cast<long>(deck.elements.size());
  run.n_root = static_cast<long>(deck.node_sets.at("ROOT").size());
  run.ccx_seconds = run_ccx(deck_path, dir, "modes", lanczos_step);
  run.hz = read_ccx_frequencies(dir + "/modes.dat");
  return run;
}

// ---------------------------------------------------------------------------
// 1. Spec validation
// ---------------------------------------------------------------------------

TEST(GmshBladeSpec, DefaultIsValid) {
  EXPECT_NO_THROW(check_gmsh_blade_spec(GmshBladeSpec{}));
}

TEST(GmshBladeSpec, RejectsEachFieldOutOfRangeNamingIt) {
  struct Case {
    const char* field;
    std::function<void(GmshBladeSpec&)> spoil;
  };
  const std::vector<Case> cases{
      {"span", [](GmshBladeSpec& s) { s.span = 0.0; }},
      {"span", [](GmshBladeSpec& s) { s.span = std::nan(""); }},
      {"chord", [](GmshBladeSpec& s) { s.chord = -40.0; }},
      {"thickness", [](GmshBladeSpec& s) { s.thickness = 0.0; }},
      {"thickness", [](GmshBladeSpec& s) { s.thickness = 25.0; }}, // > chord / 2
      {"camber", [](GmshBladeSpec& s) { s.camber = -0.01; }},
      {"camber", [](GmshBladeSpec& s) { s.camber = 0.3; }},
      {"twist", [](GmshBladeSpec& s) { s.twist = 91.0; }},
      {"twist", [](GmshBladeSpec& s) { s.twist = -90.5; }},
      {"stagger", [](GmshBladeSpec& s) { s.stagger = 100.0; }},
      {"root_length", [](GmshBladeSpec& s) { s.root_length = 42.0; }}, // < chord + thickness
      {"root_width", [](GmshBladeSpec& s) { s.root_width = 4.0; }},    // < camber chord + t
      {"root_height", [](GmshBladeSpec& s) { s.root_height = 0.0; }},
      {"element_size", [](GmshBladeSpec& s) { s.element_size = 0.0; }},
      {"element_size", [](GmshBladeSpec& s) { s.element_size = 0.3; }}, // < chord / 100
      {"element_size", [](GmshBladeSpec& s) { s.element_size = 101.0; }},
      {"young_modulus", [](GmshBladeSpec& s) { s.young_modulus = 0.0; }},
      {"poisson_ratio", [](GmshBladeSpec& s) { s.poisson_ratio = 0.5; }},
      {"poisson_ratio", [](GmshBladeSpec& s) { s.poisson_ratio = -1.0; }},
      {"density", [](GmshBladeSpec& s) { s.density = -7.85e-9; }},
      {"root_radius", [](GmshBladeSpec& s) { s.root_radius = -1.0; }},
  };
  for (const Case& c : cases) {
    GmshBladeSpec spec;
    c.spoil(spec);
    std::string message;
    try {
      check_gmsh_blade_spec(spec);
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    std::printf("%-14s -> %s\n", c.field, message.c_str());
    EXPECT_NE(message.find(std::string("GmshBladeSpec.") + c.field + ":"), std::string::npos)
        << "field " << c.field << ": message '" << message << "'";
    EXPECT_NE(message.find("allowed"), std::string::npos) << message;
    // The same check guards every entry point.
    EXPECT_THROW(gmsh_blade_geo(spec), std::invalid_argument) << c.field;
    EXPECT_THROW(write_gmsh_blade_deck(spec, "/nonexistent/never_written"), std::invalid_argument)
        << c.field;
  }
}

// ---------------------------------------------------------------------------
// 2. The tip stations and the coarse deck
// ---------------------------------------------------------------------------

TEST(GmshBladeGeometry, TipStationsAreEquallySpacedOnTheTipCamberLine) {
  const GmshBladeSpec spec;
  const std::vector<Eigen::Vector3d> q = gmsh_blade_tip_stations(spec);
  ASSERT_EQ(static_cast<int>(q.size()), n_tip_stations);
  const double x_tip = spec.root_radius + spec.root_height + spec.span;
  // Chords of equal arcs are equal; the stations lie on a circle of radius R
  // in the tip plane (turned by stagger + twist), the chord-line ends at
  // distance chord apart.
  const double f = spec.camber * spec.chord;
  const double radius = (spec.chord * spec.chord / 4 + f * f) / (2 * f);
  const double step0 = (q[1] - q[0]).norm();
  double worst = 0;
  for (int j = 0; j < n_tip_stations; ++j) {
    worst = std::max(worst, std::abs(q[j].x() - x_tip));
    if (j > 0) worst = std::max(worst, std::abs((q[j] - q[j - 1]).norm() - step0));
  }
  const double end_distance = (q.back() - q.front()).norm();
  std::printf("station spacing %.6f mm, worst deviation %.3e mm, ends %.12f mm apart\n", step0,
              worst, end_distance);
  EXPECT_LT(worst, 1e-12 * x_tip);
  EXPECT_NEAR(end_distance, spec.chord, 1e-12 * spec.chord);
  EXPECT_NEAR(step0, 2 * radius * std::sin(std::asin(spec.chord / (2 * radius)) / 15), 1e-12);
}

TEST(GmshBladeDeck, CoarseDeckMatchesAnIndependentReading) {
  SKIP_WITHOUT("gmsh");
  const WorkDir dir("coarse");
  const GmshBladeSpec spec;
  const Clock::time_point start = Clock::now();
  const std::string deck_path = write_gmsh_blade_deck(spec, dir.path());
  const double gmsh_seconds = seconds_since(start);
  EXPECT_EQ(deck_path, dir.path() + "/blade.inp");
  const Deck deck = read_deck(deck_path);

  // Model only: no step; the keywords a ccx step needs are there.
  for (const std::string& k : deck.keywords)
    EXPECT_EQ(k.find("*STEP"), std::string::npos) << k;
  const std::vector<std::string> needed{"*MATERIAL", "*ELASTIC", "*DENSITY", "*SOLID SECTION",
                                        "*BOUNDARY"};
  for (const std::string& k : needed)
    EXPECT_TRUE(std::any_of(deck.keywords.begin(), deck.keywords.end(), [&](const std::string& d) {
      return d.rfind(k, 0) == 0;
    })) << k;

  // C3D10: the midside nodes at the midpoints of edges 1-2, 2-3, 3-1, 1-4,
  // 2-4, 3-4 and positive corner volumes (ccx's order); the mesh volume
  // (straight-sided elements: the corner tetrahedra) against the geometry.
  const std::array<std::array<int, 2>, 6> edges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
  double volume = 0, worst_midside = 0, smallest = 1e300;
  std::set<long> used;
  for (const std::array<long, 11>& e : deck.elements) {
    std::array<Eigen::Vector3d, 10> p;
    for (int i = 0; i < 10; ++i) {
      p[i] = deck.nodes.at(e[i + 1]);
      used.insert(e[i + 1]);
    }
    const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
    const double v = a.cross(b).dot(c) / 6.0;
    volume += v;
    smallest = std::min(smallest, v);
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector3d mid = 0.5 * (p[edges[k][0]] + p[edges[k][1]]);
      worst_midside = std::max(worst_midside, (p[4 + k] - mid).norm());
    }
  }
  const double exact_volume = gmsh_blade_volume(spec);
  const double volume_error = std::abs(volume - exact_volume) / exact_volume;
  const long n_root = static_cast<long>(deck.node_sets.at("ROOT").size());
  std::printf("coarse deck: %zu nodes, %zu C3D10, %ld ROOT nodes, %ld dofs, gmsh %.2f s\n",
              deck.nodes.size(), deck.elements.size(), n_root,
              3 * (static_cast<long>(deck.nodes.size()) - n_root), gmsh_seconds);
  std::printf("volume %.3f mm^3 against %.3f (relative error %.2e), smallest element %.3e mm^3, "
              "worst midside offset %.2e mm\n",
              volume, exact_volume, volume_error, smallest, worst_midside);
  EXPECT_EQ(used.size(), deck.nodes.size()) << "nodes no element uses";
  EXPECT_GT(smallest, 0.0);
  EXPECT_LT(worst_midside, 1e-9);
  // Faceting of the arcs (radius ~101 mm, facets <= 10 mm: sagitta 0.12 mm)
  // takes area off the convex side and adds it on the concave side; the
  // B-spline surfaces of ThruSections follow the linear twist to far better
  // than that. 0.5 % bounds both.
  EXPECT_LT(volume_error, 5e-3);
  EXPECT_LE(3 * (static_cast<long>(deck.nodes.size()) - n_root), 5000) << "CI budget";

  // ROOT = exactly the nodes on the bottom face x = root_radius.
  std::vector<long> bottom;
  for (const auto& [id, x] : deck.nodes)
    if (std::abs(x.x() - spec.root_radius) < 1e-9) bottom.push_back(id);
  std::vector<long> root = deck.node_sets.at("ROOT");
  std::sort(root.begin(), root.end());
  EXPECT_EQ(root, bottom);

  // TIP = the 16 stations, in order.
  const std::vector<long>& tip = deck.node_sets.at("TIP");
  const std::vector<Eigen::Vector3d> stations = gmsh_blade_tip_stations(spec);
  ASSERT_EQ(tip.size(), stations.size());
  double worst_station = 0;
  for (size_t j = 0; j < tip.size(); ++j)
    worst_station = std::max(worst_station, (deck.nodes.at(tip[j]) - stations[j]).norm());
  std::printf("TIP: %zu nodes, worst distance to its station %.2e mm\n", tip.size(), worst_station);
  EXPECT_LT(worst_station, 1e-9);
}

// ---------------------------------------------------------------------------
// 3. The error channel
// ---------------------------------------------------------------------------

/// Puts a fake `gmsh` (a shell script) first on PATH for the scope.
class FakeGmsh {
public:
  FakeGmsh(const std::string& dir, const std::string& script)
      : m_old_path(std::getenv("PATH") ? std::getenv("PATH") : "") {
    fs::create_directories(dir + "/bin");
    const std::string exe = dir + "/bin/gmsh";
    std::ofstream(exe) << "#!/bin/sh\n" << script;
    fs::permissions(exe, fs::perms::owner_all);
    setenv("PATH", (dir + "/bin:" + m_old_path).c_str(), 1);
  }
  ~FakeGmsh() { setenv("PATH", m_old_path.c_str(), 1); }

private:
  std::string m_old_path;
};

std::string gmsh_error_of(const std::string& dir) {
  try {
    write_gmsh_blade_deck(GmshBladeSpec{}, dir);
  } catch (const GmshError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshBladeDeck, ReportsGmshFailures) {
  const WorkDir dir("errors");
  {
    const std::string old_path = std::getenv("PATH") ? std::getenv("PATH") : "";
    setenv("PATH", (dir.path() + "/empty").c_str(), 1);
    const std::string message = gmsh_error_of(dir.path() + "/missing");
    setenv("PATH", old_path.c_str(), 1);
    std::printf("gmsh missing -> %s\n", message.c_str());
    EXPECT_NE(message.find("cannot run 'gmsh blade.geo -3"), std::string::npos) << message;
  }
  {
    const FakeGmsh fake(dir.path(), "echo 'Info    : fake gmsh'\necho 'Error   : fake failure'\n"
                                    "exit 3\n");
    const std::string message = gmsh_error_of(dir.path() + "/failing");
    std::printf("gmsh failing -> %s\n", message.c_str());
    EXPECT_NE(message.find("'gmsh blade.geo -3 -format inp"), std::string::npos) << message;
    EXPECT_NE(message.find("exit status 3"), std::string::npos) << message;
    EXPECT_NE(message.find("Error   : fake failure"), std::string::npos) << message;
  }
  {
    // gmsh 4.8 exits with 0 after errors in a script: the Error lines count.
    const FakeGmsh fake(dir.path(), "echo 'Error   : Unknown model surface'\nexit 0\n");
    const std::string message = gmsh_error_of(dir.path() + "/script_error");
    std::printf("gmsh error, status 0 -> %s\n", message.c_str());
    EXPECT_NE(message.find("but reported errors"), std::string::npos) << message;
  }
  {
    const FakeGmsh fake(dir.path(), "echo 'Info    : done'\nexit 0\n");
    const std::string message = gmsh_error_of(dir.path() + "/no_mesh");
    std::printf("no mesh written -> %s\n", message.c_str());
    EXPECT_NE(message.find("no mesh file"), std::string::npos) << message;
  }
  {
    const FakeGmsh fake(dir.path(), "printf '*Heading\\n*NODE\\n1, 0, 0, 0\\n' > blade_gmsh.inp\n");
    const std::string message = gmsh_error_of(dir.path() + "/empty_mesh");
    std::printf("empty mesh -> %s\n", message.c_str());
    EXPECT_NE(message.find("has no C3D10 element"), std::string::npos) << message;
  }
}

// ---------------------------------------------------------------------------
// 4. Convergence of ccx's frequencies
// ---------------------------------------------------------------------------

TEST(GmshBladeCcx, FrequenciesConvergeUnderRefinement) {
  SKIP_WITHOUT("gmsh", "ccx");
  const int n_modes = 5;
  const GmshBladeSpec coarse;
  const std::vector<double> sizes{coarse.element_size, coarse.element_size / 2,
                                  coarse.element_size / 4};
  std::vector<ModelRun> runs;
  for (size_t i = 0; i < sizes.size(); ++i) {
    GmshBladeSpec spec = coarse;
    spec.element_size = sizes[i];
    const WorkDir dir("refine" + std::to_string(i));
    runs.push_back(run_model(spec, dir.path()));
    ASSERT_GE(static_cast<int>(runs.back().hz.size()), n_modes);
  }
  std::printf("  h [mm]  nodes   C3D10   dofs  gmsh [s]  ccx Lanczos [s]   f1..f5 [Hz]\n");
  for (const ModelRun& r : runs) {
    std::printf("%7.3f %6ld %7ld %6ld %9.2f %16.2f  ", r.element_size, r.n_nodes, r.n_elements,
                r.n_dofs(), r.gmsh_seconds, r.ccx_seconds);
    for (int k = 0; k < n_modes; ++k)
      std::printf(" %9.3f", r.hz[k]);
    std::printf("\n");
  }
  for (int k = 0; k < n_modes; ++k) {
    const double f1 = runs[0].hz[k], f2 = runs[1].hz[k], f3 = runs[2].hz[k];
    const double ratio = (f1 - f2) / (f2 - f3);
    const double order = std::log(ratio) / std::log(2.0);
    const double change = std::abs(f2 - f3) / f3;
    std::printf("mode %d: differences %.3f, %.3f Hz, ratio %.3f, observed order %.2f, "
                "last change %.2e\n",
                k + 1, f1 - f2, f2 - f3, ratio, order, change);
    EXPECT_GT(f1, f2) << "mode " << k + 1;
    EXPECT_GT(f2, f3) << "mode " << k + 1;
    EXPECT_GT(order, 0.5) << "mode " << k + 1;
    EXPECT_LT(change, 0.01) << "mode " << k + 1;
  }
}

// ---------------------------------------------------------------------------
// 5. The first frequency against Euler-Bernoulli
// ---------------------------------------------------------------------------

/// Second moment [mm^4] of the section about its chord-wise centroidal axis
/// (bending across the chord): the annular sector between radii R -+ t/2 of
/// half-angle phi0 (or the rectangle chord x t when straight).
double weak_second_moment(const GmshBladeSpec& s) {
  const double t = s.thickness;
  if (s.camber == 0.0) return s.chord * t * t * t / 12.0;
  const double f = s.camber * s.chord;
  const double radius = (s.chord * s.chord / 4 + f * f) / (2 * f);
  const double phi0 = std::asin(s.chord / (2 * radius));
  const double a = radius - t / 2, b = radius + t / 2;
  const double area = phi0 * (b * b - a * a);
  const double first = 2 * std::sin(phi0) * (b * b * b - a * a * a) / 3;
  const double second =
      (b * b * b * b - a * a * a * a) / 4 * (phi0 + std::sin(phi0) * std::cos(phi0));
  return second - first * first / area;
}

double euler_bernoulli_hz(const GmshBladeSpec& s, double second_moment, double area) {
  const double beta1 = 1.87510407;
  return beta1 * beta1 / (2 * M_PI) *
         std::sqrt(s.young_modulus * second_moment / (s.density * area * std::pow(s.span, 4)));
}

TEST(GmshBladeCcx, FirstFrequencyAgainstEulerBernoulli) {
  SKIP_WITHOUT("gmsh", "ccx");
  // The four combinations of camber (0 or the default) and twist (0 or the
  // default) on the same element size, so that the camber and the twist
  // effects are measured on comparable meshes.
  GmshBladeSpec cambered_twisted; // the default
  cambered_twisted.element_size = 5.0;
  GmshBladeSpec cambered = cambered_twisted;
  cambered.twist = 0.0;
  GmshBladeSpec flat_twisted = cambered_twisted;
  flat_twisted.camber = 0.0;
  GmshBladeSpec flat = flat_twisted;
  flat.twist = 0.0;

  const double area_flat = flat.chord * flat.thickness;
  const double eb_flat = euler_bernoulli_hz(flat, weak_second_moment(flat), area_flat);
  const double area_cambered = gmsh_blade_section_area(cambered);
  const double eb_cambered =
      euler_bernoulli_hz(cambered, weak_second_moment(cambered), area_cambered);

  std::vector<double> fe;
  int i = 0;
  for (const GmshBladeSpec& spec : {flat, flat_twisted, cambered, cambered_twisted}) {
    const WorkDir dir("eb" + std::to_string(i++));
    const ModelRun r = run_model(spec, dir.path());
    ASSERT_FALSE(r.hz.empty());
    fe.push_back(r.hz[0]);
  }
  std::printf("Euler-Bernoulli: flat plate %.2f Hz (I = %.1f mm^4, A = %.1f mm^2), cambered "
              "section %.2f Hz (I = %.1f mm^4, A = %.1f mm^2)\n",
              eb_flat, weak_second_moment(flat), area_flat, eb_cambered,
              weak_second_moment(cambered), area_cambered);
  std::printf("FE first frequency, h = %.1f mm:\n", flat.element_size);
  std::printf("  flat, untwisted      %8.2f Hz  %.3f x EB flat\n", fe[0], fe[0] / eb_flat);
  std::printf("  flat, twisted        %8.2f Hz  %.3f x EB flat, twist effect %+.1f %%\n", fe[1],
              fe[1] / eb_flat, 100 * (fe[1] / fe[0] - 1));
  std::printf("  cambered, untwisted  %8.2f Hz  %.3f x EB cambered, camber effect %+.1f %% "
              "(EB predicts %+.1f %%)\n",
              fe[2], fe[2] / eb_cambered, 100 * (fe[2] / fe[0] - 1),
              100 * (eb_cambered / eb_flat - 1));
  std::printf("  cambered, twisted    %8.2f Hz  %.3f x EB flat, twist effect %+.1f %%\n", fe[3],
              fe[3] / eb_flat, 100 * (fe[3] / fe[2] - 1));
  // Untwisted plates: a plate of aspect span / chord = 2.5 is stiffer than
  // the beam by at most 1 / sqrt(1 - nu^2) = 1.048 (plane strain across the
  // chord); the mesh at h = 5 lies about 1 % above its limit (test 4: f1
  // falls by 1.4 Hz from h = 5 to 2.5, and by about as much again below
  // at order ~1): upper bound 1.048 x 1.02. The elastic root block (clamped 20 mm below
  // the blade root) lowers the frequency by an amount the beam model does
  // not know: 10 % allowed.
  const double plate = 1.0 / std::sqrt(1.0 - flat.poisson_ratio * flat.poisson_ratio);
  EXPECT_LT(fe[0] / eb_flat, plate * 1.02);
  EXPECT_GT(fe[0] / eb_flat, 0.9);
  EXPECT_LT(fe[2] / eb_cambered, plate * 1.02);
  EXPECT_GT(fe[2] / eb_cambered, 0.9);
  // Twist couples flap and edge bending. No closed form here: the measured
  // effects (-0.2 % flat, -3.2 % cambered at 30 deg, gmsh 4.8.4) are
  // printed; 5 % bounds them. This catches a grossly wrong twist (sections
  // turned about the wrong axis), not a small one: the geometry itself is
  // checked through the tip stations and the volume (test 2).
  EXPECT_LT(std::abs(fe[1] / fe[0] - 1), 0.05);
  EXPECT_LT(std::abs(fe[3] / fe[2] - 1), 0.05);
}

// ---------------------------------------------------------------------------
// 6. The matrices
// ---------------------------------------------------------------------------

Eigen::SparseMatrix<double> read_ccx_matrix(const std::string& path, int n) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::vector<Eigen::Triplet<double>> entries;
  long row = 0, col = 0;
  double value = 0;
  long below_diagonal = 0;
  while (in >> row >> col >> value) {
    if (col < row) ++below_diagonal;
    entries.emplace_back(row - 1, col - 1, value);
    if (row != col) entries.emplace_back(col - 1, row - 1, value);
  }
  EXPECT_EQ(below_diagonal, 0) << path << ": expected the upper triangle only";
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

TEST(GmshBladeCcx, MatrixStorageRowsAndModes) {
  SKIP_WITHOUT("gmsh", "ccx");
  const WorkDir dir("matrices");
  const GmshBladeSpec spec;
  const std::string deck_path = write_gmsh_blade_deck(spec, dir.path());
  const Deck deck = read_deck(deck_path);
  const long n_root = static_cast<long>(deck.node_sets.at("ROOT").size());
  const double seconds = run_ccx(deck_path, dir.path(), "job", lanczos_step + matrix_step);
  const std::vector<double> hz = read_ccx_frequencies(dir.path() + "/job.dat");

  std::ifstream dof_file(dir.path() + "/job.dof");
  std::string line;
  std::set<long> dof_nodes;
  int rows = 0;
  while (std::getline(dof_file, line))
    if (!line.empty()) {
      ++rows;
      dof_nodes.insert(std::stol(line.substr(0, line.find('.'))));
    }
  for (const long id : deck.node_sets.at("ROOT"))
    EXPECT_EQ(dof_nodes.count(id), 0u) << "clamped node " << id << " has dofs";
  const int expected = static_cast<int>(3 * (static_cast<long>(deck.nodes.size()) - n_root));
  std::printf("ccx MATRIXSTORAGE (with the Lanczos step): %.2f s, .dof rows %d (3 x (%zu nodes "
              "- %ld ROOT nodes) = %d)\n",
              seconds, rows, deck.nodes.size(), n_root, expected);
  ASSERT_EQ(rows, expected);

  const Eigen::SparseMatrix<double> k = read_ccx_matrix(dir.path() + "/job.sti", rows);
  const Eigen::SparseMatrix<double> m = read_ccx_matrix(dir.path() + "/job.mas", rows);
  // Total mass: a rigid translation u = e_x of all free dofs gives e^T M e =
  // the mass of the free nodes' share, at most rho V.
  Eigen::VectorXd ex = Eigen::VectorXd::Zero(rows);
  for (int i = 0; i < rows; i += 3)
    ex[i] = 1.0;
  const double free_mass = ex.dot(m * ex);
  const double total_mass = spec.density * gmsh_blade_volume(spec);
  std::printf("e_x^T M e_x = %.4e t against rho V = %.4e t (clamped nodes excluded)\n", free_mass,
              total_mass);
  EXPECT_LT(free_mass, total_mass);
  EXPECT_GT(free_mass, 0.9 * total_mass);

  // rsi's Lanczos (Spectra, shift-invert) on ccx's matrices against ccx's
  // own Lanczos: ccx prints 7 significant digits (5e-7 relative).
  const Modes modes = lowest_modes(k, m, 5, ModalSolver::sparse);
  ASSERT_GE(hz.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const double rel = std::abs(modes.frequency_hz(i) - hz[i]) / hz[i];
    std::printf("mode %d: ccx %.4f Hz, rsi on .sti/.mas %.4f Hz, relative difference %.2e\n", i + 1,
                hz[i], modes.frequency_hz(i), rel);
    EXPECT_LT(rel, 1e-5);
  }
}

// ---------------------------------------------------------------------------
// Scaling study (not part of the suite: run with
//   test_gmsh_blade --gtest_also_run_disabled_tests --gtest_filter='*Scaling*')
// The element sizes, nodes, dofs and times documented in gmsh_blade.hpp.
// ---------------------------------------------------------------------------

TEST(GmshBladeCcx, DISABLED_ScalingStudy) {
  SKIP_WITHOUT("gmsh", "ccx");
  std::printf("  h [mm]  nodes   C3D10  ROOT    dofs  gmsh [s]  ccx matrices [s]  .sti [MB]\n");
  for (const double h : {10.0, 20.0 / 3.0, 5.0, 10.0 / 3.0, 2.5, 2.0, 1.8, 5.0 / 3.0}) {
    GmshBladeSpec spec;
    spec.element_size = h;
    const WorkDir dir("scaling");
    const Clock::time_point start = Clock::now();
    const std::string deck_path = write_gmsh_blade_deck(spec, dir.path());
    const double gmsh_seconds = seconds_since(start);
    const Deck deck = read_deck(deck_path);
    const long n_root = static_cast<long>(deck.node_sets.at("ROOT").size());
    const double ccx_seconds = run_ccx(deck_path, dir.path(), "job", matrix_step);
    long rows = 0;
    std::ifstream dof_file(dir.path() + "/job.dof");
    std::string line;
    while (std::getline(dof_file, line))
      rows += line.empty() ? 0 : 1;
    EXPECT_EQ(rows, 3 * (static_cast<long>(deck.nodes.size()) - n_root));
    std::printf("%7.3f %6zu %7zu %5ld %7ld %9.2f %17.2f %10.1f\n", h, deck.nodes.size(),
                deck.elements.size(), n_root, rows, gmsh_seconds, ccx_seconds,
                static_cast<double>(fs::file_size(dir.path() + "/job.sti")) / 1e6);
    std::fflush(stdout);
  }
}

} // namespace
} // namespace rsi
