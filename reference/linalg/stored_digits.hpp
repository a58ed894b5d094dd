#pragma once
// How many significant decimal digits the entries of a matrix carry: the
// precision of the input, for the precision statement of the frequencies
// computed from it (solver/modal_check).
//
// A matrix read from text written with d significant digits (CalculiX 2.20
// writes its .sti/.mas as %.13e, 14 digits) has entries that each read back
// unchanged from at most d digits; one assembled or computed in double
// precision needs up to 17 (the shortest representation that reads back to
// the same double, std::to_chars). So the most digits any stored entry
// needs is the number of digits the matrix carries, and its entries are
// rounded to 0.5 10^(1-d) relative. A matrix computed from rounded text
// (scaled, lumped) shows 17 digits though it carries fewer: the caller
// takes the fewest digits of the matrices it is given (K and M of a model).

#include <Eigen/SparseCore>

namespace rsi {

/// The most significant digits (1 to 17) any nonzero stored entry of `a`
/// needs to read back unchanged; 17 for a matrix without nonzero entries.
int stored_digits(const Eigen::SparseMatrix<double>& a);

/// The relative rounding of entries written with `digits` significant
/// digits, 0.5 10^(1 - digits), and not below the unit roundoff 2^-53 of a
/// double (17 digits carry no more than the double they were written from).
double digits_rounding(int digits);

} // namespace rsi
