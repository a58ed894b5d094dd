#pragma once
// The BLAS's own threads (OpenBLAS: as many as the cores the process may
// use). CHOLMOD's supernodal factorisation calls BLAS on its dense blocks,
// and a threaded BLAS sums in an order that depends on its thread count:
// under mpirun each rank is bound to one core (one BLAS thread) while one
// process alone gets two, so the same run gave different last bits
// (measured: a rotating sweep's subspace reduction, 4e-11 relative). rsi
// sweep parallelises over speeds (--jobs, ranks), so it runs the BLAS on
// one thread: a row's bytes then depend only on its speed and run.

namespace rsi {

/// Sets OpenBLAS to one thread; true if the BLAS is OpenBLAS (another BLAS
/// is left as it is, and false returned).
bool single_threaded_blas();

} // namespace rsi
