// rsi export: K, M (Matrix Market), the dof map and the node coordinates of
// every component of a case, in the layout a matrix_market source reads back.

#include <cstdio>
#include <sstream>

#include <CLI/CLI.hpp>

#include "command.hpp"
#include "command_options.hpp"
#include "usage_error.hpp"
#include "bladed_disk.hpp"
#include "casing.hpp"
#include "component_input.hpp"
#include "output_files.hpp"
#include "paper_components.hpp"
#include "staged_output.hpp"
#include "stream_text.hpp"

namespace rsi {
namespace {

struct ExportOptions {
  std::string case_path;
  std::string out = "out/export";
  ComponentLoadOptions load;
};

class ExportCommand : public Command {
public:
  explicit ExportCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  ExportOptions m_options;
};

ExportCommand::ExportCommand(CLI::App& app)
    : Command(*app.add_subcommand(
          "export", "K.mtx, M.mtx, dofs.csv, nodes.csv of each component -> DIR/<component>/")) {
  ExportOptions& export_options = m_options;
  m_command.add_option("case", export_options.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  m_command.add_option("--out", export_options.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  add_component_options(m_command, export_options.load);
}


std::string dofs_csv(const DofMap& dofs) {
  std::ostringstream csv;
  csv << "index,node,kind,boundary\n";
  for (size_t i = 0; i < dofs.size(); ++i)
    csv << i << "," << dofs[i].node << "," << dofs[i].kind << "," << (dofs[i].boundary ? 1 : 0)
        << "\n";
  return stream_text(csv);
}

std::string nodes_csv(const std::vector<ComponentNode>& nodes) {
  std::ostringstream csv;
  csv.precision(17);
  csv << "node,x,y,z\n";
  for (const ComponentNode& node : nodes)
    if (node.generated) // no position: empty coordinates (data/README.md)
      csv << node.id << ",,,\n";
    else
      csv << node.id << "," << node.x(0) << "," << node.x(1) << "," << node.x(2) << "\n";
  return stream_text(csv);
}

/// Writes into `dir` (staged); `shown` is the folder named in the message.
void write_component(const std::string& dir, const std::string& shown, const Component& c,
                     StagedOutput& output) {
  write_symmetric_matrix_market(dir + "/K.mtx", c.stiffness);
  write_symmetric_matrix_market(dir + "/M.mtx", c.mass);
  write_text_file(dir + "/dofs.csv", dofs_csv(c.dofs));
  write_text_file(dir + "/nodes.csv", nodes_csv(c.nodes));
  output.announce("wrote " + shown + "/{K.mtx,M.mtx,dofs.csv,nodes.csv}: " +
                  std::to_string(c.n_dofs()) + " dofs, " + std::to_string(c.nodes.size()) +
                  " nodes, " + std::to_string(c.boundary.size()) + " boundary dofs\n");
}

} // namespace

int ExportCommand::run(StagedOutput& output) {
  const ExportOptions& options = m_options;
  const std::vector<Component> components = load_case_structures(options.case_path, options.load);
  const std::string dir = output.open(options.out, "--out", export_output_set());
  for (const Component& c : components)
    output.make(dir + "/" + c.name);
  for (const Component& c : components)
    write_component(dir + "/" + c.name, options.out + "/" + c.name, c, output);
  return 0;
}

std::unique_ptr<Command> add_export_command(CLI::App& app) {
  return std::make_unique<ExportCommand>(app);
}

} // namespace rsi
