#include "gmsh_bladed_disk.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <locale>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <Eigen/Core>

namespace rsi {
namespace {

constexpr double deg = M_PI / 180.0;

std::string field_error(const std::string& field, const std::string& what) {
  return "GmshBladedDiskSpec." + field + ": " + what;
}

double sector_angle(const GmshBladedDiskSpec& spec) {
  return 2.0 * M_PI / spec.sectors;
}

/// The largest polar angle |atan2(y, x)| of the blade and its root block:
/// the block's corners exactly (turned about x like the blade's root
/// section, gmsh_blade.hpp), the blade by its sections' largest distance
/// from their (u, v) origin, sqrt((chord/2)^2 + (sagitta + thickness/2)^2),
/// at the smallest radius a section has (root_radius + root_height).
double blade_polar_angle(const GmshBladeSpec& b) {
  const double sagitta = b.camber * b.chord;
  const double turn = (90.0 - b.stagger) * deg;
  const double z0 = -sagitta / 2.0 - b.root_width / 2.0;
  double block = 0.0;
  for (const double y : {-b.root_length / 2.0, b.root_length / 2.0})
    for (const double z : {z0, z0 + b.root_width})
      block = std::max(block, std::abs(y * std::cos(turn) - z * std::sin(turn)));
  const double section = std::hypot(b.chord / 2.0, sagitta + b.thickness / 2.0);
  return std::max(std::atan2(block, b.root_radius),
                  std::atan2(section, b.root_radius + b.root_height));
}

/// Distance of p from the half-plane through the z axis at polar angle phi.
double off_plane(const Eigen::Vector3d& p, double phi) {
  return std::abs(-std::sin(phi) * p.x() + std::cos(phi) * p.y());
}

Eigen::Vector3d turned(const Eigen::Vector3d& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()};
}

std::string material_lines(const GmshBladeSpec& b) {
  return deck_material_lines("DISK_MATERIAL", b.young_modulus, b.poisson_ratio, b.density, "BORE");
}

} // namespace

void check_gmsh_bladed_disk_spec(const GmshBladedDiskSpec& spec) {
  check_gmsh_blade_spec(spec.blade);
  const GmshBladeSpec& b = spec.blade;
  std::ostringstream m;
  m.imbue(std::locale::classic());
  if (spec.sectors < 3 || spec.sectors > 200)
    throw std::invalid_argument(field_error("sectors", std::to_string(spec.sectors) +
                                                           " is out of range, allowed [3, 200]"));
  const double top = b.root_radius + b.root_height;
  if (!(spec.rim_radius > b.root_radius && spec.rim_radius <= top)) {
    m << deck_number(spec.rim_radius) << " mm is out of range, allowed ("
      << deck_number(b.root_radius) << ", " << deck_number(top)
      << "] mm (the root block's bottom inside the disk, its top outside)";
    throw std::invalid_argument(field_error("rim_radius", m.str()));
  }
  if (!(spec.bore_radius > 0.0 && spec.bore_radius < spec.rim_radius)) {
    m << deck_number(spec.bore_radius) << " mm is out of range, allowed (0, "
      << deck_number(spec.rim_radius) << ") mm";
    throw std::invalid_argument(field_error("bore_radius", m.str()));
  }
  if (!(spec.disk_width > 0.0) || !std::isfinite(spec.disk_width)) {
    m << deck_number(spec.disk_width) << " mm is out of range, allowed (0, inf) mm";
    throw std::invalid_argument(field_error("disk_width", m.str()));
  }
  const double needed = blade_polar_angle(b);
  if (!(needed < sector_angle(spec) / 2.0)) {
    m << spec.sectors << " sectors of " << deck_number(360.0 / spec.sectors)
      << " deg do not hold the blade: its root block and sections reach "
      << deck_number(needed / deg) << " deg from its axis, more than half a sector; allowed "
      << static_cast<int>(std::floor(M_PI / needed - 1e-12)) << " sectors at most";
    throw std::invalid_argument(field_error("sectors", m.str()));
  }
}

std::string gmsh_bladed_disk_sector_geo(const GmshBladedDiskSpec& spec) {
  check_gmsh_bladed_disk_spec(spec);
  const double a = sector_angle(spec);
  const double z0 = -spec.disk_width / 2.0;
  const double rb = spec.bore_radius, rr = spec.rim_radius;
  std::ostringstream v;
  v.imbue(std::locale::classic());
  v << "// disk sector (reference/model/gmsh_bladed_disk.hpp): " << spec.sectors
    << " sectors, bore " << deck_number(rb) << ", rim " << deck_number(rr) << ", width "
    << deck_number(spec.disk_width) << " [mm]\n"
    << "Cylinder(3) = {0, 0, " << deck_number(z0) << ", 0, 0, " << deck_number(spec.disk_width)
    << ", " << deck_number(rr) << ", " << deck_number(a) << "};\n"
    << "Cylinder(4) = {0, 0, " << deck_number(z0) << ", 0, 0, " << deck_number(spec.disk_width)
    << ", " << deck_number(rb) << ", " << deck_number(a) << "};\n"
    << "ring() = BooleanDifference{ Volume{3}; Delete; }{ Volume{4}; Delete; };\n"
    << "Rotate {{0, 0, 1}, {0, 0, 0}, " << deck_number(-a / 2.0) << "} { Volume{ring()}; }\n";
  // Each face alone in a box around it: the face at -a/2 (+a/2) spans r
  // from bore to rim along its ray, the whole width; 1e-3 of the bore as margin.
  const double e = 1e-3 * rb;
  const double c = std::cos(a / 2.0), s = std::sin(a / 2.0);
  auto box = [&](double x0, double y0, double x1, double y1) {
    return "Surface In BoundingBox{" + deck_number(x0 - e) + ", " + deck_number(y0 - e) + ", " +
           deck_number(z0 - e) + ", " + deck_number(x1 + e) + ", " + deck_number(y1 + e) + ", " +
           deck_number(-z0 + e) + "};\n";
  };
  std::ostringstream after;
  after.imbue(std::locale::classic());
  after << "left() = " << box(rb * c, -rr * s, rr * c, -rb * s)
        << "right() = " << box(rb * c, rb * s, rr * c, rr * s)
        << "If (#left() != 1 || #right() != 1)\n"
        << "  Error(\"rsi: expected one face at each side of the sector, found %g and %g\", "
           "#left(), #right());\n  Abort;\nEndIf\n"
        << "Periodic Surface{right()} = {left()} Rotate {{0, 0, 1}, {0, 0, 0}, " << deck_number(a)
        << "};\n";
  return gmsh_blade_geo(spec.blade, GmshGeoAddition{v.str(), "ring()", after.str()});
}

std::string gmsh_bladed_disk_cache_key(const GmshBladedDiskSpec& spec) {
  // The version names the deck writer: a change to what it writes from the
  // same mesh must change it.
  return gmsh_bladed_disk_sector_geo(spec) + "// bladed disk deck writer 1\n" +
         material_lines(spec.blade);
}

GmshBladedDiskDecks write_gmsh_bladed_disk_decks(const GmshBladedDiskSpec& spec,
                                                 const std::string& dir) {
  const std::string geo = gmsh_bladed_disk_sector_geo(spec); // checks the spec
  const GmshBladeSpec& b = spec.blade;
  const double tol = 1e-9 * (b.root_radius + b.root_height + b.span + b.root_length);
  GmshBladedDiskDecks decks;
  decks.disk = dir + "/disk.inp";
  decks.sector = dir + "/sector.inp";
  std::error_code ec;
  std::filesystem::remove(decks.disk, ec);
  std::filesystem::remove(decks.sector, ec);
  const GmshMeshOutcome meshed = mesh_gmsh_script(geo, dir, tol);
  const GmshMesh& mesh = meshed.mesh;
  const double a = sector_angle(spec);

  std::vector<long> left, right, bore;
  for (const long id : meshed.used) {
    const Eigen::Vector3d& x = mesh.nodes.at(id);
    if (off_plane(x, -a / 2.0) <= tol) left.push_back(id);
    if (off_plane(x, a / 2.0) <= tol) right.push_back(id);
    if (std::abs(std::hypot(x.x(), x.y()) - spec.bore_radius) <= tol) bore.push_back(id);
  }
  if (bore.size() < 3) throw meshed.failure("has fewer than 3 nodes on the bore");
  if (left.empty() || left.size() != right.size())
    throw meshed.failure("has " + std::to_string(left.size()) + " nodes on the sector face at -" +
                         "alpha/2 and " + std::to_string(right.size()) +
                         " at +alpha/2: the faces are not one node pattern");
  // LEFT node j turned by alpha is RIGHT node pair[j] (gmsh's periodic mesh).
  std::map<long, long> pair;
  for (const long j : left) {
    const Eigen::Vector3d y = turned(mesh.nodes.at(j), a);
    long best = -1;
    double distance = std::numeric_limits<double>::infinity();
    for (const long r : right) {
      const double d = (mesh.nodes.at(r) - y).norm();
      if (d < distance) distance = d, best = r;
    }
    if (!(distance <= tol))
      throw meshed.failure("has node " + std::to_string(j) +
                           " of the sector face at -alpha/2 with no node of the face at " +
                           "+alpha/2 where it turns to (nearest " + deck_number(distance) +
                           " mm away)");
    pair[j] = best;
  }
  const std::vector<long> tip = gmsh_blade_tip_nodes(b, meshed);

  const long stride = mesh.nodes.rbegin()->first + 1;
  long element_stride = 1;
  for (const std::array<long, 11>& e : mesh.elements)
    element_stride = std::max(element_stride, e[0] + 1);
  const int n = spec.sectors;
  // Sector k's number of its node j (a LEFT node is sector k-1's RIGHT node).
  const auto global = [&](int k, long j) {
    const auto p = pair.find(j);
    if (p == pair.end()) return k * stride + j;
    return ((k + n - 1) % n) * stride + p->second;
  };
  std::map<long, Eigen::Vector3d> nodes;
  std::vector<std::array<long, 11>> elements;
  std::set<long> clamped;
  std::ostringstream tips;
  std::vector<long> all_tips;
  for (int k = 0; k < n; ++k) {
    for (const long j : meshed.used)
      if (!pair.count(j)) nodes[k * stride + j] = turned(mesh.nodes.at(j), k * a);
    for (const std::array<long, 11>& e : mesh.elements) {
      std::array<long, 11> g{};
      g[0] = k * element_stride + e[0];
      for (int i = 1; i < 11; ++i)
        g[i] = global(k, e[i]);
      elements.push_back(g);
    }
    for (const long j : bore)
      clamped.insert(global(k, j));
    std::vector<long> tip_k;
    for (const long j : tip)
      tip_k.push_back(global(k, j));
    write_deck_node_set(tips, "TIP" + std::to_string(k + 1), tip_k);
    all_tips.insert(all_tips.end(), tip_k.begin(), tip_k.end());
  }
  write_deck_node_set(tips, "TIP", all_tips);

  std::ostringstream disk;
  disk.imbue(std::locale::classic());
  disk << "** rsi gmsh_bladed_disk (reference/model/gmsh_bladed_disk.hpp): " << n
       << " sectors of blade.geo beside this deck, turned about z.\n"
       << "** " << nodes.size() << " nodes, " << elements.size() << " C3D10, " << clamped.size()
       << " clamped (NSET BORE), contact nodes NSET TIP1 .. TIP" << n
       << " (all in TIP, blade by blade). Model only.\n";
  write_deck_nodes(disk, nodes);
  write_deck_c3d10(disk, elements);
  write_deck_node_set(disk, "BORE", std::vector<long>(clamped.begin(), clamped.end()));
  disk << tips.str() << material_lines(b);
  write_deck_file(decks.disk, disk.str(), "write_gmsh_bladed_disk_decks");

  std::ostringstream sector;
  sector.imbue(std::locale::classic());
  std::map<long, Eigen::Vector3d> own;
  for (const long j : meshed.used)
    own[j] = mesh.nodes.at(j);
  const std::set<long> bore_set(bore.begin(), bore.end());
  std::vector<long> dependent;
  for (const long j : left)
    if (!bore_set.count(j)) dependent.push_back(j); // ccx: no MPC on a clamped node
  sector << "** rsi gmsh_bladed_disk: one sector of " << n
         << " with ccx's cyclic symmetry tie (docs/ccx-cyclic-symmetry.md). Model only.\n";
  write_deck_nodes(sector, own);
  write_deck_c3d10(sector, mesh.elements);
  write_deck_node_set(sector, "BORE", bore);
  write_deck_node_set(sector, "NLEFT", dependent);
  write_deck_node_set(sector, "NRIGHT", right);
  write_deck_node_set(sector, "TIP", tip);
  sector << material_lines(b)
         << "*SURFACE, NAME=SLEFT, TYPE=NODE\nNLEFT\n*SURFACE, NAME=SRIGHT, TYPE=NODE\nNRIGHT\n"
         << "*TIE, NAME=T1, CYCLIC SYMMETRY\nSLEFT, SRIGHT\n*CYCLIC SYMMETRY MODEL, N=" << n
         << ", NGRAPH=1\n0., 0., 0., 0., 0., 1.\n";
  write_deck_file(decks.sector, sector.str(), "write_gmsh_bladed_disk_decks");

  return decks;
}

} // namespace rsi
