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

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

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

/// Rotation at `omega` [rad/s] about the axis through `point` along
/// `axis` (unit), the centrifugal body load of every element with a
/// section (CalculixDeck::section_elsets).
struct CentrifugalLoad {
  double omega = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
};

/// Prefix of JOB.sti, JOB.mas, JOB.dof and JOB.dat of the model of `deck`
/// prestressed by `load` (SPEC §9): a `*STEP, NLGEOM` `*STATIC` step under
/// `*DLOAD ... CENTRIF, omega^2, point, axis` printing every node's static
/// displacement into JOB.dat (*NODE PRINT, U), then a `*STEP, PERTURBATION`
/// `*FREQUENCY, SOLVER=MATRIXSTORAGE` storing the tangent stiffness there
/// (stress stiffening, spin softening, the deformed geometry) and the mass.
/// Cached as calculix_matrices is; throws ImportError as it does, and for a
/// deck without a section (nothing carries the load).
std::string calculix_prestressed_matrices(const CalculixDeck& deck, const CentrifugalLoad& load,
                                          const std::string& cache_dir,
                                          const std::string& cache_name = "the ccx cache");

/// The `count` lowest eigenvalues omega^2 of the model of `deck`
/// prestressed by `load`, from ccx's own eigensolver in the perturbation
/// step (its frequencies at that speed, an outside check of K(Omega)).
std::vector<double> calculix_prestressed_eigenvalues(const CalculixDeck& deck,
                                                     const CentrifugalLoad& load, int count,
                                                     const std::string& cache_dir);

/// Node id -> displacement (u_x, u_y, u_z) of the first displacement table
/// (*NODE PRINT, U) of a ccx .dat file (7 significant digits).
std::map<int, Eigen::Vector3d> read_calculix_displacements(const std::string& dat_path);

/// The EIGENVALUE column of the first EIGENVALUE OUTPUT table of a ccx .dat file.
std::vector<double> read_calculix_eigenvalues(const std::string& dat_path);

} // namespace rsi
