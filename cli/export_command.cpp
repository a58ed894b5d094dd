// rsi export: K, M (Matrix Market) and the dof map of both parts.

#include <cstdio>
#include <sstream>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "commands.hpp"
#include "output_files.hpp"

namespace rsi {
namespace {

std::string dofs_csv(const DofMap& dofs) {
  std::ostringstream csv;
  csv << "index,node,kind,boundary\n";
  for (size_t i = 0; i < dofs.size(); ++i)
    csv << i << "," << dofs[i].node << "," << dofs[i].kind << "," << (dofs[i].boundary ? 1 : 0)
        << "\n";
  return csv.str();
}

void write_part(const std::string& dir, const Eigen::SparseMatrix<double>& stiffness,
                const Eigen::SparseMatrix<double>& mass, const DofMap& dofs) {
  write_symmetric_matrix_market(dir + "/K.mtx", stiffness);
  write_symmetric_matrix_market(dir + "/M.mtx", mass);
  write_text_file(dir + "/dofs.csv", dofs_csv(dofs));
  std::printf("wrote %s/{K.mtx,M.mtx,dofs.csv}: %zu dofs\n", dir.c_str(), dofs.size());
}

} // namespace

int run_export(const ExportOptions& options, OutputDirectories& directories) {
  const Case c = load_case(options.case_path);
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  // Both directories before any file: an unwritable one leaves no part written.
  directories.make(options.out, "--out");
  directories.make(options.out + "/bladed-disk", "--out");
  directories.make(options.out + "/casing", "--out");
  write_part(options.out + "/bladed-disk", bd.stiffness, bd.mass, bd.dofs);
  write_part(options.out + "/casing", casing.stiffness, casing.mass, casing.dofs);
  return 0;
}

} // namespace rsi
