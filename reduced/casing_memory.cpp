#include "casing_memory.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

namespace rsi {

double process_memory_limit_bytes() {
  double limit = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit r{};
    if (getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
      limit = std::min(limit, static_cast<double>(r.rlim_cur));
  }
  return limit;
}

double dense_casing_bytes(int n_casing_dofs) {
  return 8.0 * static_cast<double>(n_casing_dofs) * n_casing_dofs;
}

void check_dense_casing_fits(const Case& c, int n_casing_dofs, int runs_at_once) {
  const double limit = process_memory_limit_bytes();
  const double needed = dense_casing_bytes(n_casing_dofs) * std::max(runs_at_once, 1);
  if (!(needed > limit)) return;
  // The casing has 4 dofs a node and one node clamped: n_c = 4 n - 4.
  const double fitting_dofs = std::sqrt(limit / (8.0 * std::max(runs_at_once, 1)));
  const long most = std::max(3L, static_cast<long>(std::floor((fitting_dofs + 4.0) / 4.0)));
  std::ostringstream what;
  what.precision(3);
  what << c.source << ": key 'casing.n_elements' (" << c.casing.n_elements
       << "): a reduced run keeps the casing's inverse mass dense, 8 n_c^2 = "
       << dense_casing_bytes(n_casing_dofs) / 1e9 << " GB for its " << n_casing_dofs << " dofs";
  if (runs_at_once > 1) what << ", " << runs_at_once << " runs at once: " << needed / 1e9 << " GB";
  what << ", more than the " << limit / 1e9
       << " GB this process may use (physical memory, ulimit -v, ulimit -d); use at most " << most
       << " casing elements";
  FailureAdvice advice;
  if (runs_at_once > 1) advice.remedies.push_back(Remedy::fewer_jobs);
  advice.remedies.push_back(Remedy::full_method_no_dense_casing);
  throw CaseError(what.str(), advice);
}

} // namespace rsi
