#include "reduction.hpp"

#include "craig_bampton.hpp"
#include "craig_chang_martinez.hpp"
#include "guyan.hpp"
#include "macneal.hpp"

namespace rsi {

ReducedBasis reduce_bladed_disk(const BladedDisk& bd, const std::string& method, int modes) {
  const Partition p = make_partition(bd.n_dofs(), bd.boundary);
  if (method == "cb") return craig_bampton(bd.stiffness, bd.mass, p, modes);
  if (method == "ccm") return craig_chang_martinez(bd.stiffness, bd.mass, p, modes);
  if (method == "macneal") return macneal(bd.stiffness, bd.mass, p, modes);
  if (method == "guyan") {
    if (modes != 0)
      throw ReductionError("--modes: Guyan reduction keeps no modes (0), got " +
                           std::to_string(modes));
    return guyan(bd.stiffness, bd.mass, p);
  }
  throw ReductionError("--method: must be full, cb, ccm, guyan or macneal, got '" + method + "'");
}

} // namespace rsi
