#pragma once
// Calibration of the blade thickness (SPEC §2): the lowest family of
// n_blades frequencies (first blade bending) must centre on a target,
// 44 Hz in the paper (Fig. 3).

#include "case_file.hpp"

namespace rsi {

/// Mean of the lowest n_blades natural frequencies of the bladed disk [Hz].
double first_family_mean_hz(const Case& c);

/// The blade thickness [m] for which first_family_mean_hz equals target_hz,
/// by GSL's Brent solver on [low, high]; the other fields of `c` are kept.
/// Throws std::invalid_argument if the target is not bracketed.
double calibrate_blade_thickness(const Case& c, double target_hz, double low, double high);

} // namespace rsi
