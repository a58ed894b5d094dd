#pragma once
// The dominant frequencies of a sampled response (issue 15): the amplitude
// spectrum of the signal with its mean removed, under a periodic Hann window
// w_i = (1 - cos(2 pi i / n)) / 2, by GSL's mixed-radix real FFT (any n).
//
// Amplitude of bin k: A_k = 2 |X_k| / sum_i w_i, so that a sinusoid
// a cos(2 pi f_k t + phi) centred on bin k (f_k = k / (n dt)) reads A_k = a:
// the periodic Hann window's transform is nonzero on bins k-1, k, k+1 only
// (weights -1/4, 1/2, -1/4 of n), X_k = a n / 4 and sum w = n / 2. Off a bin
// centre the peak sits on the nearest bin (frequency error <= 1 / (2 n dt))
// and its amplitude drops by at most the Hann scalloping loss, 1.42 dB.
// The peaks are the local maxima of A_k over 1 <= k < n/2 (the mean and
// the Nyquist bin excluded), largest first.

#include <vector>

namespace rsi {

struct SpectralPeak {
  double frequency_hz = 0.0; ///< f_k = k / (n dt)
  double amplitude = 0.0;    ///< A_k, in the signal's unit
};

/// The `count` largest spectral peaks of x (uniform samples dt [s] apart),
/// fewer if the spectrum has fewer local maxima. Throws
/// std::invalid_argument for fewer than 4 samples, dt <= 0, count < 0, or a
/// non-finite sample.
std::vector<SpectralPeak> dominant_frequencies(const std::vector<double>& x, double dt,
                                               int count);

/// A_k for k = 0 .. n/2 (the amplitude spectrum the peaks are taken from).
std::vector<double> hann_amplitude_spectrum(const std::vector<double>& x);

} // namespace rsi
