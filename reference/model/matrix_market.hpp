#pragma once
// A component from a folder in the layout `rsi export` writes: K.mtx and
// M.mtx (Matrix Market coordinate real, symmetric or general), dofs.csv
// (index,node,kind,boundary) and nodes.csv (node,x,y,z). Export then import
// round-trips exactly: values are written with 17 significant digits and
// read back by std::from_chars, the nearest double.
//
// Throws ImportError naming file and line for a bad header or size line, a
// truncated file (fewer entries than its size line says), a non-numeric
// line, an index beyond the size, NaN/Inf, a dof count different from the
// matrix size (checked on the size line, before the matrix is allocated), a
// `general` file that is not symmetric (an entry whose mirror is missing
// counts as paired with 0), a dof whose node has no coordinates;
// check_component then checks symmetry and the mass diagonal.

#include <string>

#include "component.hpp"

namespace rsi {

/// A Matrix Market coordinate real matrix (symmetric: the lower triangle
/// given; general: both triangles, every entry's mirror given or zero and
/// the pairs equal within 1e-12 of the largest entry) as a symmetric n x n
/// matrix, both triangles stored. `positive_diagonal` (a mass matrix):
/// every diagonal entry given and positive, else ImportError naming the
/// line. `expected_rows` >= 0: the size line must declare that many rows
/// (checked, with the entry count against the lines the file holds, before
/// anything is sized by them); -1: any size.
Eigen::SparseMatrix<double> read_symmetric_matrix_market(const std::string& path,
                                                         bool positive_diagonal,
                                                         long expected_rows = -1);

/// The component in `folder`; the boundary is the dofs flagged in dofs.csv
/// unless `boundary_nodes` is given (every dof of each node).
Component read_matrix_market_component(const std::string& folder, const std::string& name,
                                       const std::vector<int>* boundary_nodes);

} // namespace rsi
