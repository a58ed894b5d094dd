#pragma once
// The wear profile's summary numbers (summary.json): the deepest cell and
// the lobe count.
//
// Lobes. Around one axial row (n_theta cells, a ring: cell n_theta - 1 is
// next to cell 0) a lobe is a peak of the depth whose prominence is at least
// kLobeProminence times the deepest cell of the whole liner. A peak's
// prominence is how far one descends from it, either way around the ring,
// before climbing to a cell ranked above it (deeper, or as deep and earlier
// in cell order, which decides between equal depths): its depth less the
// higher of the two lowest depths met on the two ways. The ring's top peak,
// ranked below no cell, has the ring's range as its prominence (its depth
// less the shallowest cell's). A flat top is one peak; a flat ring has none.
// This is the peaks' 0-dimensional persistence in the depth (Edelsbrunner
// and Harer, Computational Topology, VII.1): what a user reads as lobes is
// what stands out of the profile, not every local maximum. The threshold is
// far above round-off, so that wear differing at the last bits counts the
// same lobes: the patches' staircase has plateaus one unit in the last place
// apart, which a rule of exactly equal runs counted as separate lobes
// (session 38). The liner's count is the largest over its rows (one row: the
// usual case of a tip over one band).
//
// Ranges: depths finite and >= 0; n_theta >= 1; the vector holds
// n_theta * n_axial cells in the liner's order (cell = j n_theta + i).

#include <vector>

namespace rsi {

/// The least prominence of a lobe, as a fraction of the liner's deepest cell.
inline constexpr double kLobeProminence = 0.1;

/// The lobes of one ring (header): peaks of prominence at least
/// kLobeProminence * deepest, and above 0.
int ring_lobes(const std::vector<double>& ring, double deepest);
/// max over the rows of ring_lobes, the deepest being that of all cells.
int wear_lobes(const std::vector<double>& depth, int n_theta, int n_axial);

} // namespace rsi
