#pragma once
// Whether a reduced run's dense casing matrix fits in this process's memory,
// checked before the basis and the eigensolvers (issue 13, class 1: counts
// derived from the input checked against what the machine can hold).
//
// The reduced integrator keeps the casing's inverse mass M_c^-1 dense
// (reduced_integrator.hpp: its columns are the casing's response to a tip
// force at any node), 8 n_c^2 bytes for n_c casing dofs: 131 MB at 1000
// casing elements, 12.8 GB at 10,000 (the most the definiteness check
// accepts with the default section). Its other dense matrices follow the
// basis (n_q <= 700 coordinates: under 4 MB each). A campaign holds one such
// matrix per run in progress.

#include <cstdint>

#include "case_file.hpp"

namespace rsi {

/// The bytes this process may use: the least of the physical memory
/// (sysconf), RLIMIT_AS (ulimit -v) and RLIMIT_DATA (ulimit -d).
double process_memory_limit_bytes();

/// 8 n_c^2: M_c^-1 of a casing of `n_casing_dofs` dofs.
double dense_casing_bytes(int n_casing_dofs);

/// Throws CaseError (exit 2) naming 'casing.n_elements' of `c`, the bytes
/// and the largest count that fits, if `runs_at_once` reduced runs' M_c^-1
/// exceed process_memory_limit_bytes().
void check_dense_casing_fits(const Case& c, int n_casing_dofs, int runs_at_once);

} // namespace rsi
