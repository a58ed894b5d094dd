#pragma once
// The paper's two parts as components (SPEC §2, §8): the bladed disk
// (boundary: the 44 tip u, v dofs; cyclic layout of its 22 sectors; node
// coordinates in the fixed frame at t = 0) and the casing ring (no
// boundary: contact may touch it anywhere). SI units, rotation axis z.

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "component.hpp"

namespace rsi {

Component bladed_disk_component(const BladedDisk& bladed_disk);
Component casing_component(const Casing& casing);

} // namespace rsi
