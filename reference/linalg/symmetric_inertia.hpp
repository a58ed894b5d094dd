#pragma once
// The inertia of a real symmetric matrix A: how many of its eigenvalues are
// negative, zero and positive (Sylvester's law of inertia: A = L D L^T has
// the inertia of D for any nonsingular L).
//
// Used as a Sturm count: for K - tau M of a definite pencil (K, M) (M
// symmetric positive semi-definite, K - sigma M positive definite for some
// sigma), the number of negative eigenvalues of K - tau M is the number of
// eigenvalues of K phi = lambda M phi below tau (simultaneously diagonalize
// X^T K X = diag(k_i), X^T M X = diag(m_i): k_i - tau m_i < 0 iff
// m_i > 0 and k_i / m_i < tau; a massless direction m_i = 0 has k_i > 0).
//
// Sparse: UMFPACK's multifrontal LU (BLAS-3 fronts) of the whole matrix,
// symmetric strategy, METIS order, no scaling; when every pivot it took is
// a diagonal entry (its row order equal to its column order), that is the
// LU of a symmetric matrix without pivoting, U = D L^T, and the signs of
// diag(U) are the inertia; its diagonal threshold is 0 (any nonzero
// diagonal entry is a pivot, as in an L D L^T without pivoting). When it
// pivoted off the diagonal all the same (a zero diagonal entry met, with
// nonzeros left in its column), or failed (out of memory: its LU holds L and
// U, int-indexed), CHOLMOD's simplicial L D L^T (its own fill-reducing
// order, no pivoting), D read from the factor.
// CHOLMOD has no supernodal L D L^T: on Rotor 37's K (61,098 dofs, 28 GFlop)
// its simplicial one took 23-33 s against 1.5-1.9 s for the supernodal
// L L^T (bench/RESULTS.md), the Sturm count most of a lowest_modes call.
// Without pivoting an indefinite matrix may grow its factor, but the count
// stays right unless an eigenvalue of A lies within the factorization's
// backward error of zero; the caller keeps tau clear of the eigenvalues it
// knows. A pivot exactly zero (or NaN) makes no count (`factorized` false):
// tau sits on an eigenvalue to working precision. Dense: LAPACKE_dsytrf
// (Bunch-Kaufman, diagonal pivoting with 1x1 and 2x2 blocks, backward
// stable), the inertia of each block of D.
//
// Out of memory (CHOLMOD's status, LAPACKE's workspace) throws std::bad_alloc.

#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

struct Inertia {
  int negative = 0;
  int zero = 0;
  int positive = 0;
  bool factorized = false; ///< a count was made
  std::string why;         ///< when not
  std::string method;      ///< the factorization that counted (or failed to)
};

/// Inertia of the symmetric `a` from its lower triangle (compressed column
/// storage, the upper triangle ignored): UMFPACK, or CHOLMOD's simplicial
/// L D L^T when UMFPACK pivoted off the diagonal.
Inertia sparse_inertia(const Eigen::SparseMatrix<double>& lower);

/// The same by CHOLMOD's simplicial L D L^T alone (the other count of tests).
Inertia simplicial_inertia(const Eigen::SparseMatrix<double>& lower);

/// Inertia of the symmetric dense `a` (its lower triangle is read).
Inertia dense_inertia(const Eigen::Ref<const Eigen::MatrixXd>& a);

} // namespace rsi
