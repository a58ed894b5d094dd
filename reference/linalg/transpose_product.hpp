#pragma once
// y = A^T x for a compressed-column sparse A and a dense block x of many
// columns, by gathering: row i of y is the sum over column i of A of
// a_ki x_k, so each output row reads contiguous rows of x (x and y are
// copied to row-major). For a symmetric A in full storage this is A x.
//
// Why not Eigen's A * x: for a column-major A, Eigen scatters each column
// of A into the result once per column of x, so the 9 M nonzeros of Rotor
// 37's stiffness are read 98 times for a 98-column basis (memory-bound:
// 1.1 s for T^T K T); the gather reads them once for all columns. Large
// products are split in two ranges of rows of equal nonzeros, one thread
// each (each row is summed by one thread, so the result does not depend on
// the split).
//
// Round-off: y(i, c) = sum over the stored entries of column i, in their
// stored (ascending row) order, of a_ki x(k, c), added from zero. Eigen's
// column-major A x adds a_ik x(k, c) into y(i, c) in ascending k from zero
// too, so for a symmetric A (a_ki == a_ik to the bit) both give the same
// bits.

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace rsi {

/// A^T x (A: n x m compressed columns, x: n x c); throws
/// std::invalid_argument if the sizes do not match.
Eigen::MatrixXd transpose_product(const Eigen::SparseMatrix<double>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& x);

} // namespace rsi
