#pragma once
// Nodal diameters of the modes of 3D components (issue 27 item 6, the
// nodal-diameter map of the paper's Fig. 3).
//
// A bladed disk of N identical sectors about its axis: every node x has its
// images R(k alpha) x, alpha = 2 pi / N, in the other sectors. Grouped by
// their place in one sector (each node turned back into the sector at polar
// angle 0 by the nearest multiple of alpha, keyed by that position to 1e-6
// of the model's size), a mode's displacements turned back the same way are
// N identical blocks, block k in its own sector's frame: nodal_diameter.hpp
// reads the nodal diameter from the discrete Fourier transform over k.
// Nodes whose images fall on both sides of a bin's edge (those on the
// bisectors between sectors, where a sector's faces may lie) give groups of
// fewer than N and are left out; the rest (the sectors' insides) decide.
//
// A ring with no such symmetry (the flexible casing): the lobes of a mode
// are the circumferential harmonic h of its radial displacement u_r over
// the nodes, the h in [0, h_max] with the largest |sum_i u_r,i e^(-i h
// theta_i)| (the nodes all but evenly spread around the ring: the sum is
// the Fourier coefficient up to the spread's own, small, harmonics).

#include <array>
#include <vector>

#include <Eigen/Core>

#include "component.hpp"

namespace rsi {

struct CyclicImages {
  int sectors = 0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  /// places[p][k]: the ux, uy, uz dofs of the image in sector k of place p.
  std::vector<std::vector<std::array<int, 3>>> places;
};

/// The places of an N-fold cyclic component about its rotation axis. Throws
/// std::invalid_argument for N < 2, ImportError if no place has N images
/// (the component is not N-fold cyclic).
CyclicImages cyclic_images(const Component& c, int sectors);

/// The mode's N blocks (3 x places each, sector k's in its own frame), for
/// nodal_diameter(blocks, N, 3 x places).
Eigen::VectorXd sector_blocks(const CyclicImages& images,
                              const Eigen::Ref<const Eigen::VectorXd>& mode);

/// The nodal diameter in [0, N/2] of a mode of a cyclic component.
int cyclic_nodal_diameter(const CyclicImages& images,
                          const Eigen::Ref<const Eigen::VectorXd>& mode);

/// The lobes in [0, h_max] of a mode of a ring about c's rotation axis.
int circumferential_harmonic(const Component& c, const Eigen::Ref<const Eigen::VectorXd>& mode,
                             int h_max);

} // namespace rsi
