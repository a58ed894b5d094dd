#include "basis_memory.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "case_file.hpp"
#include "casing_memory.hpp"

namespace rsi {

double dense_basis_bytes(int n_dofs, int n_reduced) {
  return 16.0 * static_cast<double>(n_dofs) * n_reduced;
}

void check_dense_basis_fits(const FailureAdvice& where, int n_dofs, int n_boundary, int modes,
                            int runs_at_once) {
  const int runs = std::max(runs_at_once, 1);
  const double limit = process_memory_limit_bytes();
  const double needed = dense_basis_bytes(n_dofs, n_boundary + modes) * runs;
  if (!(needed > limit)) return;
  const double fitting_columns = std::floor(limit / (16.0 * n_dofs * runs));
  std::ostringstream what;
  what.precision(3);
  what << modes << " modes: the reduced basis T is dense, " << n_dofs << " x " << n_boundary + modes
       << " (" << n_boundary
       << " boundary dofs and the modes), and a reduced run holds it twice, 16 n r = "
       << dense_basis_bytes(n_dofs, n_boundary + modes) / 1e9 << " GB";
  if (runs > 1) what << ", " << runs << " runs at once: " << needed / 1e9 << " GB";
  what << ", more than the " << limit / 1e9
       << " GB this process may use (physical memory, ulimit -v, ulimit -d); ";
  if (fitting_columns > n_boundary)
    what << "use at most " << static_cast<long>(fitting_columns) - n_boundary << " modes";
  else
    what << "no mode count fits: use fewer blades or blade elements (keys "
            "'bladed_disk.n_blades', 'bladed_disk.n_blade_elements')";
  FailureAdvice advice = where;
  if (runs > 1) advice.remedies.push_back(Remedy::fewer_jobs);
  throw CaseError(what.str(), advice);
}

} // namespace rsi
