#include "gmsh_casing.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <locale>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "casing_surface.hpp"

namespace rsi {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// Throws unless lo < value < hi (or <= hi when hi_closed), naming the field.
void require(const std::string& field, double value, double lo, double hi, bool hi_closed,
             const std::string& unit) {
  const bool ok = std::isfinite(value) && value > lo && (hi_closed ? value <= hi : value < hi);
  if (ok) return;
  std::ostringstream m;
  m.imbue(std::locale::classic());
  m << "GmshCasingSpec." << field << ": " << deck_number(value) << (unit.empty() ? "" : " ") << unit
    << " is out of range, allowed (" << deck_number(lo) << ", "
    << (hi == inf ? std::string("inf") : deck_number(hi)) << (hi_closed ? "]" : ")")
    << (unit.empty() ? "" : " ") << unit;
  throw std::invalid_argument(m.str());
}

std::string material_lines(const GmshCasingSpec& s) {
  return deck_material_lines("CASING_MATERIAL", s.young_modulus, s.poisson_ratio, s.density,
                             "FLANGE");
}

} // namespace

double gmsh_casing_estimated_dofs(const GmshCasingSpec& s) {
  const double tet = 1.0 / (6.0 * std::sqrt(2.0)); // a regular tetrahedron of edge 1
  const double h = s.element_size;
  const double volume =
      M_PI * (std::pow(s.inner_radius + s.thickness, 2) - std::pow(s.inner_radius, 2)) * s.width;
  return 3.0 * 2.0 * volume / (tet * h * h * std::min(h, s.thickness));
}

void check_gmsh_casing_spec(const GmshCasingSpec& s) {
  require("inner_radius", s.inner_radius, 0.0, inf, false, "mm");
  require("thickness", s.thickness, 0.0, inf, false, "mm");
  require("width", s.width, 0.0, inf, false, "mm");
  require("element_size", s.element_size, 0.0, M_PI * s.inner_radius / 6.0, true,
          "mm (pi inner_radius / 6: at least 12 elements around)");
  if (s.clamped_flanges != 1 && s.clamped_flanges != 2)
    throw std::invalid_argument(
        "GmshCasingSpec.clamped_flanges: " + std::to_string(s.clamped_flanges) +
        " is out of range, allowed 1 (front) or 2 (both)");
  require("young_modulus", s.young_modulus, 0.0, inf, false, "N/mm^2");
  require("poisson_ratio", s.poisson_ratio, -1.0, 0.5, false, "");
  require("density", s.density, 0.0, inf, false, "t/mm^3");
  const double dofs = gmsh_casing_estimated_dofs(s);
  if (!(dofs <= gmsh_casing_max_estimated_dofs)) {
    std::ostringstream m;
    m.imbue(std::locale::classic());
    m << "GmshCasingSpec.element_size: " << deck_number(s.element_size) << " mm gives about "
      << std::fixed << std::setprecision(0) << dofs
      << " dofs (estimated before gmsh from the volume), more than the "
      << gmsh_casing_max_estimated_dofs
      << " allowed; use a larger element_size, or mesh the casing yourself and give its deck "
         "as component.source.calculix_deck";
    throw std::invalid_argument(m.str());
  }
}

std::string gmsh_casing_geo(const GmshCasingSpec& s) {
  check_gmsh_casing_spec(s);
  const double z0 = -s.width / 2.0;
  std::ostringstream g;
  g.imbue(std::locale::classic());
  g << "// rsi gmsh_casing: a ring clamped at "
    << (s.clamped_flanges == 2 ? "both flanges" : "its front flange")
    << " (reference/model/gmsh_casing.hpp)\n"
    << "// inner radius " << deck_number(s.inner_radius) << ", thickness "
    << deck_number(s.thickness) << ", width " << deck_number(s.width) << ", element size "
    << deck_number(s.element_size) << " [mm]\n"
    << "SetFactory(\"OpenCASCADE\");\n"
    << "Cylinder(1) = {0, 0, " << deck_number(z0) << ", 0, 0, " << deck_number(s.width) << ", "
    << deck_number(s.inner_radius + s.thickness) << "};\n"
    << "Cylinder(2) = {0, 0, " << deck_number(z0) << ", 0, 0, " << deck_number(s.width) << ", "
    << deck_number(s.inner_radius) << "};\n"
    << "ring() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };\n"
    << "If (#ring() != 1)\n  Error(\"rsi: expected one ring volume, found %g\", #ring());\n"
    << "  Abort;\nEndIf\n"
    << "Physical Volume(\"CASING\") = {ring()};\n"
    << gmsh_mesh_options(s.element_size);
  return g.str();
}

std::string gmsh_casing_cache_key(const GmshCasingSpec& spec) {
  // The version names the deck writer: a change to what it writes from the
  // same mesh must change it.
  return gmsh_casing_geo(spec) + "// casing deck writer 2\n" + material_lines(spec);
}

std::string write_gmsh_casing_deck(const GmshCasingSpec& spec, const std::string& dir) {
  const std::string geo = gmsh_casing_geo(spec); // checks the spec
  const std::string deck = dir + "/casing.inp";
  std::error_code ec;
  std::filesystem::remove(deck, ec);
  const double tol = 1e-9 * (spec.inner_radius + spec.thickness + spec.width);
  const GmshMeshOutcome meshed = mesh_gmsh_script(geo, dir, tol, "casing");
  std::vector<long> flange;
  std::set<long> clamped;
  int front = 0, back = 0;
  for (const long id : meshed.used) {
    const Eigen::Vector3d& x = meshed.mesh.nodes.at(id);
    const bool at_front = std::abs(x.z() + spec.width / 2.0) <= tol;
    const bool at_back = std::abs(x.z() - spec.width / 2.0) <= tol;
    front += at_front;
    back += at_back;
    if (at_front || (at_back && spec.clamped_flanges == 2)) {
      flange.push_back(id);
      clamped.insert(id);
    }
  }
  if (front < 3 || back < 3)
    throw meshed.failure("has " + std::to_string(front) + " nodes on the flange z = -width/2 and " +
                         std::to_string(back) + " on z = +width/2 (3 at least each)");
  // The inner surface: the faces whose three corners lie on r = inner_radius
  // (their midside nodes lie on the chords, inside it), as an element surface.
  const auto on_inner = [&](long id) {
    const Eigen::Vector3d& x = meshed.mesh.nodes.at(id);
    return std::abs(std::hypot(x.x(), x.y()) - spec.inner_radius) <= tol;
  };
  std::ostringstream faces;
  std::set<long> inner_set;
  int n_faces = 0;
  for (const std::array<long, 11>& e : meshed.mesh.elements)
    for (int face = 1; face <= 4; ++face) {
      const std::array<int, 6> local = c3d10_face_nodes(face);
      if (!(on_inner(e[1 + local[0]]) && on_inner(e[1 + local[1]]) && on_inner(e[1 + local[2]])))
        continue;
      faces << e[0] << ", S" << face << "\n";
      ++n_faces;
      for (const int i : local)
        if (!clamped.count(e[1 + i])) inner_set.insert(e[1 + i]); // clamped: no dof
    }
  const std::vector<long> inner(inner_set.begin(), inner_set.end());
  if (inner.empty())
    throw meshed.failure("has no element face on the inner face r = inner_radius off the flanges");

  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << "** rsi gmsh_casing (reference/model/gmsh_casing.hpp): the ring of casing.geo beside "
         "this deck.\n"
      << "** " << meshed.used.size() << " nodes, " << meshed.mesh.elements.size() << " C3D10, "
      << flange.size() << " clamped (NSET FLANGE), " << n_faces
      << " faces on the inner face (SURFACE SINNER), their " << inner.size()
      << " nodes off the flanges (NSET INNER). Model only.\n";
  std::map<long, Eigen::Vector3d> nodes;
  for (const long id : meshed.used)
    nodes[id] = meshed.mesh.nodes.at(id);
  write_deck_nodes(out, nodes);
  write_deck_c3d10(out, meshed.mesh.elements);
  write_deck_node_set(out, "FLANGE", flange);
  write_deck_node_set(out, "INNER", inner);
  out << "*SURFACE, NAME=SINNER, TYPE=ELEMENT\n" << faces.str() << material_lines(spec);
  write_deck_file(deck, out.str(), "write_gmsh_casing_deck");
  return deck;
}

} // namespace rsi
