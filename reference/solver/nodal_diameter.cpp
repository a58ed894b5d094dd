#include "nodal_diameter.hpp"

#include <cassert>
#include <cmath>
#include <complex>

namespace rsi {
namespace {

/// Energy in each harmonic n = 0..N/2 (n and N - n combined); by Parseval
/// the entries sum to N times the sum of squares of the mode.
Eigen::VectorXd harmonic_energy(const Eigen::Ref<const Eigen::VectorXd>& mode, int n_blocks,
                                int block_size) {
  assert(mode.size() == static_cast<Eigen::Index>(n_blocks) * block_size);
  const int half = n_blocks / 2;
  Eigen::VectorXd energy = Eigen::VectorXd::Zero(half + 1);
  for (int n = 0; n < n_blocks; ++n) {
    for (int j = 0; j < block_size; ++j) {
      std::complex<double> x = 0.0;
      for (int k = 0; k < n_blocks; ++k)
        x += mode(k * block_size + j) * std::polar(1.0, -2.0 * M_PI * n * k / n_blocks);
      energy(std::min(n, n_blocks - n)) += std::norm(x);
    }
  }
  return energy;
}

} // namespace

int nodal_diameter(const Eigen::Ref<const Eigen::VectorXd>& mode, int n_blocks, int block_size) {
  Eigen::Index n = 0;
  harmonic_energy(mode, n_blocks, block_size).maxCoeff(&n);
  return static_cast<int>(n);
}

double nodal_diameter_purity(const Eigen::Ref<const Eigen::VectorXd>& mode, int n_blocks,
                             int block_size) {
  const Eigen::VectorXd energy = harmonic_energy(mode, n_blocks, block_size);
  return energy.maxCoeff() / energy.sum();
}

} // namespace rsi
