#include "gmsh_blade.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <locale>
#include <map>
#include <set>
#include <sstream>

#include <Eigen/Geometry>

#include "child_process.hpp"
#include "stream_text.hpp"

namespace rsi {
namespace {

constexpr double deg = M_PI / 180.0;
constexpr double inf = std::numeric_limits<double>::infinity();

std::string number(double x) {
  return deck_number(x);
}

/// Rejects `value` of `field` unless low (<|<=) value (<|<=) high.
void require(const char* field, double value, double low, bool open_low, double high,
             bool open_high, const std::string& unit, const std::string& range_note = "") {
  const bool ok = std::isfinite(value) && (open_low ? value > low : value >= low) &&
                  (open_high ? value < high : value <= high);
  if (ok) return;
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s << "GmshBladeSpec." << field << ": " << value << " " << unit << " is out of range, allowed "
    << (open_low ? "(" : "[") << low << ", " << high << (open_high ? ")" : "]") << " " << unit;
  if (!range_note.empty()) s << " (" << range_note << ")";
  throw std::invalid_argument(s.str());
}

/// The section in its own (u, v) plane: camber arc of radius R about
/// (0, f - R) through (-+c/2, 0), from angle -phi0 to phi0 (measured from +v).
struct SectionShape {
  double chord = 0.0;
  double thickness = 0.0;
  double sagitta = 0.0; ///< f
  double radius = inf;  ///< R; inf for a straight camber line
  double half_angle = 0.0;

  explicit SectionShape(const GmshBladeSpec& spec)
      : chord(spec.chord)
      , thickness(spec.thickness)
      , sagitta(spec.camber * spec.chord) {
    if (sagitta > 0.0) {
      radius = (chord * chord / 4.0 + sagitta * sagitta) / (2.0 * sagitta);
      half_angle = std::asin(chord / (2.0 * radius));
    }
  }
  bool straight() const { return !(sagitta > 0.0); }
  /// Point at camber parameter tau in [-1, 1], offset d along the camber
  /// line's normal (towards +v at the middle).
  Eigen::Vector2d point(double tau, double d) const {
    if (straight()) return {tau * chord / 2.0, d};
    const double phi = tau * half_angle;
    return {(radius + d) * std::sin(phi), sagitta - radius + (radius + d) * std::cos(phi)};
  }
  Eigen::Vector2d centre() const { return {0.0, sagitta - radius}; }
  double camber_length() const { return straight() ? chord : 2.0 * half_angle * radius; }
  double area() const { return camber_length() * thickness; }
};

/// A section point (u, v) at span coordinate s in the model frame.
Eigen::Vector3d place(const GmshBladeSpec& spec, double s, const Eigen::Vector2d& uv) {
  const double x_top = spec.root_radius + spec.root_height;
  const double theta = (spec.stagger + spec.twist * s / spec.span) * deg;
  return {x_top + s, uv.x() * std::sin(theta) + uv.y() * std::cos(theta),
          uv.x() * std::cos(theta) - uv.y() * std::sin(theta)};
}

int n_sections(const GmshBladeSpec& spec) {
  return std::max(2, 1 + static_cast<int>(std::ceil(std::abs(spec.twist) / 5.0)));
}

double station_tau(int j) {
  return -1.0 + 2.0 * j / (n_tip_stations - 1);
}


std::string upper(std::string s) {
  for (char& c : s)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) {
    const size_t a = field.find_first_not_of(" \t\r");
    const size_t b = field.find_last_not_of(" \t\r");
    fields.push_back(a == std::string::npos ? std::string() : field.substr(a, b - a + 1));
  }
  return fields;
}

GmshMesh read_gmsh_inp(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw GmshError("write_gmsh_blade_deck: gmsh wrote no mesh file " + path);
  GmshMesh mesh;
  enum class Block { none, nodes, c3d10 } block = Block::none;
  std::vector<long> pending; // an element's numbers, possibly over several lines
  std::string line;
  long line_no = 0;
  auto bad = [&](const std::string& what) {
    return GmshError("write_gmsh_blade_deck: " + path + ":" + std::to_string(line_no) + ": " +
                     what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line.rfind("**", 0) == 0) continue;
    if (line[0] == '*') {
      if (!pending.empty()) throw bad("element cut short");
      const std::string key = upper(line);
      if (key == "*NODE" || key.rfind("*NODE,", 0) == 0)
        block = Block::nodes;
      else if (key.rfind("*ELEMENT", 0) == 0 && key.find("TYPE=C3D10") != std::string::npos)
        block = Block::c3d10;
      else if (key.rfind("*ELEMENT", 0) == 0)
        throw bad("unexpected element type (only C3D10 expected): " + line);
      else
        block = Block::none;
      continue;
    }
    if (block == Block::none) continue;
    std::vector<std::string> fields = split_commas(line);
    while (!fields.empty() && fields.back().empty())
      fields.pop_back();
    try {
      if (block == Block::nodes) {
        if (fields.size() != 4) throw bad("a node line needs 4 fields: " + line);
        mesh.nodes[std::stol(fields[0])] = {std::stod(fields[1]), std::stod(fields[2]),
                                            std::stod(fields[3])};
      } else {
        for (const std::string& f : fields)
          pending.push_back(std::stol(f));
        if (pending.size() > 11) throw bad("a C3D10 element needs 11 numbers: " + line);
        if (pending.size() == 11) {
          std::array<long, 11> e{};
          std::copy(pending.begin(), pending.end(), e.begin());
          mesh.elements.push_back(e);
          pending.clear();
        }
      }
    } catch (const std::logic_error&) { // stol/stod: not a number
      throw bad("not a number in: " + line);
    }
  }
  if (!pending.empty()) throw bad("element cut short at the end of the file");
  return mesh;
}

/// The lines of gmsh's output that report errors or warnings, and its last
/// lines: enough to say why it failed without the whole log.
std::string output_excerpt(const std::string& output) {
  std::istringstream in(output);
  std::string line;
  std::vector<std::string> lines;
  std::string flagged;
  while (std::getline(in, line)) {
    lines.push_back(line);
    if (line.rfind("Error", 0) == 0 || line.rfind("Warning", 0) == 0) flagged += line + "\n";
  }
  std::string tail;
  const size_t first = lines.size() > 10 ? lines.size() - 10 : 0;
  for (size_t i = first; i < lines.size(); ++i)
    tail += lines[i] + "\n";
  return flagged + (flagged.empty() ? "" : "...\n") + tail;
}

bool has_error_line(const std::string& output) {
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("Error", 0) == 0) return true;
  return false;
}

/// Abaqus C3D10: corner nodes 1-4 (1-2-3 counter-clockwise seen from 4),
/// then the midpoints of edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4.
constexpr std::array<std::array<int, 2>, 6> c3d10_edges{
    {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};


} // namespace

std::string deck_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.15g", x);
  return buffer;
}

void write_deck_file(const std::string& path, const std::string& text, const std::string& who) {
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(who + ": cannot write " + partial);
  }
  std::error_code ec;
  std::filesystem::rename(partial, path, ec);
  if (ec) throw std::runtime_error(who + ": cannot rename " + partial + ": " + ec.message());
}

std::string deck_material_lines(const std::string& material, double young_modulus,
                                double poisson_ratio, double density,
                                const std::string& clamped) {
  return "*MATERIAL, NAME=" + material + "\n*ELASTIC\n" + deck_number(young_modulus) + ", " +
         deck_number(poisson_ratio) + "\n*DENSITY\n" + deck_number(density) +
         "\n*SOLID SECTION, ELSET=EALL, MATERIAL=" + material + "\n*BOUNDARY\n" + clamped +
         ", 1, 3\n";
}

void write_deck_nodes(std::ostream& out, const std::map<long, Eigen::Vector3d>& nodes) {
  const auto coordinate = [](double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.12e", x);
    return std::string(buffer);
  };
  out << "*NODE, NSET=NALL\n";
  for (const auto& [id, x] : nodes)
    out << id << ", " << coordinate(x.x()) << ", " << coordinate(x.y()) << ", " << coordinate(x.z())
        << "\n";
}

void write_deck_c3d10(std::ostream& out, const std::vector<std::array<long, 11>>& elements) {
  out << "*ELEMENT, TYPE=C3D10, ELSET=EALL\n";
  for (const std::array<long, 11>& e : elements)
    for (int i = 0; i < 11; ++i)
      out << e[i] << (i < 10 ? ", " : "\n");
}

void write_deck_node_set(std::ostream& out, const std::string& name,
                         const std::vector<long>& nodes) {
  out << "*NSET, NSET=" << name << "\n";
  for (size_t i = 0; i < nodes.size(); ++i)
    out << nodes[i] << ((i + 1) % 8 == 0 || i + 1 == nodes.size() ? ",\n" : ", ");
}

void check_gmsh_blade_spec(const GmshBladeSpec& s) {
  require("span", s.span, 0.0, true, inf, true, "mm");
  require("chord", s.chord, 0.0, true, inf, true, "mm");
  require("thickness", s.thickness, 0.0, true, s.chord / 2.0, false, "mm", "up to chord / 2");
  require("camber", s.camber, 0.0, false, 0.25, false, "(fraction of the chord)");
  require("twist", s.twist, -90.0, false, 90.0, false, "deg");
  require("stagger", s.stagger, -90.0, false, 90.0, false, "deg");
  require("root_length", s.root_length, s.chord + s.thickness, true, inf, true, "mm",
          "more than chord + thickness, so that the root section lies inside the block");
  require("root_width", s.root_width, s.camber * s.chord + s.thickness, true, inf, true, "mm",
          "more than camber chord + thickness, so that the root section lies inside the block");
  require("root_height", s.root_height, 0.0, true, inf, true, "mm");
  require("element_size", s.element_size, s.chord / 100.0, false, std::max(s.span, s.chord), false,
          "mm", "from chord / 100 to max(span, chord)");
  require("young_modulus", s.young_modulus, 0.0, true, inf, true, "N/mm^2");
  require("poisson_ratio", s.poisson_ratio, -1.0, true, 0.5, true, "");
  require("density", s.density, 0.0, true, inf, true, "t/mm^3");
  require("root_radius", s.root_radius, 0.0, false, inf, true, "mm");
  const GmshBladeMeshEstimate size = gmsh_blade_mesh_estimate(s);
  if (!(size.dofs <= gmsh_blade_max_estimated_dofs)) {
    std::ostringstream m;
    m.imbue(std::locale::classic());
    m << "GmshBladeSpec.element_size: " << number(s.element_size) << " mm gives about "
      << std::fixed << std::setprecision(0) << size.dofs
      << " dofs (estimated before gmsh from the volume: " << size.elements
      << " quadratic tetrahedra, within a factor 2 of gmsh's meshes), more than the "
      << gmsh_blade_max_estimated_dofs
      << " allowed (the finest mesh measured, element_size 5/3 mm: 149,865 dofs, estimated "
         "264,804); "
         "use a larger element_size, or mesh the blade yourself and give its deck as "
         "component.source.calculix_deck";
    throw std::invalid_argument(m.str());
  }
}

GmshBladeMeshEstimate gmsh_blade_mesh_estimate(const GmshBladeSpec& s) {
  // A regular tetrahedron of edge h has the volume h^3 / (6 sqrt 2). The
  // root block fills with them; the plate, thinner than h at coarse sizes,
  // still needs about one element across its thickness t, so its elements
  // are h x h x min(h, t). Second-order tetrahedra carry about 2 nodes an
  // element (1.7 to 2.2 in the table of gmsh_blade.hpp), 3 dofs a node.
  const double tet = 1.0 / (6.0 * std::sqrt(2.0));
  const double h = s.element_size;
  const double block = s.root_length * s.root_width * s.root_height;
  const double plate = SectionShape(s).area() * s.span;
  GmshBladeMeshEstimate e;
  e.elements = block / (tet * h * h * h) + plate / (tet * h * h * std::min(h, s.thickness));
  e.nodes = 2.0 * e.elements;
  e.dofs = 3.0 * e.nodes;
  return e;
}

std::vector<Eigen::Vector3d> gmsh_blade_tip_stations(const GmshBladeSpec& spec) {
  check_gmsh_blade_spec(spec);
  const SectionShape shape(spec);
  std::vector<Eigen::Vector3d> stations;
  for (int j = 0; j < n_tip_stations; ++j)
    stations.push_back(place(spec, spec.span, shape.point(station_tau(j), 0.0)));
  return stations;
}

double gmsh_blade_section_area(const GmshBladeSpec& spec) {
  check_gmsh_blade_spec(spec);
  return SectionShape(spec).area();
}

double gmsh_blade_volume(const GmshBladeSpec& spec) {
  return spec.root_length * spec.root_width * spec.root_height +
         gmsh_blade_section_area(spec) * spec.span;
}

std::string gmsh_blade_geo(const GmshBladeSpec& spec) {
  return gmsh_blade_geo(spec, GmshGeoAddition{});
}

std::string gmsh_blade_geo(const GmshBladeSpec& spec, const GmshGeoAddition& addition) {
  check_gmsh_blade_spec(spec);
  const SectionShape shape(spec);
  const double t = spec.thickness;
  const int n = n_sections(spec);
  std::ostringstream g;
  g.imbue(std::locale::classic());
  g << "// rsi gmsh_blade: twisted cambered plate blade on a root block (reference/model/"
       "gmsh_blade.hpp)\n"
    << "// span " << number(spec.span) << ", chord " << number(spec.chord) << ", thickness "
    << number(t) << ", camber " << number(spec.camber) << ", twist " << number(spec.twist)
    << " deg, stagger " << number(spec.stagger) << " deg, root block " << number(spec.root_length)
    << " x " << number(spec.root_width) << " x " << number(spec.root_height) << ", root radius "
    << number(spec.root_radius) << ", element size " << number(spec.element_size) << " [mm]\n"
    << "SetFactory(\"OpenCASCADE\");\n";
  auto point = [&](int tag, const Eigen::Vector3d& p) {
    g << "Point(" << tag << ") = {" << number(p.x()) << ", " << number(p.y()) << ", "
      << number(p.z()) << "};\n";
  };
  // Section k: points 10k+1..10k+7, curves 10k+1..10k+6, curve loop 10k+7.
  std::string loops;
  for (int k = 0; k < n; ++k) {
    const double s = spec.span * k / (n - 1);
    const int p = 10 * k;
    point(p + 1, place(spec, s, shape.point(-1.0, t / 2.0)));  // o1: outer (+v) side, u < 0 end
    point(p + 2, place(spec, s, shape.point(1.0, t / 2.0)));   // o2
    point(p + 3, place(spec, s, shape.point(1.0, -t / 2.0)));  // i2: inner (-v) side
    point(p + 4, place(spec, s, shape.point(-1.0, -t / 2.0))); // i1
    point(p + 5, place(spec, s, shape.point(-1.0, 0.0)));      // e1: camber line ends
    point(p + 6, place(spec, s, shape.point(1.0, 0.0)));       // e2
    if (!shape.straight()) {
      point(p + 7, place(spec, s, shape.centre()));
      g << "Circle(" << p + 1 << ") = {" << p + 1 << ", " << p + 7 << ", " << p + 2 << "};\n";
      g << "Circle(" << p + 4 << ") = {" << p + 3 << ", " << p + 7 << ", " << p + 4 << "};\n";
    } else {
      g << "Line(" << p + 1 << ") = {" << p + 1 << ", " << p + 2 << "};\n";
      g << "Line(" << p + 4 << ") = {" << p + 3 << ", " << p + 4 << "};\n";
    }
    g << "Line(" << p + 2 << ") = {" << p + 2 << ", " << p + 6 << "};\n"
      << "Line(" << p + 3 << ") = {" << p + 6 << ", " << p + 3 << "};\n"
      << "Line(" << p + 5 << ") = {" << p + 4 << ", " << p + 5 << "};\n"
      << "Line(" << p + 6 << ") = {" << p + 5 << ", " << p + 1 << "};\n"
      << "Curve Loop(" << p + 7 << ") = {" << p + 1 << ", " << p + 2 << ", " << p + 3 << ", "
      << p + 4 << ", " << p + 5 << ", " << p + 6 << "};\n";
    loops += (k == 0 ? "" : ", ") + std::to_string(p + 7);
  }
  g << "ThruSections(1) = {" << loops << "};\n";
  // Root block: y along the chord, z against v before the turn about x by
  // 90 deg - stagger, which takes (y, z) = (u, -v) to the section's frame.
  const double x0 = spec.root_radius;
  g << "Box(2) = {" << number(x0) << ", " << number(-spec.root_length / 2.0) << ", "
    << number(-shape.sagitta / 2.0 - spec.root_width / 2.0) << ", " << number(spec.root_height)
    << ", " << number(spec.root_length) << ", " << number(spec.root_width) << "};\n"
    << "Rotate {{1, 0, 0}, {0, 0, 0}, " << number((90.0 - spec.stagger) * deg)
    << "} { Volume{2}; }\n"
    << addition.volumes
    << "v() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; "
    << (addition.fused.empty() ? "" : "Volume{" + addition.fused + "}; ") << "Delete; };\n"
    << "If (#v() != 1)\n  Error(\"rsi: the union of blade and root block is not one volume\");\n"
    << "  Abort;\nEndIf\n"
    << addition.after_union;
  // The tip face and the interior stations embedded in it.
  const double x_tip = spec.root_radius + spec.root_height + spec.span;
  const double eps = 1e-4 * spec.thickness;
  const double far =
      10.0 * (spec.root_radius + spec.root_height + spec.span + spec.root_length + spec.chord);
  g << "tip() = Surface In BoundingBox{" << number(x_tip - eps) << ", " << number(-far) << ", "
    << number(-far) << ", " << number(x_tip + eps) << ", " << number(far) << ", " << number(far)
    << "};\n"
    << "If (#tip() != 1)\n  Error(\"rsi: expected one tip face, found %g\", #tip());\n"
    << "  Abort;\nEndIf\n";
  const std::vector<Eigen::Vector3d> stations = gmsh_blade_tip_stations(spec);
  const double spacing = shape.camber_length() / (n_tip_stations - 1);
  const double station_size = std::min(spec.element_size, spacing);
  for (int j = 1; j + 1 < n_tip_stations; ++j) {
    const Eigen::Vector3d& q = stations[j];
    g << "station(" << j - 1 << ") = newp; Point(station(" << j - 1 << ")) = {" << number(q.x())
      << ", " << number(q.y()) << ", " << number(q.z()) << ", " << number(station_size) << "};\n";
  }
  g << "Point{station()} In Surface{tip(0)};\n"
    << "Physical Volume(\"BLADE\") = {v()};\n"
    << gmsh_mesh_options(spec.element_size);
  return stream_text(g);
}

std::string gmsh_mesh_options(double element_size) {
  std::ostringstream g;
  g.imbue(std::locale::classic());
  g << "Mesh.MeshSizeMax = " << number(element_size) << ";\n"
    << "Mesh.ElementOrder = 2;\n"
    << "Mesh.SecondOrderLinear = 1;\n"
    << "Mesh.Optimize = 1;\n"
    // gmsh 4.8's defaults, set here so that a user's ~/.gmsh-options
    // cannot change the mesh.
    << "Mesh.MeshSizeMin = 0;\nMesh.MeshSizeFactor = 1;\nMesh.MeshSizeFromPoints = 1;\n"
    << "Mesh.MeshSizeFromCurvature = 0;\nMesh.MeshSizeExtendFromBoundary = 1;\n"
    << "Mesh.Algorithm = 6;\nMesh.Algorithm3D = 1;\nMesh.RecombineAll = 0;\n"
    << "Mesh.HighOrderOptimize = 0;\nMesh.OptimizeNetgen = 0;\nMesh.SaveAll = 0;\n"
    << "General.NumThreads = 1;\n";
  return stream_text(g);
}

namespace {

/// Runs gmsh on DIR/blade.geo; throws GmshError unless it exits with 0 and
/// reports no error.
void run_gmsh(const std::vector<std::string>& command, const std::string& dir,
              const std::string& where) {
  const ChildResult run = run_child(command, dir, dir + "/gmsh.log");
  if (!run.started)
    throw GmshError("write_gmsh_blade_deck: cannot run '" + command_text(command) + "'" + where +
                    ": " + run.error + " (is gmsh installed and on PATH?)");
  // gmsh 4.8 exits with 0 after errors in a script (unknown entity, failed
  // boolean): its Error lines count as a failure too.
  if (!run.succeeded() || has_error_line(run.output)) {
    const std::string status = run.signal != 0 ? "killed by signal " + std::to_string(run.signal)
                                               : "exit status " + std::to_string(run.exit_status);
    throw GmshError("write_gmsh_blade_deck: '" + command_text(command) + "' failed (" + status +
                    (run.succeeded() ? ", but reported errors" : "") + ")" + where + ":\n" +
                    output_excerpt(run.output));
  }
}

/// Checks every element (its nodes exist, its corners are positively
/// oriented, its midside nodes are the Abaqus edge midpoints to `tol`);
/// returns the nodes the elements use. `what` is an empty string when all
/// is well, else the first problem.
std::set<long> check_elements(const GmshMesh& mesh, double tol, std::string& what) {
  std::set<long> used;
  for (const std::array<long, 11>& e : mesh.elements) {
    std::array<Eigen::Vector3d, 10> p;
    for (int i = 0; i < 10; ++i) {
      const auto it = mesh.nodes.find(e[i + 1]);
      if (it == mesh.nodes.end()) {
        what = "element " + std::to_string(e[0]) + " uses missing node " + std::to_string(e[i + 1]);
        return used;
      }
      p[i] = it->second;
      used.insert(e[i + 1]);
    }
    const Eigen::Vector3d a = p[1] - p[0];
    const Eigen::Vector3d b = p[2] - p[0];
    const Eigen::Vector3d c = p[3] - p[0];
    const double six_volume = a.cross(b).dot(c);
    if (!(six_volume > 0.0)) {
      what = "element " + std::to_string(e[0]) + " has a non-positive volume " +
             number(six_volume / 6.0) + " mm^3";
      return used;
    }
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector3d mid = 0.5 * (p[c3d10_edges[k][0]] + p[c3d10_edges[k][1]]);
      if ((p[4 + k] - mid).norm() > tol) {
        what = "element " + std::to_string(e[0]) + ": node " + std::to_string(k + 5) +
               " is not the midpoint of its C3D10 edge (node order not Abaqus')";
        return used;
      }
    }
  }
  return used;
}

/// The deck's lines after the node sets: material, section, clamping.
std::string material_and_clamping(const GmshBladeSpec& spec) {
  return deck_material_lines("BLADE_MATERIAL", spec.young_modulus, spec.poisson_ratio,
                             spec.density, "ROOT");
}

/// The deck: header comment, nodes, elements, node sets, material, section
/// and clamping.
void write_deck(std::ostream& out, const GmshBladeSpec& spec, const GmshMesh& mesh,
                const std::set<long>& used, const std::vector<long>& root,
                const std::vector<long>& tip) {
  out.imbue(std::locale::classic());
  // Comment lines stay short: ccx reads at most 132 characters a line.
  out << "** rsi gmsh_blade (reference/model/gmsh_blade.hpp), meshed by gmsh from\n"
      << "** blade.geo beside this deck. A twisted, cambered plate blade on a root block.\n"
      << "** Units mm, t, s, N; z = rotation axis, blade along +x.\n"
      << "** span " << number(spec.span) << ", chord " << number(spec.chord) << ", thickness "
      << number(spec.thickness) << ", camber " << number(spec.camber) << ", twist "
      << number(spec.twist) << " deg, stagger " << number(spec.stagger) << " deg\n"
      << "** root block " << number(spec.root_length) << " x " << number(spec.root_width) << " x "
      << number(spec.root_height) << " at radius " << number(spec.root_radius) << ", element size "
      << number(spec.element_size) << "\n"
      << "** " << used.size() << " nodes, " << mesh.elements.size() << " C3D10, " << root.size()
      << " clamped (NSET ROOT), " << tip.size() << " contact nodes (NSET TIP)\n"
      << "** Model only: add a *STEP.\n"
      << "*NODE, NSET=NALL\n";
  for (const long id : used) {
    const Eigen::Vector3d& x = mesh.nodes.at(id);
    out << id << ", " << number(x.x()) << ", " << number(x.y()) << ", " << number(x.z()) << "\n";
  }
  out << "*ELEMENT, TYPE=C3D10, ELSET=EALL\n";
  for (const std::array<long, 11>& e : mesh.elements) {
    for (int i = 0; i < 11; ++i)
      out << e[i] << (i < 10 ? ", " : "\n");
  }
  write_deck_node_set(out, "ROOT", root);
  write_deck_node_set(out, "TIP", tip);
  out << material_and_clamping(spec);
}

} // namespace

std::string gmsh_blade_cache_key(const GmshBladeSpec& spec) {
  // The mesh is gmsh's of the script; the rest of the deck is the text
  // below. The version names the deck writer: a change to what it writes
  // from the same mesh must change it.
  return gmsh_blade_geo(spec) + "// deck writer 2\n" + material_and_clamping(spec);
}

GmshMeshOutcome mesh_gmsh_script(const std::string& geo_text, const std::string& dir, double tol,
                                 const std::string& stem) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw std::runtime_error("write_gmsh_blade_deck: cannot create " + dir + ": " + ec.message());
  const std::string geo = dir + "/" + stem + ".geo";
  const std::string gmsh_mesh = dir + "/" + stem + "_gmsh.inp";
  fs::remove(gmsh_mesh, ec); // never read a previous run's files
  {
    std::ofstream out(geo);
    out << geo_text;
    if (!out) throw std::runtime_error("write_gmsh_blade_deck: cannot write " + geo);
  }
  GmshMeshOutcome outcome;
  outcome.command = {"gmsh", stem + ".geo", "-3", "-format", "inp", "-o", stem + "_gmsh.inp",
                     "-nopopup"};
  outcome.where = " (in " + dir + ", output in " + dir + "/gmsh.log)";
  run_gmsh(outcome.command, dir, outcome.where);
  outcome.mesh = read_gmsh_inp(gmsh_mesh);
  if (outcome.mesh.elements.empty()) throw outcome.failure("has no C3D10 element");
  std::string problem;
  outcome.used = check_elements(outcome.mesh, tol, problem);
  if (!problem.empty()) throw outcome.failure(problem);
  return outcome;
}

GmshError GmshMeshOutcome::failure(const std::string& what) const {
  return GmshError("write_gmsh_blade_deck: the mesh of '" + command_text(command) + "'" + where +
                   " " + what);
}

std::vector<long> gmsh_blade_tip_nodes(const GmshBladeSpec& spec, const GmshMeshOutcome& meshed) {
  std::vector<long> tip;
  const std::vector<Eigen::Vector3d> stations = gmsh_blade_tip_stations(spec);
  for (int j = 0; j < n_tip_stations; ++j) {
    long best = -1;
    double best_distance = inf;
    for (const long id : meshed.used) {
      const double d = (meshed.mesh.nodes.at(id) - stations[j]).norm();
      if (d < best_distance) {
        best_distance = d;
        best = id;
      }
    }
    if (best_distance > 1e-6 * spec.thickness)
      throw meshed.failure("has no node at tip station " + std::to_string(j) + " (nearest " +
                           number(best_distance) + " mm away)");
    tip.push_back(best);
  }
  return tip;
}

std::string write_gmsh_blade_deck(const GmshBladeSpec& spec, const std::string& dir) {
  namespace fs = std::filesystem;
  const std::string geo_text = gmsh_blade_geo(spec); // checks the spec
  const std::string deck = dir + "/blade.inp";
  std::error_code ec;
  fs::remove(deck, ec); // never leave a previous run's deck beside a failed mesh
  const double extent = spec.root_radius + spec.root_height + spec.span + spec.root_length;
  const double tol = 1e-9 * extent;
  const GmshMeshOutcome meshed = mesh_gmsh_script(geo_text, dir, tol);
  const GmshMesh& mesh = meshed.mesh;
  const std::set<long>& used = meshed.used;
  auto fail = [&](const std::string& what) { return meshed.failure(what); };

  std::vector<long> root; // the clamped face x = root_radius
  for (const long id : used)
    if (std::abs(mesh.nodes.at(id).x() - spec.root_radius) <= tol) root.push_back(id);
  if (root.size() < 3) throw fail("has fewer than 3 nodes on the root block's bottom face");

  const std::vector<long> tip = gmsh_blade_tip_nodes(spec, meshed);

  std::ostringstream text;
  write_deck(text, spec, mesh, used, root, tip);
  write_deck_file(deck, text.str(), "write_gmsh_blade_deck");
  return deck;
}

} // namespace rsi
