#include "residual_solve.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rsi {

namespace {

/// [A | L] (n x 2n): row i holds A's row i, then L's row i shifted by n.
RowMajorMatrix side_by_side(const RowMajorMatrix& a, const RowMajorMatrix& l) {
  const Eigen::Index n = a.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(a.nonZeros() + l.nonZeros()));
  for (Eigen::Index i = 0; i < n; ++i) {
    for (RowMajorMatrix::InnerIterator it(a, i); it; ++it)
      entries.emplace_back(static_cast<int>(i), static_cast<int>(it.col()), it.value());
    for (RowMajorMatrix::InnerIterator it(l, i); it; ++it)
      entries.emplace_back(static_cast<int>(i), static_cast<int>(n + it.col()), it.value());
  }
  RowMajorMatrix both(n, 2 * n);
  both.setFromTriplets(entries.begin(), entries.end());
  both.makeCompressed();
  return both;
}

} // namespace

ResidualSolve::ResidualSolve(const MassFactor& factor, const RowMajorMatrix& a)
    : m_factor(factor)
    , m_nonzeros_a(a.nonZeros())
    , m_stack(Eigen::VectorXd::Zero(2 * factor.n_dofs())) {
  const Eigen::Index n = factor.n_dofs();
  if (a.rows() != n || a.cols() != n)
    throw std::invalid_argument("ResidualSolve: A must be square, of the mass factor's size");
  const RowMajorMatrix both = side_by_side(a, factor.strictly_lower_l());
  // Level by level upward (a row reads only lower levels of y); within a
  // level, shortest first (longer runs of one length).
  const std::vector<int>& level = factor.levels();
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
    return std::make_pair(level[i], both.row(i).nonZeros()) <
           std::make_pair(level[j], both.row(j).nonZeros());
  });
  m_rows = SparseRows(both, order, level);
}

Eigen::Ref<const Eigen::VectorXd> ResidualSolve::apply(const Eigen::Ref<const Eigen::VectorXd>& f,
                                                       const Eigen::Ref<const Eigen::VectorXd>& u) {
  const Eigen::Index n = m_factor.n_dofs();
  if (f.size() != n || u.size() != n)
    throw std::invalid_argument("ResidualSolve: f and u must have one entry per dof");
  m_stack.head(n) = u;
  // L y = f - A u: y_i = f_i - (A_i u + L_i y), y stored after u.
  double* y = m_stack.data() + n;
  const double* fs = f.data();
  m_rows.for_each_row(m_stack.data(), [y, fs](int i, double sum) { y[i] = fs[i] - sum; });
  m_factor.solve_upper_in_place(m_stack.tail(n));
  return m_stack.tail(n);
}

} // namespace rsi
