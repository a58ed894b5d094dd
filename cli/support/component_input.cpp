#include "component_input.hpp"

#include <fstream>
#include <memory>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include "bladed_disk.hpp"
#include "case_json.hpp"
#include "casing.hpp"
#include "cyclic_images.hpp"
#include "usage_error.hpp"
#include "nodal_diameter.hpp"
#include "paper_components.hpp"
#include "rotating_component.hpp"

namespace rsi {

namespace {

/// The nodal diameter of a mode of a component case's model: a bladed
/// disk's (its sectors' images, cyclic_images.hpp), the flexible casing's
/// lobes (its radial displacement's harmonic up to 64); none for a blade.
std::function<std::optional<int>(const Eigen::VectorXd&)>
component_diameter(const ComponentCase& c, const Component& component) {
  const int sectors = c.source == ComponentSource::gmsh_bladed_disk ? c.gmsh_bladed_disk.sectors
                      : c.source == ComponentSource::calculix_sector ? c.sectors
                                                                      : 0;
  if (sectors > 0) {
    auto images = std::make_shared<const CyclicImages>(cyclic_images(component, sectors));
    return [images](const Eigen::VectorXd& x) -> std::optional<int> {
      return cyclic_nodal_diameter(*images, x);
    };
  }
  if (c.source == ComponentSource::gmsh_casing) {
    // Its nodes, dofs and axis: what the lobes read (not K and M).
    auto ring = std::make_shared<Component>();
    ring->nodes = component.nodes;
    ring->dofs = component.dofs;
    ring->rotation_axis = component.rotation_axis;
    return [ring](const Eigen::VectorXd& x) -> std::optional<int> {
      return circumferential_harmonic(*ring, x, 64);
    };
  }
  return {};
}

} // namespace

ComponentInput load_component_input(const std::string& case_path, const std::string& part,
                                    const ComponentLoadOptions& load, double speed,
                                    const std::string& speed_option) {
  const nlohmann::json document = read_case_document(case_path);
  ComponentInput input;
  input.case_source = case_path;
  if (is_component_case(document)) {
    input.component_case = parse_component_case(document, case_path);
    if (!part.empty() && part != input.component_case->name)
      throw UsageError("--part: the case " + case_path + " has one component, '" +
                       input.component_case->name + "', got '" + part + "'");
    if (speed == 0.0) {
      input.component = load_component(*input.component_case, load);
      input.diameter = component_diameter(*input.component_case, input.component);
      return input;
    }
    RotatingComponent rotating = rotating_component(*input.component_case, load, speed);
    input.component = std::move(rotating.component);
    input.speed = speed;
    input.deflection = std::move(rotating.deflection);
    return input;
  }
  if (speed != 0.0)
    throw UsageError(speed_option + ": rotation effects are for a component case (a CalculiX "
                     "deck or the gmsh blade); " + case_path + " is the paper's 2D case");
  if (!load.source_override.empty())
    throw UsageError("--source: only for a component case (a CalculiX deck or Matrix Market "
                     "folder); " + case_path + " is the paper's case");
  ComponentInput input_of_part = paper_part_input(parse_case(document, case_path), part);
  input_of_part.case_source = case_path;
  return input_of_part;
}

std::vector<Component> load_case_structures(const std::string& case_path,
                                            const ComponentLoadOptions& load) {
  ComponentInput first = load_component_input(case_path, "", load);
  const bool paper = !first.component_case.has_value();
  std::vector<Component> structures;
  structures.push_back(std::move(first.component));
  if (paper) structures.push_back(load_component_input(case_path, "casing", load).component);
  return structures;
}

ComponentInput paper_part_input(const Case& c, const std::string& part) {
  ComponentInput input;
  input.case_source = c.source;
  input.case_time_step = c.time.step;
  if (part.empty() || part == "bladed-disk") {
    const BladedDisk bd = assemble_bladed_disk(c);
    input.component = bladed_disk_component(bd);
    const int n = bd.n_sectors;
    const int block = bd.dofs_per_sector;
    input.diameter = [n, block](const Eigen::VectorXd& x) -> std::optional<int> {
      return nodal_diameter(x, n, block);
    };
  } else if (part == "casing") {
    const Casing casing = assemble_casing(c);
    input.component = casing_component(casing);
    input.diameter = [casing](const Eigen::VectorXd& x) -> std::optional<int> {
      return nodal_diameter(on_all_nodes(casing, x), casing.n_elements, 4);
    };
  } else {
    throw UsageError("--part: must be bladed-disk or casing for the paper's case, got '" + part +
                     "'");
  }
  return input;
}

long long peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<long long>(usage.ru_maxrss) * 1024;
}

} // namespace rsi
