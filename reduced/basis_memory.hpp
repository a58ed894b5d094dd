#pragma once
// Whether a reduced basis of the bladed disk fits in this process's memory,
// checked before it is built (issue 13, class 1: counts derived from the
// input checked against what the machine can hold).
//
// T is dense, n x r doubles (r = boundary dofs + kept modes), and a reduced
// run holds it twice at least: the basis it integrates with and the copy it
// hands back (reduced_run.hpp), 16 n r bytes, before counting the modes T
// is assembled from. That lower bound is what is checked, so a refused
// basis could not have been built: 1000 blades of 1000 elements (3.0e6
// dofs, 2000 boundary dofs) need 96 GB at 0 modes.

#include <string>

#include "failure_kinds.hpp"

namespace rsi {

/// 16 n r: T (n x r) and its copy.
double dense_basis_bytes(int n_dofs, int n_reduced);

/// Throws CaseError, shown after `where` (the case file and the input the
/// mode count came from), with the bytes and the most modes that fit, when
/// `runs_at_once` bases of `n_boundary + modes` columns over `n_dofs` dofs
/// exceed process_memory_limit_bytes() (casing_memory.hpp).
void check_dense_basis_fits(const FailureAdvice& where, int n_dofs, int n_boundary, int modes,
                            int runs_at_once);

} // namespace rsi
