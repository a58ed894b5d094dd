#include "reduction.hpp"

#include "craig_bampton.hpp"
#include "craig_chang_martinez.hpp"
#include "guyan.hpp"
#include "macneal.hpp"

namespace rsi {

ReducedBasis reduce(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, const std::vector<int>& boundary,
                    const std::string& method, int modes) {
  const Partition p = make_partition(static_cast<int>(stiffness.rows()), boundary);
  if (method == "cb") return craig_bampton(stiffness, mass, p, modes);
  if (method == "ccm") return craig_chang_martinez(stiffness, mass, p, modes);
  if (method == "macneal") return macneal(stiffness, mass, p, modes);
  if (method == "guyan") {
    if (modes != 0)
      throw ReductionError("--modes: Guyan reduction keeps no modes (0), got " +
                           std::to_string(modes));
    return guyan(stiffness, mass, p);
  }
  throw ReductionError("--method: must be full, cb, ccm, guyan or macneal, got '" + method + "'");
}

ReducedBasis reduce_bladed_disk(const BladedDisk& bd, const std::string& method, int modes) {
  return reduce(bd.stiffness, bd.mass, bd.boundary, method, modes);
}

} // namespace rsi
