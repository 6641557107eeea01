// The dense kernels inside CHOLMOD's supernodal factorisation run in the system BLAS, which
// keeps its own thread pool; this caps it so `--threads N` means N for the whole solve.
#pragma once

namespace kontakt::linsolve {

/// Asks the BLAS in use (OpenBLAS or BLIS, found at run time) to use `threads` threads.
/// Returns false when the BLAS offers no way to set it (e.g. the single-threaded reference BLAS).
bool set_blas_threads(int threads);

}  // namespace kontakt::linsolve
