#include "response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_real.h>

namespace rsi {
namespace {

struct WavetableDeleter {
  void operator()(gsl_fft_real_wavetable* w) const { gsl_fft_real_wavetable_free(w); }
};
struct WorkspaceDeleter {
  void operator()(gsl_fft_real_workspace* w) const { gsl_fft_real_workspace_free(w); }
};

} // namespace

std::vector<double> hann_amplitude_spectrum(const std::vector<double>& x, int padding) {
  const size_t samples = x.size();
  if (samples < 4 || padding < 1)
    throw std::invalid_argument("hann_amplitude_spectrum: needs at least 4 samples and padding "
                                ">= 1, got " + std::to_string(samples) + " and " +
                                std::to_string(padding));
  const size_t n = samples * static_cast<size_t>(padding);
  for (double v : x)
    if (!std::isfinite(v))
      throw std::invalid_argument("hann_amplitude_spectrum: a sample is not finite");
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(samples);
  std::vector<double> data(n, 0.0); // zeros past the samples: the padding
  double window_sum = 0.0;
  for (size_t i = 0; i < samples; ++i) {
    const double w = 0.5 * (1.0 - std::cos(2.0 * M_PI * static_cast<double>(i) / samples));
    window_sum += w;
    data[i] = w * (x[i] - mean);
  }
  const std::unique_ptr<gsl_fft_real_wavetable, WavetableDeleter> table(
      gsl_fft_real_wavetable_alloc(n));
  const std::unique_ptr<gsl_fft_real_workspace, WorkspaceDeleter> work(
      gsl_fft_real_workspace_alloc(n));
  if (!table || !work) throw std::bad_alloc();
  const int status = gsl_fft_real_transform(data.data(), 1, n, table.get(), work.get());
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("hann_amplitude_spectrum: GSL FFT failed: ") +
                             gsl_strerror(status));
  // GSL's half-complex layout: data[0] = Re X_0; for 1 <= k < n/2,
  // data[2k-1] = Re X_k, data[2k] = Im X_k; for even n, data[n-1] = Re X_{n/2}.
  std::vector<double> amplitude(n / 2 + 1);
  amplitude[0] = std::abs(data[0]);
  for (size_t k = 1; 2 * k < n; ++k)
    amplitude[k] = std::hypot(data[2 * k - 1], data[2 * k]);
  if (n % 2 == 0) amplitude[n / 2] = std::abs(data[n - 1]);
  for (double& a : amplitude)
    a *= 2.0 / window_sum;
  return amplitude;
}

std::vector<SpectralPeak> dominant_frequencies(const std::vector<double>& x, double dt,
                                               int count) {
  if (!(dt > 0.0) || count < 0)
    throw std::invalid_argument("dominant_frequencies: dt must be > 0 and count >= 0");
  const std::vector<double> a = hann_amplitude_spectrum(x);
  const double resolution = 1.0 / (static_cast<double>(x.size()) * spectrum_padding * dt);
  std::vector<SpectralPeak> peaks;
  for (size_t k = 1; k + 1 < a.size(); ++k)
    if (a[k] > a[k - 1] && a[k] >= a[k + 1]) peaks.push_back({k * resolution, a[k]});
  // Largest first; equal amplitudes by frequency, so the order is fixed.
  std::sort(peaks.begin(), peaks.end(), [](const SpectralPeak& p, const SpectralPeak& q) {
    return p.amplitude != q.amplitude ? p.amplitude > q.amplitude
                                      : p.frequency_hz < q.frequency_hz;
  });
  if (static_cast<int>(peaks.size()) > count) peaks.resize(static_cast<size_t>(count));
  return peaks;
}

} // namespace rsi
