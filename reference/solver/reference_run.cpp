#include "reference_run.hpp"

#include "full_order_run.hpp"
#include "problem.hpp"

namespace rsi {

RunResult run_reference(const Case& c, const RunOptions& options) {
  return run_full_order(paper_problem(c), options);
}

} // namespace rsi
