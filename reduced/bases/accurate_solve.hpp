#pragma once
// Linear solves to the last bit: iterative refinement with residuals in twice
// working precision (Wilkinson 1963; Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed., §12.1). Each step x <- x + A^-1 r uses the
// working-precision factor of A for the correction and a residual
// r = b - A x summed with error-free transformations (TwoSum, and TwoProduct
// through fma: Ogita, Rump, Oishi 2005, "Dot2"), so r is accurate even when
// it is a tiny difference of large terms. While cond(A) eps < 1 the iteration
// contracts, and it stops at the solution rounded to working precision: the
// result no longer depends on the factorization's round-off.
//
// Why the reductions need it: CB(0), CCM(0) and Guyan are the same basis
// (SPEC V4), but computed through K_II^-1 (constraint modes) or K^-1 and
// R_B^-1 (attachment modes) they differ by a few 1e-14, and a contact
// history amplifies such differences a million-fold (a 5e-15 change of T
// moves the blade-1 gap by 5e-9 of its maximum). Rounded to the last bit,
// both come out the same.

#include <functional>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

/// A matrix known to about twice working precision: value + low, with
/// |low| below the last bit of |value|.
struct AccurateMatrix {
  Eigen::MatrixXd value;
  Eigen::MatrixXd low; ///< empty: exactly `value`
};

/// b + b_low - (a + a_low) x, summed in twice working precision and rounded
/// once. a_low and b_low may be empty (zero); a_low is applied in working
/// precision (it is below the last bit of a).
Eigen::MatrixXd compensated_residual(const Eigen::SparseMatrix<double>& a,
                                     const Eigen::MatrixXd& a_low, const AccurateMatrix& b,
                                     const Eigen::MatrixXd& x);

/// Applies A^-1 in working precision (a factorization of A).
using WorkingSolve = std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>;

/// X with (a + a_low) X = b + b_low: starting from solve(b), refined until a
/// step changes no entry. `value` is X rounded to working precision, `low`
/// the last correction (below its last bit). Throws std::runtime_error naming
/// `name` if ten steps do not get there (cond(A) eps too close to 1).
AccurateMatrix accurate_solve(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& a_low,
                              const AccurateMatrix& b, const WorkingSolve& solve,
                              const std::string& name);

} // namespace rsi
