#pragma once
// Running CalculiX (`ccx`, Debian's calculix-ccx 2.20, found on PATH) on the
// model part of a deck, in a cache: an entry CACHE/<deck stem>-<hash>-<step>
// holds the self-contained deck (includes inlined) and what ccx wrote. The
// hash (64-bit FNV-1a) covers the model text and the step, so an edited deck
// or an included mesh runs again; a finished entry is reused. ccx runs in a
// temporary folder renamed into place only when it succeeded, so a failed or
// interrupted run leaves no entry (a signal is forwarded to ccx:
// child_process.hpp). ccx exits 0 when its writes fail (a full disk), so
// the matrices are checked whole before they are cached, and again when a
// cached entry is found (one cut since is run again): JOB.dof lists n dofs,
// JOB.sti and JOB.mas end with the entry "n n value".
// Cut files are refused (ImportError: the disk may be full, nothing cached).

#include <string>
#include <vector>

#include "calculix_deck.hpp"

namespace rsi {

/// Path of `ccx` on PATH; throws ImportError (exit 2) if there is none,
/// saying which Debian package provides it.
std::string find_ccx();

/// Prefix (path without extension) of JOB.sti, JOB.mas and JOB.dof for the
/// model of `deck`, from ccx's `*FREQUENCY, SOLVER=MATRIXSTORAGE` step.
/// Throws ImportError when ccx is missing or fails (its log's error lines);
/// a full disk's message names the folder after `cache_name`.
std::string calculix_matrices(const CalculixDeck& deck, const std::string& cache_dir,
                              const std::string& cache_name = "the ccx cache");

/// The `count` lowest eigenvalues omega^2 [rad^2/time^2] of the model of
/// `deck` from ccx's own eigensolver (`*FREQUENCY` step, `count` modes), read
/// from the EIGENVALUE OUTPUT table of JOB.dat (7 significant digits).
std::vector<double> calculix_eigenvalues(const CalculixDeck& deck, int count,
                                         const std::string& cache_dir);

/// The EIGENVALUE column of the first EIGENVALUE OUTPUT table of a ccx .dat file.
std::vector<double> read_calculix_eigenvalues(const std::string& dat_path);

} // namespace rsi
