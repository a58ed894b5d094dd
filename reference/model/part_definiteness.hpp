#pragma once
// The assembled parts of the paper's case checked as a whole: K and M
// positive definite to working precision (issue 13, class 7; the criterion
// and why it is the right one: linalg/energy_resolution.hpp). Every
// section, length and material of the case file is in range key by key,
// yet a blade 1e-8 m thick bends with an energy below the rounding of its
// axial terms: the dense modal solver then printed negative frequencies,
// and every path that factorizes K or integrates it worked on rounding.
// Such a case is refused here, where every command builds the parts,
// with CaseError (exit status 2) naming the keys of the part whose motion
// is not resolved and the numbers: the energy's condition number against
// the 1/gamma_p double precision resolves.

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "casing.hpp"

namespace rsi {

/// The clamped bladed disk of `c`: K and M positive definite to working
/// precision, else CaseError.
void check_bladed_disk_definite(const BladedDisk& bladed_disk, const Case& c);

/// The clamped casing of `c`: the same.
void check_casing_definite(const Casing& casing, const Case& c);

} // namespace rsi
