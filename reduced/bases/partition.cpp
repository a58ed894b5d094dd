#include "partition.hpp"

#include <stdexcept>
#include <string>

namespace rsi {

Partition make_partition(int n_dofs, const std::vector<int>& boundary) {
  std::vector<int> position(n_dofs, -1);
  for (size_t b = 0; b < boundary.size(); ++b) {
    const int dof = boundary[b];
    if (dof < 0 || dof >= n_dofs)
      throw std::invalid_argument("make_partition: boundary dof " + std::to_string(dof) +
                                  " outside [0, " + std::to_string(n_dofs) + ")");
    if (position[dof] >= 0)
      throw std::invalid_argument("make_partition: boundary dof " + std::to_string(dof) +
                                  " given twice");
    position[dof] = static_cast<int>(b);
  }
  Partition p;
  p.boundary = boundary;
  for (int i = 0; i < n_dofs; ++i)
    if (position[i] < 0) p.interior.push_back(i);
  return p;
}

Eigen::SparseMatrix<double> sparse_block(const Eigen::SparseMatrix<double>& a,
                                         const std::vector<int>& rows,
                                         const std::vector<int>& cols) {
  std::vector<int> row_position(a.rows(), -1);
  for (size_t i = 0; i < rows.size(); ++i)
    row_position[rows[i]] = static_cast<int>(i);
  std::vector<Eigen::Triplet<double>> t;
  for (size_t j = 0; j < cols.size(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, cols[j]); it; ++it)
      if (row_position[it.row()] >= 0)
        t.emplace_back(row_position[it.row()], static_cast<int>(j), it.value());
  Eigen::SparseMatrix<double> block(static_cast<int>(rows.size()), static_cast<int>(cols.size()));
  block.setFromTriplets(t.begin(), t.end());
  return block;
}

Eigen::MatrixXd place_rows(int n, const std::vector<int>& rows,
                           const Eigen::Ref<const Eigen::MatrixXd>& block) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, block.cols());
  for (size_t i = 0; i < rows.size(); ++i)
    out.row(rows[i]) = block.row(static_cast<Eigen::Index>(i));
  return out;
}

Eigen::MatrixXd take_rows(const Eigen::Ref<const Eigen::MatrixXd>& a,
                          const std::vector<int>& rows) {
  Eigen::MatrixXd out(rows.size(), a.cols());
  for (size_t i = 0; i < rows.size(); ++i)
    out.row(static_cast<Eigen::Index>(i)) = a.row(rows[i]);
  return out;
}

Eigen::MatrixXd take_columns(const Eigen::Ref<const Eigen::MatrixXd>& a,
                             const std::vector<int>& columns) {
  Eigen::MatrixXd out(a.rows(), static_cast<Eigen::Index>(columns.size()));
  for (size_t j = 0; j < columns.size(); ++j)
    out.col(static_cast<Eigen::Index>(j)) = a.col(columns[j]);
  return out;
}

Eigen::VectorXd take_entries(const Eigen::Ref<const Eigen::VectorXd>& a,
                             const std::vector<int>& entries) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(entries.size()));
  for (size_t j = 0; j < entries.size(); ++j)
    out(static_cast<Eigen::Index>(j)) = a(entries[j]);
  return out;
}

} // namespace rsi
