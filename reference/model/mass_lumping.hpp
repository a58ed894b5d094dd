#pragma once
// A diagonal mass for explicit full-order runs of models whose consistent
// mass is singular (CalculiX's C3D15 wedges of Rotor 37: about 100 null
// directions, from the element's reduced integration): the row-sum lumping
// of quadratic elements gives negative masses at corner nodes (13,668 of
// Rotor 37's 61,098 rows sum to <= 0), so the lumping is HRZ's (Hinton,
// Rock, Zienkiewicz, Earthq. Eng. Struct. Dyn. 4 (1976) 245): the diagonal
// of the consistent mass, scaled so that the translational mass of each
// direction is kept. rsi applies the scaling to the assembled matrix, one
// factor per direction kind d (ux, uy, uz, and each rotation kind):
//   (M_l)_ii = s_d M_ii,  s_d = e_d^T M e_d / sum_{i of kind d} M_ii,
// e_d the indicator of the dofs of kind d (the rigid translation along d of
// every dof the model keeps). For a mesh of one element type and uniform
// elements this is element-wise HRZ; otherwise it keeps the total, not each
// element's share. Every diagonal entry is positive (check_component), so
// M_l is positive definite and its inverse costs n divisions a step.

#include "component.hpp"

namespace rsi {

/// M_l of the header, both triangles of a diagonal matrix. Throws
/// ImportError if a direction's total e_d^T M e_d is not positive.
Eigen::SparseMatrix<double> hrz_lumped_mass(const Component& component);

} // namespace rsi
