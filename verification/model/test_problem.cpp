// The one loader (reference/model/problem.hpp): every case file in
// data/cases gives a Problem of the expected kind and sizes, and the
// contact handle (reference/contact/structure_contact.hpp) holds the law the
// problem names. Each expected number says where it comes from: the paper's
// sizes from the case's own parameters (formula below), the components'
// from the model's documentation (docs/case-files.md, the external model's
// README) and the case file's keys.
//
// Paper's bladed disk, SPEC §2 and bladed_disk.hpp's block layout: a sector
// is the rim node (u, u_s, v, v_s: 4 dofs), n - 1 blade nodes (ux, uy,
// theta: 3 each) and the tip node (u, v, theta: 3), so 4 + 3 n dofs a
// sector, N sectors; the casing ring: 4 dofs a node (casing.hpp), n_c
// nodes, one clamped:
//   n_dofs = N (4 + 3 n) + 4 (n_c - 1).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "calculix_run.hpp"
#include "case_file.hpp"
#include "child_process.hpp"
#include "problem.hpp"
#include "structure_contact.hpp"

namespace rsi {
namespace {

namespace fs = std::filesystem;

std::string case_path(const std::string& name) {
  return std::string(RSI_SOURCE_DIR) + "/data/cases/" + name;
}

std::string cache_dir() {
  const char* env = std::getenv("RSI_CCX_CACHE");
  return env && *env ? env : RSI_BINARY_DIR "/ccx-cache";
}

/// N (4 + 3 n) + 4 (n_c - 1), the header's formula.
int paper_dofs(int n_blades, int n_blade_elements, int n_casing_elements) {
  return n_blades * (4 + 3 * n_blade_elements) + 4 * (n_casing_elements - 1);
}

/// Why a component case cannot load here (a tool or the external model
/// absent), or empty.
std::string component_missing(const std::string& name) {
  const bool gmsh_blade = name.rfind("blade3d", 0) == 0 || name.rfind("bladed-disk3d", 0) == 0 ||
                          name.rfind("casing3d", 0) == 0;
  if (gmsh_blade && !executable_on_path("gmsh")) return "gmsh is not on PATH (Debian package gmsh)";
  if (!gmsh_blade && !fs::exists(RSI_SOURCE_DIR "/../shared/external/rotor37/blade.inp"))
    return "the external Rotor 37 model (shared/external/rotor37/blade.inp) is absent";
  try {
    find_ccx();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

void expect_paper(const std::string& name, int n_blade_elements, double step, double duration,
                  int output_every) {
  const Problem p = load_problem(case_path(name));
  // data/cases/NAME: 22 blades, casing of 40 elements.
  const int expected = paper_dofs(22, n_blade_elements, 40);
  std::printf("%s: %d dofs (expected %d), %d contacts, %ld steps\n", name.c_str(), p.n_dofs(),
              expected, p.contact.n_contacts(), p.steps.fixed_steps());
  EXPECT_EQ(p.kind, ProblemKind::paper);
  ASSERT_EQ(p.structures.size(), 2u);
  EXPECT_EQ(p.structures[0].n_dofs(), 22 * (4 + 3 * n_blade_elements));
  EXPECT_EQ(p.structures[1].n_dofs(), 4 * 39);
  EXPECT_EQ(p.n_dofs(), expected);
  EXPECT_EQ(p.offset(1), p.structures[0].n_dofs());
  EXPECT_EQ(p.stiffness().rows(), expected);
  EXPECT_EQ(p.mass().cols(), expected);
  // The tips' u, v are the bladed disk's boundary: one contact a blade.
  EXPECT_EQ(p.contact.kind, ContactKind::tip_ring);
  EXPECT_EQ(p.contact.rotor_dofs, p.structures[0].boundary);
  EXPECT_EQ(p.contact.n_contacts(), 22);
  // operating_point: 310 rad/s, mu 0.15, friction_law absent = coulomb (data/README.md).
  EXPECT_EQ(p.contact.friction_law, FrictionLaw::coulomb);
  EXPECT_EQ(p.contact.friction_coefficient, 0.15);
  EXPECT_EQ(p.contact.rotation_speed, 310.0);
  // The flexible casing is structure 1; R_c - R_t = 0.501 - 0.5 m.
  EXPECT_FALSE(p.casing.rigid);
  EXPECT_EQ(p.casing.structure, 1);
  EXPECT_NEAR(p.casing.clearance, 1e-3, 1e-15); // two decimal inputs: a few ulps of 0.5
  // forcing: F0 = 1000 N cos(2 theta_j) on the casing only, node 0 at
  // theta = 0 (the clamp is at 180 degrees), until 0.2 ms.
  ASSERT_EQ(p.forcing.force.size(), expected);
  EXPECT_EQ(p.forcing.force.head(p.structures[0].n_dofs()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NEAR(p.forcing.force.cwiseAbs().maxCoeff(), 1000.0, 1e-9); // cos(0) = 1, exact
  EXPECT_EQ(p.forcing.until, 2e-4);
  // time: the fixed rule, duration / step steps, output_every of the file.
  EXPECT_EQ(p.steps.rule, ProblemSteps::Rule::fixed);
  EXPECT_EQ(p.steps.step, step);
  EXPECT_EQ(p.steps.fixed_steps(), std::lround(duration / step));
  EXPECT_EQ(p.outputs.output_every, output_every);
  EXPECT_EQ(p.outputs.response_dof, -1);
  ASSERT_TRUE(p.paper.has_value());
  EXPECT_EQ(p.paper->bladed_disk.n_dofs(), p.structures[0].n_dofs());

  // The contact handle holds the Coulomb law over the 22 tips.
  const StructureContact contact(p);
  EXPECT_TRUE(contact.coulomb());
  EXPECT_EQ(contact.law(), nullptr);
  EXPECT_EQ(contact.n_contacts(), 22);
}

TEST(Problem, PaperCasesHaveTheirModelsSizes) {
  // 838 = 22 x 31 + 156: the default case's count (SPEC §2).
  EXPECT_EQ(paper_dofs(22, 9, 40), 838);
  expect_paper("batailly2007.json", 9, 5e-7, 0.02, 50);
  expect_paper("batailly2007-36el.json", 36, 3.125e-7, 0.02, 80);
  expect_paper("batailly2007-72el.json", 72, 1e-7, 0.02, 250);
}

TEST(Problem, SlidingSignCaseGetsTheSlidingSignLaw) {
  Case c = load_case(case_path("batailly2007.json"));
  c.operating_point.friction_law = FrictionLaw::sliding_sign;
  const Problem p = paper_problem(c);
  EXPECT_EQ(p.contact.friction_law, FrictionLaw::sliding_sign);
  const StructureContact contact(p);
  EXPECT_FALSE(contact.coulomb());
  ASSERT_NE(contact.law(), nullptr);
  EXPECT_EQ(contact.n_contacts(), 22);
}

/// What a component case must give: dofs and the rubbing set-up's numbers.
struct ComponentExpectation {
  int n_dofs = 0;
  int contacts = 0;            ///< 0: no "rubbing"
  int response_node = 0;
  double mu = 0.0;
  double revolutions = 0.0;
  double sliding_sign = 1.0;   ///< Omega_s / Omega
  bool lumped = false;         ///< component.mass "lumped": M diagonal (HRZ)
  int steps_per_revolution = 1000;
};

void expect_component(const std::string& name, const ComponentExpectation& e) {
  const Problem p = load_problem(case_path(name), {"", cache_dir()});
  std::printf("%s: %d dofs (expected %d), %d contacts\n", name.c_str(), p.n_dofs(), e.n_dofs,
              p.contact.n_contacts());
  EXPECT_EQ(p.kind, ProblemKind::component);
  ASSERT_EQ(p.structures.size(), 1u);
  EXPECT_EQ(p.n_dofs(), e.n_dofs);
  EXPECT_EQ(p.stiffness().rows(), e.n_dofs);
  EXPECT_TRUE(p.casing.rigid);
  EXPECT_FALSE(p.forcing.any());
  ASSERT_TRUE(p.component_case.has_value());
  // HRZ lumping leaves one entry a row; a consistent mass couples the nodes.
  if (e.lumped)
    EXPECT_EQ(p.structures[0].mass.nonZeros(), e.n_dofs);
  else
    EXPECT_GT(p.structures[0].mass.nonZeros(), e.n_dofs);
  if (e.contacts == 0) {
    EXPECT_EQ(p.contact.kind, ContactKind::none);
    EXPECT_THROW(StructureContact{p}, std::invalid_argument);
    return;
  }
  EXPECT_EQ(p.contact.kind, ContactKind::rigid_surface);
  EXPECT_EQ(p.contact.n_contacts(), e.contacts);
  // ux, uy, uz of each contact node, and the boundary is exactly those
  // (the cases' boundary is the tip node set).
  EXPECT_EQ(static_cast<int>(p.contact.rotor_dofs.size()), 3 * e.contacts);
  EXPECT_EQ(p.contact.rotor_dofs, p.structures[0].boundary);
  EXPECT_EQ(p.contact.friction_law, FrictionLaw::coulomb);
  EXPECT_EQ(p.contact.friction_coefficient, e.mu);
  // rubbing: Omega = 1344 rad/s, oval gap g_m = 0.356 mm, w = 0.15,
  // N samples a revolution (1000 unless the case says), step_safety 0.9.
  EXPECT_EQ(p.contact.rotation_speed, 1344.0);
  EXPECT_EQ(p.contact.sliding_speed, e.sliding_sign * 1344.0);
  EXPECT_TRUE(p.casing.oval_gap);
  EXPECT_EQ(p.casing.gap, 0.356);
  EXPECT_EQ(p.casing.gap_width, 0.15);
  EXPECT_EQ(p.steps.rule, ProblemSteps::Rule::per_revolution);
  EXPECT_EQ(p.steps.steps_per_revolution, e.steps_per_revolution);
  EXPECT_EQ(p.steps.revolutions, e.revolutions);
  EXPECT_EQ(p.steps.step_safety, 0.9);
  EXPECT_EQ(p.outputs.output_every, 1);
  // rubbing.response: direction 2 of its node.
  ASSERT_GE(p.outputs.response_dof, 0);
  EXPECT_EQ(p.structures[0].dofs[p.outputs.response_dof].node, e.response_node);
  EXPECT_EQ(p.structures[0].dofs[p.outputs.response_dof].kind, "uy");
  EXPECT_EQ(p.outputs.response_name, "u_" + std::to_string(e.response_node) + "_2");

  const StructureContact contact(p);
  EXPECT_TRUE(contact.coulomb());
  ASSERT_NE(contact.rigid_surface(), nullptr);
  EXPECT_EQ(contact.n_contacts(), e.contacts);
  EXPECT_EQ(contact.rigid_surface()->sliding_speed(), e.sliding_sign * 1344.0);
}

/// The soft liner both liner cases carry (h 2 mm, E 1e4, sigma_y 10,
/// H 1e3 MPa, 200 cells around, one row), its surface at the contact nodes'
/// largest radius about z and its axial extent their span widened by 5 %
/// a side (problem.cpp).
/// The cells and tip patch a liner case gives (the case file's values).
struct LinerExpectation {
  int n_theta = 0;
  int n_axial = 0;
  double patch_circumferential = 0.0; ///< 0: no tip patch
  double patch_axial = 0.0;
};

void expect_liner(const Problem& p, const LinerExpectation& e) {
  ASSERT_TRUE(p.casing.liner.has_value());
  const ProblemLiner& l = *p.casing.liner;
  EXPECT_EQ(l.thickness, 2.0);
  EXPECT_EQ(l.young, 1e4);
  EXPECT_EQ(l.yield, 10.0);
  EXPECT_EQ(l.hardening, 1e3);
  EXPECT_EQ(l.n_theta, e.n_theta);
  EXPECT_EQ(l.n_axial, e.n_axial);
  EXPECT_EQ(l.patch_circumferential, e.patch_circumferential);
  EXPECT_EQ(l.patch_axial, e.patch_axial);
  const Component& c = p.structures[0];
  double radius = 0.0, z_low = 1e300, z_high = -1e300;
  for (int id : p.contact.contact_nodes)
    for (const ComponentNode& node : c.nodes)
      if (node.id == id) {
        radius = std::max(radius, std::hypot(node.x(0), node.x(1)));
        z_low = std::min(z_low, node.x(2));
        z_high = std::max(z_high, node.x(2));
      }
  EXPECT_NEAR(l.radius, radius, 1e-12 * radius);
  EXPECT_NEAR(l.z_min, z_low - 0.05 * (z_high - z_low), 1e-12 * radius);
  EXPECT_NEAR(l.z_max, z_high + 0.05 * (z_high - z_low), 1e-12 * radius);
}

// The gmsh blade at element_size 10: 4,101 dofs (docs/case-files.md; the
// element-size table of test_gmsh_blade_cache), its TIP node set 16 nodes
// (test_component_rubbing). blade3d-rubbing.json: mu 0.05, 1 revolution,
// response node 11, the tip sliding with the rotation (no tip_sliding key).
TEST(Problem, GmshBladeCases) {
  if (const std::string why = component_missing("blade3d"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  expect_component("blade3d.json", {4101, 0, 0, 0.0, 0.0, 1.0, false});
  // component.mass: lumped in the rubbing case.
  expect_component("blade3d-rubbing.json", {4101, 16, 11, 0.05, 1.0, 1.0, true});
  EXPECT_TRUE(load_problem(case_path("blade3d-rubbing.json"), {"", cache_dir()}).casing.tip_growth.empty());
  // The same with rotation effects: K(Omega) at 1344 rad/s and each contact
  // node's static growth, outward (the centrifugal load pulls the tip out).
  expect_component("blade3d-rubbing-rotating.json", {4101, 16, 11, 0.05, 1.0, 1.0, true});
  const Problem rotating = load_problem(case_path("blade3d-rubbing-rotating.json"), {"", cache_dir()});
  ASSERT_EQ(rotating.casing.tip_growth.size(), 16u);
  for (double g : rotating.casing.tip_growth) EXPECT_GT(g, 0.0);
  // The same cutting the soft abradable liner over half a revolution at
  // 2000 samples: the case's liner keys (h 2 mm, E 1e4, sigma_y 10, H 1e3
  // MPa, 1600 cells, 8 rows, 2.5 x 3.0 mm tip patches) and the unworn
  // surface at the contact nodes' largest radius.
  expect_component("blade3d-rubbing-liner.json", {4101, 16, 11, 0.05, 0.5, 1.0, true, 2000});
  expect_liner(load_problem(case_path("blade3d-rubbing-liner.json"), {"", cache_dir()}),
               {1600, 8, 2.5, 3.0});
}

// The 3D bladed disk's CI model: 6 gmsh-blade sectors at element size 20,
// 29,484 dofs (test_gmsh_bladed_disk checks its modes against ccx's cyclic
// symmetry), no rubbing yet.
TEST(Problem, GmshBladedDiskCase) {
  if (const std::string why = component_missing("bladed-disk3d"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  expect_component("bladed-disk3d-ci.json", {29484, 0, 0, 0.0, 0.0, 1.0, false});
}

// The 3D bladed disk's default model: read, not loaded here (gmsh and ccx
// on 107,976 dofs take about 20 s; `rsi modes data/cases/bladed-disk3d.json`
// lists its families, docs/bladed-disk-sector.md): its spec is the paper's
// 22 sectors on the thin disk.
TEST(Problem, GmshBladedDiskDefaultCaseReads) {
  const std::string path = case_path("bladed-disk3d.json");
  const ComponentCase c = parse_component_case(read_case_document(path), path);
  ASSERT_EQ(c.source, ComponentSource::gmsh_bladed_disk);
  EXPECT_EQ(c.gmsh_bladed_disk.sectors, 22);
  EXPECT_EQ(c.gmsh_bladed_disk.disk_width, 10.0);
  EXPECT_EQ(c.gmsh_bladed_disk.blade.element_size, 12.0);
  EXPECT_EQ(c.boundary_node_set, "TIP");
}

// The paper's system in 3D at the default size: the 22-sector disk beside
// the ring at element size 10 mm (loading both takes about 25 s of gmsh and
// ccx: read here, run outside ctest; docs/bladed-disk-sector.md).
TEST(Problem, SystemDefaultCaseReads) {
  const std::string path = case_path("bladed-disk3d-casing.json");
  const ComponentCase c = parse_component_case(read_case_document(path), path);
  ASSERT_EQ(c.source, ComponentSource::gmsh_bladed_disk);
  EXPECT_EQ(c.gmsh_bladed_disk.sectors, 22);
  EXPECT_EQ(c.gmsh_bladed_disk.blade.element_size, 12.0);
  ASSERT_TRUE(c.rubbing && c.rubbing->casing);
  EXPECT_EQ(c.rubbing->casing->element_size, 10.0);
  EXPECT_EQ(c.rubbing->casing_modes, 30);
  ASSERT_TRUE(c.rubbing->casing_forcing);
  EXPECT_EQ(c.rubbing->casing_forcing->nodal_diameters, 2);
}

// The paper's system in 3D, CI size: the 6-sector disk (29,484 dofs) and the
// flexible casing beside it (structure 1; 21,777 dofs, casing3d-ci.json's
// ring), meeting through the solid-casing law at the 96 tip nodes, the
// casing loaded by p0 cos(2 theta) on its inner face until 2e-4 s.
TEST(Problem, SystemCase) {
  if (const std::string why = component_missing("bladed-disk3d"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  const Problem p = load_problem(case_path("bladed-disk3d-casing-ci.json"), {"", cache_dir()});
  ASSERT_EQ(p.structures.size(), 2u);
  EXPECT_EQ(p.structures[0].n_dofs(), 29484);
  EXPECT_EQ(p.structures[1].n_dofs(), 21777);
  EXPECT_EQ(p.n_dofs(), 29484 + 21777);
  ASSERT_TRUE(p.forcing.any());
  EXPECT_EQ(p.forcing.until, 2e-4);
  EXPECT_EQ(p.forcing.force.head(29484).norm(), 0.0) << "the load is on the casing only";
  EXPECT_GT(p.forcing.force.norm(), 0.0);
  EXPECT_EQ(p.contact.kind, ContactKind::solid_casing);
  EXPECT_EQ(p.contact.n_contacts(), 96);
  EXPECT_FALSE(p.casing.rigid);
  EXPECT_EQ(p.casing.structure, 1);
  ASSERT_TRUE(p.casing.surface.has_value());
  EXPECT_GT(p.casing.surface->n_faces(), 0);
  const StructureContact contact(p);
  ASSERT_NE(contact.solid_casing(), nullptr);
  EXPECT_EQ(contact.n_contacts(), 96);
}

// The flexible 3D casing's CI model: a ring at element size 15 clamped at its
// front flange, 21,777 dofs (test_gmsh_casing checks its modes against ccx's
// Lanczos), no rubbing yet.
TEST(Problem, GmshCasingCase) {
  if (const std::string why = component_missing("casing3d"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  expect_component("casing3d-ci.json", {21777, 0, 0, 0.0, 0.0, 1.0, false});
}

// Rotor 37 (shared/external/rotor37/README.md): 61,098 dofs, 16 contact
// nodes, response node 1353 direction 2, mu 0.15, NLstep's set-up with the
// tip sliding against the rotation (tip_sliding: against_rotation).
// rotor37-rubbing.json runs 50 revolutions, the lumped variant 1. One test
// a case: each loads the 61,098-dof model (a few seconds).
TEST(Problem, Rotor37Case) {
  if (const std::string why = component_missing("rotor37"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  expect_component("rotor37.json", {61098, 0, 0, 0.0, 0.0, 1.0, false});
}

TEST(Problem, Rotor37RubbingCase) {
  if (const std::string why = component_missing("rotor37"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  expect_component("rotor37-rubbing.json", {61098, 16, 1353, 0.15, 50.0, -1.0, false});
}

TEST(Problem, Rotor37RubbingLinerCase) {
  if (const std::string why = component_missing("rotor37"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  expect_component("rotor37-rubbing-liner.json", {61098, 16, 1353, 0.15, 50.0, -1.0, false});
  expect_liner(load_problem(case_path("rotor37-rubbing-liner.json"), {"", cache_dir()}),
               {4096, 80, 4.4, 5.7});
}

TEST(Problem, Rotor37RubbingLumpedCase) {
  if (const std::string why = component_missing("rotor37"); !why.empty())
    GTEST_SKIP() << "not run: " << why;
  expect_component("rotor37-rubbing-lumped.json", {61098, 16, 1353, 0.15, 1.0, -1.0, true});
}

// Every case file in data/cases is one of the above: a new case needs its
// expectations here.
TEST(Problem, EveryCaseFileIsCovered) {
  const std::map<std::string, std::string> covered = {
      {"batailly2007.json", "paper"},        {"batailly2007-36el.json", "paper"},
      {"batailly2007-72el.json", "paper"},   {"blade3d.json", "component"},
      {"blade3d-rubbing.json", "component"}, {"blade3d-rubbing-rotating.json", "component"},
      {"blade3d-rubbing-liner.json", "component"},
      {"bladed-disk3d-ci.json", "component"}, {"bladed-disk3d.json", "component"},
      {"bladed-disk3d-casing-ci.json", "component"}, {"bladed-disk3d-casing.json", "component"},
      {"casing3d-ci.json", "component"},
      {"rotor37.json", "component"},
      {"rotor37-rubbing.json", "component"}, {"rotor37-rubbing-lumped.json", "component"},
      {"rotor37-rubbing-liner.json", "component"}};
  int files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(RSI_SOURCE_DIR "/data/cases")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    EXPECT_EQ(covered.count(entry.path().filename().string()), 1u)
        << entry.path() << " has no expectations in test_problem.cpp";
  }
  std::printf("%d case files, %zu covered\n", files, covered.size());
  EXPECT_EQ(files, static_cast<int>(covered.size()));
}

TEST(Problem, MissingFileIsACaseError) {
  EXPECT_THROW(load_problem(case_path("no-such-case.json")), CaseError);
}

} // namespace
} // namespace rsi
