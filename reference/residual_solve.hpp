#pragma once
// a = M'^-1 (f - A u) in one pass over the rows of A and L: the
// acceleration of the central-difference predictor (SPEC §3),
// u~ = 2 u_n - u_{n-1} + dt^2 M^-1 (F_n - K u_n), with A = K'.
//
// With M' = L D L^T (reference/mass_factor), the forward solve L y = f - A u
// reads, row by row, y_i = f_i - (A_i u + L_i y). Each row of A is stored
// with the row of L of the same index as one sparse row over the stacked
// vector [u; y], so one row sum covers both: the product A u costs no pass
// of its own, and the short rows of L (4 entries on average on the default
// case) share the work per row with A's (9.4). The rows are taken in the
// factor's levels, then D^-1 and L^-T are applied by the factor. The gain
// is modest: bench_mass_solve (predictor/*) measured 13.7 us against 14.5
// us for the product followed by the solve.
//
// The result equals MassFactor::solve_in_place(f - A u) up to the order of
// the sums: every row sum of A u and of the forward solve is added in
// another order (bounds in reference/sparse_rows.hpp).

#include <Eigen/Core>

#include "mass_factor.hpp"
#include "sparse_rows.hpp"

namespace rsi {

class ResidualSolve {
public:
  /// `factor` must outlive this object (not owned); A square, of the
  /// factor's size, in its permuted coordinates (std::invalid_argument
  /// otherwise).
  ResidualSolve(const MassFactor& factor, const RowMajorMatrix& a);

  /// M'^-1 (f - A u) for f and u of n entries, held until the next call.
  Eigen::Ref<const Eigen::VectorXd> apply(const Eigen::Ref<const Eigen::VectorXd>& f,
                                          const Eigen::Ref<const Eigen::VectorXd>& u);
  /// Nonzeros of A (a product costs 2 flops each).
  Eigen::Index nonzeros_a() const { return m_nonzeros_a; }

private:
  const MassFactor& m_factor;
  Eigen::Index m_nonzeros_a = 0;
  SparseRows m_rows;       ///< [A_i | L_i] over [u; y], in the factor's levels
  Eigen::VectorXd m_stack; ///< [u; y]
};

} // namespace rsi
