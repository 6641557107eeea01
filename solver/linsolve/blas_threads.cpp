#include "linsolve/blas_threads.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <initializer_list>
#include <thread>

namespace kontakt::linsolve {

namespace {

std::atomic<int> g_cap{0};  ///< set_blas_threads' value; 0: all cores

bool apply(int threads) {
  // Looked up by name so the build does not tie itself to one BLAS implementation; Debian
  // switches implementations through update-alternatives behind libblas.so.3.
  using SetThreads = void (*)(int);
  for (const char* symbol : {"openblas_set_num_threads", "bli_thread_set_num_threads"}) {
    if (auto fn = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, symbol))) {
      fn(threads);
      return true;
    }
  }
  return false;
}

}  // namespace

bool set_blas_threads(int threads) {
  g_cap = threads;
  return apply(threads);
}

void use_blas_threads_for(double flops) {
  const int cap = g_cap > 0 ? g_cap.load() : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  apply(flops < kThreadedBlasFlops ? 1 : cap);
}

}  // namespace kontakt::linsolve
