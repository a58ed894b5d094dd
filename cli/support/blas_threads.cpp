#include "blas_threads.hpp"

// OpenBLAS's own entry point, weak: null when the BLAS linked is not OpenBLAS.
extern "C" void openblas_set_num_threads(int) __attribute__((weak));

namespace rsi {

bool single_threaded_blas() {
  if (openblas_set_num_threads == nullptr) return false;
  openblas_set_num_threads(1);
  return true;
}

} // namespace rsi
