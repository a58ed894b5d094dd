#pragma once
// The wear profile's summary numbers (summary.json): the deepest cell and
// the lobe count.
//
// Lobes. Around one axial row (n_theta cells, a ring: cell n_theta - 1 is
// next to cell 0) a lobe is a maximal run of consecutive cells of equal
// depth that is deeper than the cells on both sides of the run and deeper
// than half of `threshold_of` (the deepest cell of the whole liner): a flat
// top counts once, a shallow ripple below half the maximum not at all. A
// row whose cells are all equal has 1 lobe if that depth is above the half,
// else 0. The liner's count is the largest over its rows (one row: the
// usual case of a tip over one band).
//
// Ranges: depths finite and >= 0; n_theta >= 1; the vector holds
// n_theta * n_axial cells in the liner's order (cell = j n_theta + i).

#include <vector>

namespace rsi {

/// The lobes of one ring (header), with threshold half of `deepest`.
int ring_lobes(const std::vector<double>& ring, double deepest);
/// max over the rows of ring_lobes, the deepest being that of all cells.
int wear_lobes(const std::vector<double>& depth, int n_theta, int n_axial);

} // namespace rsi
