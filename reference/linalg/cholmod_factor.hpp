#pragma once
// A sparse symmetric positive definite matrix A = P^T L L^T P, factorized by
// CHOLMOD (SuiteSparse 5): the fill-reducing analysis of the pattern once
// (CHOLMOD's default: AMD, then METIS if AMD's fill is large), then any
// number of numeric factorizations of matrices with that pattern, and solves
// with one or many right-hand sides.
//
// Supernodal (the default) or simplicial; both end as L L^T (final_ll), so
// that the half solves L^-1 P b and P^T L^-T b exist for Spectra's Cholesky
// mode. The supernodal factorization and the solves with many right-hand
// sides run on the BLAS (dpotrf, dtrsm, dgemm); on the Rotor 37 stiffness
// (61,098 dofs, 7.1 M nonzeros, 31.5 M in L) supernodal took 2.2 s, simplicial
// 23.5 s (bench/RESULTS.md).
//
// Failure is a status, never ignored: factorize() returns it, message()
// says why (a pivot <= 0 at a column: A not positive definite to working
// precision; another CHOLMOD failure), and solve() returns false if the
// factor is missing or cholmod_solve2 fails. Out of memory is no status of
// the matrix: CHOLMOD's CHOLMOD_OUT_OF_MEMORY throws std::bad_alloc, as
// operator new would. CHOLMOD's own printing of warnings is
// switched off (print level 1: errors only), the status carries them.
//
// Owns its cholmod_common, factor and solve workspace; not copyable; one
// object is not for concurrent use (the workspace is shared by the solves).

#include <memory>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

class CholmodFactor {
public:
  enum class Method { supernodal, simplicial };
  enum class Status { empty, successful, not_positive_definite, failed };
  /// Which solve: x = A^-1 b, x = L^-1 P b, or x = P^T L^-T b.
  enum class System { a, l_p, pt_lt };

  explicit CholmodFactor(Method method = Method::supernodal);
  ~CholmodFactor();
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  /// Factorizes A from its lower triangle (compressed column storage).
  /// The first call analyzes the pattern; later calls must pass the same
  /// pattern (same size and number of stored entries, else
  /// std::invalid_argument) and reuse that analysis.
  Status factorize(const Eigen::SparseMatrix<double>& lower);

  Status info() const { return m_status; }
  /// Why the last factorize() failed (empty if it did not).
  const std::string& message() const { return m_message; }
  Eigen::Index rows() const { return m_n; }
  Method method() const { return m_method; }

  /// x = the solution of `system` for every column of b (n x k, k >= 1).
  /// False if there is no successful factor or CHOLMOD fails.
  [[nodiscard]] bool solve(System system, const Eigen::Ref<const Eigen::MatrixXd>& b,
                           Eigen::Ref<Eigen::MatrixXd> x) const;

  /// Entries of L and flops of one factorization (CHOLMOD's analysis counts).
  double nonzeros_l() const { return m_nonzeros_l; }
  double factorization_flops() const { return m_flops; }
  /// CHOLMOD's reciprocal condition estimate (min L_jj / max L_jj)^2; 0 without a factor.
  double rcond() const;

private:
  struct Cholmod; ///< cholmod_common, factor and workspace (cholmod.h stays in the .cpp)
  std::unique_ptr<Cholmod> m_cholmod;
  Method m_method;
  Status m_status = Status::empty;
  std::string m_message;
  Eigen::Index m_n = 0;
  Eigen::Index m_pattern_nonzeros = 0;
  double m_nonzeros_l = 0.0;
  double m_flops = 0.0;
};

} // namespace rsi
