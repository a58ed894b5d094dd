#pragma once
// The dominant frequencies of a sampled response (issue 15): the amplitude
// spectrum of the signal with its mean removed, under a periodic Hann window
// w_i = (1 - cos(2 pi i / n)) / 2, by GSL's mixed-radix real FFT (any n).
//
// The windowed signal is zero-padded to 8 n samples before the transform:
// the padded spectrum samples the same continuous transform 8 times more
// finely, so an isolated peak is located to 1 / (16 n dt) instead of half a
// bin 1 / (2 n dt) (two peaks closer than the Hann main lobe's half-width,
// 2 / (n dt), are still not told apart: padding interpolates, it does not
// resolve). Amplitude of padded bin m: A_m = 2 |X_m| / sum_i w_i, so that a
// sinusoid a cos(2 pi f t + phi) with f on a padded bin reads A = a (its
// windowed transform peaks at a sum(w) / 2, leakage from its image at -f
// aside: at f on an unpadded bin k it is zero, the periodic Hann window's
// transform vanishing at every other unpadded bin). Off a padded bin the
// amplitude drops by the Hann main lobe over at most 1/16 bin: below 0.6 %.
// The peaks are the local maxima of A_m strictly inside (0, Nyquist),
// largest first; their frequency is f_m = m / (8 n dt).

#include <vector>

namespace rsi {

struct SpectralPeak {
  double frequency_hz = 0.0; ///< f_m = m / (8 n dt)
  double amplitude = 0.0;    ///< A_m, in the signal's unit
};

/// The `count` largest spectral peaks of x (uniform samples dt [s] apart),
/// fewer if the spectrum has fewer local maxima. Throws
/// std::invalid_argument for fewer than 4 samples, dt <= 0, count < 0, or a
/// non-finite sample.
std::vector<SpectralPeak> dominant_frequencies(const std::vector<double>& x, double dt,
                                               int count);

/// Samples per input sample of the padded transform.
inline constexpr int spectrum_padding = 8;

/// A_m for m = 0 .. N/2, N = padding n (the amplitude spectrum the peaks are
/// taken from; padding 1: the plain DFT's bins).
std::vector<double> hann_amplitude_spectrum(const std::vector<double>& x,
                                            int padding = spectrum_padding);

} // namespace rsi
