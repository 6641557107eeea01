// The dense kernels inside CHOLMOD's supernodal factorisation run in the system BLAS, which
// keeps its own thread pool; this caps it so `--threads N` means N for the whole solve.
#pragma once

namespace kontakt::linsolve {

/// Asks the BLAS in use (OpenBLAS or BLIS, found at run time) to use at most `threads`
/// threads from now on. Returns false when the BLAS offers no way to set it (e.g. the
/// single-threaded reference BLAS).
bool set_blas_threads(int threads);

/// Below this many flops a factorisation's dense kernels are too small for threads: waking
/// and parking the BLAS pool per supernode costs more than it saves (measured: a 1.2 GFlop
/// factorisation ran faster on one thread, a 76 GFlop one faster on two).
inline constexpr double kThreadedBlasFlops = 1e10;

/// Sets the BLAS to one thread for a factorisation of `flops`, or back to the cap of
/// set_blas_threads (all cores when never called) for a larger one.
void use_blas_threads_for(double flops);

}  // namespace kontakt::linsolve
